#include "slBRDFFileEvaluator.h"

#include "shadelab/AlbedoQuadrature.h"
#include "shadelab/Error.h"

#include "slBRDFLobeSource.h"
#include "slOffscreen.h"

#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{
/// Texels per row of the direction texture and rows per render (OpenGL 3.2
/// guarantees textures of 1024 x 1024).
constexpr size_t kRowLength = 1024;
constexpr size_t kMaxRows = 1024;

const char* const kVertexShader = "#version 150\n"
                                  "in vec4 ndCoordIn;\n"
                                  "in vec2 texCoordIn;\n"
                                  "out vec2 texCoord;\n"
                                  "void main()\n"
                                  "{\n"
                                  "  gl_Position = ndCoordIn;\n"
                                  "  texCoord = texCoordIn;\n"
                                  "}\n";

/// The fragment shader: the file's uniforms directly before its shader
/// text (brdfCompileError() maps an error on them to the parameter's line),
/// then main(), which evaluates BRDF at the texel's direction.
/// @p firstShaderLine receives the source line of the shader text's first line.
std::string fragmentShader(const shadelab::BrdfFile& file, int& firstShaderLine)
{
  std::string source = "#version 150\n"
                       "uniform sampler2D slDirections;\n"
                       "uniform vec3 slToLight;\n"
                       "in vec2 texCoord;\n";
  source += shadelab::brdfUniformDeclarations(file);
  firstShaderLine = static_cast<int>(std::count(source.begin(), source.end(), '\n')) + 1;
  source += file.shader;
  source += "\n//VTK::Output::Dec\n"
            "void main()\n"
            "{\n"
            "  ivec2 slTexel = ivec2(texCoord * vec2(textureSize(slDirections, 0)));\n"
            "  vec3 slV = texelFetch(slDirections, slTexel, 0).xyz;\n"
            "  // Alpha (not read back) keeps texCoord in use whatever BRDF reads.\n"
            "  gl_FragData[0] = vec4(BRDF(slToLight, slV, vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0),\n"
            "    vec3(0.0, 1.0, 0.0)), texCoord.x);\n"
            "}\n";
  return source;
}

/// What vtkOpenGLShaderCache makes of the fragment shader (its one output
/// declared and named), so that the check compiles exactly what runs.
std::string asCompiled(std::string source)
{
  vtkShaderProgram::Substitute(source, "gl_FragData[0]", "fragOutput0");
  vtkShaderProgram::Substitute(source, "//VTK::Output::Dec", "out vec4 fragOutput0;\n");
  return source;
}

/// The driver's log for a program of the two compiled shaders that does not
/// link, or "" if it links.
std::string linkProblem(int vertex, int fragment)
{
  const GLuint program = glCreateProgram();
  glAttachShader(program, static_cast<GLuint>(vertex));
  glAttachShader(program, static_cast<GLuint>(fragment));
  glBindFragDataLocation(program, 0, "fragOutput0");
  glLinkProgram(program);
  GLint linked = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  std::string log;
  if (linked != GL_TRUE)
  {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    log.assign(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, &log[0]);
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    if (log.empty())
    {
      log = "the shader does not link";
    }
  }
  glDetachShader(program, static_cast<GLuint>(vertex));
  glDetachShader(program, static_cast<GLuint>(fragment));
  glDeleteProgram(program);
  return log;
}
} // namespace

struct slBRDFFileEvaluator::Internals
{
  shadelab::BrdfFile File;
  std::vector<glm::vec3> Values;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkOpenGLRenderWindow* GL = nullptr;
  std::string FragmentSource;
  // Destroyed before the window (members are destroyed in reverse order).
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;

  void SetUniforms(vtkShaderProgram* program)
  {
    for (size_t k = 0; k < File.parameters.size(); ++k)
    {
      const shadelab::BrdfParameter& p = File.parameters[k];
      const char* name = p.name.c_str();
      // A uniform the shader does not read is not in the program: setting it fails harmlessly.
      switch (p.kind)
      {
        case shadelab::BrdfParameter::Kind::Float:
          program->SetUniformf(name, Values[k].x);
          break;
        case shadelab::BrdfParameter::Kind::Bool:
          program->SetUniformi(name, Values[k].x != 0.0f ? 1 : 0);
          break;
        case shadelab::BrdfParameter::Kind::Color:
          program->SetUniform3f(name, &Values[k].x);
          break;
      }
    }
  }

