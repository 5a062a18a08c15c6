#include "slTangentsCheck.h"

#include "shadelab/Scene.h"
#include "slLitFilter.h"

std::string slTangentsProblem(vtkPolyData* mesh, int model)
{
  const auto m = static_cast<shadelab::ShadingModel>(model);
  if (!shadelab::isLightingModel(model) || !shadelab::modelNeedsTangents(m) || slLitFilter::HasTangents(mesh))
  {
    return "";
  }
  return std::string("the ") + shadelab::modelName(m) +
    " model is anisotropic and needs tangents (a 4-component point array \"Tangents\"); compute them first "
    "(shadelab tangents, slPolyDataTangents)";
}
