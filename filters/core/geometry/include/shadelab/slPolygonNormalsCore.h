#ifndef slPolygonNormalsCore_h
#define slPolygonNormalsCore_h
/**
 * @file slPolygonNormalsCore.h
 * @brief The whole normals computation of slPolyDataNormals, without VTK:
 * welding, consistent orientation, feature-angle splitting and point
 * normals, in the order and with the choices the filter documents.
 *
 * The caller (the VTK filter) owns every array the result lands in: it gives
 * allocation callbacks, so normals and split connectivity are written
 * straight into the arrays it hands on, without a copy. It then assembles
 * its output from the result: points (the input's, or one per split point
 * from PolygonNormals::source), point data, the polygons (PolygonNormals::
 * polygons: the input's, or the reoriented copy) and the verts and lines
 * (renumbered through PolygonNormals::pointMap when points were split).
 */

#include "shadelab/Error.h"
#include "slFeatureSplitCore.h"
#include "slNormalsParallel.h"
#include "slOrientationCore.h"
#include "slPointWeldCore.h"
#include "slVertexCorners.h"
#include "slVertexNormalsCore.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace slnormals
{

/// What to compute (slPolyDataNormals' settings).
struct PolygonNormalsSettings
{
  Weighting weighting = Weighting::Angle;
  double featureAngleDegrees = 30.0;
  bool split = true;        ///< split points along edges sharper than the feature angle
  bool orient = true;       ///< make neighbouring polygons agree
  bool outward = false;     ///< and turn closed pieces outward
  bool weld = false;        ///< treat points of equal coordinates as one
  bool pointNormals = true; ///< compute point normals at all

  /// Whether computePolygonNormals() checks the polygons' point ids itself:
  /// on the plain vertex-normal path, which reads every id once anyway and
  /// checks it before following it. Every other path (splitting,
  /// orientation, welding, no point normals) builds tables from the ids
  /// first, so its caller must check that they lie in [0, numPoints).
  bool checksPointIds() const { return this->pointNormals && !(this->split || this->orient || this->outward || this->weld); }
};

/// Where the result goes, and the result.
template <typename Id>
struct PolygonNormals
{
  // In: given by the caller.
  /// Storage for @p n point normals (3 floats each); called once, with the
  /// input's point count, or without splitting the split point count.
  std::function<float*(int64_t n)> allocateNormals;
  /// Storage for the split polygons' @p n corners (32-bit point ids).
  std::function<int32_t*(int64_t n)> allocateSplitConnectivity;
  /// A writable copy of the input polygons, asked for the first time
  /// polygons must be reversed (not called when the polygons given are
  /// already writable).
  std::function<Polygons<Id>()> copyPolygons;

  // Out.
  /// The output polygons: those given, or the copy, reversed where needed.
  Polygons<Id> polygons;
  /// Polygons reversed by the orientation.
  int64_t flipped = 0;
  /// False when a polygon names a point outside [0, numPoints), found on
  /// the path that checks ids itself (PolygonNormalsSettings::
  /// checksPointIds()); the normals are then incomplete and must not be used.
  bool pointIdsInRange = true;
  /// With splitting: output point -> input point (split points first,
  /// then the points no polygon uses), and input point -> first output
  /// point made from it. Empty without splitting (output point = input point).
  ScratchArray<int64_t> source, pointMap;
  /// With splitting: the split connectivity given by allocateSplitConnectivity.
  int32_t* splitConnectivity = nullptr;
};

namespace detail
{
/// Reverses the polygons @p flips marks in @p polys (the given polygons,
/// when the orientation ran on welded topology).
template <typename Id>
void reverseFlipped(const Polygons<Id>& polys, const std::vector<char>& flips)
{
  for (int64_t f = 0; f < polys.numPolygons; ++f)
  {
    if (flips[static_cast<size_t>(f)])
    {
      std::reverse(polys.connectivity + polys.begin(f), polys.connectivity + polys.end(f));
    }
  }
}
} // namespace detail

/**
 * Computes @p result from the polygons @p polys (writable if
 * @p polysWritable, e.g. a copy made to turn strips into triangles) over
 * @p numPoints points @p xyz (packed xyz of T).
 *
 * Throws shadelab::Error when splitting, orientation or welding is asked
 * of a mesh of 2^31 or more corners (their tables are 32-bit).
 */
template <typename T, typename Id>
void computePolygonNormals(const PolygonNormalsSettings& s, Polygons<Id> polys, bool polysWritable, const T* xyz,
  int64_t numPoints, const Parallel& par, PolygonNormals<Id>& result)
{
  const int64_t numCorners = polys.numPolygons ? polys.end(polys.numPolygons - 1) : 0;
  const bool splitting = s.pointNormals && s.split;
  const bool needCorners = s.orient || s.outward || splitting;
  if ((needCorners || s.weld) && numCorners >= std::numeric_limits<int32_t>::max())
  {
    throw shadelab::Error("the mesh has " + std::to_string(numCorners) +
      " polygon corners; splitting, orientation and welding handle fewer than 2^31");
  }

  // Welding: polygons on canonical ids for everything topological.
  std::vector<int64_t> canonical;
  std::vector<Id> topologyIds;
  Polygons<Id> topology = polys;
  if (s.weld)
  {
    weldCoincidentPoints(xyz, numPoints, canonical);
    topologyIds.resize(static_cast<size_t>(numCorners));
    Id* t = topologyIds.data();
    par.forRange(0, numCorners, 65536, [&](int64_t b, int64_t e) {
      for (int64_t c = b; c < e; ++c)
      {
        t[c] = static_cast<Id>(canonical[static_cast<size_t>(polys.connectivity[c])]);
      }
    });
    topology.connectivity = t;
  }
  const bool welded = s.weld;

  // Orientation: reverse polygons in a writable copy, only if needed.
  auto orient = [&](const VertexCorners<Id>& corners) {
    if (!polysWritable)
    {
      polys = result.copyPolygons();
      polysWritable = true;
      if (!welded)
      {
        topology = polys;
      }
    }
    std::vector<char> flips;
    const int64_t flipped = orientPolygons(topology, xyz, corners, s.outward, &flips);
    if (welded)
    {
      detail::reverseFlipped(polys, flips);
    }
    return flipped;
  };

  // With splitting, the pass that builds the smooth groups looks for
  // inconsistent edges itself (it reads the same corners), so a separate
  // check runs only without splitting.
  VertexCorners<Id> corners;
  bool cornersValid = false;
  result.flipped = 0;
  if (s.orient || s.outward)
  {
    corners.build(topology, numPoints, par);
    cornersValid = true;
    if (s.outward || (!splitting && hasInconsistentEdge(topology, corners, par)))
    {
      result.flipped = orient(corners);
      cornersValid = result.flipped == 0;
    }
  }

  if (splitting)
  {
    if (!cornersValid)
    {
      corners.build(topology, numPoints, par);
    }
    const bool check = s.orient && !s.outward;
    const T cosFeature = static_cast<T>(std::cos(s.featureAngleDegrees * 0.017453292519943295));
    result.splitConnectivity = result.allocateSplitConnectivity(numCorners);
    float* normals = nullptr;
    int64_t unused = 0;
    auto allocate = [&](int64_t splitPoints) {
      // Points used by no polygon are kept after the split ones, with (0,0,0).
      // Without welding they are the points with no corner in the table. With
      // welding, a seam duplicate has no corners in the welded topology, yet
      // the split emits it as a point: they are counted on the polygons as given.
      if (!welded)
      {
        unused = corners.pointsWithoutCorners(par);
      }
      else
      {
        ScratchArray<char> used(par, static_cast<size_t>(numPoints));
        std::fill(used.begin(), used.end(), char(0));
        for (int64_t c = 0; c < numCorners; ++c)
        {
          used[static_cast<size_t>(polys.connectivity[c])] = 1;
        }
        unused = std::count(used.begin(), used.end(), 0);
      }
      normals = result.allocateNormals(splitPoints + unused);
      result.source = ScratchArray<int64_t>(par, static_cast<size_t>(splitPoints + unused));
      SplitOutput out;
      out.normals = normals;
      out.source = result.source.data();
      return out;
    };
    auto splitOnce = [&](bool checkOrientation) {
      bool inconsistent = false;
      const int64_t split = splitVertexNormals(topology, welded ? polys.connectivity : nullptr, xyz, numPoints,
        corners, s.weighting, cosFeature, result.splitConnectivity, allocate, par,
        checkOrientation ? &inconsistent : nullptr);
      return inconsistent ? int64_t(-1) : split;
    };
    int64_t split = splitOnce(check);
    if (split < 0)
    {
      result.flipped = orient(corners);
      if (result.flipped != 0)
      {
        corners.build(topology, numPoints, par);
      }
      split = splitOnce(false);
    }

    result.pointMap = ScratchArray<int64_t>(par, static_cast<size_t>(numPoints));
    std::fill(result.pointMap.begin(), result.pointMap.end(), int64_t(-1));
    for (int64_t i = split - 1; i >= 0; --i)
    {
      result.pointMap[static_cast<size_t>(result.source[static_cast<size_t>(i)])] = i;
    }
    for (int64_t v = 0, next = split; v < numPoints; ++v)
    {
      if (result.pointMap[static_cast<size_t>(v)] < 0)
      {
        result.source[static_cast<size_t>(next)] = v;
        std::fill(normals + 3 * next, normals + 3 * next + 3, 0.0f);
        result.pointMap[static_cast<size_t>(v)] = next++;
      }
    }
  }
  else if (s.pointNormals)
  {
    float* n = result.allocateNormals(numPoints);
    result.pointIdsInRange = computeVertexNormals(topology, xyz, numPoints, s.weighting, n, par);
    if (welded && result.pointIdsInRange)
    {
      par.forRange(0, numPoints, 65536, [&](int64_t b, int64_t e) {
        for (int64_t v = b; v < e; ++v)
        {
          const int64_t c = canonical[static_cast<size_t>(v)];
          if (c != v)
          {
            std::memcpy(n + 3 * v, n + 3 * c, 3 * sizeof(float));
          }
        }
      });
    }
  }
  result.polygons = polys;
}

} // namespace slnormals

#endif
