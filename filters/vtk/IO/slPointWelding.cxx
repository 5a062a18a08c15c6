#include "slPointWelding.h"

#include "slPointDeduplication.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <vector>

namespace
{
/// Point @p id as a row of doubles: coordinates, then every point-data tuple.
void pointRow(vtkPolyData* mesh, vtkIdType id, double* row)
{
  mesh->GetPoint(id, row);
  int at = 3;
  vtkPointData* pd = mesh->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    if (vtkDataArray* array = pd->GetArray(a))
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        row[at++] = array->GetComponent(id, c);
      }
    }
  }
}

vtkSmartPointer<vtkCellArray> remap(vtkCellArray* cells, const std::vector<std::int64_t>& newId)
{
  auto out = vtkSmartPointer<vtkCellArray>::New();
  out->AllocateExact(cells->GetNumberOfCells(), cells->GetNumberOfConnectivityIds());
  vtkNew<vtkIdList> ids;
  for (cells->InitTraversal(); cells->GetNextCell(ids);)
  {
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      ids->SetId(k, newId[static_cast<size_t>(ids->GetId(k))]);
    }
    out->InsertNextCell(ids);
  }
  return out;
}
} // namespace

long long slMergeIdenticalPoints(vtkPolyData* mesh)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  size_t width = 3;
  for (int a = 0; a < mesh->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = mesh->GetPointData()->GetArray(a);
    width += array ? static_cast<size_t>(array->GetNumberOfComponents()) : 0;
  }
  std::vector<double> rows(static_cast<size_t>(n) * width);
  for (vtkIdType i = 0; i < n; ++i)
  {
    pointRow(mesh, i, &rows[static_cast<size_t>(i) * width]);
  }
  std::vector<std::int64_t> newId;
  const std::vector<std::int64_t> kept = slUniqueRows(
    reinterpret_cast<const unsigned char*>(rows.data()), width * sizeof(double), static_cast<size_t>(n), newId);
  const long long removed = n - static_cast<vtkIdType>(kept.size());
  if (removed == 0)
  {
    return 0;
  }

  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints()->GetDataType());
  points->SetNumberOfPoints(static_cast<vtkIdType>(kept.size()));
  vtkNew<vtkPointData> pointData;
  pointData->CopyAllocate(mesh->GetPointData(), static_cast<vtkIdType>(kept.size()));
  for (size_t k = 0; k < kept.size(); ++k)
  {
    points->SetPoint(static_cast<vtkIdType>(k), mesh->GetPoint(kept[k]));
    pointData->CopyData(mesh->GetPointData(), kept[k], static_cast<vtkIdType>(k));
  }
  mesh->SetVerts(remap(mesh->GetVerts(), newId));
  mesh->SetLines(remap(mesh->GetLines(), newId));
  mesh->SetPolys(remap(mesh->GetPolys(), newId));
  mesh->SetStrips(remap(mesh->GetStrips(), newId));
  mesh->SetPoints(points);
  mesh->GetPointData()->ShallowCopy(pointData);
  return removed;
}
