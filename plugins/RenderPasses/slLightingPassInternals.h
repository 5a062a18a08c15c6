#ifndef slLightingPassInternals_h
#define slLightingPassInternals_h
/**
 * @file slLightingPassInternals.h
 * @brief slLightingPass's private state (slLightingPass::Internals).
 * Internal to ShadeLab::RenderPasses.
 *
 * In a header because the pass's member functions are defined in several
 * files: slLightingPass.cxx (lights, shaders, uniforms),
 * slLightingPassBrdf.cxx (the .brdf file) and
 * slLightingPassInterpolation.cxx (the actors' interpolation).
 */

#include "slLightingPass.h"
#include "slLightingPassInterpolation.h"
#include "slLightingPassQueries.h"
#include "slLightingPassUniforms.h"
#include "slPassObjectMap.h"

#include "shadelab/BrdfFile.h"
#include "shadelab/LightingGLSL.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

class vtkMapper;
class vtkRenderer;
class vtkShaderProgram;

struct slLightingPass::Internals
{
  std::vector<shadelab::glsl::slLight> LightsVC; // view coordinates
  std::vector<slLightingPassUniforms::LightUniformNames> Names;
  const slLightingPassUniforms::MaterialUniformNames FrontMaterialNames{ "slMat" };
  const slLightingPassUniforms::MaterialUniformNames BackMaterialNames{ "slMatBack" };
  bool Parallel = false;
  bool ReportedTooManyLights = false; // until the lights fit again
  bool WarnedNoNormals = false;
  bool WarnedNoTangents = false;
  bool WarnedShadows = false;
  // Mappers given the slTangentMC attribute (a new mapper at a freed one's
  // address is not taken for it).
  slPassObjectMap<vtkMapper, bool> TangentMappers;
  // What each shader program the pass sets is (ProgramFacts).
  slPassObjectMap<vtkShaderProgram, slLightingPassQueries::ProgramFacts> Programs;
  // The properties whose interpolation the pass changed, with the user's
  // (weak: the pass keeps no property alive).
  slLightingPassInterpolation::InterpolationChanges Interpolations;
  // The renderers the pass has drawn (WatchRenderer).
  slPassObjectMap<vtkRenderer, slLightingPassInterpolation::DrawnRenderer> Renderers;

  /// The facts of @p program, read from its fragment shader the first time
  /// it is asked for (Programs).
  const slLightingPassQueries::ProgramFacts& FactsOf(vtkShaderProgram* program);

  // The .brdf file, if any: its GLSL as the shaders hold it, its parameter
  // values (uniforms), and what compiling its GLSL on its own gave.
  std::unique_ptr<shadelab::BrdfFile> Brdf;
  std::string BrdfSource;
  std::vector<glm::vec3> BrdfValues;
  // What compiling each (file, text) gave: "" or its one-line error. VTK
  // keeps built variants, so a text already checked is not seen again.
  std::map<std::string, std::string> BrdfChecked;

  std::string BrdfKey() const { return this->Brdf->path + '\n' + this->BrdfSource; }
  std::string BrdfError;
  int ShaderBuilds = 0;

  std::vector<int> LightTypes() const
  {
    std::vector<int> types;
    for (const shadelab::glsl::slLight& l : this->LightsVC)
    {
      types.push_back(l.type);
    }
    return types;
  }
};

#endif
