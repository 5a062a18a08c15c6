#ifndef slTangentsCheck_h
#define slTangentsCheck_h
/**
 * @file slTangentsCheck.h
 * @brief Whether a mesh can be shaded with a lighting model: an anisotropic
 * model (shadelab::modelNeedsTangents()) reads the surface's tangent, so
 * the mesh must carry it. The lighting filters (slLitFilter) and the
 * `shadelab render` command ask the same question in the same words. Not
 * wrapped.
 */

#include "ShadeLabLightingModule.h"

#include <string>

class vtkPolyData;

/// "" if @p mesh can be shaded with @p model: the model is isotropic or the
/// mesh has them (slLitFilter::HasTangents()). Else the problem, one line without the mesh's
/// name: "the ward model is anisotropic and needs tangents (...); compute
/// them first (shadelab tangents, slPolyDataTangents)".
SHADELABLIGHTING_EXPORT std::string slTangentsProblem(vtkPolyData* mesh, int model);

#endif
