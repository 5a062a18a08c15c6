// The VTK-free geometry core against values worked out by hand: face
// normals, the four corner weightings of vertex normals, orientation repair,
// point welding, tangent frames across a mirror seam, and the composed
// computation of slPolyDataNormals, on meshes small enough to check on paper.
#include "shadelab/slFaceNormalsCore.h"
#include "shadelab/slIdsBelow.h"
#include "shadelab/slOrientationCore.h"
#include "shadelab/slPointWeldCore.h"
#include "shadelab/slPolygonNormalsCore.h"
#include "shadelab/slTangentSeamsCore.h"
#include "shadelab/slVertexCorners.h"
#include "shadelab/slVertexNormalsCore.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace
{
using slnormals::Parallel;
using slnormals::Polygons;
using slnormals::Weighting;

/// A polygon list over its own arrays (VTK 9's layout: offsets + connectivity).
struct Mesh
{
  std::vector<double> xyz;
  std::vector<int64_t> offsets{ 0 };
  std::vector<int64_t> connectivity;

  void add(std::initializer_list<int64_t> ids)
  {
    this->connectivity.insert(this->connectivity.end(), ids);
    this->offsets.push_back(static_cast<int64_t>(this->connectivity.size()));
  }
  Polygons<int64_t> polygons()
  {
    Polygons<int64_t> p;
    p.offsets = this->offsets.data();
    p.connectivity = this->connectivity.data();
    p.numPolygons = static_cast<int64_t>(this->offsets.size()) - 1;
    return p;
  }
  int64_t numPoints() const { return static_cast<int64_t>(this->xyz.size() / 3); }
};

/// A serial stand-in for a pool of @p threads threads: ranges of the grain,
/// run last first, as a pool might run them.
Parallel backwardsInGrains(int threads)
{
  Parallel p;
  p.threads = threads;
  p.forRange = [](int64_t begin, int64_t end, int64_t grain, const Parallel::Body& body) {
    const int64_t step = std::max<int64_t>(grain, 1);
    for (int64_t b = begin + (end - begin - 1) / step * step; b >= begin; b -= step)
    {
      body(b, std::min(end, b + step));
    }
  };
  return p;
}

void expectUnit(const float* n, double x, double y, double z)
{
  const double length = std::sqrt(x * x + y * y + z * z);
  EXPECT_NEAR(n[0], x / length, 1e-6);
  EXPECT_NEAR(n[1], y / length, 1e-6);
  EXPECT_NEAR(n[2], z / length, 1e-6);
}

/// Two triangles meeting at point 0 (the origin): A in the plane z = 0
/// (normal +z, area 2, a right angle at 0, edges of length 2 there) and B in
/// the plane y = 0 (normal +y, area 1/2, 45 degrees at 0, edges 1 and sqrt 2).
Mesh twoTriangles()
{
  Mesh m;
  m.xyz = { 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 1, 1, 0, 1 };
  m.add({ 0, 1, 2 });
  m.add({ 0, 3, 4 });
  return m;
}

std::vector<float> vertexNormals(Mesh& m, Weighting w)
{
  std::vector<float> out(static_cast<size_t>(3 * m.numPoints()));
  EXPECT_TRUE(slnormals::computeVertexNormals(m.polygons(), m.xyz.data(), m.numPoints(), w, out.data(), Parallel()));
  return out;
}
} // namespace

TEST(GeometryCore, FaceNormalsAreUnitNewellNormals)
{
  Mesh m;
  // A triangle in z = 0, a quad in the plane x + y + z = 1 and a degenerate
  // triangle (three points on a line).
  m.xyz = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5, 0, 0.5, 2, 0, 0 };
  m.add({ 0, 1, 2 });
  m.add({ 3, 4, 5, 6 });
  m.add({ 0, 1, 7 });
  std::vector<float> n(9);
  slnormals::computeUnitFaceNormals(m.polygons(), m.xyz.data(), n.data(), Parallel());
  expectUnit(&n[0], 0, 0, 1);
  expectUnit(&n[3], 1, 1, 1);
  EXPECT_EQ(n[6], 0.0f);
  EXPECT_EQ(n[7], 0.0f);
  EXPECT_EQ(n[8], 0.0f);
}

TEST(GeometryCore, VertexNormalWeightings)
{
  Mesh m = twoTriangles();
  // Sum of weight * face normal at point 0, with A's normal +z and B's +y:
  expectUnit(&vertexNormals(m, Weighting::Uniform)[0], 0, 1, 1);       // 1 and 1
  expectUnit(&vertexNormals(m, Weighting::Area)[0], 0, 1, 4);          // twice the areas: 1 and 4
  expectUnit(&vertexNormals(m, Weighting::Angle)[0], 0, 1, 2);         // pi/4 and pi/2
  expectUnit(&vertexNormals(m, Weighting::Max)[0], 0, 2, 1);           // sin/(|e1||e2|): 1/2 and 1/4
  // A point of one triangle only takes that triangle's normal.
  expectUnit(&vertexNormals(m, Weighting::Angle)[3], 0, 0, 1);
}

