#ifndef slBRDFFileEvaluator_h
#define slBRDFFileEvaluator_h
/**
 * @class   slBRDFFileEvaluator
 * @brief   A BRDF Explorer `.brdf` file's `vec3 BRDF(vec3 L, vec3 V, vec3 N,
 *          vec3 X, vec3 Y)` evaluated on the GPU at a list of outgoing
 *          directions, and its directional albedo.
 *
 * The file's GLSL cannot run on the CPU, so each evaluation is an offscreen
 * float render: the directions go up as an RGB32F texture, a full-screen
 * quad (vtkOpenGLQuadHelper) into an RGBA32F framebuffer object evaluates
 * the BRDF once per texel with N = +z, X = +x, Y = +y and the file's
 * parameters as uniforms, and the values are read back as floats.
 *
 * Albedo() integrates f_r cos(theta_o) over the hemisphere on the nodes of
 * shadelab::albedoQuadrature() (see AlbedoQuadrature.h for its accuracy):
 * one render of about 20,000 texels per incidence.
 *
 * Errors are shadelab::Error, one line: no X display or OpenGL context;
 * a shader that does not compile, as shadelab::brdfCompileError() gives
 * it (`FILE:LINE: the driver's message`, LINE the .brdf file's); a shader
 * that does not link (`FILE: message`); a BRDF value that is not finite in
 * an albedo.
 *
 * C++ only (not wrapped). Each object holds its own offscreen window and
 * OpenGL context.
 *
 * @warning Needs an X display, like every ShadeLab rendering (xvfb-run).
 *
 * @sa shadelab::BrdfFile slBRDFLobeSource slLobeImageRenderer
 */

#include "ShadeLabRenderingModule.h"

#include "shadelab/BrdfFile.h"

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

class slBRDFLobeSource;

class SHADELABRENDERING_EXPORT slBRDFFileEvaluator
{
public:
  /// Opens the offscreen context and compiles @p file's shader with the
  /// values of its parameters (brdfParameterValues(), one per parameter).
  slBRDFFileEvaluator(const shadelab::BrdfFile& file, const std::vector<glm::vec3>& parameterValues);
  ~slBRDFFileEvaluator();
  slBRDFFileEvaluator(const slBRDFFileEvaluator&) = delete;
  slBRDFFileEvaluator& operator=(const slBRDFFileEvaluator&) = delete;

  /// f_r(L, V) for the unit direction toward the light @p toLight and each
  /// unit outgoing direction V of @p directions, in their order.
  std::vector<glm::vec3> Evaluate(const glm::vec3& toLight, const std::vector<glm::vec3>& directions);

  /// The directional albedo (mean of R, G, B) for the unit direction
  /// toward the light @p toLight.
  double Albedo(const glm::dvec3& toLight);

  /// Albedo() for the light of an slBRDFLobeSource at @p degrees of
  /// incidence (in the x-z plane, on the -x side).
  double AlbedoAtIncidence(double degrees);

  /// Gives @p lobe this BRDF (slBRDFLobeSource::SetBRDFValues()) at the
  /// directions of its points, for its incidence angle.
  void SetLobeValues(slBRDFLobeSource* lobe);

  const shadelab::BrdfFile& GetFile() const;

private:
  struct Internals;
  std::unique_ptr<Internals> I;
};

#endif
