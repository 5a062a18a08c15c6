#ifndef slModelCheck_h
#define slModelCheck_h
/**
 * @file slModelCheck.h
 * @brief The check every VTK setter of a lighting model makes: the number
 * must be a row of shadelab/LightingTables.h (an SL_MODEL_* value). Not
 * wrapped.
 */

#include "ShadeLabLightingModule.h"

class vtkObject;

/// True if @p model is a lighting model (or -1 when @p sceneOwnAllowed: the
/// scene's own); else reports "SetModel: 7 is not a lighting model (0
/// lambert, 1 phong, ...)" as an error of @p self (vtkErrorWithObjectMacro,
/// so observers of @p self's ErrorEvent receive it) and returns false.
SHADELABLIGHTING_EXPORT bool slCheckModel(vtkObject* self, int model, bool sceneOwnAllowed = false);

#endif
