#ifndef shadelab_bench_BenchBareLoop_h
#define shadelab_bench_BenchBareLoop_h
// The bare loop of vertex normals, the bench's reference for what the
// machine's memory allows in a mesh's order: for each triangle, read its
// three points and add their cross product at each of them. No id checks,
// no weights, no normalising, no merging of the per-thread sums. Any vertex
// normal filter does at least this much memory traffic, in the same order;
// in a mesh without locality that traffic is a cache miss per point and
// per sum, which the bandwidth floor does not see.

#include <vector>

class vtkDataArray;
class vtkPolyData;

class slBenchBareLoop
{
public:
  /// @p mesh: triangles only, float points (the bench's tori); at most
  /// @p chunks chunks per run. @p prefetch: ask for the points and sums 16
  /// triangles ahead, as slPolyDataNormals does in a mesh in random order.
  /// Exits with a message when the mesh is not of that kind.
  slBenchBareLoop(vtkPolyData* mesh, int chunks, bool prefetch);

  /// One pass: the triangles cut into @p chunks contiguous chunks (1 to the
  /// constructor's), run through vtkSMPTools, each into its own zeroed sums.
  void Run(int chunks);

  /// Largest angle, in degrees, between @p normals (3 components a point)
  /// and the direction of the last run's sums added over its chunks: the
  /// area-weighted normals. Points whose sum is zero are skipped.
  double LargestAngleTo(vtkDataArray* normals) const;

private:
  vtkPolyData* Mesh;
  bool Prefetch;
  int LastChunks = 0;
  std::vector<std::vector<float>> Sums; ///< one per chunk
};

#endif
