/**
 * @file slLightingPassBrdf.cxx
 * @brief slLightingPass's BRDF Explorer .brdf file: loading it (from a path,
 * a text or the scene), its parameters, and checking that its GLSL compiles.
 *
 * Apart from slLightingPass.cxx because it is a public API of its own (the
 * .brdf half of slLightingPass.h) that only fills Internals::Brdf*; the
 * shaders and uniforms read those where the rest of the lighting is done.
 */
#include "slLightingPass.h"

#include "slLightingPassInternals.h"
#include "slLightingPassShaders.h"
#include "slScene.h"

#include "shadelab/BrdfAssignment.h"
#include "shadelab/BrdfFile.h"
#include "shadelab/Error.h"
#include "shadelab/Scene.h"

#include <vtkNew.h>
#include <vtkShader.h>

namespace shaders = slLightingPassShaders;

void slLightingPass::SetBrdfFromScene()
{
  const shadelab::SceneBrdf& brdf = this->Scene->GetScene().brdf;
  if (brdf.file.empty())
  {
    this->RemoveBrdf();
    return;
  }
  // Read each time: the file may have been edited since.
  try
  {
    const shadelab::BrdfFile file = shadelab::readBrdfFile(this->Scene->GetBrdfFilePath());
    this->SetBrdf(file, shadelab::brdfParameterValues(file, brdf.parameters));
  }
  catch (const shadelab::Error& e)
  {
    const std::string& source = this->Scene->GetScene().sourceFile;
    this->RemoveBrdf();
    this->Internal->BrdfError = e.what() + (source.empty() ? std::string() : " (brdf of " + source + ")");
    vtkErrorMacro(<< this->Internal->BrdfError);
  }
}

void slLightingPass::SetBrdf(const shadelab::BrdfFile& file, const std::vector<glm::vec3>& values)
{
  Internals& in = *this->Internal;
  const std::string source = shaders::brdfSource(shadelab::brdfUniformDeclarations(file), file.shader);
  if (source != in.BrdfSource)
  {
    this->ShaderStageTime.Modified(); // the BRDF's text is compiled into the shaders
  }
  in.Brdf.reset(new shadelab::BrdfFile(file));
  in.BrdfSource = source;
  in.BrdfValues = values;
  in.BrdfValues.resize(file.parameters.size());
  const auto checked = in.BrdfChecked.find(in.BrdfKey());
  in.BrdfError = checked == in.BrdfChecked.end() ? std::string() : checked->second;
  this->Modified();
}

bool slLightingPass::LoadBrdfFile(const char* path)
{
  try
  {
    const shadelab::BrdfFile file = shadelab::readBrdfFile(path ? path : "");
    this->SetBrdf(file, shadelab::brdfParameterValues(file, {}));
    return true;
  }
  catch (const shadelab::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return false;
  }
}

bool slLightingPass::SetBrdfText(const char* text, const char* path)
{
  try
  {
    const shadelab::BrdfFile file = shadelab::parseBrdfText(text ? text : "", path ? path : "(text)");
    this->SetBrdf(file, shadelab::brdfParameterValues(file, {}));
    return true;
  }
  catch (const shadelab::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return false;
  }
}

void slLightingPass::RemoveBrdf()
{
  Internals& in = *this->Internal;
  if (in.Brdf)
  {
    in.Brdf.reset();
    in.BrdfSource.clear();
    in.BrdfValues.clear();
    in.BrdfError.clear();
    this->ShaderStageTime.Modified();
    this->Modified();
  }
}

bool slLightingPass::HasBrdf() const
{
  return this->Internal->Brdf != nullptr;
}

const char* slLightingPass::GetBrdfFileName() const
{
  return this->Internal->Brdf ? this->Internal->Brdf->path.c_str() : "";
}

int slLightingPass::GetNumberOfBrdfParameters() const
{
  return this->Internal->Brdf ? static_cast<int>(this->Internal->Brdf->parameters.size()) : 0;
}

