// A scene's diffuse texture (material.diffuseTexture) shows the same colours
// whatever the file's depth: 8-bit PNG, 16-bit PNG (RGB and grey), float EXR
// and Radiance HDR of the same picture render alike through slSceneRenderer
// (what `shadelab render`, `shadelab compare` and the viewer use), with the
// ShadeLab pass and with VTK's own lighting; and the render matches the
// texel colours a Lambert quad lit head-on must show (0.8 x texel). Images
// deeper than 8 bits come from slImageReader as float; vtkTexture's default
// colour mode would map them through a lookup table (a blue cow).
#include "slImageWriter.h"
#include "slRadianceFilter.h"
#include "slScene.h"
#include "slSceneRenderer.h"
#include "TestFolder.h"
#include "VTKErrors.h"

#include "shadelab/Scene.h"

#include <vtkCoordinate.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace
{
constexpr int kImageSize = 64;    // pixels, square
constexpr int kTextureSize = 8;   // texels, square: four 4 x 4 blocks
constexpr float kDiffuse = 0.8f;  // k_d of the scene
constexpr float kTolerance = 2.0f / 255.0f;

/// The 8-bit colour of each block: bottom left, bottom right, top left, top
/// right (row 0 of a VTK image is the bottom).
const std::array<std::array<int, 3>, 4> kBlockColours = { { { 200, 100, 50 }, { 30, 160, 220 }, { 250, 240, 10 },
  { 90, 20, 140 } } };

/// The block of texel (x, y), y counted from the bottom.
int blockOf(int x, int y)
{
  return (y >= kTextureSize / 2 ? 2 : 0) + (x >= kTextureSize / 2 ? 1 : 0);
}

/// The block texture with @p channels channels (1: the red channel as
/// grey; 3: RGB): 8-bit values v, or v / 255 as float.
vtkSmartPointer<vtkImageData> blockTexture(int channels, bool asFloat)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(kTextureSize, kTextureSize, 1);
  image->AllocateScalars(asFloat ? VTK_FLOAT : VTK_UNSIGNED_CHAR, channels);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  for (int y = 0; y < kTextureSize; ++y)
  {
    for (int x = 0; x < kTextureSize; ++x)
    {
      for (int c = 0; c < channels; ++c)
      {
        const int v = kBlockColours[static_cast<size_t>(blockOf(x, y))][static_cast<size_t>(c)];
        scalars->SetComponent(y * kTextureSize + x, c, asFloat ? v / 255.0 : v);
      }
    }
  }
  return image;
}

/// Writes @p image with slImageWriter (format from the extension).
void writeImage(vtkImageData* image, const std::string& path)
{
  vtkNew<slImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  ASSERT_EQ(callError(writer, [&] { return writer->Write(); }), "") << path;
}

