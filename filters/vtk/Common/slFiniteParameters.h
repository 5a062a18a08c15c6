#ifndef slFiniteParameters_h
#define slFiniteParameters_h
/**
 * @file slFiniteParameters.h
 * @brief The check a filter runs on its own numeric parameters when it
 * updates: vtkSetClampMacro keeps a NaN (it compares false with both
 * bounds), and a NaN angle, scale or weight would otherwise hang a loop,
 * fill the output with NaN or quietly change the result.
 */

#include <cmath>
#include <initializer_list>
#include <sstream>
#include <string>
#include <utility>

/// The first of @p parameters (its setter's name and its value) that is NaN
/// or infinite, as one line ("FeatureAngle: nan is not a finite number"),
/// or "" when all are finite.
inline std::string slNonFiniteParameter(std::initializer_list<std::pair<const char*, double>> parameters)
{
  for (const auto& parameter : parameters)
  {
    if (!std::isfinite(parameter.second))
    {
      std::ostringstream line;
      line << parameter.first << ": " << parameter.second << " is not a finite number";
      return line.str();
    }
  }
  return "";
}

#endif
