#ifndef slNormalsVTKBridge_h
#define slNormalsVTKBridge_h
/**
 * @file slNormalsVTKBridge.h
 * @brief What the ShadeLab::Normals filters share between the VTK-free
 * algorithms and VTK: vtkSMPTools as slnormals::Parallel, polygon views of a
 * vtkCellArray, and the NaN check. Internal to ShadeLab::Normals.
 */

#include "shadelab/slNormalsParallel.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>

#include <type_traits>

class vtkPoints;

/// vtkSMPTools::For behind the VTK-free loop interface.
slnormals::Parallel slSMPParallel();

/// Index of the first point with a NaN or infinite coordinate, or -1. When
/// all are finite and @p largestSide is given, it gets the longest side of
/// their bounding box (from the same pass over the points).
vtkIdType slFirstNonFinitePoint(vtkPoints* points, double* largestSide = nullptr);

/// The VTK array that holds ids of type @p Id (vtkTypeInt32Array or vtkTypeInt64Array).
template <typename Id>
using slIdArray = typename std::conditional<sizeof(Id) == 8, vtkTypeInt64Array, vtkTypeInt32Array>::type;

/// Calls f(Id{}) with Id the storage type of @p cells.
template <typename F>
auto slDispatchStorage(vtkCellArray* cells, F&& f)
{
  if (cells->IsStorage64Bit())
  {
    return f(vtkTypeInt64{});
  }
  return f(vtkTypeInt32{});
}

/// A polygon view of @p cells, whose storage must have ids of type @p Id.
template <typename Id>
slnormals::Polygons<Id> slPolygonsOf(vtkCellArray* cells)
{
  slnormals::Polygons<Id> p;
  if (sizeof(Id) == 8)
  {
    p.offsets = reinterpret_cast<const Id*>(cells->GetOffsetsArray64()->GetPointer(0));
    p.connectivity = reinterpret_cast<Id*>(cells->GetConnectivityArray64()->GetPointer(0));
  }
  else
  {
    p.offsets = reinterpret_cast<const Id*>(cells->GetOffsetsArray32()->GetPointer(0));
    p.connectivity = reinterpret_cast<Id*>(cells->GetConnectivityArray32()->GetPointer(0));
  }
  p.numPolygons = cells->GetNumberOfCells();
  return p;
}

#endif
