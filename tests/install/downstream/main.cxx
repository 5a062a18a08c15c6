// Uses an installed ShadeLab: normals of a sphere against the analytic
// normal p/|p|, and the N.L field of a directional light against N.L
// computed here from those normals. Exit 0 only if both agree.
#include "slCosineField.h"
#include "slPolyDataNormals.h"
#include "slScene.h"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

int main()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(2.0);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);

  vtkNew<slPolyDataNormals> normals;
  normals->SetInputConnection(sphere->GetOutputPort());
  normals->SetWeightingToAngle();
  normals->SetSplitting(false);

  // A light shining along -z: it comes from +z, so N.L = max(0, n_z).
  vtkNew<slScene> scene;
  const char* json = R"({"lights":[{"type":"directional","space":"world","direction":[0,0,-1]}]})";
  if (!scene->ReadString(json, "downstream scene"))
  {
    std::fprintf(stderr, "downstream: the scene was rejected (VTK printed why)\n");
    return 1;
  }
  vtkNew<slCosineField> cosine;
  cosine->SetInputConnection(normals->GetOutputPort());
  cosine->SetScene(scene);
  cosine->SetLightIndex(0);
  cosine->Update();

  vtkPolyData* out = cosine->GetOutput();
  vtkDataArray* n = out->GetPointData()->GetArray("Normals");
  vtkDataArray* c = out->GetPointData()->GetArray("CosTheta");
  if (!n || !c || out->GetNumberOfPoints() != 64 * 30 + 2)
  {
    std::fprintf(stderr, "downstream: %lld points, Normals %s, CosTheta %s\n",
      static_cast<long long>(out->GetNumberOfPoints()), n ? "present" : "missing",
      c ? "present" : "missing");
    return 1;
  }
  double worstAngle = 0.0, worstCos = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3], v[3];
    out->GetPoint(i, p);
    n->GetTuple(i, v);
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const double dot = (p[0] * v[0] + p[1] * v[1] + p[2] * v[2]) / r;
    worstAngle = std::max(worstAngle, std::acos(std::min(1.0, dot)) * 180.0 / M_PI);
    worstCos = std::max(worstCos, std::abs(c->GetTuple1(i) - std::max(0.0, v[2])));
  }
  std::printf("downstream: %lld points, largest normal error %.4f deg, largest N.L error %.2e\n",
    static_cast<long long>(out->GetNumberOfPoints()), worstAngle, worstCos);
  // A 64 x 32 sphere's vertex normals are within a few tenths of a degree
  // of the true normal; N.L is a float product of unit vectors.
  return (worstAngle < 2.0 && worstCos < 1e-6) ? 0 : 1;
}
