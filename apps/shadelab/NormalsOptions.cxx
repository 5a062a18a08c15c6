#include "NormalsOptions.h"

#include "Inputs.h"

#include "slPolyDataFilter.h"
#include "slPolyDataNormals.h"
#include "slUpdateOrThrow.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

#include <iostream>

namespace shadelab
{
namespace app
{

std::vector<OptionSpec> normalsOptionSpecs()
{
  return {
    { "weighting", "w", "NAME", "vertex normal weighting: uniform, area, angle (default), max" },
    { "feature-angle", "", "DEG", "edges sharper than this are split (0-180, default 30)" },
    { "no-split", "", "", "do not split points along sharp edges" },
    { "no-consistency", "", "", "do not reorder polygons to agree across shared edges" },
    { "outward", "", "", "orient closed surfaces outward" },
    { "weld", "", "", "compute normals as if coincident points were one (unwelded seams)" },
    meshCompressionOption(),
  };
}

void applyNormalsOptions(const CommandLine& cl, slPolyDataNormals* filter)
{
  if (cl.has("weighting"))
  {
    const std::string name = cl.get("weighting");
    int found = -1;
    for (int w = slPolyDataNormals::UNIFORM; w <= slPolyDataNormals::MAX; ++w)
    {
      found = name == slPolyDataNormals::GetWeightingName(w) ? w : found;
    }
    if (found < 0)
    {
      throw UsageError("unknown --weighting \"" + name + "\" (uniform, area, angle, max)");
    }
    filter->SetWeighting(found);
  }
  filter->SetFeatureAngle(cl.getNumber("feature-angle", 30.0, 0.0, 180.0));
  filter->SetSplitting(!cl.has("no-split"));
  filter->SetConsistency(!cl.has("no-consistency"));
  filter->SetAutoOrientNormals(cl.has("outward"));
  filter->SetWeldCoincidentPoints(cl.has("weld"));
}

vtkSmartPointer<vtkPolyData> runMeshFilter(slPolyDataFilter* filter, const std::string& meshPath)
{
  return inStep(std::string("in ") + filter->GetClassName(), [&] {
    slUpdateOrThrow(filter, meshPath + ": ");
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->ShallowCopy(vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0)));
    return out;
  });
}

void noteNonPolygonCells(vtkPolyData* mesh, const std::string& command, const std::string& meshPath)
{
  const vtkIdType others = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines();
  if (others > 0)
  {
    std::cerr << "shadelab " << command << ": note: " << meshPath << ": " << others
              << " vertex and line cells are not polygons: passed through unchanged\n";
  }
}

} // namespace app
} // namespace shadelab