  /// One render of at most kRowLength x kMaxRows directions.
  void EvaluateBlock(const glm::vec3& toLight, const glm::vec3* directions, size_t count, glm::vec3* out)
  {
    const unsigned int width = static_cast<unsigned int>(std::min(count, kRowLength));
    const unsigned int height = static_cast<unsigned int>((count + width - 1) / width);
    std::vector<float> texels(static_cast<size_t>(width) * height * 3, 0.0f);
    std::copy(&directions[0].x, &directions[0].x + 3 * count, texels.begin());

    GL->MakeCurrent();
    vtkNew<vtkTextureObject> input;
    input->SetContext(GL);
    input->SetMinificationFilter(vtkTextureObject::Nearest);
    input->SetMagnificationFilter(vtkTextureObject::Nearest);
    vtkNew<vtkTextureObject> output;
    output->SetContext(GL);
    if (!input->Create2DFromRaw(width, height, 3, VTK_FLOAT, texels.data()) ||
      !output->Allocate2D(width, height, 4, VTK_FLOAT))
    {
      throw shadelab::Error(File.path + ": cannot create float textures of " + std::to_string(width) + " x " +
        std::to_string(height) + " texels");
    }
    vtkNew<vtkOpenGLFramebufferObject> fbo;
    fbo->SetContext(GL);
    vtkOpenGLState* state = GL->GetState();
    fbo->SaveCurrentBindingsAndBuffers();
    fbo->Bind();
    fbo->AddColorAttachment(0, output);
    fbo->ActivateDrawBuffer(0);
    fbo->ActivateReadBuffer(0);
    const char* status = "";
    if (!vtkOpenGLFramebufferObject::GetFrameBufferStatus(vtkOpenGLFramebufferObject::GetBothMode(), status))
    {
      fbo->RestorePreviousBindingsAndBuffers();
      throw shadelab::Error(File.path + ": cannot render to a float framebuffer: " + status);
    }
    state->vtkglViewport(0, 0, static_cast<int>(width), static_cast<int>(height));
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_SCISSOR_TEST);

    GL->GetShaderCache()->ReadyShaderProgram(Quad->Program);
    input->Activate();
    vtkShaderProgram* program = Quad->Program;
    program->SetUniformi("slDirections", input->GetTextureUnit());
    program->SetUniform3f("slToLight", &toLight.x);
    SetUniforms(program);
    Quad->Render();
    input->Deactivate();

    std::vector<float> pixels(static_cast<size_t>(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, static_cast<GLsizei>(width), static_cast<GLsizei>(height), GL_RGBA, GL_FLOAT, pixels.data());
    fbo->RestorePreviousBindingsAndBuffers();
    for (size_t k = 0; k < count; ++k)
    {
      out[k] = glm::vec3(pixels[4 * k], pixels[4 * k + 1], pixels[4 * k + 2]);
    }
  }
};

slBRDFFileEvaluator::slBRDFFileEvaluator(const shadelab::BrdfFile& file, const std::vector<glm::vec3>& values)
  : I(new Internals)
{
  I->File = file;
  I->Values = values;
  I->Values.resize(file.parameters.size(), glm::vec3(0.0f));
  const std::string displayProblem = slDisplayProblem();
  if (!displayProblem.empty())
  {
    throw shadelab::Error(displayProblem);
  }
  I->Window = slOffscreenWindow(1, 1);
  I->GL = vtkOpenGLRenderWindow::SafeDownCast(I->Window);
  if (!I->GL)
  {
    throw shadelab::Error(file.path + ": evaluating a .brdf file needs VTK's OpenGL render window");
  }
  I->GL->Initialize();
  I->GL->MakeCurrent();

  // Compile and link here, where the driver's log can be read; the shader
  // cache then builds the same program.
  int firstShaderLine = 0;
  I->FragmentSource = fragmentShader(file, firstShaderLine);
  vtkNew<vtkShader> vertex, fragment;
  vertex->SetType(vtkShader::Vertex);
  vertex->SetSource(kVertexShader);
  fragment->SetType(vtkShader::Fragment);
  fragment->SetSource(asCompiled(I->FragmentSource));
  if (!vertex->Compile())
  {
    throw shadelab::Error(file.path + ": the evaluation's vertex shader does not compile: " + vertex->GetError());
  }
  if (!fragment->Compile())
  {
    throw shadelab::Error(shadelab::brdfCompileError(file, fragment->GetError(), firstShaderLine));
  }
  const std::string linkLog = linkProblem(vertex->GetHandle(), fragment->GetHandle());
  if (!linkLog.empty())
  {
    throw shadelab::Error(shadelab::brdfCompileError(file, linkLog, firstShaderLine));
  }
  I->Quad.reset(new vtkOpenGLQuadHelper(I->GL, kVertexShader, I->FragmentSource.c_str(), ""));
  if (!I->Quad->Program)
  {
    throw shadelab::Error(file.path + ": VTK's shader cache rejects the shader");
  }
}

