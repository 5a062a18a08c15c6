#ifndef shadelab_tests_AzimuthTangents_h
#define shadelab_tests_AzimuthTangents_h
// Tangents for test meshes shaded with the anisotropic models.

#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace shadelab
{
namespace test
{

/// Adds a 4-component "Tangents" point array (the layout slPolyDataTangents
/// makes, handedness w = 1) along the azimuth around z, (-y, x, 0): on a
/// sphere about the origin the direction of increasing longitude. On the z
/// axis it is zero (no tangent: the lighting picks a frame, slTangentX()).
inline void addAzimuthTangents(vtkPolyData* mesh)
{
  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(4);
  tangents->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    tangents->SetTuple4(i, -p[1], p[0], 0.0, 1.0);
  }
  mesh->GetPointData()->AddArray(tangents);
}

} // namespace test
} // namespace shadelab

#endif