TEST(GeometryCore, UnusedPointGetsAZeroNormal)
{
  Mesh m = twoTriangles();
  m.xyz.insert(m.xyz.end(), { 5, 5, 5 });
  const std::vector<float> n = vertexNormals(m, Weighting::Angle);
  EXPECT_EQ(n[15], 0.0f);
  EXPECT_EQ(n[16], 0.0f);
  EXPECT_EQ(n[17], 0.0f);
}

TEST(GeometryCore, OrientationRepairsAFlippedNeighbour)
{
  // The unit square as two triangles sharing the edge 0-2; the second one
  // is listed clockwise, so both traverse the edge from 0 to 2.
  Mesh m;
  m.xyz = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
  m.add({ 0, 1, 2 });
  m.add({ 0, 2, 3 });
  m.connectivity = { 0, 1, 2, 2, 0, 3 };
  Polygons<int64_t> p = m.polygons();
  slnormals::VertexCorners<int64_t> vc;
  vc.build(p, m.numPoints(), Parallel());
  EXPECT_TRUE(slnormals::hasInconsistentEdge(p, vc, Parallel()));
  std::vector<char> flipped;
  EXPECT_EQ(slnormals::orientPolygons(p, m.xyz.data(), vc, false, &flipped), 1);
  EXPECT_EQ(flipped[0] + flipped[1], 1);
  vc.build(p, m.numPoints(), Parallel());
  EXPECT_FALSE(slnormals::hasInconsistentEdge(p, vc, Parallel()));
  // Both faces now point the same way.
  std::vector<float> n(6);
  slnormals::computeUnitFaceNormals(p, m.xyz.data(), n.data(), Parallel());
  EXPECT_EQ(n[2], n[5]);
  EXPECT_NEAR(std::abs(n[2]), 1.0f, 1e-6);
}

TEST(GeometryCore, CornerTableListsEachPointsCornersInOrderOnAnyThreadCount)
{
  // 100 000 triangles (300 000 corners, more than the 2^18 under which the
  // table is built in one chunk) on 20 000 points, ids from a fixed
  // pseudo-random sequence, so that points have 0 to 40 corners in no order.
  Mesh m;
  m.xyz.assign(3 * 20000, 0.0);
  uint64_t state = 12345;
  auto nextId = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<int64_t>((state >> 33) % 20000);
  };
  for (int f = 0; f < 100000; ++f)
  {
    m.add({ nextId(), nextId(), nextId() });
  }
  // The table by hand: every point's connectivity positions, in increasing order.
  std::vector<std::vector<int32_t>> expected(20000);
  for (size_t c = 0; c < m.connectivity.size(); ++c)
  {
    expected[static_cast<size_t>(m.connectivity[c])].push_back(static_cast<int32_t>(c));
  }
  for (const int threads : { 1, 2, 3, 8 })
  {
    const Parallel chunked = backwardsInGrains(threads);
    slnormals::VertexCorners<int64_t> vc;
    vc.build(m.polygons(), m.numPoints(), chunked);
    ASSERT_EQ(vc.offsets.size(), expected.size() + 1) << threads << " threads";
    EXPECT_EQ(vc.offsets[0], 0);
    for (size_t v = 0; v < expected.size(); ++v)
    {
      const std::vector<int32_t> got(vc.corners.data() + vc.offsets[v], vc.corners.data() + vc.offsets[v + 1]);
      ASSERT_EQ(got, expected[v]) << "point " << v << ", " << threads << " threads";
    }
    EXPECT_EQ(vc.offsets[expected.size()], 300000);
  }
}