// A minimal 16-bit PNG encoder (stored deflate blocks), as slImageWriter
// writes 8-bit or float only.
uint32_t crc32(const std::string& bytes)
{
  uint32_t crc = 0xFFFFFFFFu;
  for (const unsigned char b : bytes)
  {
    crc ^= b;
    for (int k = 0; k < 8; ++k)
    {
      crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
  }
  return ~crc;
}

void putBigEndian(std::string& out, uint32_t value, int bytes)
{
  for (int i = bytes - 1; i >= 0; --i)
  {
    out += static_cast<char>((value >> (8 * i)) & 0xFFu);
  }
}

void putChunk(std::string& out, const std::string& type, const std::string& data)
{
  putBigEndian(out, static_cast<uint32_t>(data.size()), 4);
  out += type + data;
  putBigEndian(out, crc32(type + data), 4);
}

/// Writes the 8-bit @p image (1 or 3 channels) as a 16-bit PNG, v -> 257 v
/// (the same value: 257 v / 65535 = v / 255).
void writePNG16(vtkImageData* image, const std::string& path)
{
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const int channels = scalars->GetNumberOfComponents();
  std::string raw; // filter byte 0, then the samples, top row first
  for (int row = dims[1] - 1; row >= 0; --row)
  {
    raw += '\0';
    for (int x = 0; x < dims[0]; ++x)
    {
      for (int c = 0; c < channels; ++c)
      {
        putBigEndian(raw, static_cast<uint32_t>(257.0 * scalars->GetComponent(row * dims[0] + x, c)), 2);
      }
    }
  }
  std::string zlib("\x78\x01", 2);
  for (size_t start = 0; start == 0 || start < raw.size(); start += 65535)
  {
    const size_t length = std::min<size_t>(65535, raw.size() - start);
    zlib += static_cast<char>(start + length >= raw.size() ? 1 : 0);
    zlib += static_cast<char>(length & 0xFF);
    zlib += static_cast<char>(length >> 8);
    zlib += static_cast<char>(~length & 0xFF);
    zlib += static_cast<char>((~length >> 8) & 0xFF);
    zlib += raw.substr(start, length);
  }
  uint32_t a = 1, b = 0;
  for (const unsigned char byte : raw)
  {
    a = (a + byte) % 65521u;
    b = (b + a) % 65521u;
  }
  putBigEndian(zlib, (b << 16) | a, 4);

  std::string header;
  putBigEndian(header, static_cast<uint32_t>(dims[0]), 4);
  putBigEndian(header, static_cast<uint32_t>(dims[1]), 4);
  header += static_cast<char>(16);                     // bit depth
  header += static_cast<char>(channels == 1 ? 0 : 2);  // grey or RGB
  header += std::string(3, '\0');                      // deflate, no filter choice, no interlace
  std::string png("\x89PNG\r\n\x1a\n", 8);
  putChunk(png, "IHDR", header);
  putChunk(png, "IDAT", zlib);
  putChunk(png, "IEND", "");
  std::ofstream(path, std::ios::binary) << png;
}

/// A 2 x 2 quad in the z = 0 plane facing +z, texture coordinates over
/// [0, 1]^2, cut into @p resolution^2 squares.
vtkSmartPointer<vtkPolyData> quad(int resolution)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1.0, -1.0, 0.0);
  plane->SetPoint1(1.0, -1.0, 0.0);
  plane->SetPoint2(-1.0, 1.0, 0.0);
  plane->SetResolution(resolution, resolution);
  plane->Update();
  vtkSmartPointer<vtkPolyData> mesh = plane->GetOutput();
  return mesh;
}

/// Lambert, k_d = @p diffuse, nothing else; one white directional light
/// along the view of a camera on the +z axis: every pixel of the quad is
/// k_d x texel.
shadelab::Scene texturedScene(const std::string& texture, float diffuse)
{
  shadelab::Scene s;
  s.model = shadelab::ShadingModel::Lambert;
  s.frequency = shadelab::ShadingFrequency::Phong;
  s.background = glm::vec3(1.0f, 0.0f, 1.0f);
  s.width = s.height = kImageSize;
  s.camera.hasPosition = true;
  s.camera.position = glm::vec3(0.0f, 0.0f, 4.0f);
  s.camera.focalPoint = glm::vec3(0.0f);
  s.material.ambient = glm::vec3(0.0f);
  s.material.diffuse = glm::vec3(diffuse);
  s.material.specular = glm::vec3(0.0f);
  s.material.emission = glm::vec3(0.0f);
  s.material.diffuseTexture = texture;
  shadelab::SceneLight key;
  key.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  key.diffuse = glm::vec3(1.0f);
  key.specular = glm::vec3(0.0f);
  s.lights.push_back(key);
  return s;
}

struct Render
{
  int width = 0;
  int height = 0;
  std::vector<float> rgb; ///< in [0, 1], row 0 at the bottom
  std::array<std::array<int, 2>, 4> blockPixels{}; ///< the pixel at each block's centre

  const float* at(int x, int y) const { return &rgb[3 * (static_cast<size_t>(y) * width + x)]; }
  const float* atBlock(int block) const
  {
    return this->at(blockPixels[static_cast<size_t>(block)][0], blockPixels[static_cast<size_t>(block)][1]);
  }
};

