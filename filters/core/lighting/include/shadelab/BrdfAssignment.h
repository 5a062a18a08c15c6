#ifndef shadelab_BrdfAssignment_h
#define shadelab_BrdfAssignment_h
/**
 * @file BrdfAssignment.h
 * @brief A .brdf parameter value written as the "name=value" text that
 * `--param`, brdfParameterValues() and the scene's brdf.parameters take:
 * one spelling for every program that hands values on (the render pass,
 * the scene reader, the viewer).
 */

#include "shadelab/BrdfFile.h"

#include <string>

namespace shadelab
{

/// A number as such a text: %.9g, which reads back to the same float.
std::string brdfNumberText(double value);

/// "name=value" for parameter @p parameter at @p value: a float its number,
/// a bool 1 or 0, a colour "r,g,b".
std::string brdfAssignment(const BrdfParameter& parameter, const glm::vec3& value);

} // namespace shadelab

#endif
