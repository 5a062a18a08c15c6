// Fills the ParaView plugin's server-manager XML with the lighting models and
// the material numbers of shadelab/LightingTables.h. In TEMPLATE, at the
// comment's indentation:
// - <!-- shadelab:lighting-model-entries --> becomes one enumeration entry
//   per model, <Entry value="ID" text="LABEL" />, LABEL the model's name in
//   words: "blinn-phong-normalized" -> "Blinn-Phong (normalized)";
// - <!-- shadelab:material-number-properties --> becomes one
//   DoubleVectorProperty per number row of the material table (roughnessX ->
//   "RoughnessX", command SetRoughnessX), with the row's default, range and
//   meaning, unless the proxy around the comment writes that property
//   itself (a source with a default of its own); with "override" after the
//   marker name, each is shown only when OverrideMaterial is on;
// - <!-- shadelab:material-number-names --> becomes <Property name="..." />
//   for every number row (a property group's list).
// The other lines are copied. Run by the plugin's build
// (plugins/ParaView/Plugin/CMakeLists.txt) and by the main build for
// tests/python/test_paraview_xml.py.
#include "WriteGenerated.h"
#include "shadelab/LightingTables.h"
#include "shadelab/MaterialParameters.h"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
const std::string kMarker = "<!-- shadelab:lighting-model-entries -->";
const std::string kPropertiesMarker = "<!-- shadelab:material-number-properties";
const std::string kNamesMarker = "<!-- shadelab:material-number-names -->";
const std::string kNormalizedSuffix = "-normalized";

/// "cook-torrance-ggx" -> "Cook-Torrance GGX": a family name and its
/// microfacet distribution, written as their authors write them.
const std::string kCookTorrance = "cook-torrance-";

/// "blinn-phong-normalized" -> "Blinn-Phong (normalized)".
std::string label(std::string name)
{
  if (name.compare(0, kCookTorrance.size(), kCookTorrance) == 0)
  {
    const std::string distribution = name.substr(kCookTorrance.size());
    return "Cook-Torrance " + (distribution == "ggx" ? std::string("GGX") : label(distribution));
  }
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

/// "roughnessX" -> "RoughnessX", the property's and the setter's name.
std::string propertyName(const char* key)
{
  std::string name = key;
  name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
  return name;
}

/// "roughnessX" -> "Roughness X".
std::string propertyLabel(const char* key)
{
  std::string out;
  for (const char& c : propertyName(key))
  {
    out += std::string(!out.empty() && std::isupper(static_cast<unsigned char>(c)) ? " " : "") + c;
  }
  return out;
}

/// @p text with XML's special characters escaped.
std::string escaped(const std::string& text)
{
  std::string out;
  for (char c : text)
  {
    out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '"' ? "&quot;" : std::string(1, c);
  }
  return out;
}

std::string number(double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}

/// The properties each proxy of @p lines writes itself: for every line, the
/// names defined in the proxy (<...Proxy ...> to </...Proxy>) around it.
std::vector<std::set<std::string>> propertiesByLine(const std::vector<std::string>& lines)
{
  std::vector<std::set<std::string>> byLine(lines.size());
  size_t first = 0;
  std::set<std::string> names;
  for (size_t i = 0; i < lines.size(); ++i)
  {
    const std::string& line = lines[i];
    const size_t tag = line.find("VectorProperty name=\"");
    if (tag != std::string::npos && line.find('<') < tag)
    {
      const size_t begin = tag + std::string("VectorProperty name=\"").size();
      names.insert(line.substr(begin, line.find('"', begin) - begin));
    }
    if (line.find("Proxy>") != std::string::npos && line.find("</") != std::string::npos)
    {
      for (size_t j = first; j <= i; ++j)
      {
        byLine[j] = names;
      }
      names.clear();
      first = i + 1;
    }
  }
  return byLine;
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
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
  {
    lines.push_back(line);
  }
  if (in.bad())
  {
    std::fprintf(stderr, "%s: read error\n", argv[1]);
    return 1;
  }
  const std::vector<std::set<std::string>> written = propertiesByLine(lines);
  std::ostringstream out;
  for (size_t i = 0; i < lines.size(); ++i)
  {
    const std::string& line = lines[i];
    const size_t at = line.find("<!-- shadelab:");
    const std::string indent = line.substr(0, at == std::string::npos ? 0 : at);
    if (at != std::string::npos && line.compare(at, kMarker.size(), kMarker) == 0)
    {
      for (const shadelab::LightingModelInfo& m : shadelab::kLightingModels)
      {
        out << indent << "<Entry value=\"" << static_cast<int>(m.model) << "\" text=\"" << label(m.name) << "\" />\n";
      }
    }
    else if (at != std::string::npos && line.compare(at, kNamesMarker.size(), kNamesMarker) == 0)
    {
      for (const shadelab::MaterialParameterInfo& row : shadelab::kMaterialParameters)
      {
        out << (row.colour ? "" : indent + "<Property name=\"" + propertyName(row.key) + "\" />\n");
      }
    }
    else if (at != std::string::npos && line.compare(at, kPropertiesMarker.size(), kPropertiesMarker) == 0)
    {
      const bool override = line.find(" override ", at) != std::string::npos;
      for (const shadelab::MaterialParameterInfo& row : shadelab::kMaterialParameters)
      {
        const std::string name = propertyName(row.key);
        if (row.colour || written[i].count(name))
        {
          continue;
        }
        out << indent << "<DoubleVectorProperty name=\"" << name << "\" label=\"" << propertyLabel(row.key)
            << "\" command=\"Set" << name << "\" number_of_elements=\"1\" default_values=\"" << number(row.number)
            << "\">\n"
            << indent << "  <DoubleRangeDomain name=\"range\" min=\"" << number(row.lo) << "\" max=\""
            << number(row.hi) << "\" />\n"
            << indent << "  <Documentation>" << escaped(row.meaning) << ".</Documentation>\n";
        if (override)
        {
          out << indent << "  <Hints>\n"
              << indent
              << "    <PropertyWidgetDecorator type=\"GenericDecorator\" mode=\"visibility\" "
                 "property=\"OverrideMaterial\" value=\"1\" />\n"
              << indent << "  </Hints>\n";
        }
        out << indent << "</DoubleVectorProperty>\n";
      }
    }
    else
    {
      out << line << "\n";
    }
  }
  return shadelab::generator::writeGenerated(argv[2], out.str()) ? 0 : 1;
}
