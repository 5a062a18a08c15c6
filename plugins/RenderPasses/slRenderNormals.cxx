#include "slRenderNormals.h"

#include "slPolyDataNormals.h"

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkSmartPointer<vtkPolyData> slWithRenderNormals(vtkPolyData* mesh, std::string& error)
{
  if (mesh->GetPointData()->GetNormals())
  {
    return mesh;
  }
  vtkNew<slPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->SetWeighting(slPolyDataNormals::ANGLE);
  normals->SplittingOn();
  normals->SetFeatureAngle(30.0);
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
