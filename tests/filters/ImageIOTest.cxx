// slImageReader / slImageWriter through OpenImageIO, and their errors.
#include "TestFolder.h"

#include "slImageCodec.h"
#include "slImageReader.h"
#include "slImageWriter.h"
#include "VTKErrors.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

namespace
{
/// A 5 x 3 image whose pixel (x, y) has channel c = 40 x + 7 y + c.
vtkSmartPointer<vtkImageData> gradient(bool asFloat)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(5, 3, 1);
  vtkSmartPointer<vtkDataArray> scalars;
  if (asFloat)
  {
    scalars = vtkSmartPointer<vtkFloatArray>::New();
  }
  else
  {
    scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
  }
  scalars->SetNumberOfComponents(3);
  scalars->SetNumberOfTuples(15);
  for (int y = 0; y < 3; ++y)
  {
    for (int x = 0; x < 5; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        scalars->SetComponent(y * 5 + x, c, 40 * x + 7 * y + c + (asFloat ? 0.25 : 0.0));
      }
    }
  }
  image->GetPointData()->SetScalars(scalars);
  return image;
}

std::string slurp(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
} // namespace

TEST(ImageIO, PNGRoundTripKeepsPixelsAndOrientation)
{
  const TestFolder folder;
  vtkNew<slImageWriter> writer;
  writer->SetInputData(gradient(false));
  writer->SetFileName(folder.path("g.png").c_str());
  ASSERT_EQ(callError(writer, [&] { return writer->Write(); }), "");

  vtkNew<slImageReader> reader;
  reader->SetFileName(folder.path("g.png").c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 5);
  EXPECT_EQ(dims[1], 3);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  ASSERT_EQ(scalars->GetDataType(), VTK_UNSIGNED_CHAR);
  EXPECT_EQ(scalars->GetComponent(2 * 5 + 4, 1), 40 * 4 + 7 * 2 + 1); // pixel (4, 2), row 0 at the bottom
  EXPECT_EQ(scalars->GetComponent(0, 2), 2);
}

TEST(ImageIO, PixelsOfAFileReplacedAfterItsHeaderAreNotRead)
{
  // The reader sizes its buffer from the header, then opens the file again
  // for the pixels: a larger image found there must not be written into it.
  const TestFolder folder;
  const std::string path = folder.path("swapped.png");
  vtkNew<slImageWriter> writer;
  writer->SetInputData(gradient(false));
  writer->SetFileName(path.c_str());
  ASSERT_EQ(callError(writer, [&] { return writer->Write(); }), "");
  std::string error;
  const slImageCodec* codec = slLoadImageCodec(error);
  ASSERT_NE(codec, nullptr) << error;
  slImageHeader header;
  ASSERT_TRUE(codec->ReadHeader(path, header, error)) << error;
  ASSERT_EQ(header.Width * header.Height * header.Channels, 5 * 3 * 3);

  vtkNew<vtkImageData> wider;
  wider->SetDimensions(9, 3, 1);
  wider->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  writer->SetInputData(wider);
  ASSERT_EQ(callError(writer, [&] { return writer->Write(); }), "");
  std::vector<unsigned char> pixels(5 * 3 * 3, 0xAB);
  EXPECT_FALSE(codec->ReadPixels(path, header, false, pixels.data(), error));
  EXPECT_EQ(error, "it changed while it was read");
  EXPECT_EQ(std::count(pixels.begin(), pixels.end(), 0xAB), 5 * 3 * 3);
}

TEST(ImageIO, EXRKeepsFloats)
{
  const TestFolder folder;
  vtkNew<slImageWriter> writer;
  writer->SetInputData(gradient(true));
  writer->SetFileName(folder.path("g.exr").c_str());
  ASSERT_EQ(callError(writer, [&] { return writer->Write(); }), "");
  vtkNew<slImageReader> reader;
  reader->SetFileName(folder.path("g.exr").c_str());
  reader->Update();
  vtkDataArray* scalars = reader->GetOutput()->GetPointData()->GetScalars();
  ASSERT_EQ(scalars->GetDataType(), VTK_FLOAT);
  EXPECT_FLOAT_EQ(static_cast<float>(scalars->GetComponent(1 * 5 + 3, 0)), 40 * 3 + 7 + 0.25f);
}

TEST(ImageIO, ReadsAMultiPartEXR)
{
  // Two parts, so two headers that the reader's header check must walk; the
  // first part is what is read.
  const TestFolder folder;
  const std::string path = folder.path("two.exr");
  OIIO::ImageSpec specs[2] = { OIIO::ImageSpec(4, 2, 3, OIIO::TypeDesc::FLOAT),
    OIIO::ImageSpec(4, 2, 1, OIIO::TypeDesc::FLOAT) }; // one display window for all parts
  specs[0].attribute("oiio:subimagename", "first"); // OpenEXR's parts need names
  specs[1].attribute("oiio:subimagename", "second");
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out && out->supports("multiimage"));
  ASSERT_TRUE(out->open(path, 2, specs)) << out->geterror();
  const std::vector<float> first(4 * 2 * 3, 0.75f), second(4 * 2, 0.5f);
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, first.data()));
  ASSERT_TRUE(out->open(path, specs[1], OIIO::ImageOutput::AppendSubimage));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, second.data()));
  ASSERT_TRUE(out->close());

  vtkNew<slImageReader> reader;
  reader->SetFileName(path.c_str());
  ASSERT_EQ(updateError(reader), "");
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 4);
  EXPECT_EQ(dims[1], 2);
  EXPECT_FLOAT_EQ(static_cast<float>(reader->GetOutput()->GetPointData()->GetScalars()->GetComponent(5, 2)), 0.75f);
}

TEST(ImageIO, ReadsTheSharedHDREnvironmentMap)
{
  vtkNew<slImageReader> reader;
  reader->SetFileName((std::string(SHADELAB_DATA_DIR) + "/envmaps/venice_sunset_1k.hdr").c_str());
  ASSERT_EQ(updateError(reader), "");
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 1024);
  EXPECT_EQ(dims[1], 512);
  double range[2];
  reader->GetOutput()->GetPointData()->GetScalars()->GetRange(range, 0);
  EXPECT_GT(range[1], 100.0) << "HDR values above 1 survive";
}

TEST(ImageIO, UnreadableImageNamesTheFile)
{
  const TestFolder folder;
  folder.write("fake.png", "not a png");
  vtkNew<slImageReader> reader;
  reader->SetFileName(folder.path("fake.png").c_str());
  const std::string error = updateError(reader);
  EXPECT_EQ(error.rfind(folder.path("fake.png") + ": cannot read image", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);

  reader->SetFileName("/nonexistent/texture.png");
  EXPECT_EQ(updateError(reader).rfind("/nonexistent/texture.png: cannot read image", 0), 0u);
}

TEST(ImageIO, FailedWriteLeavesTheExistingFile)
{
  const TestFolder folder;
  folder.write("keep.png", "precious");
  vtkNew<vtkImageData> empty;
  vtkNew<slImageWriter> writer;
  writer->SetInputData(empty);
  writer->SetFileName(folder.path("keep.png").c_str());
  EXPECT_FALSE(writer->Write());
  EXPECT_EQ(slurp(folder.path("keep.png")), "precious");

  writer->SetInputData(gradient(false));
  writer->SetFileName("/nonexistent-folder/out.png");
  EXPECT_EQ(callError(writer, [&] { return writer->Write(); }).rfind("/nonexistent-folder/out.png: cannot create output file", 0), 0u);
}