namespace
{
/// Parameter @p i of @p file, or null (after a warning) when out of range.
const shadelab::BrdfParameter* parameterAt(const shadelab::BrdfFile* file, int i)
{
  if (!file || i < 0 || i >= static_cast<int>(file->parameters.size()))
  {
    return nullptr;
  }
  return &file->parameters[static_cast<size_t>(i)];
}

void copyTo(const glm::vec3& v, double out[3])
{
  for (int c = 0; c < 3; ++c)
  {
    out[c] = static_cast<double>(v[c]);
  }
}
} // namespace

const char* slLightingPass::GetBrdfParameterName(int i) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  return p ? p->name.c_str() : nullptr;
}

int slLightingPass::GetBrdfParameterKind(int i) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  return p ? static_cast<int>(p->kind) : -1;
}

double slLightingPass::GetBrdfParameterMinimum(int i) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  return p ? static_cast<double>(p->minimum) : 0.0;
}

double slLightingPass::GetBrdfParameterMaximum(int i) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  return p ? static_cast<double>(p->maximum) : 0.0;
}

void slLightingPass::GetBrdfParameterDefault(int i, double value[3]) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  copyTo(p ? p->defaultValue : glm::vec3(0.0f), value);
}

void slLightingPass::GetBrdfParameterValue(int i, double value[3]) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  copyTo(p ? this->Internal->BrdfValues[static_cast<size_t>(i)] : glm::vec3(0.0f), value);
}

bool slLightingPass::SetBrdfValues(const std::vector<std::string>& assignments)
{
  Internals& in = *this->Internal;
  if (!in.Brdf)
  {
    vtkErrorMacro(<< "no .brdf file to set parameters of");
    return false;
  }
  try
  {
    // The current values first (as assignments), then the new ones: the
    // core parses and checks every value, as it does for --param.
    std::vector<std::string> all;
    for (size_t i = 0; i < in.Brdf->parameters.size(); ++i)
    {
      all.push_back(shadelab::brdfAssignment(in.Brdf->parameters[i], in.BrdfValues[i]));
    }
    all.insert(all.end(), assignments.begin(), assignments.end());
    in.BrdfValues = shadelab::brdfParameterValues(*in.Brdf, all);
  }
  catch (const shadelab::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return false;
  }
  this->Modified(); // a uniform: the shaders stay as they are
  return true;
}

bool slLightingPass::SetBrdfParameter(const char* assignment)
{
  return this->SetBrdfValues({ assignment ? assignment : "" });
}

bool slLightingPass::SetBrdfParameter(const char* name, double value)
{
  return this->SetBrdfValues({ std::string(name ? name : "") + "=" + shadelab::brdfNumberText(value) });
}

bool slLightingPass::SetBrdfParameter(const char* name, double r, double g, double b)
{
  return this->SetBrdfValues({ std::string(name ? name : "") + "=" + shadelab::brdfNumberText(r) + "," +
    shadelab::brdfNumberText(g) + "," + shadelab::brdfNumberText(b) });
}

const char* slLightingPass::GetBrdfError() const
{
  return this->Internal->BrdfError.c_str();
}

bool slLightingPass::CheckBrdf(const std::string& checkShader)
{
  Internals& in = *this->Internal;
  const auto checked = in.BrdfChecked.find(in.BrdfKey());
  if (checked != in.BrdfChecked.end())
  {
    in.BrdfError = checked->second;
    return in.BrdfError.empty();
  }
  vtkNew<vtkShader> shader;
  shader->SetType(vtkShader::Fragment);
  shader->SetSource(checkShader);
  const bool compiled = shader->Compile();
  const std::string log = shader->GetError();
  shader->Cleanup();
  in.BrdfError = compiled ? std::string()
                          : shadelab::brdfCompileError(*in.Brdf, log,
                              shaders::brdfShaderFirstLine(checkShader, static_cast<int>(in.Brdf->parameters.size())));
  in.BrdfChecked[in.BrdfKey()] = in.BrdfError;
  if (!compiled)
  {
    vtkErrorMacro(<< in.BrdfError);
  }
  return compiled;
}
