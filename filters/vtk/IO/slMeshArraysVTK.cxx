#include "slMeshArraysVTK.h"

#include "slCoreBoundary.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>

#include <cstring>
#include <type_traits>

namespace
{
/// A VTK array of @p components per tuple holding @p values, which it
/// empties.
template <typename Array, typename T>
vtkSmartPointer<Array> adopt(std::vector<T>& values, int components)
{
  auto array = vtkSmartPointer<Array>::New();
  array->SetNumberOfComponents(components);
  slSetNumberOfTuplesOrThrow(array, static_cast<vtkIdType>(values.size() / static_cast<std::size_t>(components)));
  // memcpy wants valid pointers even for no bytes, and an empty vector or
  // array may have none.
  if (!values.empty())
  {
    std::memcpy(array->GetPointer(0), values.data(), values.size() * sizeof(T));
  }
  std::vector<T>().swap(values);
  return array;
}

vtkSmartPointer<vtkFloatArray> floats(std::vector<float>& values, int components, const char* name)
{
  auto array = adopt<vtkFloatArray>(values, components);
  if (name)
  {
    array->SetName(name);
  }
  return array;
}

vtkSmartPointer<vtkIdTypeArray> ids(std::vector<std::int64_t>& values)
{
  static_assert(sizeof(vtkIdType) == sizeof(std::int64_t), "64-bit vtkIdType");
  return adopt<vtkIdTypeArray>(values, 1);
}

bool values(vtkDataArray* array, int components, slValuesView& view)
{
  if (!array)
  {
    return true;
  }
  if (array->GetNumberOfComponents() != components ||
    (array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE))
  {
    return false;
  }
  view.data = array->GetVoidPointer(0);
  view.isDouble = array->GetDataType() == VTK_DOUBLE;
  return true;
}

bool indices(vtkDataArray* array, slIndicesView& view)
{
  if (vtkTypeInt64Array::SafeDownCast(array) || vtkIdTypeArray::SafeDownCast(array))
  {
    view.data = array->GetVoidPointer(0);
    view.is64 = true;
    return true;
  }
  if (vtkTypeInt32Array::SafeDownCast(array))
  {
    view.data = array->GetVoidPointer(0);
    view.is64 = false;
    return true;
  }
  return false;
}
} // namespace

void slToPolyData(slMeshArrays& mesh, bool tcoordsFirst, vtkPolyData* output)
{
  output->Initialize();
  // The lines and vertex cells, whose ids follow the polygons'.
  std::size_t from = mesh.offsets.empty() ? 0 : static_cast<std::size_t>(mesh.offsets.back());
  const std::size_t polygonIds = from;
  for (std::vector<std::int64_t>* sizes : { &mesh.lineSizes, &mesh.vertexSizes })
  {
    if (sizes->empty())
    {
      continue;
    }
    std::vector<std::int64_t> offsets{ 0 };
    for (std::int64_t size : *sizes)
    {
      offsets.push_back(offsets.back() + size);
    }
    std::vector<std::int64_t> cellIds(mesh.connectivity.begin() + static_cast<std::ptrdiff_t>(from),
      mesh.connectivity.begin() + static_cast<std::ptrdiff_t>(from) + offsets.back());
    from += static_cast<std::size_t>(offsets.back());
    vtkNew<vtkCellArray> cells;
    cells->SetData(ids(offsets), ids(cellIds));
    if (sizes == &mesh.lineSizes)
    {
      output->SetLines(cells);
    }
    else
    {
      output->SetVerts(cells);
    }
    std::vector<std::int64_t>().swap(*sizes);
  }
  mesh.connectivity.resize(polygonIds);
  vtkNew<vtkPoints> points;
  points->SetData(floats(mesh.points, 3, nullptr));
  vtkNew<vtkCellArray> polys;
  vtkSmartPointer<vtkIdTypeArray> offsets = ids(mesh.offsets);
  polys->SetData(offsets, ids(mesh.connectivity));
  output->SetPoints(points);
  output->SetPolys(polys);
  vtkPointData* pd = output->GetPointData();
  if (!mesh.colours.empty())
  {
    // As vtkPLYReader gives them: the first array, the active scalars.
    vtkSmartPointer<vtkUnsignedCharArray> colours = adopt<vtkUnsignedCharArray>(mesh.colours, mesh.colourComponents);
    colours->SetName(mesh.colourComponents == 4 ? "RGBA" : "RGB");
    pd->SetScalars(colours);
  }
  auto addTCoords = [&] {
    if (!mesh.tcoords.empty())
    {
      pd->SetTCoords(floats(mesh.tcoords, 2, "TCoords"));
    }
  };
  if (tcoordsFirst)
  {
    addTCoords();
  }
  if (!mesh.normals.empty())
  {
    pd->SetNormals(floats(mesh.normals, 3, "Normals"));
  }
  addTCoords();
}

bool slViewOf(vtkPolyData* mesh, slMeshView& view)
{
  vtkCellArray* polys = mesh->GetPolys();
  // Point colours as PLY and VTK's readers give them: 8-bit RGB or RGBA.
  auto* colours = vtkUnsignedCharArray::SafeDownCast(mesh->GetPointData()->GetScalars());
  const bool colourScalars = colours && (colours->GetNumberOfComponents() == 3 || colours->GetNumberOfComponents() == 4);
  if (!mesh->GetPoints() || mesh->GetNumberOfVerts() > 0 || mesh->GetNumberOfLines() > 0 ||
    mesh->GetNumberOfStrips() > 0 || (mesh->GetPointData()->GetScalars() && !colourScalars) ||
    mesh->GetCellData()->GetScalars())
  {
    return false;
  }
  view = slMeshView();
  if (colourScalars)
  {
    view.colours = colours->GetPointer(0);
    view.colourComponents = colours->GetNumberOfComponents();
  }
  view.numberOfPoints = mesh->GetNumberOfPoints();
  view.numberOfPolygons = polys ? polys->GetNumberOfCells() : 0;
  vtkNew<vtkCellArray> empty;
  vtkCellArray* cells = polys ? polys : empty.Get();
  return values(mesh->GetPoints()->GetData(), 3, view.points) &&
    values(mesh->GetPointData()->GetNormals(), 3, view.normals) &&
    values(mesh->GetPointData()->GetTCoords(), 2, view.tcoords) && indices(cells->GetOffsetsArray(), view.offsets) &&
    indices(cells->GetConnectivityArray(), view.connectivity) && polys;
}