slBRDFFileEvaluator::~slBRDFFileEvaluator()
{
  if (I->GL)
  {
    I->GL->MakeCurrent();
  }
  I->Quad.reset();
}

const shadelab::BrdfFile& slBRDFFileEvaluator::GetFile() const
{
  return I->File;
}

std::vector<glm::vec3> slBRDFFileEvaluator::Evaluate(const glm::vec3& toLight, const std::vector<glm::vec3>& directions)
{
  std::vector<glm::vec3> values(directions.size());
  const size_t block = kRowLength * kMaxRows;
  for (size_t first = 0; first < directions.size(); first += block)
  {
    const size_t count = std::min(block, directions.size() - first);
    I->EvaluateBlock(toLight, &directions[first], count, &values[first]);
  }
  return values;
}

double slBRDFFileEvaluator::Albedo(const glm::dvec3& toLight)
{
  const shadelab::AlbedoQuadrature rule = shadelab::albedoQuadrature(toLight);
  const std::vector<glm::vec3> directions(rule.directions.begin(), rule.directions.end());
  const double albedo = shadelab::albedoFromValues(rule, Evaluate(glm::vec3(toLight), directions));
  if (!std::isfinite(albedo))
  {
    char degrees[32];
    std::snprintf(degrees, sizeof degrees, "%g",
      std::acos(std::clamp(toLight.z / glm::length(toLight), -1.0, 1.0)) * 180.0 / 3.14159265358979323846);
    throw shadelab::Error(
      I->File.path + ": BRDF gives a value that is not finite at incidence " + degrees + " degrees: no albedo");
  }
  return albedo;
}

double slBRDFFileEvaluator::AlbedoAtIncidence(double degrees)
{
  vtkNew<slBRDFLobeSource> convention;
  convention->SetIncidenceAngle(degrees);
  double L[3];
  convention->GetDirectionToLight(L);
  return this->Albedo(glm::dvec3(L[0], L[1], L[2]));
}

void slBRDFFileEvaluator::SetLobeValues(slBRDFLobeSource* lobe)
{
  vtkNew<vtkFloatArray> surface, slice;
  lobe->ComputeOutgoingDirections(surface, slice);
  double L[3];
  lobe->GetDirectionToLight(L);
  const glm::vec3 toLight(glm::dvec3(L[0], L[1], L[2]));
  auto evaluate = [&](vtkFloatArray* directions) {
    std::vector<glm::vec3> V(static_cast<size_t>(directions->GetNumberOfTuples()));
    for (size_t k = 0; k < V.size(); ++k)
    {
      directions->GetTypedTuple(static_cast<vtkIdType>(k), &V[k].x);
    }
    const std::vector<glm::vec3> f = this->Evaluate(toLight, V);
    auto values = vtkSmartPointer<vtkFloatArray>::New();
    values->SetNumberOfComponents(3);
    values->SetNumberOfTuples(static_cast<vtkIdType>(f.size()));
    for (size_t k = 0; k < f.size(); ++k)
    {
      values->SetTypedTuple(static_cast<vtkIdType>(k), &f[k].x);
    }
    return values;
  };
  lobe->SetBRDFValues(evaluate(surface), evaluate(slice));
}