TEST(GeometryCore, PointsWithoutCornersAreThoseNoPolygonUses)
{
  // A strip of 4000 quads over two rows of 4001 points, except that every
  // tenth point of the bottom row (10, 20, ..., 3990) is left out of both
  // quads beside it, which are triangles instead; and 7 more points that no
  // polygon names. Counted in ranges of the grain, run last first, as a
  // thread pool might.
  Mesh m;
  const int64_t n = 4001;
  m.xyz.assign(static_cast<size_t>(3 * 2 * n + 3 * 7), 0.0); // 7 more points no polygon names
  size_t skipped = 0;
  for (int64_t x = 0; x + 1 < n; ++x)
  {
    const int64_t a = x, b = x + 1, c = n + x + 1, d = n + x;
    if (a % 10 == 0 && a > 0 && a + 1 < n)
    {
      m.add({ b, c, d });
      ++skipped;
    }
    else if (b % 10 == 0 && b + 1 < n)
    {
      m.add({ a, c, d });
    }
    else
    {
      m.add({ a, b, c, d });
    }
  }
  std::vector<char> named(static_cast<size_t>(m.numPoints()), 0);
  for (const int64_t id : m.connectivity)
  {
    named[static_cast<size_t>(id)] = 1;
  }
  const int64_t unnamed = std::count(named.begin(), named.end(), char(0));
  ASSERT_EQ(unnamed, static_cast<int64_t>(skipped) + 7);

  const Parallel chunked = backwardsInGrains(1);
  slnormals::VertexCorners<int64_t> vc;
  vc.build(m.polygons(), m.numPoints(), chunked);
  EXPECT_EQ(vc.pointsWithoutCorners(chunked), unnamed);
  EXPECT_EQ(vc.pointsWithoutCorners(Parallel()), unnamed);
}

TEST(GeometryCore, OrientationTurnsAClosedSurfaceOutward)
{
  // A tetrahedron with every face listed inward (normals toward the centre).
  Mesh m;
  m.xyz = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  m.add({ 0, 1, 2 }); // normal +z, inward for the face at z = 0
  m.add({ 0, 3, 1 }); // +y, inward at y = 0
  m.add({ 0, 2, 3 }); // +x, inward at x = 0
  m.add({ 1, 3, 2 }); // -(1,1,1), inward for the slanted face
  Polygons<int64_t> p = m.polygons();
  slnormals::VertexCorners<int64_t> vc;
  vc.build(p, m.numPoints(), Parallel());
  EXPECT_FALSE(slnormals::hasInconsistentEdge(p, vc, Parallel()));
  EXPECT_EQ(slnormals::orientPolygons(p, m.xyz.data(), vc, true), 4);
  std::vector<float> n(12);
  slnormals::computeUnitFaceNormals(p, m.xyz.data(), n.data(), Parallel());
  expectUnit(&n[0], 0, 0, -1);
  expectUnit(&n[3], 0, -1, 0);
  expectUnit(&n[6], -1, 0, 0);
  expectUnit(&n[9], 1, 1, 1);
}

TEST(GeometryCore, WeldingMapsCoincidentPointsToTheFirst)
{
  const std::vector<float> xyz = { 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0, 1, 0, 0 };
  std::vector<int64_t> canonical;
  EXPECT_EQ(slnormals::weldCoincidentPoints(xyz.data(), 6, canonical), 3);
  EXPECT_EQ(canonical, (std::vector<int64_t>{ 0, 1, 0, 1, 4, 1 }));
}

TEST(GeometryCore, MirrorSeamPointsAreSplitWithBothFrames)
{
  // Two triangles in z = 0 sharing the edge 0-2 (the y axis); the texture
  // is mirrored across it: u = x on the right one, u = -x on the left one.
  // Right: tangent +x, w = +1; left: d(u) along +x is -1, so the tangent is
  // -x with w = -1. Points 0 and 2 carry both and get a copy each.
  Mesh m;
  m.xyz = { 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0 };
  m.add({ 0, 1, 2 });
  m.add({ 0, 2, 3 });
  const std::vector<glm::dvec3> pos = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 } };
  const std::vector<glm::dvec2> uv = { { 0, 0 }, { 1, 0 }, { 0, 1 }, { 1, 0 } };
  const std::vector<glm::dvec3> nrm(4, glm::dvec3(0, 0, 1));
  Polygons<int64_t> p = m.polygons();
  const slnormals::SeamTangents t = slnormals::tangentFramesWithSeams(p, 4, pos, uv, nrm, Parallel());
  EXPECT_EQ(t.numSplitPoints, 2);
  EXPECT_EQ(t.source, (std::vector<int64_t>{ 0, 1, 2, 3, 0, 2 }));
  EXPECT_EQ(m.connectivity, (std::vector<int64_t>{ 0, 1, 2, 4, 5, 3 }));
  const std::vector<float> expected = {
    1, 0, 0, 1,   // point 0, right side
    1, 0, 0, 1,   // point 1
    1, 0, 0, 1,   // point 2, right side
    -1, 0, 0, -1, // point 3
    -1, 0, 0, -1, // copy of point 0, left side
    -1, 0, 0, -1, // copy of point 2, left side
  };
  ASSERT_EQ(t.tangents.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i)
  {
    EXPECT_NEAR(t.tangents[i], expected[i], 1e-6) << "component " << i;
  }
}

