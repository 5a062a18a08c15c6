#ifndef slMaterialNumbers_h
#define slMaterialNumbers_h
/**
 * @file slMaterialNumbers.h
 * @brief The numbers of a material (shininess, roughness, the anisotropic
 * pair, the index of refraction: the number rows of
 * SHADELAB_MATERIAL_PARAMETERS in shadelab/LightingTables.h) set by their
 * scene-file keys, for the filters that take a material without a scene
 * (slBRDFLobeSource, slAlbedoTable). A new number row is a new key here
 * without an edit. Not wrapped.
 */

#include "ShadeLabLightingModule.h"

#include "shadelab/Scene.h"
#include "shadelab/SceneKeys.h"

#include <vtkIndent.h>
#include <vtkIOStream.h>

class vtkObject;

/// Sets the number @p key of @p material to @p value clamped to the key's
/// range (shadelab::materialKeys()): 1 if the value changed, 0 if not. An
/// unknown key, one that is not a number, or a NaN value is reported as an
/// error of @p self ("SetMaterialParameter: \"gloss\" is not a number of
/// the material (shininess, roughness, ...)"), changes nothing and gives -1.
SHADELABLIGHTING_EXPORT int slSetMaterialNumber(
  vtkObject* self, shadelab::SceneMaterial& material, const char* key, double value);

/// The number @p key of @p material; NaN, with the same error, for an unknown key.
SHADELABLIGHTING_EXPORT double slGetMaterialNumber(
  vtkObject* self, const shadelab::SceneMaterial& material, const char* key);

/// Every number of @p material, one "key: value" line each (PrintSelf).
SHADELABLIGHTING_EXPORT void slPrintMaterialNumbers(
  ostream& os, vtkIndent indent, const shadelab::SceneMaterial& material);

/// Every number of the material of @p from (Get/SetMaterialParameter())
/// set on @p to: slBRDFLobeSource, slAlbedoTable.
template <typename From, typename To>
void slCopyMaterialNumbers(From* from, To* to)
{
  for (const auto& key : shadelab::materialKeys())
  {
    if (key.number)
    {
      to->SetMaterialParameter(key.name, from->GetMaterialParameter(key.name));
    }
  }
}

/// Defines @p Class's SetMaterialParameter(), GetMaterialParameter(),
/// SetShininess() and GetShininess() over its member
/// std::unique_ptr<shadelab::SceneMaterial> Material (slBRDFLobeSource,
/// slAlbedoTable: the declarations stay in their headers for the wrappers).
#define SL_MATERIAL_NUMBER_METHODS(Class)                                                                             \
  bool Class::SetMaterialParameter(const char* key, double value)                                                    \
  {                                                                                                                   \
    const int set = slSetMaterialNumber(this, *this->Material, key, value);                                           \
    if (set > 0)                                                                                                      \
    {                                                                                                                 \
      this->Modified();                                                                                               \
    }                                                                                                                 \
    return set >= 0;                                                                                                  \
  }                                                                                                                   \
  double Class::GetMaterialParameter(const char* key)                                                                \
  {                                                                                                                   \
    return slGetMaterialNumber(this, *this->Material, key);                                                           \
  }                                                                                                                   \
  void Class::SetShininess(double shininess)                                                                          \
  {                                                                                                                   \
    this->SetMaterialParameter("shininess", shininess);                                                               \
  }                                                                                                                   \
  double Class::GetShininess()                                                                                        \
  {                                                                                                                   \
    return this->GetMaterialParameter("shininess");                                                                   \
  }

#endif
