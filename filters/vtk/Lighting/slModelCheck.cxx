#include "slModelCheck.h"

#include "shadelab/Scene.h"

#include <vtkObject.h>

bool slCheckModel(vtkObject* self, int model, bool sceneOwnAllowed, const char* setter)
{
  const std::string problem = sceneOwnAllowed && model == -1 ? std::string() : shadelab::modelValueProblem(model);
  if (problem.empty())
  {
    return true;
  }
  vtkErrorWithObjectMacro(self, << setter << ": " << problem << (sceneOwnAllowed ? ", or -1 for the scene's own" : ""));
  return false;
}

bool slCheckModelName(vtkObject* self, const char* name, const char* setter)
{
  const std::string problem = shadelab::modelNameProblem(name);
  if (problem.empty())
  {
    return true;
  }
  vtkErrorWithObjectMacro(self, << setter << ": " << problem);
  return false;
}

int slModelNumber(const char* name)
{
  shadelab::ShadingModel model;
  return name && shadelab::parseModelName(name, model) ? static_cast<int>(model) : -2;
}

std::string slModelNameOf(int model)
{
  return shadelab::modelValueProblem(model).empty() ? shadelab::modelName(static_cast<shadelab::ShadingModel>(model))
                                                     : std::string();
}
