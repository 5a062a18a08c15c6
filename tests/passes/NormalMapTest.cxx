// Normal maps in Phong mode: the pass lights the normal that VTK's mapper
// perturbs with the property's normal texture and the mesh's Tangents.
#include "PassTestUtilities.h"

#include "slLightingPass.h"

#include <vtkActor.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkTexture.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
/// A plane facing +z with texture coordinates and tangents along +x
/// (3 components, or 4 with handedness w = +1 or -1 given by @p handedness).
vtkSmartPointer<vtkPolyData> tangentPlane(int tangentComponents, float handedness = 1.0f)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);
  plane->SetResolution(8, 8);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(plane->GetOutputPort());
  normals->Update();
  vtkSmartPointer<vtkPolyData> mesh = normals->GetOutput();
  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(tangentComponents);
  tangents->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const float t[4] = { 1.0f, 0.0f, 0.0f, handedness };
    tangents->SetTypedTuple(i, t);
  }
  if (tangentComponents == 3)
  {
    mesh->GetPointData()->SetTangents(tangents);
  }
  else
  {
    mesh->GetPointData()->AddArray(tangents); // VTK's TANGENTS attribute takes 3 components only
  }
  return mesh;
}

/// A 4 x 4 normal map whose every texel encodes the tangent-space normal
/// (sin a, 0, cos a), or (0, sin a, cos a) along the bitangent; OpenGL
/// convention (RGB = (n + 1) / 2).
vtkSmartPointer<vtkTexture> tiltedNormalMap(double a, bool alongBitangent = false)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* texels = static_cast<unsigned char*>(image->GetScalarPointer());
  const double n[3] = { alongBitangent ? 0.0 : std::sin(a), alongBitangent ? std::sin(a) : 0.0, std::cos(a) };
  for (int i = 0; i < 16; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      texels[3 * i + c] = static_cast<unsigned char>(std::lround((n[c] + 1.0) * 0.5 * 255.0));
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  return texture;
}

shadelab::Scene lambertScene()
{
  shadelab::Scene s;
  s.model = shadelab::ShadingModel::Lambert;
  s.frequency = shadelab::ShadingFrequency::Phong;
  s.camera.hasPosition = true;
  s.camera.position = glm::vec3(0.0f, 0.0f, 3.0f);
  s.material.ambient = glm::vec3(0.0f);
  s.material.diffuse = glm::vec3(1.0f);
  shadelab::SceneLight light; // straight down the view axis
  light.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  s.lights.push_back(light);
  return s;
}
} // namespace

class NormalMap : public ::testing::TestWithParam<int>
{
};

TEST_P(NormalMap, TiltedNormalsDimTheLambertTermByTheirCosine)
{
  const double tilt = 0.7; // radians
  passtest::Stage plain = passtest::litStage(tangentPlane(GetParam()), lambertScene(), 100, 100);
  const float unmapped = plain.render().at(50, 50)[0];

  passtest::Stage mapped = passtest::litStage(tangentPlane(GetParam()), lambertScene(), 100, 100);
  mapped.actor->GetProperty()->SetNormalTexture(tiltedNormalMap(tilt));
  const float value = mapped.render().at(50, 50)[0];

  EXPECT_NEAR(unmapped, 1.0f, 1.0f / 255.0f);
  // The light is along the geometric normal: N.L = cos(tilt) for the mapped normal.
  EXPECT_NEAR(value, std::cos(tilt), 3.0f / 255.0f) << GetParam() << "-component tangents";
}

INSTANTIATE_TEST_SUITE_P(TangentComponents, NormalMap, ::testing::Values(3, 4));

TEST(NormalMap, HandednessFlipsTheBitangent)
{
  // Normal map tilted by a toward +bitangent; light arriving from a toward +y.
  // w = +1: bitangent = N x T = +y, the mapped normal faces the light (N.L = 1).
  // w = -1: bitangent = -y, the mapped normal tilts away (N.L = cos 2a).
  const double a = 0.4;
  shadelab::Scene scene = lambertScene();
  scene.lights[0].direction = glm::vec3(0.0f, -static_cast<float>(std::sin(a)), -static_cast<float>(std::cos(a)));
  for (float w : { 1.0f, -1.0f })
  {
    passtest::Stage stage = passtest::litStage(tangentPlane(4, w), scene, 100, 100);
    stage.actor->GetProperty()->SetNormalTexture(tiltedNormalMap(a, true));
    const float expected = static_cast<float>(w > 0.0f ? 1.0 : std::cos(2.0 * a));
    EXPECT_NEAR(stage.render().at(50, 50)[0], expected, 3.0f / 255.0f) << "w = " << w;
  }
}