/// The quad textured with @p textureFile, rendered as `shadelab render`
/// does; through the ShadeLab pass or VTK's own lighting.
Render renderQuad(const std::string& textureFile, bool shadeLabLighting, float diffuse = kDiffuse)
{
  vtkNew<slScene> scene;
  scene->SetScene(texturedScene(textureFile, diffuse));
  vtkNew<slSceneRenderer> renderer;
  renderer->SetScene(scene);
  renderer->SetMesh(quad(1));
  renderer->SetUseShadeLabLighting(shadeLabLighting);
  Render out;
  const std::string error = callError(renderer, [&] { return renderer->Render(); });
  EXPECT_EQ(error, "") << textureFile;
  if (!error.empty())
  {
    return out;
  }
  vtkImageData* image = renderer->GetImage();
  int dims[3];
  image->GetDimensions(dims);
  out.width = dims[0];
  out.height = dims[1];
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  out.rgb.resize(static_cast<size_t>(3) * out.width * out.height);
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.rgb[static_cast<size_t>(3 * i + c)] = static_cast<float>(scalars->GetComponent(i, c) / 255.0);
    }
  }
  for (int block = 0; block < 4; ++block)
  {
    vtkNew<vtkCoordinate> world;
    world->SetCoordinateSystemToWorld();
    world->SetValue(block % 2 ? 0.5 : -0.5, block / 2 ? 0.5 : -0.5, 0.0);
    const double* display = world->GetComputedDoubleDisplayValue(renderer->GetRenderer());
    out.blockPixels[static_cast<size_t>(block)] = { static_cast<int>(display[0]), static_cast<int>(display[1]) };
  }
  return out;
}

/// Every block's centre pixel is k_d x the block's colour (@p channels 1:
/// the red value in every channel).
void expectBlockColours(const Render& image, int channels, const std::string& what)
{
  ASSERT_EQ(image.width, kImageSize) << what;
  for (int block = 0; block < 4; ++block)
  {
    const float* pixel = image.atBlock(block);
    for (int c = 0; c < 3; ++c)
    {
      const int v = kBlockColours[static_cast<size_t>(block)][static_cast<size_t>(channels == 1 ? 0 : c)];
      EXPECT_NEAR(pixel[c], kDiffuse * v / 255.0f, kTolerance) << what << ", block " << block << ", channel " << c;
    }
  }
}

/// Every pixel of @p image within 2/255 of @p reference in every channel.
void expectAgreement(const Render& reference, const Render& image, const std::string& what)
{
  ASSERT_EQ(image.rgb.size(), reference.rgb.size()) << what;
  float worst = 0.0f;
  size_t differing = 0;
  for (size_t i = 0; i < image.rgb.size(); ++i)
  {
    const float d = std::abs(image.rgb[i] - reference.rgb[i]);
    worst = std::max(worst, d);
    differing += d > kTolerance + 1e-6f;
  }
  EXPECT_EQ(differing, 0u) << what << ": " << differing << " channel values differ from the 8-bit texture's render by more "
                           << "than 2/255, the worst by " << worst * 255.0f << "/255";
}

class SceneTexture : public ::testing::TestWithParam<bool> // ShadeLab lighting pass or VTK's own
{
};

std::string lightingName(const ::testing::TestParamInfo<bool>& info)
{
  return info.param ? "LightingPass" : "VTKLighting";
}
} // namespace

TEST_P(SceneTexture, DeepImagesRenderAsTheEightBitOne)
{
  TestFolder folder;
  ASSERT_TRUE(folder.valid());
  vtkSmartPointer<vtkImageData> bytes = blockTexture(3, false);
  vtkSmartPointer<vtkImageData> floats = blockTexture(3, true);
  writeImage(bytes, folder.path("texture8.png"));
  writePNG16(bytes, folder.path("texture16.png"));
  writeImage(floats, folder.path("texture.exr"));
  writeImage(floats, folder.path("texture.hdr"));

  const Render reference = renderQuad(folder.path("texture8.png"), GetParam());
  expectBlockColours(reference, 3, "8-bit PNG"); // so that a wrong reference fails too
  for (const char* file : { "texture16.png", "texture.exr", "texture.hdr" })
  {
    const Render image = renderQuad(folder.path(file), GetParam());
    expectBlockColours(image, 3, file);
    expectAgreement(reference, image, file);
  }
}

TEST_P(SceneTexture, SixteenBitGreyRendersAsEightBitGrey)
{
  TestFolder folder;
  ASSERT_TRUE(folder.valid());
  vtkSmartPointer<vtkImageData> grey = blockTexture(1, false);
  writeImage(grey, folder.path("grey8.png"));
  writePNG16(grey, folder.path("grey16.png"));
  const Render reference = renderQuad(folder.path("grey8.png"), GetParam());
  expectBlockColours(reference, 1, "8-bit grey PNG");
  const Render image = renderQuad(folder.path("grey16.png"), GetParam());
  expectBlockColours(image, 1, "16-bit grey PNG");
  expectAgreement(reference, image, "16-bit grey PNG");
}

