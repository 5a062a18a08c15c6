#include "shadelab/BrdfAssignment.h"

#include <cstdio>

namespace shadelab
{

std::string brdfNumberText(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", value);
  return text;
}

std::string brdfAssignment(const BrdfParameter& parameter, const glm::vec3& value)
{
  switch (parameter.kind)
  {
    case BrdfParameter::Kind::Bool:
      return parameter.name + "=" + (value.x != 0.0f ? "1" : "0");
    case BrdfParameter::Kind::Color:
      return parameter.name + "=" + brdfNumberText(value.x) + "," + brdfNumberText(value.y) + "," +
        brdfNumberText(value.z);
    case BrdfParameter::Kind::Float:
      break;
  }
  return parameter.name + "=" + brdfNumberText(value.x);
}

} // namespace shadelab