namespace
{
/// The unit cube as 12 triangles, each face's normal pointing out.
Mesh cube()
{
  Mesh m;
  m.xyz = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1 };
  for (auto q : std::vector<std::array<int64_t, 4>>{ { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 },
         { 2, 3, 7, 6 }, { 1, 2, 6, 5 }, { 0, 4, 7, 3 } })
  {
    m.add({ q[0], q[1], q[2] });
    m.add({ q[0], q[2], q[3] });
  }
  return m;
}

/// computePolygonNormals() with its callbacks on plain vectors.
struct Computed
{
  std::vector<float> normals;
  std::vector<int32_t> splitConnectivity;
  Mesh copy;
  int copies = 0;
  slnormals::PolygonNormals<int64_t> result;

  Computed(const slnormals::PolygonNormalsSettings& s, Mesh& m)
  {
    this->result.allocateNormals = [&](int64_t n) {
      this->normals.assign(static_cast<size_t>(3 * n), -7.0f);
      return this->normals.data();
    };
    this->result.allocateSplitConnectivity = [&](int64_t n) {
      this->splitConnectivity.assign(static_cast<size_t>(n), -1);
      return this->splitConnectivity.data();
    };
    this->result.copyPolygons = [&] {
      ++this->copies;
      this->copy = m;
      return this->copy.polygons();
    };
    slnormals::computePolygonNormals(s, m.polygons(), false, m.xyz.data(), m.numPoints(), Parallel(), this->result);
  }
};
} // namespace

