#include "slOwnedPolygons.h"

#include <vtkIdList.h>
#include <vtkNew.h>

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

vtkSmartPointer<vtkFloatArray> slMakeNormalsArray(vtkIdType tuples)
{
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName("Normals");
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(tuples);
  return a;
}
