// slImageReader on any bytes as a file of one extension (SL_FUZZ_EXTENSION):
// an image or an error message, never a crash.
#include "FuzzInputFile.h"
#include "FuzzToolOutput.h"

#include "slImageReader.h"

#include <vtkImageData.h>
#include <vtkNew.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string path = fuzzInputFile(data, size, SL_FUZZ_EXTENSION);
  vtkNew<slImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return 0;
}
