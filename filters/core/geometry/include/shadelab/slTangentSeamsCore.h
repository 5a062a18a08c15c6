#ifndef slTangentSeamsCore_h
#define slTangentSeamsCore_h
/**
 * @file slTangentSeamsCore.h
 * @brief Tangent frames of a whole mesh, with the points of mirror seams
 * split in two. VTK-free. Geometry core (ShadeLab::GeometryCore).
 *
 * Runs accumulateTangents() (slTangentFramesCore.h) and then gives every
 * point whose corners have both orientation signs a copy, after the input
 * points, that takes its mirrored (w = −1) corners: the polygons' point ids
 * of those corners are rewritten to the copy. Output point i is a copy of
 * input point source[i] (source[i] = i for i < numPoints).
 */

#include "slNormalsParallel.h"
#include "slTangentFramesCore.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace slnormals
{

/// Output of tangentFramesWithSeams().
struct SeamTangents
{
  std::vector<int64_t> source; ///< input point of each output point
  std::vector<float> tangents; ///< 4 per output point: xyz, w = ±1
  int64_t numSplitPoints = 0;  ///< output points that are copies
};

/// Tangent frames of @p polys over points [0, numPoints): @p pos, @p uv and
/// @p nrm hold each point's position, texture coordinates and unit normal.
/// Rewrites the point ids of mirrored corners at mirror seams in
/// @p polys.connectivity (see the file's comment).
template <typename Id>
SeamTangents tangentFramesWithSeams(Polygons<Id>& polys, int64_t numPoints, const std::vector<glm::dvec3>& pos,
  const std::vector<glm::dvec2>& uv, const std::vector<glm::dvec3>& nrm, const Parallel& parallel)
{
  TangentSums sums;
  std::vector<signed char> sign;
  accumulateTangents(
    polys, numPoints, [&](int64_t v) { return pos[static_cast<size_t>(v)]; },
    [&](int64_t v) { return uv[static_cast<size_t>(v)]; }, [&](int64_t v) { return nrm[static_cast<size_t>(v)]; },
    sums, sign);
  // Mirror seams: the mirrored corners of points with both signs go to a copy.
  std::vector<int64_t> copyOf(static_cast<size_t>(numPoints), -1);
  int64_t next = numPoints;
  for (int64_t v = 0; v < numPoints; ++v)
  {
    if (sums.used[0][static_cast<size_t>(v)] && sums.used[1][static_cast<size_t>(v)])
    {
      copyOf[static_cast<size_t>(v)] = next++;
    }
  }
  const int64_t numCorners = polys.numPolygons ? polys.end(polys.numPolygons - 1) : 0;
  for (int64_t c = 0; c < numCorners; ++c)
  {
    const int64_t v = static_cast<int64_t>(polys.connectivity[c]);
    if (sign[static_cast<size_t>(c)] < 0 && copyOf[static_cast<size_t>(v)] >= 0)
    {
      polys.connectivity[c] = static_cast<Id>(copyOf[static_cast<size_t>(v)]);
    }
  }

  SeamTangents out;
  out.numSplitPoints = next - numPoints;
  out.source.resize(static_cast<size_t>(next));
  for (int64_t v = 0; v < numPoints; ++v)
  {
    out.source[static_cast<size_t>(v)] = v;
    if (copyOf[static_cast<size_t>(v)] >= 0)
    {
      out.source[static_cast<size_t>(copyOf[static_cast<size_t>(v)])] = v;
    }
  }
  out.tangents.resize(static_cast<size_t>(4 * next));
  float* t4 = out.tangents.data();
  auto put = [t4](int64_t i, const glm::dvec3& t, float w) {
    float* o = t4 + 4 * i;
    o[0] = static_cast<float>(t.x);
    o[1] = static_cast<float>(t.y);
    o[2] = static_cast<float>(t.z);
    o[3] = w;
  };
  parallel.forRange(0, numPoints, 8192, [&](int64_t b, int64_t e) {
    for (int64_t v = b; v < e; ++v)
    {
      const size_t s = static_cast<size_t>(v);
      const bool plus = sums.used[0][s] || !sums.used[1][s];
      put(v, finishTangent(sums.sum[plus ? 0 : 1][s], nrm[s]), plus ? 1.0f : -1.0f);
      if (copyOf[s] >= 0)
      {
        put(copyOf[s], finishTangent(sums.sum[1][s], nrm[s]), -1.0f);
      }
    }
  });
  return out;
}

} // namespace slnormals

#endif
