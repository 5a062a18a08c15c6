#include "slPointWelding.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <string>
#include <unordered_map>
#include <vector>

namespace
{
/// The bytes of point @p id: coordinates and every point-data tuple.
void pointKey(vtkPolyData* mesh, vtkIdType id, std::string& key)
{
  key.clear();
  double p[3];
  mesh->GetPoint(id, p);
  key.append(reinterpret_cast<const char*>(p), sizeof(p));
  vtkPointData* pd = mesh->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array)
    {
      continue;
    }
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      const double v = array->GetComponent(id, c);
      key.append(reinterpret_cast<const char*>(&v), sizeof(v));
    }
  }
}

vtkSmartPointer<vtkCellArray> remap(vtkCellArray* cells, const std::vector<vtkIdType>& newId)
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
  std::vector<vtkIdType> newId(static_cast<size_t>(n));
  std::vector<vtkIdType> kept;
  kept.reserve(static_cast<size_t>(n));
  std::unordered_map<std::string, vtkIdType> seen;
  seen.reserve(static_cast<size_t>(n));
  std::string key;
  for (vtkIdType i = 0; i < n; ++i)
  {
    pointKey(mesh, i, key);
    auto inserted = seen.emplace(key, static_cast<vtkIdType>(kept.size()));
    if (inserted.second)
    {
      kept.push_back(i);
    }
    newId[static_cast<size_t>(i)] = inserted.first->second;
  }
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
