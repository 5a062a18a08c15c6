#include "BenchOpenMesh.h"

#include <vtkCellArray.h>
#include <vtkPolyData.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <vector>

struct slBenchOpenMesh::Impl
{
  OpenMesh::TriMesh_ArrayKernelT<> Mesh;
};

slBenchOpenMesh::slBenchOpenMesh(vtkPolyData* triangles)
  : P(new Impl)
{
  auto& om = this->P->Mesh;
  std::vector<OpenMesh::VertexHandle> v;
  v.reserve(static_cast<size_t>(triangles->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < triangles->GetNumberOfPoints(); ++i)
  {
    double p[3];
    triangles->GetPoint(i, p);
    v.push_back(om.add_vertex(OpenMesh::Vec3f(
      static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]))));
  }
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = triangles->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    om.add_face(v[static_cast<size_t>(ids[0])], v[static_cast<size_t>(ids[1])], v[static_cast<size_t>(ids[2])]);
  }
  om.request_face_normals();
  om.request_vertex_normals();
}

slBenchOpenMesh::~slBenchOpenMesh() = default;

void slBenchOpenMesh::UpdateNormals()
{
  this->P->Mesh.update_face_normals();
  this->P->Mesh.update_vertex_normals();
}
