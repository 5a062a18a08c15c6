#include "slOwnedPolygons.h"

#include "slParallelFillArray.h"

#include <vtkIdList.h>
#include <vtkNew.h>

#include <utility>

vtkSmartPointer<vtkCellArray> slRemapCells(vtkCellArray* cells, const std::vector<vtkIdType>& map)
{
  auto out = vtkSmartPointer<vtkCellArray>::New();
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
  {
    cells->GetCellAtId(c, ids);
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
    {
      ids->SetId(i, map[static_cast<size_t>(ids->GetId(i))]);
    }
    out->InsertNextCell(ids);
  }
  return out;
}

vtkSmartPointer<vtkFloatArray> slMakeNormalsArray(vtkIdType tuples, vtkSmartPointer<vtkDataArray> previous)
{
  // Large outputs on huge pages: a 2M-triangle mesh's normals would
  // otherwise cost thousands of 4 KiB page faults at their first write.
  return shadelab::recycleParallelFillArray(std::move(previous), "Normals", 3, tuples);
}