TEST_P(SceneTexture, FloatValuesAreUsedAsStored)
{
  // The rule of slDiffuseColors on the CPU: float texels are used as they
  // are, above 1 included (HDR brightens k_d; the pixel is clamped at the
  // end), not normalised to their range; a value that is not finite is 0.
  TestFolder folder;
  ASSERT_TRUE(folder.valid());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::array<std::array<float, 3>, 4> texels = { { { 2.5f, 0.5f, 1.0f }, { 0.25f, 0.25f, 0.25f },
    { nan, nan, nan }, { 3.0f, 0.0f, 1.5f } } };
  vtkNew<vtkImageData> image;
  image->SetDimensions(kTextureSize, kTextureSize, 1);
  image->AllocateScalars(VTK_FLOAT, 3);
  auto* values = static_cast<float*>(image->GetScalarPointer());
  for (int y = 0; y < kTextureSize; ++y)
  {
    for (int x = 0; x < kTextureSize; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        values[3 * (y * kTextureSize + x) + c] = texels[static_cast<size_t>(blockOf(x, y))][static_cast<size_t>(c)];
      }
    }
  }
  writeImage(image, folder.path("bright.exr"));
  const float diffuse = 0.3f;
  const Render rendered = renderQuad(folder.path("bright.exr"), GetParam(), diffuse);
  ASSERT_EQ(rendered.width, kImageSize);
  for (int block = 0; block < 4; ++block)
  {
    const float* pixel = rendered.atBlock(block);
    for (int c = 0; c < 3; ++c)
    {
      const float texel = texels[static_cast<size_t>(block)][static_cast<size_t>(c)];
      const float expected = std::isfinite(texel) ? std::min(1.0f, diffuse * texel) : 0.0f;
      EXPECT_NEAR(pixel[c], expected, kTolerance) << "block " << block << ", channel " << c;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Lighting, SceneTexture, ::testing::Bool(), lightingName);

TEST(SceneTextureCPU, DeepImagesGiveTheEightBitColours)
{
  // slRadianceFilter's lookup (slDiffuseColors) of the same picture as 8-bit
  // PNG, 16-bit PNG and float EXR: the same k_d at every point.
  TestFolder folder;
  ASSERT_TRUE(folder.valid());
  vtkSmartPointer<vtkImageData> bytes = blockTexture(3, false);
  writeImage(bytes, folder.path("texture8.png"));
  writePNG16(bytes, folder.path("texture16.png"));
  writeImage(blockTexture(3, true), folder.path("texture.exr"));
  vtkSmartPointer<vtkPolyData> mesh = quad(13); // points between and on texel centres
  auto diffuseOf = [&](const std::string& file) {
    vtkNew<slScene> scene;
    scene->SetScene(texturedScene("", 1.0f));
    vtkNew<slRadianceFilter> filter;
    filter->SetScene(scene);
    filter->SetDiffuseTextureFileName(file.c_str());
    filter->SetInputData(mesh);
    EXPECT_EQ(updateError(filter), "") << file;
    vtkSmartPointer<vtkDataArray> diffuse = filter->GetOutput()->GetPointData()->GetArray("Diffuse");
    return diffuse;
  };
  vtkSmartPointer<vtkDataArray> reference = diffuseOf(folder.path("texture8.png"));
  ASSERT_TRUE(reference);
  for (const char* file : { "texture16.png", "texture.exr" })
  {
    vtkSmartPointer<vtkDataArray> diffuse = diffuseOf(folder.path(file));
    ASSERT_TRUE(diffuse) << file;
    ASSERT_EQ(diffuse->GetNumberOfValues(), reference->GetNumberOfValues()) << file;
    double worst = 0.0;
    for (vtkIdType i = 0; i < diffuse->GetNumberOfValues(); ++i)
    {
      worst = std::max(worst, std::abs(diffuse->GetVariantValue(i).ToDouble() - reference->GetVariantValue(i).ToDouble()));
    }
    EXPECT_LT(worst, 1e-5) << file;
  }
}
