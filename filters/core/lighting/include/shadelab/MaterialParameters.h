#ifndef shadelab_MaterialParameters_h
#define shadelab_MaterialParameters_h
/**
 * @file MaterialParameters.h
 * @brief The rows of SHADELAB_MATERIAL_PARAMETERS (LightingTables.h) as
 * constants: each parameter's key, whether it is a colour, its range, a
 * number's default and what it means, by field name
 * (materialRows::roughness) and as one list (kMaterialParameters). Header
 * only, without GLM, so that the public headers of the VTK classes clamp
 * their material setters to the table's ranges (vtkSetClampMacro) and the
 * command line and the ParaView plugin's generator make one option or
 * property per row. A colour's default is in SceneMaterial (Scene.h).
 */

#include "shadelab/LightingTables.h"
#include "shadelab/ValueLimits.h"

namespace shadelab
{

/// One row of SHADELAB_MATERIAL_PARAMETERS without its default.
struct MaterialParameterInfo
{
  const char* key;     ///< as written in scene files: "roughnessX"
  bool colour;         ///< an RGB colour (each component in [lo, hi]), else one number
  double lo, hi;       ///< the closed range of the number or of each component
  double number;       ///< a number's default (a colour: 0, see SceneMaterial)
  unsigned bit;        ///< its MaterialParameterBit: the models that read it
  const char* meaning; ///< the row's "what it means"
};

/// The range column's spellings (SceneKeys.cxx reads the same column with
/// its own, which also carry open ends for light keys).
namespace materialRows
{
struct Range
{
  double lo, hi;
};
/// A colour: each component in [0, kMaxColourValue].
constexpr Range anyValue()
{
  return { 0.0, kMaxColourValue };
}
constexpr Range closed(double lo, double hi)
{
  return { lo, hi };
}

// By the GLSL type: whether a row is a colour, and a number's default (a
// colour's, a glm::vec3, is dropped unexpanded).
#define SHADELAB_MATERIAL_IS_COLOUR_vec3 true
#define SHADELAB_MATERIAL_IS_COLOUR_float false
#define SHADELAB_MATERIAL_NUMBER_vec3(value) 0.0
#define SHADELAB_MATERIAL_NUMBER_float(value) static_cast<double>(value)
#define SHADELAB_ROW(type, field, bit, key, value, range, meaning)                                                   \
  inline constexpr MaterialParameterInfo field = { key, SHADELAB_MATERIAL_IS_COLOUR_##type, range.lo, range.hi,       \
    SHADELAB_MATERIAL_NUMBER_##type(value), bit, meaning };
SHADELAB_MATERIAL_PARAMETERS(SHADELAB_ROW)
#undef SHADELAB_ROW
} // namespace materialRows

/// Every row, in table order.
inline constexpr MaterialParameterInfo kMaterialParameters[] = {
#define SHADELAB_ROW(type, field, ...) materialRows::field,
  SHADELAB_MATERIAL_PARAMETERS(SHADELAB_ROW)
#undef SHADELAB_ROW
};

} // namespace shadelab

#endif
