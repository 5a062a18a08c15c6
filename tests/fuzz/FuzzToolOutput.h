// The fuzz targets report problems the way the shadelab tool does
// (slOutputWindow without echo), with one difference: stderr stays the
// process's own. A sanitizer's or libFuzzer's report printed while an image
// library runs would otherwise go to slStderrCapture's temporary file and be
// lost with it.
#ifndef FuzzToolOutput_h
#define FuzzToolOutput_h

#include "slOutputWindow.h"
#include "slStderrCapture.h"

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  slOutputWindow::Install(false);
  slStderrCapture::SetEnabled(false);
  return 0;
}

#endif
