// Normal maps in Phong mode: the pass lights the normal that VTK's mapper
// perturbs with the property's normal texture and the mesh's Tangents.
#include "PassTestUtilities.h"

#include "slImageWriter.h"
#include "slLightingPass.h"
#include "slNormalMapFilter.h"
#include "TestFolder.h"
#include "VTKErrors.h"

#include <vtkActor.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkProperty.h>
#include <vtkTexture.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <unistd.h>

namespace
{
/// A plane facing +z with texture coordinates and tangents along +x
/// (3 components, or 4 with handedness w = +1 or -1 given by @p handedness),
/// tilted out of the plane by @p skew (tangent (1, 0, skew)) if given.
vtkSmartPointer<vtkPolyData> tangentPlane(int tangentComponents, float handedness = 1.0f, float skew = 0.0f)
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
    const float t[4] = { 1.0f, 0.0f, skew, handedness };
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
vtkSmartPointer<vtkImageData> tiltedNormalImage(double a, bool alongBitangent = false)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
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
  return image;
}

vtkSmartPointer<vtkTexture> tiltedNormalMap(double a, bool alongBitangent = false)
{
  vtkSmartPointer<vtkImageData> image = tiltedNormalImage(a, alongBitangent);
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

TEST_P(NormalMap, GPUDecodesAsTheCPUFilter)
{
  // Tangents that are not orthogonal to the normal (as interpolated ones are
  // not): both sides must make them orthogonal the same way, so the CPU's
  // slNormalMapFilter normal lit by the light equals the GPU's pixel.
  const double tilt = 0.7;
  const float skew = 0.6f;
  shadelab::Scene scene = lambertScene();
  passtest::Stage stage = passtest::litStage(tangentPlane(GetParam(), 1.0f, skew), scene, 100, 100);
  stage.actor->GetProperty()->SetNormalTexture(tiltedNormalMap(tilt));
  const float gpu = stage.render().at(50, 50)[0];

  const TestFolder folder;
  ASSERT_TRUE(folder.valid());
  const std::string path = folder.path("map.png");
  vtkNew<slImageWriter> writer;
  writer->SetInputData(tiltedNormalImage(tilt));
  writer->SetFileName(path.c_str());
  ASSERT_EQ(callError(writer, [&] { return writer->Write(); }), "");
  vtkNew<slNormalMapFilter> mapped;
  mapped->SetInputData(tangentPlane(GetParam(), 1.0f, skew));
  mapped->SetFileName(path.c_str());
  ASSERT_EQ(updateError(mapped), "");
  double n[3];
  mapped->GetOutput()->GetPointData()->GetNormals()->GetTuple(0, n);
  const double cpu = std::max(0.0, -(n[0] * scene.lights[0].direction.x + n[1] * scene.lights[0].direction.y +
                                   n[2] * scene.lights[0].direction.z));
  EXPECT_NEAR(gpu, cpu, 2.0 / 255.0) << GetParam() << "-component tangents";
  // And both are the orthogonalised frame's cos(tilt), 8-bit texels aside.
  EXPECT_NEAR(cpu, std::cos(tilt), 2.0 / 255.0);
}

INSTANTIATE_TEST_SUITE_P(TangentComponents, NormalMap, ::testing::Values(3, 4));

TEST(NormalMap, ANewMapperWhereAFreedOneWasGetsItsTangents)
{
  // The pass maps the 4-component Tangents of each mapper once; a mapper
  // made after another was freed (often at the same address) is a new one
  // and needs its own mapping, or its normal map reads no tangents.
  const double a = 0.4;
  shadelab::Scene scene = lambertScene();
  scene.lights[0].direction = glm::vec3(0.0f, -static_cast<float>(std::sin(a)), -static_cast<float>(std::cos(a)));
  passtest::Stage stage = passtest::litStage(tangentPlane(4, -1.0f), scene, 100, 100);
  stage.actor->GetProperty()->SetNormalTexture(tiltedNormalMap(a, true));
  const float expected = static_cast<float>(std::cos(2.0 * a)); // w = -1: the normal tilts away
  EXPECT_NEAR(stage.render().at(50, 50)[0], expected, 3.0f / 255.0f);

  bool sameAddress = false;
  for (int attempt = 0; attempt < 8 && !sameAddress; ++attempt)
  {
    const void* freed = stage.actor->GetMapper();
    stage.actor->SetMapper(nullptr); // the actor held the only reference
    stage.renderer->GetRenderWindow()->Render(); // nothing to draw
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(tangentPlane(4, -1.0f));
    mapper->ScalarVisibilityOff();
    stage.actor->SetMapper(mapper);
    sameAddress = static_cast<const void*>(mapper.GetPointer()) == freed;
    EXPECT_NEAR(stage.render().at(50, 50)[0], expected, 3.0f / 255.0f) << "attempt " << attempt;
  }
  if (!sameAddress)
  {
    // AddressSanitizer quarantines freed memory, for one: then the case
    // this test is about never arose, and passing would say nothing.
    GTEST_SKIP() << "no new mapper was made at a freed one's address";
  }
}
