#include "slConnectivityCheck.h"

#include "shadelab/PrintableText.h"
#include "shadelab/slAtomicMinimum.h"
#include "shadelab/slIdsBelow.h"
#include "shadelab/slVectorClones.h"
#include "slSMPFor.h"

#include <vtkAbstractArray.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>

#include <algorithm>
#include <atomic>
#include <type_traits>

namespace
{
/// Whether offsets[begin, end) decreases anywhere (offsets[begin - 1] counts),
/// vectorised as slIdsBelow() is (a mask or-ed into an integer).
template <typename Id>
SL_ALWAYS_INLINE bool anyDecreaseLoop(const Id* offsets, vtkIdType begin, vtkIdType end)
{
  using U = std::make_unsigned_t<Id>;
  U bad = 0;
  for (vtkIdType c = begin; c < end; ++c)
  {
    bad |= offsets[c] < offsets[c - 1] ? ~U(0) : U(0);
  }
  return bad != 0;
}

template <typename Id>
SL_TARGET_AVX2 bool anyDecreaseAVX2(const Id* offsets, vtkIdType begin, vtkIdType end)
{
  return anyDecreaseLoop(offsets, begin, end);
}

/// anyDecreaseLoop() in its AVX2 version where the CPU has it (64-bit compares).
template <typename Id>
bool anyDecrease(const Id* offsets, vtkIdType begin, vtkIdType end)
{
  return slHasAVX2() ? anyDecreaseAVX2(offsets, begin, end) : anyDecreaseLoop(offsets, begin, end);
}

/// The problem with one cell array whose ids are of type Id, or "".
template <typename Id>
std::string cellsProblem(const Id* offsets, vtkIdType numOffsets, const Id* ids, vtkIdType numIds,
  vtkIdType numPoints, const char* kind, bool checkIds)
{
  if (numOffsets == 0)
  {
    return numIds == 0 ? std::string() : std::string(kind) + " cells: point ids without offsets";
  }
  // Offsets start at 0, never decrease and end at the number of ids.
  if (offsets[0] != 0 || offsets[numOffsets - 1] != numIds)
  {
    return std::string(kind) + " cells: offsets do not span their " + std::to_string(numIds) + " point ids";
  }
  // The first decrease, found in parallel like the ids below.
  std::atomic<vtkIdType> firstDecrease(numOffsets);
  slSMPFor(1, numOffsets, 65536, [&](vtkIdType begin, vtkIdType end) {
    const bool bad = anyDecrease(offsets, begin, end);
    for (vtkIdType c = begin; bad && c < end; ++c)
    {
      if (offsets[c] < offsets[c - 1])
      {
        slAtomicMinimum(firstDecrease, c);
        return;
      }
    }
  });
  if (firstDecrease.load() < numOffsets)
  {
    return std::string(kind) + " " + std::to_string(firstDecrease.load() - 1) + ": its offset decreases";
  }
  if (!checkIds)
  {
    return std::string();
  }
  // The first id outside [0, numPoints), found in parallel: the common case
  // (none) is one branch-free pass.
  std::atomic<vtkIdType> firstBad(numIds);
  slSMPFor(0, numIds, 65536, [&](vtkIdType begin, vtkIdType end) {
    const bool bad = !slIdsBelow(ids + begin, end - begin, numPoints);
    for (vtkIdType i = begin; bad && i < end; ++i)
    {
      if (ids[i] < 0 || ids[i] >= numPoints)
      {
        slAtomicMinimum(firstBad, i);
        return;
      }
    }
  });
  const vtkIdType at = firstBad.load();
  if (at == numIds)
  {
    return std::string();
  }
  // The cell holding id number `at`: the last offset <= at.
  const vtkIdType cell = static_cast<vtkIdType>(std::upper_bound(offsets, offsets + numOffsets, static_cast<Id>(at)) - offsets) - 1;
  return std::string(kind) + " " + std::to_string(cell) + " names point " + std::to_string(ids[at]) +
    ", but the mesh has " + std::to_string(numPoints) + " points" +
    (numPoints > 0 ? " (0 to " + std::to_string(numPoints - 1) + ")" : std::string());
}

std::string arrayProblem(vtkCellArray* cells, vtkIdType numPoints, const char* kind, bool checkIds = true)
{
  if (!cells)
  {
    return std::string();
  }
  if (cells->IsStorage64Bit())
  {
    vtkTypeInt64Array* offsets = cells->GetOffsetsArray64();
    vtkTypeInt64Array* ids = cells->GetConnectivityArray64();
    return cellsProblem(offsets->GetPointer(0), offsets->GetNumberOfValues(), ids->GetPointer(0),
      ids->GetNumberOfValues(), numPoints, kind, checkIds);
  }
  vtkTypeInt32Array* offsets = cells->GetOffsetsArray32();
  vtkTypeInt32Array* ids = cells->GetConnectivityArray32();
  return cellsProblem(offsets->GetPointer(0), offsets->GetNumberOfValues(), ids->GetPointer(0),
    ids->GetNumberOfValues(), numPoints, kind, checkIds);
}
} // namespace

std::string slArrayLengthProblem(vtkDataSetAttributes* data, vtkIdType items, const char* kind, bool exact)
{
  for (int i = 0; data && i < data->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = data->GetAbstractArray(i);
    const vtkIdType tuples = array ? array->GetNumberOfTuples() : items;
    if (tuples < items || (exact && tuples != items))
    {
      const char* name = array->GetName();
      return std::string(kind) + " array " +
        (name ? "\"" + shadelab::printableText(name, 100) + "\"" : "number " + std::to_string(i)) + " has " +
        std::to_string(tuples) + (tuples == 1 ? " tuple for " : " tuples for ") + std::to_string(items) + " " + kind +
        "s";
    }
  }
  return std::string();
}

std::string slConnectivityProblem(vtkPolyData* mesh)
{
  return slConnectivityProblem(mesh, true);
}

std::string slConnectivityProblem(vtkPolyData* mesh, bool polygonIds)
{
  if (!mesh)
  {
    return std::string();
  }
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  std::string problem = arrayProblem(mesh->GetPolys(), numPoints, "polygon", polygonIds);
  if (problem.empty())
  {
    problem = arrayProblem(mesh->GetStrips(), numPoints, "strip");
  }
  if (problem.empty())
  {
    problem = arrayProblem(mesh->GetLines(), numPoints, "line");
  }
  if (problem.empty())
  {
    problem = arrayProblem(mesh->GetVerts(), numPoints, "vertex cell");
  }
  if (problem.empty())
  {
    problem = slArrayLengthProblem(mesh->GetPointData(), numPoints, "point", false);
  }
  if (problem.empty())
  {
    problem = slArrayLengthProblem(mesh->GetCellData(), mesh->GetNumberOfCells(), "cell", false);
  }
  return problem;
}
