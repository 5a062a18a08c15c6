// The lobe image with .brdf files overlaid on built-in models: fixed size,
// the same pixels every time, every BRDF's colour drawn, the files' albedo
// at the lobes' incidence, and one-line errors.
#include "slBRDFLobeSource.h"
#include "slLobeImageRenderer.h"
#include "VTKErrors.h"

#include <vtkImageData.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <cstring>

namespace
{
const std::string kData = SHADELAB_DATA_DIR;

/// Pixels of exactly @p rgb in @p image (RGB, unsigned char).
int countColor(vtkImageData* image, const unsigned char rgb[3])
{
  int dims[3];
  image->GetDimensions(dims);
  const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer());
  int count = 0;
  for (int k = 0; k < dims[0] * dims[1]; ++k)
  {
    count += p[3 * k] == rgb[0] && p[3 * k + 1] == rgb[1] && p[3 * k + 2] == rgb[2];
  }
  return count;
}

void addOverlay(slLobeImageRenderer* image)
{
  ASSERT_TRUE(image->AddModel("phong"));
  ASSERT_TRUE(image->AddBRDFFile((kData + "/brdf/blinn-phong-normalized.brdf").c_str()));
  image->AddBRDFFileParameter("kd=0");
  image->AddBRDFFileParameter("ks=1");
  image->AddBRDFFileParameter("n=20");
  ASSERT_TRUE(image->AddBRDFFile((kData + "/brdf/ward-anisotropic.brdf").c_str()));
  image->GetLobeParameters()->SetIncidenceAngle(0.0);
}
} // namespace

TEST(LobeImage, BRDFFilesOverlayModelsInTheirColours)
{
  vtkNew<slLobeImageRenderer> image;
  addOverlay(image);
  ASSERT_EQ(callError(image, [&] { return image->Render(); }), "");
  vtkImageData* first = image->GetImage();
  int dims[3];
  first->GetDimensions(dims);
  EXPECT_EQ(dims[0], 3 * image->GetPanelWidth());
  EXPECT_EQ(dims[1], image->GetPanelHeight());
  for (int i = 0; i < 3; ++i)
  {
    unsigned char rgb[3];
    slLobeImageRenderer::GetColor(i, rgb);
    EXPECT_GT(countColor(first, rgb), 50) << "BRDF " << i;
  }
  unsigned char unused[3];
  slLobeImageRenderer::GetColor(3, unused);
  EXPECT_EQ(countColor(first, unused), 0);
  // Normalised Blinn-Phong reflects exactly 1 at normal incidence.
  ASSERT_EQ(image->GetNumberOfBRDFFiles(), 2);
  EXPECT_EQ(image->GetBRDFFileName(0), "blinn-phong-normalized.brdf");
  EXPECT_NEAR(image->GetBRDFFileAlbedo(0), 1.0, 1e-4);
  EXPECT_EQ(image->GetBRDFFileName(1), "ward-anisotropic.brdf");

  // Deterministic: a second renderer draws the same pixels.
  vtkNew<slLobeImageRenderer> again;
  addOverlay(again);
  ASSERT_EQ(callError(again, [&] { return again->Render(); }), "");
  vtkImageData* second = again->GetImage();
  const size_t bytes = static_cast<size_t>(dims[0]) * dims[1] * 3;
  EXPECT_EQ(std::memcmp(first->GetScalarPointer(), second->GetScalarPointer(), bytes), 0);
}

TEST(LobeImage, BadBRDFFileIsOneLine)
{
  vtkNew<slLobeImageRenderer> image;
  ASSERT_TRUE(image->AddBRDFFile((kData + "/brdf/broken-glsl.brdf").c_str()));
  const std::string message = callError(image, [&] { return image->Render(); });
  EXPECT_EQ(message.rfind(kData + "/brdf/broken-glsl.brdf:12: ", 0), 0u) << message;
  vtkNew<slLobeImageRenderer> other;
  ASSERT_TRUE(other->AddBRDFFile((kData + "/brdf/ward-anisotropic.brdf").c_str()));
  other->AddBRDFFileParameter("alpha_x=7");
  EXPECT_EQ(callError(other, [&] { return other->Render(); }),
    kData + "/brdf/ward-anisotropic.brdf: --param \"alpha_x=7\": alpha_x 7 is out of range [0.01, 1] (line 12)");
  // Six BRDFs at most.
  vtkNew<slLobeImageRenderer> many;
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_TRUE(many->AddBRDFFile("a.brdf"));
  }
  EXPECT_EQ(callError(many, [&] { return many->AddModel("phong"); }),
    "AddModel: 6 BRDFs (models and .brdf files) are overlaid already, the most there can be");
  EXPECT_EQ(callError(many, [&] { return many->AddBRDFFile("a.brdf"); }),
    "AddBRDFFile: 6 BRDFs (models and .brdf files) are overlaid already, the most there can be");
  // A model's name as scene files spell it; a file's name.
  vtkNew<slLobeImageRenderer> named;
  const std::string toon = callError(named, [&] { return named->AddModel("Phong"); });
  EXPECT_EQ(toon.rfind("AddModel: \"Phong\" is not a lighting model (lambert, phong, blinn-phong,", 0), 0u) << toon;
  EXPECT_EQ(callError(named, [&] { return named->AddBRDFFile(""); }), "AddBRDFFile: no file name given");
  EXPECT_TRUE(named->AddModel("phong"));
}
