#include "slRenderNormals.h"

#include "slPolyDataNormals.h"

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkSmartPointer<vtkPolyData> slWithRenderNormals(
  vtkPolyData* mesh, std::string& error, const slRenderNormalsOptions& options)
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
  normals->Update();
  if (*normals->GetErrorMessage())
  {
    error = normals->GetErrorMessage();
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}