TEST(GeometryCore, CubeSplitsIntoThreePointsPerCornerWithFaceNormals)
{
  // Every cube edge is 90 degrees, sharper than 30: each corner becomes one
  // point per face around it (8 x 3 = 24), each with its face's normal, and
  // no polygon needs reversing.
  Mesh m = cube();
  slnormals::PolygonNormalsSettings s;
  s.featureAngleDegrees = 30;
  const Computed c(s, m);
  EXPECT_EQ(c.result.flipped, 0);
  EXPECT_EQ(c.copies, 0);
  ASSERT_EQ(c.result.source.size(), 24u);
  ASSERT_EQ(c.result.pointMap.size(), 8u);
  ASSERT_EQ(c.splitConnectivity.size(), 36u);
  for (int64_t f = 0; f < 12; ++f)
  {
    // The face normal of triangle f, from the cube's own corners.
    const double* a = &m.xyz[static_cast<size_t>(3 * m.connectivity[static_cast<size_t>(3 * f)])];
    const double* b = &m.xyz[static_cast<size_t>(3 * m.connectivity[static_cast<size_t>(3 * f + 1)])];
    const double* d = &m.xyz[static_cast<size_t>(3 * m.connectivity[static_cast<size_t>(3 * f + 2)])];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, v[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    for (int k = 0; k < 3; ++k)
    {
      const int32_t out = c.splitConnectivity[static_cast<size_t>(3 * f + k)];
      ASSERT_GE(out, 0);
      ASSERT_LT(out, 24);
      // The split point stands where its input point is, with the face's normal.
      EXPECT_EQ(c.result.source[static_cast<size_t>(out)], m.connectivity[static_cast<size_t>(3 * f + k)]);
      expectUnit(&c.normals[static_cast<size_t>(3 * out)], n[0], n[1], n[2]);
    }
  }
}

TEST(GeometryCore, ASmoothCubeKeepsItsPointsWithDiagonalNormals)
{
  // Without splitting, angle weighting gives each corner (1,1,1)/sqrt(3)
  // pointing away from the centre: each face meets a corner at 90 degrees
  // in total, whatever its triangulation.
  Mesh m = cube();
  slnormals::PolygonNormalsSettings s;
  s.split = false;
  const Computed c(s, m);
  EXPECT_TRUE(c.result.source.empty());
  ASSERT_EQ(c.normals.size(), 24u);
  for (int64_t p = 0; p < 8; ++p)
  {
    const double* x = &m.xyz[static_cast<size_t>(3 * p)];
    expectUnit(&c.normals[static_cast<size_t>(3 * p)], x[0] - 0.5, x[1] - 0.5, x[2] - 0.5);
  }
}

TEST(GeometryCore, InwardSurfaceIsTurnedOutInACopyOfThePolygons)
{
  // The cube with every triangle listed backwards: AutoOrient reverses all
  // 12 in a copy (asked for once), leaving the caller's polygons as given.
  Mesh m = cube();
  for (size_t f = 0; f < 12; ++f)
  {
    std::swap(m.connectivity[3 * f + 1], m.connectivity[3 * f + 2]);
  }
  const std::vector<int64_t> given = m.connectivity;
  slnormals::PolygonNormalsSettings s;
  s.split = false;
  s.outward = true;
  const Computed c(s, m);
  EXPECT_EQ(c.result.flipped, 12);
  EXPECT_EQ(c.copies, 1);
  EXPECT_EQ(m.connectivity, given);
  EXPECT_EQ(c.result.polygons.connectivity, c.copy.connectivity.data());
  for (int64_t p = 0; p < 8; ++p)
  {
    const double* x = &m.xyz[static_cast<size_t>(3 * p)];
    expectUnit(&c.normals[static_cast<size_t>(3 * p)], x[0] - 0.5, x[1] - 0.5, x[2] - 0.5);
  }
}

TEST(GeometryCore, IdsBelowTakesNegativeIdsForHugeOnesWhateverTheLimit)
{
  // Both versions of the loop: the baseline one (inlined here) and, where the
  // CPU has it, the AVX2 one that slIdsBelow() picks; a CPU picks only one.
  const auto slIdsBelow = [](const auto* ids, int64_t n, int64_t limit) {
    const bool baseline = slIdsBelowInline(ids, n, limit);
    EXPECT_TRUE(!slHasAVX2() || slIdsBelowAVX2(ids, n, limit) == baseline) << n << " ids below " << limit;
    return baseline;
  };
  // Long enough for the vectorised loop and its remainder; one bad id at a time.
  for (const int64_t limit : { int64_t(0), int64_t(7), (int64_t(1) << 31) - 1, int64_t(1) << 31, int64_t(1) << 33 })
  {
    std::vector<int32_t> ids(37, 0);
    EXPECT_EQ(slIdsBelow(ids.data(), 37, limit), limit > 0) << limit;
    for (const int32_t bad : { int32_t(-1), int32_t(-2), std::numeric_limits<int32_t>::min() })
    {
      ids[29] = bad;
      EXPECT_FALSE(slIdsBelow(ids.data(), 37, limit)) << bad << " against " << limit;
    }
    // The largest id a 32-bit array holds names a point only when there are more.
    ids[29] = std::numeric_limits<int32_t>::max();
    EXPECT_EQ(slIdsBelow(ids.data(), 37, limit), limit > std::numeric_limits<int32_t>::max()) << limit;
    std::vector<int64_t> wide(37, 0);
    wide[36] = limit;
    EXPECT_FALSE(slIdsBelow(wide.data(), 37, limit)) << "the limit itself, " << limit;
    wide[36] = limit - 1;
    EXPECT_EQ(slIdsBelow(wide.data(), 37, limit), limit > 0) << limit;
  }
}

TEST(GeometryCore, IdsWithinAgreesWithTwoSignedComparesOnEveryBound)
{
  // Each id alone, then all of them, against ranges around them and at the
  // ends of both id widths, compared with lo <= id && id < hi in 64 bits;
  // a negative id names no point, whatever lo says.
  const auto check = [](const auto& ids, int64_t lo, int64_t hi) {
    bool all = true;
    for (size_t i = 0; i < ids.size(); ++i)
    {
      const auto id = static_cast<int64_t>(ids[i]);
      const bool in = id >= 0 && lo <= id && id < hi;
      all = all && in;
      EXPECT_EQ(slIdsWithinInline(&ids[i], 1, lo, hi), in) << id << " in [" << lo << ", " << hi << ")";
    }
    // 37 ids: the vectorised loop and its remainder.
    std::vector<std::decay_t<decltype(ids[0])>> many(37, ids[0]);
    for (size_t i = 0; i < ids.size(); ++i)
    {
      many[36 - i] = ids[i];
    }
    EXPECT_EQ(slIdsWithinInline(many.data(), 37, lo, hi), all) << "[" << lo << ", " << hi << ")";
    EXPECT_TRUE(!slHasAVX2() || slIdsWithinAVX2(many.data(), 37, lo, hi) == all) << "[" << lo << ", " << hi << ")";
  };
  const int64_t big = int64_t(1) << 31;
  const std::vector<int32_t> narrow = { 0, 5, 6, 9, -1, std::numeric_limits<int32_t>::max(),
    std::numeric_limits<int32_t>::min() };
  const std::vector<int64_t> wide = { 0, 5, 6, 9, -1, big, big * 4, std::numeric_limits<int64_t>::min() };
  for (const int64_t lo : { int64_t(-3), int64_t(0), int64_t(5), int64_t(6), big - 1, big, big * 4 })
  {
    for (const int64_t hi : { int64_t(0), int64_t(6), int64_t(10), big - 1, big, big + 1, big * 4 + 1 })
    {
      for (size_t i = 0; i < narrow.size(); ++i)
      {
        check(std::vector<int32_t>{ narrow[i] }, lo, hi);
      }
      for (size_t i = 0; i < wide.size(); ++i)
      {
        check(std::vector<int64_t>{ wide[i] }, lo, hi);
      }
      check(std::vector<int32_t>{ 5, 6, 9 }, lo, hi);
      check(std::vector<int64_t>{ 5, 6, 9 }, lo, hi);
    }
  }
}

TEST(GeometryCore, VectorAndBaselineLoopsGiveTheSameBits)
{
  if (!slHasAVX2())
  {
    GTEST_SKIP() << "this CPU runs the baseline loops only";
  }
  // Triangles of every shape, degenerate ones included; no version fuses
  // multiply-adds (AVX-512 brings FMA, its clone turns fusing off), so the
  // weights and unit vectors must agree to the bit.
  slnormals::TriangleBlock<float> triangles{};
  uint32_t state = 12345;
  const auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / 16777216.0f - 0.5f;
  };
  for (int i = 0; i < triangles.Capacity; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      triangles.x[k][i] = next();
      triangles.y[k][i] = i % 7 == 0 ? 0.0f : next();
      triangles.z[k][i] = i % 11 == 0 ? triangles.z[0][i] : next();
    }
  }
  triangles.x[1][5] = triangles.x[0][5]; // a triangle with two equal points
  triangles.y[1][5] = triangles.y[0][5];
  triangles.z[1][5] = triangles.z[0][5];
  const auto same = [](const float* a, const float* b, int n) {
    for (int i = 0; i < n; ++i)
    {
      if (std::memcmp(a + i, b + i, sizeof(float)) != 0)
      {
        return ::testing::AssertionFailure() << "value " << i << ": " << a[i] << " against " << b[i];
      }
    }
    return ::testing::AssertionSuccess();
  };
  const auto sameWeights = [&same](const slnormals::TriangleBlock<float>& a, const slnormals::TriangleBlock<float>& b) {
    const int n = 3 * a.Capacity;
    return same(&a.cornerX[0][0], &b.cornerX[0][0], n) && same(&a.cornerY[0][0], &b.cornerY[0][0], n) &&
      same(&a.cornerZ[0][0], &b.cornerZ[0][0], n);
  };
  // A full block, and one whose last triangles go through the loops' scalar ends.
  for (const int count : { triangles.Capacity, triangles.Capacity - 3 })
  {
    SCOPED_TRACE(count);
    triangles.count = count;
    slnormals::TriangleBlock<float> baseline = triangles, avx2 = triangles, avx512 = triangles;
    baseline.weighLoop<Weighting::Angle>();
    avx2.weighAVX2<Weighting::Angle>();
    EXPECT_TRUE(sameWeights(baseline, avx2));
    EXPECT_EQ(baseline.cornerX[0][5], 0.0f); // the degenerate triangle weighs 0
    if (slHasAVX512())
    {
      avx512.weighAVX512<Weighting::Angle>();
      EXPECT_TRUE(sameWeights(baseline, avx512));
    }
  }

  // Normalising, in place and apart, a zero sum among them.
  std::vector<float> sums(3 * 37);
  for (float& v : sums)
  {
    v = next();
  }
  sums[30] = sums[31] = sums[32] = 0.0f;
  std::vector<float> inPlace = sums, inPlaceAVX2 = sums, apart(sums.size()), apartAVX2(sums.size());
  slnormals::detail::normaliseLoop(inPlace.data(), inPlace.data(), 0, 37);
  slnormals::detail::normaliseSumsAVX2(inPlaceAVX2.data(), inPlaceAVX2.data(), 0, 37);
  slnormals::detail::normaliseLoop(sums.data(), apart.data(), 0, 37);
  slnormals::detail::normaliseSumsAVX2(sums.data(), apartAVX2.data(), 0, 37);
  EXPECT_TRUE(same(inPlace.data(), inPlaceAVX2.data(), 3 * 37));
  EXPECT_TRUE(same(apart.data(), apartAVX2.data(), 3 * 37));
  EXPECT_TRUE(same(inPlace.data(), apart.data(), 3 * 37));
  if (slHasAVX512())
  {
    std::vector<float> inPlaceAVX512 = sums, apartAVX512(sums.size());
    slnormals::detail::normaliseSumsAVX512(inPlaceAVX512.data(), inPlaceAVX512.data(), 0, 37);
    slnormals::detail::normaliseSumsAVX512(sums.data(), apartAVX512.data(), 0, 37);
    EXPECT_TRUE(same(inPlace.data(), inPlaceAVX512.data(), 3 * 37));
    EXPECT_TRUE(same(apart.data(), apartAVX512.data(), 3 * 37));
  }
  EXPECT_EQ(apart[31], 0.0f);
  EXPECT_NEAR(std::sqrt(apart[0] * apart[0] + apart[1] * apart[1] + apart[2] * apart[2]), 1.0f, 1e-6f);
}

