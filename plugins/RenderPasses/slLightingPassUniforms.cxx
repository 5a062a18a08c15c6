/**
 * @file slLightingPassUniforms.cxx
 * @brief The uniforms slLightingPass sets in its shaders (see
 * slLightingPassUniforms.h).
 */
#include "slLightingPassUniforms.h"

#include "shadelab/BrdfFile.h"
#include "shadelab/LightingTables.h"
#include "shadelab/Scene.h"

#include <vtkProperty.h>
#include <vtkShaderProgram.h>

namespace slLightingPassUniforms
{

namespace
{
void setUniform(vtkShaderProgram* program, const std::string& name, const glm::vec3& value)
{
  program->SetUniform3f(name.c_str(), &value[0]);
}
void setUniform(vtkShaderProgram* program, const std::string& name, float value)
{
  program->SetUniformf(name.c_str(), value);
}
/// The light's type is compiled into the shaders (slLightTypeOf), not uploaded.
void setUniform(vtkShaderProgram*, const std::string&, int) {}
} // namespace

glm::vec3 toVec3(const double v[3])
{
  return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

LightUniformNames::LightUniformNames(int i)
{
  const std::string base = "slLights[" + std::to_string(i) + "].";
#define SHADELAB_NAME(type, field, ...) fields.push_back(base + #field);
  SHADELAB_LIGHT_FIELDS(SHADELAB_NAME)
#undef SHADELAB_NAME
}

MaterialUniformNames::MaterialUniformNames(const std::string& uniform)
{
#define SHADELAB_NAME(type, field, ...) fields.push_back(uniform + "." #field);
  SHADELAB_MATERIAL_PARAMETERS(SHADELAB_NAME)
#undef SHADELAB_NAME
}

void setLightUniforms(vtkShaderProgram* program, const LightUniformNames& names, const shadelab::glsl::slLight& light)
{
  size_t f = 0;
#define SHADELAB_UPLOAD(type, field, ...) setUniform(program, names.fields[f++], light.field);
  SHADELAB_LIGHT_FIELDS(SHADELAB_UPLOAD)
#undef SHADELAB_UPLOAD
}

void setMaterialUniforms(
  vtkShaderProgram* program, const MaterialUniformNames& names, const shadelab::glsl::slMaterial& m)
{
  size_t f = 0;
#define SHADELAB_UPLOAD(type, field, ...) setUniform(program, names.fields[f++], m.field);
  SHADELAB_MATERIAL_PARAMETERS(SHADELAB_UPLOAD)
#undef SHADELAB_UPLOAD
}

void setBrdfUniforms(vtkShaderProgram* program, const shadelab::BrdfFile& file, const std::vector<glm::vec3>& values)
{
  for (size_t i = 0; i < file.parameters.size(); ++i)
  {
    const shadelab::BrdfParameter& p = file.parameters[i];
    const glm::vec3& v = values[i];
    switch (p.kind)
    {
      case shadelab::BrdfParameter::Kind::Float:
        program->SetUniformf(p.name.c_str(), v.x);
        break;
      case shadelab::BrdfParameter::Kind::Bool:
        program->SetUniformi(p.name.c_str(), v.x != 0.0f ? 1 : 0);
        break;
      case shadelab::BrdfParameter::Kind::Color:
        program->SetUniform3f(p.name.c_str(), &v[0]);
        break;
    }
  }
}

shadelab::glsl::slMaterial materialOf(vtkProperty* p)
{
  shadelab::glsl::slMaterial m = shadelab::toEvaluationMaterial(shadelab::SceneMaterial());
  m.ambient = static_cast<float>(p->GetAmbient()) * toVec3(p->GetAmbientColor());
  m.diffuse = static_cast<float>(p->GetDiffuse()) * toVec3(p->GetDiffuseColor());
  m.specular = static_cast<float>(p->GetSpecular()) * toVec3(p->GetSpecularColor());
  m.emission = glm::vec3(0.0f);
  m.shininess = static_cast<float>(p->GetSpecularPower());
  return m;
}

} // namespace slLightingPassUniforms
