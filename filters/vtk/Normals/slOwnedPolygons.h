#ifndef slOwnedPolygons_h
#define slOwnedPolygons_h
/**
 * @file slOwnedPolygons.h
 * @brief Polygon storage that slPolyDataNormals owns (copies it may reverse,
 * strips as triangles), and small output helpers. Internal to
 * ShadeLab::Normals.
 */

#include "slNormalsVTKBridge.h"
#include "slCoreBoundary.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkSmartPointer.h>

#include <cstring>
#include <vector>

/// Owned polygon storage as VTK arrays of ids of type Id.
template <typename Id>
struct slOwnedPolygons
{
  vtkSmartPointer<slIdArray<Id>> offsets, connectivity;
  slnormals::Polygons<Id> view() const
  {
    slnormals::Polygons<Id> p;
    p.offsets = reinterpret_cast<const Id*>(this->offsets->GetPointer(0));
    p.connectivity = reinterpret_cast<Id*>(this->connectivity->GetPointer(0));
    p.numPolygons = this->offsets->GetNumberOfValues() - 1;
    return p;
  }
  vtkSmartPointer<vtkCellArray> cells() const
  {
    auto c = vtkSmartPointer<vtkCellArray>::New();
    c->SetData(this->offsets, this->connectivity);
    return c;
  }
};

/// Copies @p polys and appends every strip of @p strips as triangles.
template <typename Id>
slOwnedPolygons<Id> slCopyPolygons(vtkCellArray* polys, vtkCellArray* strips)
{
  std::vector<Id> offsets{ 0 }, conn;
  vtkIdType n;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    conn.insert(conn.end(), ids, ids + n);
    offsets.push_back(static_cast<Id>(conn.size()));
  }
  for (strips->InitTraversal(); strips->GetNextCell(n, ids);)
  {
    for (vtkIdType i = 0; i + 2 < n; ++i)
    {
      // Strips alternate orientation: even triangles (i, i+1, i+2), odd (i+1, i, i+2).
      conn.push_back(static_cast<Id>(ids[i % 2 ? i + 1 : i]));
      conn.push_back(static_cast<Id>(ids[i % 2 ? i : i + 1]));
      conn.push_back(static_cast<Id>(ids[i + 2]));
      offsets.push_back(static_cast<Id>(conn.size()));
    }
  }
  slOwnedPolygons<Id> o;
  o.offsets = vtkSmartPointer<slIdArray<Id>>::New();
  slSetNumberOfTuplesOrThrow(o.offsets, static_cast<vtkIdType>(offsets.size()));
  std::memcpy(o.offsets->GetPointer(0), offsets.data(), offsets.size() * sizeof(Id));
  o.connectivity = vtkSmartPointer<slIdArray<Id>>::New();
  slSetNumberOfTuplesOrThrow(o.connectivity, static_cast<vtkIdType>(conn.size()));
  if (!conn.empty())
  {
    std::memcpy(o.connectivity->GetPointer(0), conn.data(), conn.size() * sizeof(Id));
  }
  return o;
}

/// Replaces every id of @p cells by map[id].
vtkSmartPointer<vtkCellArray> slRemapCells(vtkCellArray* cells, const std::vector<vtkIdType>& map);

/// A 3-component float point or cell array named "Normals" of @p tuples
/// tuples, its values to be written: @p previous (the filter's last output
/// array, moved in) when nothing else holds it and it has that shape
/// (shadelab::recycleParallelFillArray()), else a new one.
vtkSmartPointer<vtkFloatArray> slMakeNormalsArray(vtkIdType tuples, vtkSmartPointer<vtkDataArray> previous);

#endif