/// fillBelowLastPoint() against fill() on 64 triangles whose ids are below
/// the last point, for both id widths: the same coordinates to the bit.
template <typename Id>
void expectFourWideFillAsFill()
{
  const int64_t numPoints = 200;
  std::vector<float> xyz(static_cast<size_t>(3 * numPoints));
  uint32_t state = 987;
  for (float& v : xyz)
  {
    state = state * 1664525u + 1013904223u;
    v = static_cast<float>(state >> 8) / 4096.0f - 2048.0f;
  }
  const int capacity = slnormals::TriangleBlock<float>::Capacity;
  std::vector<Id> ids(static_cast<size_t>(3 + 3 * capacity));
  for (Id& id : ids)
  {
    state = state * 1664525u + 1013904223u;
    id = static_cast<Id>(state % (numPoints - 1));
  }
  ids[3] = 0;
  ids[4] = static_cast<Id>(numPoints - 2);
  slnormals::TriangleBlock<float> one, four;
  one.fill(ids.data(), xyz.data(), 3, capacity);
  four.fillBelowLastPoint(ids.data(), xyz.data(), 3, capacity);
  EXPECT_EQ(four.start, 3);
  EXPECT_EQ(four.count, capacity);
  EXPECT_EQ(std::memcmp(one.x, four.x, sizeof(one.x)), 0);
  EXPECT_EQ(std::memcmp(one.y, four.y, sizeof(one.y)), 0);
  EXPECT_EQ(std::memcmp(one.z, four.z, sizeof(one.z)), 0);
}

