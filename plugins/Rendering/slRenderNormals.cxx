#include "slRenderNormals.h"

#include "slPolyDataNormals.h"
#include "slUpdateOrThrow.h"

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkSmartPointer<vtkPolyData> slWithRenderNormals(
  vtkPolyData* mesh, const slRenderNormalsOptions& options)
{
  static_assert(slPolyDataNormals::ANGLE == slRenderNormalsOptions().weighting, "the default is angle weighting");
  if (mesh->GetPointData()->GetNormals() && !options.replace)
  {
    return mesh;
  }
  vtkNew<slPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->SetWeighting(options.weighting);
  normals->SetSplitting(options.splitting);
  normals->SetFeatureAngle(options.featureAngle);
  normals->ConsistencyOn();
  normals->WeldCoincidentPointsOn();
  normals->ComputeCellNormalsOn();
  slUpdateOrThrow(normals);
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}
