// Fills the ParaView plugin's server-manager XML with the lighting models of
// shadelab/LightingTables.h: every line of TEMPLATE holding the comment
// <!-- shadelab:lighting-model-entries --> becomes one enumeration entry per
// model, <Entry value="ID" text="LABEL" />, at the comment's indentation; the
// other lines are copied. LABEL is the model's name in words:
// "blinn-phong-normalized" -> "Blinn-Phong (normalized)". Run by the
// plugin's build (plugins/ParaView/Plugin/CMakeLists.txt) and by the main
// build for tests/python/test_paraview_xml.py.
#include "WriteGenerated.h"
#include "shadelab/LightingTables.h"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace
{
const std::string kMarker = "<!-- shadelab:lighting-model-entries -->";
const std::string kNormalizedSuffix = "-normalized";

/// "blinn-phong-normalized" -> "Blinn-Phong (normalized)".
std::string label(std::string name)
{
  std::string suffix;
  if (name.size() > kNormalizedSuffix.size() &&
    name.compare(name.size() - kNormalizedSuffix.size(), kNormalizedSuffix.size(), kNormalizedSuffix) == 0)
  {
    name.resize(name.size() - kNormalizedSuffix.size());
    suffix = " (normalized)";
  }
  for (size_t i = 0; i < name.size(); ++i)
  {
    if (i == 0 || name[i - 1] == '-')
    {
      name[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[i])));
    }
  }
  return name + suffix;
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 3)
  {
    std::fprintf(stderr, "usage: %s TEMPLATE.xml OUTPUT.xml\n", argv[0]);
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  if (!in)
  {
    std::fprintf(stderr, "%s: cannot open\n", argv[1]);
    return 1;
  }
  std::ostringstream out;
  std::string line;
  while (std::getline(in, line))
  {
    const size_t at = line.find(kMarker);
    if (at == std::string::npos)
    {
      out << line << "\n";
      continue;
    }
    const std::string indent = line.substr(0, at);
    for (const shadelab::LightingModelInfo& m : shadelab::kLightingModels)
    {
      out << indent << "<Entry value=\"" << static_cast<int>(m.model) << "\" text=\"" << label(m.name) << "\" />\n";
    }
  }
  if (in.bad())
  {
    std::fprintf(stderr, "%s: read error\n", argv[1]);
    return 1;
  }
  return shadelab::generator::writeGenerated(argv[2], out.str()) ? 0 : 1;
}
