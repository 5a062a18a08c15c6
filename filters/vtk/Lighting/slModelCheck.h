#ifndef slModelCheck_h
#define slModelCheck_h
/**
 * @file slModelCheck.h
 * @brief The check every VTK setter of a lighting model makes: the number
 * must be a row of shadelab/LightingTables.h (an SL_MODEL_* value). Not
 * wrapped.
 */

#include "ShadeLabLightingModule.h"

#include <string>

class vtkObject;

/// True if @p model is a lighting model (or -1 when @p sceneOwnAllowed: the
/// scene's own); else reports "SetModel: 7 is not a lighting model (0
/// lambert, 1 phong, ...)" (the @p setter's name first) as an error of
/// @p self (vtkErrorWithObjectMacro, so observers of @p self's ErrorEvent
/// receive it) and returns false.
SHADELABLIGHTING_EXPORT bool slCheckModel(
  vtkObject* self, int model, bool sceneOwnAllowed = false, const char* setter = "SetModel");

/// The SL_MODEL_* value of the model named @p name in scene files
/// ("phong", "cook-torrance-ggx", ...; shadelab::modelNames()), or -2 for a
/// null or unknown name: what every SetModelName() passes to its SetModel().
SHADELABLIGHTING_EXPORT int slModelNumber(const char* name);

/// True if @p name is a model's scene-file name; else reports
/// "SetModelName: \"Phong\" is not a lighting model (lambert, phong, ...)"
/// (the @p setter's name first) as an error of @p self and returns false.
SHADELABLIGHTING_EXPORT bool slCheckModelName(vtkObject* self, const char* name, const char* setter = "SetModelName");

/// @p self->SetModel() with the model named @p name; false, an error
/// (slCheckModelName()) and nothing set for a null or unknown name. The
/// body of every SetModelName().
template <typename Self>
bool slSetModelByName(Self* self, const char* name)
{
  const int model = slModelNumber(name);
  if (model < 0)
  {
    return slCheckModelName(self, name); // reports it
  }
  self->SetModel(model);
  return true;
}

/// The scene-file name of model @p model, or "" for -1 (the scene's own)
/// and any other number that is not a model: what every GetModelName() says.
SHADELABLIGHTING_EXPORT std::string slModelNameOf(int model);

#endif
