#ifndef shadelab_generator_WriteGenerated_h
#define shadelab_generator_WriteGenerated_h
// Writing the build's generated files (GenerateGLSLTables.cxx,
// GenerateSceneSchema.cxx): a failed write prints the path and fails the
// build step.
#include <cstdio>
#include <fstream>
#include <string>

namespace shadelab
{
namespace generator
{
/// Writes @p text to @p path; false, with one line on stderr, if it cannot.
inline bool writeGenerated(const std::string& path, const std::string& text)
{
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << text;
  file.close();
  if (!file)
  {
    std::fprintf(stderr, "%s: cannot write\n", path.c_str());
    return false;
  }
  return true;
}
} // namespace generator
} // namespace shadelab

#endif
