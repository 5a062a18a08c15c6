#ifndef slPointWeldCore_h
#define slPointWeldCore_h
/**
 * @file slPointWeldCore.h
 * @brief Maps every point to the first point with exactly the same
 * coordinates. VTK-free. Geometry core (ShadeLab::GeometryCore).
 */

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace slnormals
{

/// canonical[i] = the smallest id j with xyz(j) == xyz(i). Returns the number
/// of points that map to another one.
template <typename T>
int64_t weldCoincidentPoints(const T* xyz, int64_t numPoints, std::vector<int64_t>& canonical)
{
  std::vector<int64_t> order(static_cast<size_t>(numPoints));
  std::iota(order.begin(), order.end(), int64_t(0));
  auto less = [xyz](int64_t a, int64_t b) {
    for (int k = 0; k < 3; ++k)
    {
      if (xyz[3 * a + k] != xyz[3 * b + k])
      {
        return xyz[3 * a + k] < xyz[3 * b + k];
      }
    }
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  canonical.resize(static_cast<size_t>(numPoints));
  int64_t merged = 0;
  for (size_t i = 0; i < order.size();)
  {
    size_t j = i + 1;
    while (j < order.size() && xyz[3 * order[j]] == xyz[3 * order[i]] &&
      xyz[3 * order[j] + 1] == xyz[3 * order[i] + 1] && xyz[3 * order[j] + 2] == xyz[3 * order[i] + 2])
    {
      ++j;
    }
    for (size_t m = i; m < j; ++m)
    {
      canonical[static_cast<size_t>(order[m])] = order[i]; // the run is sorted by id
    }
    merged += static_cast<int64_t>(j - i - 1);
    i = j;
  }
  return merged;
}

} // namespace slnormals

#endif