TEST(GeometryCore, FourWideFillReadsWhatFillReads)
{
  expectFourWideFillAsFill<int32_t>();
  expectFourWideFillAsFill<int64_t>();
}

/// Scatters @p polys (float points @p xyz) into @p sums with one chunk that
/// owns every point, asking ahead or not; what scatter() returns.
bool scatterAngles(const Polygons<int64_t>& polys, const std::vector<float>& xyz, bool lookahead, std::vector<float>& sums)
{
  const int64_t numPoints = static_cast<int64_t>(xyz.size() / 3);
  sums.assign(xyz.size(), 0.0f);
  const int64_t bounds[2] = { 0, numPoints };
  std::vector<std::vector<slnormals::detail::Kept<float>>> kept(1);
  slnormals::detail::ChunkSink<float> sink{ sums.data(), 0, numPoints, bounds, 1, kept.data() };
  return slnormals::detail::scatter<Weighting::Angle>(
    polys, polys.connectivity, xyz.data(), numPoints, 0, polys.numPolygons, lookahead, sink);
}

TEST(GeometryCore, AskingAheadChangesNoSumAndNoCheck)
{
  // Three blocks of triangles with random ids (a mesh in random order): the
  // second block asks for the third, which ends where the connectivity
  // array does (AddressSanitizer sees a read past it). Asking ahead only
  // hints, so the sums are the same bits; and a bad id in the third block,
  // hinted while the second is filled, is still reported and never read.
  const int64_t numPoints = 300;
  const int capacity = slnormals::TriangleBlock<float>::Capacity;
  std::vector<float> xyz(static_cast<size_t>(3 * numPoints));
  uint32_t state = 4242;
  const auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return state >> 8;
  };
  for (float& v : xyz)
  {
    v = static_cast<float>(next() % 2001) / 1000.0f - 1.0f;
  }
  std::vector<int64_t> offsets{ 0 }, connectivity;
  for (int f = 0; f < 3 * capacity; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      connectivity.push_back(static_cast<int64_t>(next() % numPoints));
    }
    offsets.push_back(static_cast<int64_t>(connectivity.size()));
  }
  Polygons<int64_t> p;
  p.offsets = offsets.data();
  p.connectivity = connectivity.data();
  p.numPolygons = 3 * capacity;
  std::vector<float> plain, ahead;
  ASSERT_TRUE(scatterAngles(p, xyz, false, plain));
  ASSERT_TRUE(scatterAngles(p, xyz, true, ahead));
  EXPECT_EQ(std::memcmp(plain.data(), ahead.data(), plain.size() * sizeof(float)), 0);
  EXPECT_GT(std::count(plain.begin(), plain.end(), 0.0f), 0) << "some points unused";
  EXPECT_LT(std::count(plain.begin(), plain.end(), 0.0f), static_cast<long>(plain.size()) / 4);
  for (const int64_t bad : { int64_t(-1), numPoints, std::numeric_limits<int64_t>::max() / 2,
         std::numeric_limits<int64_t>::min() })
  {
    SCOPED_TRACE(bad);
    connectivity[static_cast<size_t>(3 * (2 * capacity + 5) + 1)] = bad;
    EXPECT_FALSE(scatterAngles(p, xyz, false, plain));
    EXPECT_FALSE(scatterAngles(p, xyz, true, ahead));
  }
}

