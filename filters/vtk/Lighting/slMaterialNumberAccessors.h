#ifndef slMaterialNumberAccessors_h
#define slMaterialNumberAccessors_h
/**
 * @file slMaterialNumberAccessors.h
 * @brief Plain Set/Get methods for the material's numbers besides the
 * shininess (roughness, the anisotropic pair, the index of refraction: the
 * number rows of the material table, shadelab/LightingTables.h, with their
 * ranges and defaults from shadelab/MaterialParameters.h), which ParaView's
 * wrapping and the plugin's generated properties need: clamped members for
 * slLitFilter, and forwarders to SetMaterialParameter() for the classes that
 * keep their material by key (slBRDFLobeSource). Not wrapped itself: the
 * classes expand its macros in their declarations.
 */

#include "shadelab/MaterialParameters.h"

#include <vtkIndent.h>

#include <ostream>

/// X(Name, field): the methods' name and the table row's field.
#define SL_MATERIAL_NUMBERS(X)                                                                                        \
  X(Roughness, roughness)                                                                                            \
  X(RoughnessX, roughnessX)                                                                                          \
  X(RoughnessY, roughnessY)                                                                                          \
  X(Ior, ior)

#define SL_MATERIAL_NUMBER_ACCESSORS(Name, field)                                                                    \
  vtkSetClampMacro(Name, double, shadelab::materialRows::field.lo, shadelab::materialRows::field.hi);               \
  vtkGetMacro(Name, double);
#define SL_MATERIAL_NUMBER_MEMBER(Name, field) double Name = shadelab::materialRows::field.number;
#define SL_MATERIAL_NUMBER_FORWARDERS(Name, field)                                                                   \
  void Set##Name(double value) { this->SetMaterialParameter(shadelab::materialRows::field.key, value); }             \
  double Get##Name() { return this->GetMaterialParameter(shadelab::materialRows::field.key); }

/// In a class's public declarations: Set<Name> clamped to the row's range
/// (a NaN is kept) and Get<Name>, for each of SL_MATERIAL_NUMBERS.
#define slMaterialNumberAccessorsMacro() SL_MATERIAL_NUMBERS(SL_MATERIAL_NUMBER_ACCESSORS)
/// In its data members: each number, at the row's default.
#define slMaterialNumberMembersMacro() SL_MATERIAL_NUMBERS(SL_MATERIAL_NUMBER_MEMBER)
/// In the public declarations of a class with SetMaterialParameter(key,
/// value) and GetMaterialParameter(key): Set<Name> and Get<Name> through them.
#define slMaterialNumberForwardersMacro() SL_MATERIAL_NUMBERS(SL_MATERIAL_NUMBER_FORWARDERS)

/// The members of @p from (a class with slMaterialNumberAccessorsMacro())
/// into the material @p m (a shadelab::SceneMaterial).
template <typename From, typename Material>
void slMaterialNumbersInto(From* from, Material& m)
{
#define SL_COPY(Name, field) m.field = static_cast<float>(from->Get##Name());
  SL_MATERIAL_NUMBERS(SL_COPY)
#undef SL_COPY
}

/// PrintSelf's lines for the members of @p from.
template <typename From>
void slPrintMaterialNumberMembers(From* from, std::ostream& os, vtkIndent indent)
{
#define SL_PRINT(Name, field) os << indent << #Name ": " << from->Get##Name() << "\n";
  SL_MATERIAL_NUMBERS(SL_PRINT)
#undef SL_PRINT
}

#endif
