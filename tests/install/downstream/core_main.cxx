// Uses the installed VTK-free geometry core alone (no VTK included): the
// face normal of a triangle in the plane x + y + z = 1 is (1, 1, 1)/sqrt(3).
#include "shadelab/slFaceNormalsCore.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

int main()
{
  const double xyz[] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const int64_t offsets[] = { 0, 3 };
  int64_t connectivity[] = { 0, 1, 2 };
  slnormals::Polygons<int64_t> polys;
  polys.offsets = offsets;
  polys.connectivity = connectivity;
  polys.numPolygons = 1;
  float n[3];
  slnormals::computeUnitFaceNormals(polys, xyz, n, slnormals::Parallel());
  const double expected = 1.0 / std::sqrt(3.0);
  double error = 0.0;
  for (float v : n)
  {
    error = std::fmax(error, std::abs(v - expected));
  }
  std::printf("downstream core: face normal %.6f %.6f %.6f, error %.1e\n", n[0], n[1], n[2], error);
  return error < 1e-6 ? 0 : 1;
}
