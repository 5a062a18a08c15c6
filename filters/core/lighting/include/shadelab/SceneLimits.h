#ifndef shadelab_SceneLimits_h
#define shadelab_SceneLimits_h
/**
 * @file SceneLimits.h
 * @brief The ranges a scene's values must lie in, and the check of a Scene
 * against them (for scenes not read from a file: built in code or from
 * VTK's lights, property and camera; SceneFile checks each value as it
 * reads it, with the same limits). The largest colour, shininess and spot
 * exponent are in ValueLimits.h.
 */

#include "shadelab/Scene.h"
#include "shadelab/ValueLimits.h"

#include <string>

namespace shadelab
{

/// Smallest and largest image width or height, in pixels.
constexpr int kMinImageSize = 16;
constexpr int kMaxImageSize = 8192;

/// "" if @p x can be a scene value in [@p lo, @p hi] (an end excluded when
/// its flag is set; an infinite end is open): a finite number within
/// float's range, as every scene value is stored as a float. Else the
/// problem: "1e+39 is beyond the float range", "2e+06 is out of range
/// [0, 1e+06]". SceneFile and sceneValueProblem() word their errors with it.
std::string numberProblem(double x, double lo, double hi, bool openLo = false, bool openHi = false);

/// "" if every value of @p scene that reaches the lighting formulas is finite
/// and in range; else the first problem, naming the value as a scene file
/// would, with the light's name if it has one
/// ("lights[1] (\"VTK light 0\").intensity: nan is not a finite number").
/// Light cutoffs in (0, 90] and edges in [0, cutoff], as in scene files.
/// A model or light type that is not a row of LightingTables.h is a problem
/// too ("shading.model: 7 is not a lighting model (one of ...)").
std::string sceneValueProblem(const Scene& scene);

} // namespace shadelab

#endif