TEST(GeometryCore, ABlockNamingTheLastPointIsReadOnePointAtATime)
{
  // A strip of 128 triangles over 130 float points, numbered backwards so
  // that the first block names the last point. The four-wide fill reads 16
  // bytes a point, 4 past the last one's: that block must be read point by
  // point (under AddressSanitizer, the points end exactly where the array
  // does). The reference sums the Newell vectors in double.
  const int64_t numPoints = 130;
  std::vector<float> xyz(static_cast<size_t>(3 * numPoints));
  for (int64_t j = 0; j < numPoints; ++j)
  {
    const int64_t id = numPoints - 1 - j;
    xyz[static_cast<size_t>(3 * id)] = static_cast<float>(j / 2);
    xyz[static_cast<size_t>(3 * id + 1)] = static_cast<float>(j % 2);
    xyz[static_cast<size_t>(3 * id + 2)] = static_cast<float>((j * 7) % 5) * 0.25f;
  }
  std::vector<int64_t> offsets{ 0 }, connectivity;
  for (int64_t j = 0; j + 2 < numPoints; ++j)
  {
    for (const int64_t k : { j, j + 1 + (j % 2), j + 2 - (j % 2) })
    {
      connectivity.push_back(numPoints - 1 - k);
    }
    offsets.push_back(static_cast<int64_t>(connectivity.size()));
  }
  Polygons<int64_t> p;
  p.offsets = offsets.data();
  p.connectivity = connectivity.data();
  p.numPolygons = static_cast<int64_t>(offsets.size()) - 1;
  ASSERT_EQ(p.numPolygons, 2 * slnormals::TriangleBlock<float>::Capacity);
  std::vector<float> out(xyz.size());
  ASSERT_TRUE(slnormals::computeVertexNormals(p, xyz.data(), numPoints, Weighting::Area, out.data(), Parallel()));
  std::vector<double> sums(xyz.size(), 0.0);
  for (int64_t f = 0; f < p.numPolygons; ++f)
  {
    const int64_t* t = &connectivity[static_cast<size_t>(3 * f)];
    double e1[3], e2[3];
    for (int c = 0; c < 3; ++c)
    {
      e1[c] = static_cast<double>(xyz[static_cast<size_t>(3 * t[1] + c)]) - xyz[static_cast<size_t>(3 * t[0] + c)];
      e2[c] = static_cast<double>(xyz[static_cast<size_t>(3 * t[2] + c)]) - xyz[static_cast<size_t>(3 * t[0] + c)];
    }
    const double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0] };
    for (int k = 0; k < 3; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        sums[static_cast<size_t>(3 * t[k] + c)] += n[c];
      }
    }
  }
  for (int64_t v = 0; v < numPoints; ++v)
  {
    SCOPED_TRACE(v);
    expectUnit(&out[static_cast<size_t>(3 * v)], sums[static_cast<size_t>(3 * v)],
      sums[static_cast<size_t>(3 * v + 1)], sums[static_cast<size_t>(3 * v + 2)]);
  }
}

/// Largest |cornerAngle(c, d) - atan2(c, d)| in T over angles swept across
/// [0, pi] at lengths from 1e-6 to 1e6; atan2 in double on the same
/// (rounded) inputs is the independent reference.
template <typename T>
double worstCornerAngleError()
{
  double worst = 0;
  for (double length : { 1e-6, 1.0, 1e6 })
  {
    for (int i = 0; i <= 200000; ++i)
    {
      const double theta = M_PI * i / 200000;
      const T cross = static_cast<T>(length * std::sin(theta));
      const T dot = static_cast<T>(length * std::cos(theta));
      const double reference = std::atan2(static_cast<double>(cross), static_cast<double>(dot));
      worst = std::max(worst, std::fabs(static_cast<double>(slnormals::cornerAngle(cross, dot)) - reference));
    }
  }
  return worst;
}

TEST(GeometryCore, CornerAngleIsAtan2WithinItsDocumentedError)
{
  // slCornerWeights.h: |error| <= 4e-8 rad in double, 4e-7 rad in float.
  EXPECT_LT(worstCornerAngleError<double>(), 4e-8);
  EXPECT_LT(worstCornerAngleError<float>(), 4e-7);
  // Both lengths zero (a degenerate corner): 0, not NaN.
  EXPECT_EQ(slnormals::cornerAngle(0.0f, 0.0f), 0.0f);
  EXPECT_EQ(slnormals::cornerAngle(0.0, -0.0), 0.0);
  // The ends: a straight corner is pi, a closed one 0.
  EXPECT_NEAR(slnormals::cornerAngle(0.0, -2.0), M_PI, 1e-15);
  EXPECT_EQ(slnormals::cornerAngle(0.0, 2.0), 0.0);
}
