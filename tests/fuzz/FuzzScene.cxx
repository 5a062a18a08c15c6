// The scene parser: any bytes give a scene or a shadelab::Error, nothing else.
#include "shadelab/SceneFile.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  try
  {
    shadelab::parseScene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  }
  catch (const shadelab::Error&)
  {
  }
  return 0;
}
