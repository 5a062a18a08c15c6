#ifndef ShuffledMesh_h
#define ShuffledMesh_h
// A triangle mesh as plain arrays, copied from and back to vtkPolyData, and
// the same mesh in random order (points renumbered, triangles shuffled):
// what the normals tests give the filters to check that order changes no
// normal. Header-only, for the normals test binary.

#include "shadelab/slNormalsParallel.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

namespace normalstest
{
/// Points (xyz) and triangles (3 ids each) as plain arrays.
template <typename T>
struct Mesh
{
  std::vector<T> xyz;
  std::vector<int64_t> offsets, connectivity;

  slnormals::Polygons<int64_t> view()
  {
    slnormals::Polygons<int64_t> p;
    p.offsets = this->offsets.data();
    p.connectivity = this->connectivity.data();
    p.numPolygons = static_cast<int64_t>(this->offsets.size()) - 1;
    return p;
  }
  int64_t numPoints() const { return static_cast<int64_t>(this->xyz.size() / 3); }
};

template <typename T>
Mesh<T> meshOf(vtkPolyData* poly)
{
  Mesh<T> m;
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    const double* p = poly->GetPoint(i);
    m.xyz.insert(m.xyz.end(), { static_cast<T>(p[0]), static_cast<T>(p[1]), static_cast<T>(p[2]) });
  }
  m.offsets.push_back(0);
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = poly->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    m.connectivity.insert(m.connectivity.end(), ids, ids + n);
    m.offsets.push_back(static_cast<int64_t>(m.connectivity.size()));
  }
  return m;
}

/// @p m with its points renumbered by @p newId, its triangles in random
/// order and, with @p rotateCorners, each one's corners rotated by a random
/// step (same orientation).
template <typename T>
Mesh<T> shuffled(const Mesh<T>& m, const std::vector<int64_t>& newId, std::mt19937& rng, bool rotateCorners = true)
{
  Mesh<T> s;
  s.xyz.resize(m.xyz.size());
  for (int64_t v = 0; v < m.numPoints(); ++v)
  {
    std::copy_n(&m.xyz[static_cast<size_t>(3 * v)], 3, &s.xyz[static_cast<size_t>(3 * newId[static_cast<size_t>(v)])]);
  }
  std::vector<int64_t> order(m.offsets.size() - 1);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  std::uniform_int_distribution<int> step(0, 2);
  s.offsets.push_back(0);
  for (int64_t f : order)
  {
    const int r = rotateCorners ? step(rng) : 0;
    for (int k = 0; k < 3; ++k)
    {
      s.connectivity.push_back(newId[static_cast<size_t>(m.connectivity[static_cast<size_t>(3 * f + (k + r) % 3)])]);
    }
    s.offsets.push_back(static_cast<int64_t>(s.connectivity.size()));
  }
  return s;
}

/// A random numbering of @p n points: point v becomes point result[v].
inline std::vector<int64_t> randomNumbering(int64_t n, std::mt19937& rng)
{
  std::vector<int64_t> newId(static_cast<size_t>(n));
  std::iota(newId.begin(), newId.end(), 0);
  std::shuffle(newId.begin(), newId.end(), rng);
  return newId;
}

/// @p m as a vtkPolyData of float points and triangles.
inline vtkSmartPointer<vtkPolyData> polyDataOf(const Mesh<float>& m)
{
  vtkNew<vtkFloatArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(m.numPoints());
  std::copy(m.xyz.begin(), m.xyz.end(), xyz->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  vtkNew<vtkCellArray> cells;
  for (size_t f = 0; f + 1 < m.offsets.size(); ++f)
  {
    const vtkIdType ids[3] = { m.connectivity[3 * f], m.connectivity[3 * f + 1], m.connectivity[3 * f + 2] };
    cells->InsertNextCell(3, ids);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(cells);
  return out;
}

/// Triangle mesh @p poly in random order (float points): points renumbered
/// at random, triangles shuffled and their corners rotated.
inline vtkSmartPointer<vtkPolyData> inRandomOrder(vtkPolyData* poly, unsigned seed)
{
  const Mesh<float> ordered = meshOf<float>(poly);
  std::mt19937 rng(seed);
  return polyDataOf(shuffled(ordered, randomNumbering(ordered.numPoints(), rng), rng));
}

} // namespace normalstest

#endif
