// The .brdf reader: any bytes give a file or a shadelab::Error, nothing else.
// A file that parses is checked for what the rest of ShadeLab relies on;
// the same bytes are also given to brdfCompileError() as a driver's log,
// which must come back as one line.
#include "shadelab/BrdfFile.h"
#include "shadelab/Error.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  shadelab::BrdfFile file;
  try
  {
    file = shadelab::parseBrdfText(text, "fuzz.brdf");
  }
  catch (const shadelab::Error&)
  {
    return 0;
  }
  if (file.shaderFirstLine < 1 || brdfParameterValues(file, {}).size() != file.parameters.size())
  {
    std::abort();
  }
  for (const shadelab::BrdfParameter& p : file.parameters)
  {
    if (p.kind == shadelab::BrdfParameter::Kind::Float && !(p.minimum <= p.defaultValue.x && p.defaultValue.x <= p.maximum))
    {
      std::abort();
    }
  }
  brdfUniformDeclarations(file);
  for (int first : { 1, 7, 1 << 30 })
  {
    if (brdfCompileError(file, text, first).find('\n') != std::string::npos)
    {
      std::abort();
    }
  }
  return 0;
}
