#ifndef slLightingPassUniforms_h
#define slLightingPassUniforms_h
/**
 * @file slLightingPassUniforms.h
 * @brief The uniforms slLightingPass sets in its shaders: the names of the
 * lights' and materials' fields, and the uploads of lights, materials and
 * a .brdf file's parameters. Internal to ShadeLab::RenderPasses.
 *
 * Apart from the pass because the field lists come from the lighting core's
 * X-macros (SHADELAB_LIGHT_FIELDS, SHADELAB_MATERIAL_PARAMETERS): a field
 * added there is named and uploaded here without the pass changing.
 */

#include "shadelab/LightingGLSL.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace shadelab
{
struct BrdfFile;
}
class vtkProperty;
class vtkShaderProgram;

namespace slLightingPassUniforms
{

/// @p v (a VTK colour, position or direction) as the shaders' vec3.
glm::vec3 toVec3(const double v[3]);

/// The uniform names of light i's fields, in the order of
/// SHADELAB_LIGHT_FIELDS ("slLights[2].position", ...), made once.
struct LightUniformNames
{
  std::vector<std::string> fields;
  explicit LightUniformNames(int i);
};

/// The uniform names of a material's fields, in the order of
/// SHADELAB_MATERIAL_PARAMETERS ("slMat.ambient", ...), made once.
struct MaterialUniformNames
{
  std::vector<std::string> fields;
  explicit MaterialUniformNames(const std::string& uniform);
};

/// Every field of @p light as the uniforms named @p names.
void setLightUniforms(vtkShaderProgram* program, const LightUniformNames& names, const shadelab::glsl::slLight& light);

/// Every field of @p m as the uniforms named @p names.
void setMaterialUniforms(
  vtkShaderProgram* program, const MaterialUniformNames& names, const shadelab::glsl::slMaterial& m);

/// The parameters of the .brdf file @p file, at @p values (one per
/// parameter, in the file's order: floats and bools in x, colours RGB), as
/// the uniforms the file's GLSL declares (brdfUniformDeclarations()).
void setBrdfUniforms(vtkShaderProgram* program, const shadelab::BrdfFile& file, const std::vector<glm::vec3>& values);

/// The material of an actor's vtkProperty, as VTK's own lighting reads it;
/// the numbers VTK has no place for (roughness, ...) at their defaults.
shadelab::glsl::slMaterial materialOf(vtkProperty* p);

} // namespace slLightingPassUniforms

#endif
