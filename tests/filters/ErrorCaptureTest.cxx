// slErrorCapture and slOutputWindow: every VTK error of an operation reaches
// ShadeLab's message, and nothing reaches stderr.
#include "slErrorCapture.h"
#include "slOutputWindow.h"

#include <vtkNew.h>
#include <vtkXMLPolyDataReader.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <unistd.h>

namespace
{
std::string writeGarbage()
{
  char path[] = "/tmp/shadelab-capture-XXXXXX.vtp";
  const int fd = mkstemps(path, 4);
  const std::string text = "not xml\n";
  EXPECT_EQ(write(fd, text.data(), text.size()), static_cast<ssize_t>(text.size()));
  close(fd);
  return path;
}
} // namespace

TEST(ErrorCapture, StripsVTKPreambles)
{
  EXPECT_EQ(slErrorCapture::StripPreamble(
              "ERROR: In /build/vtk/IO/XML/vtkXMLReader.cxx, line 306\nvtkXMLPolyDataReader (0x55d0): Error opening "
              "file x.vtp\n\n"),
    "Error opening file x.vtp");
  EXPECT_EQ(slErrorCapture::StripPreamble("Generic Warning: In a.cxx, line 3\ntwo\nlines\n"), "two lines");
  // Text that only looks like a class preamble further in is kept.
  EXPECT_EQ(slErrorCapture::StripPreamble("bad value (see above): 3"), "bad value (see above): 3");
}

TEST(ErrorCapture, HearsUnwatchedObjectsSilently)
{
  slOutputWindow::Install(false);
  const std::string path = writeGarbage();
  vtkNew<slErrorCapture> errors;
  testing::internal::CaptureStderr();
  {
    // Not watched: the reader's error, then its executive's, reach the output window.
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
  }
  const std::string printed = testing::internal::GetCapturedStderr();
  std::remove(path.c_str());
  EXPECT_EQ(printed, "");
  EXPECT_EQ(errors->GetError().rfind("Error parsing XML in stream at line 1", 0), 0u)
    << "the first error, the cause: " << errors->GetError();
}

TEST(ErrorCapture, NewestCaptureHearsAndWatchedObjectsToo)
{
  slOutputWindow::Install(false);
  const std::string path = writeGarbage();
  vtkNew<slErrorCapture> outer;
  vtkNew<slErrorCapture> inner;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  inner->Watch(reader);
  reader->Update();
  std::remove(path.c_str());
  EXPECT_TRUE(inner->HasError());
  EXPECT_FALSE(outer->HasError());
}
