#ifndef shadelab_bench_BenchOpenMesh_h
#define shadelab_bench_BenchOpenMesh_h
// The OpenMesh peer: the bench mesh as an OpenMesh TriMesh, and its
// update_face_normals + update_vertex_normals.

#include <memory>

class vtkPolyData;

class slBenchOpenMesh
{
public:
  explicit slBenchOpenMesh(vtkPolyData* triangles);
  ~slBenchOpenMesh();
  void UpdateNormals();

private:
  struct Impl;
  std::unique_ptr<Impl> P;
};

#endif
