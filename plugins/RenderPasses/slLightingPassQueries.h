#ifndef slLightingPassQueries_h
#define slLightingPassQueries_h
/**
 * @file slLightingPassQueries.h
 * @brief What slLightingPass reads off VTK's actors, mappers and shader
 * sources to decide what to light and what its shaders have to work with.
 * Internal to ShadeLab::RenderPasses.
 *
 * Apart from the pass because these are questions about VTK 9.1's own
 * shader code and props (the names its shaders use, what its mappers
 * draw): they change with VTK, not with the pass's lighting.
 */

#include <string>

class vtkAbstractMapper;
class vtkActor;
class vtkProp;

namespace slLightingPassQueries
{

/// Whether @p text holds @p what.
bool contains(const std::string& text, const char* what);

/// True if the mapper draws a point array "Tangents" with 4 components (xyz,
/// handedness). VTK's TANGENTS attribute only takes 3 components, so the
/// array is found by name.
bool hasTangentsWithHandedness(vtkAbstractMapper* mapper);

/// Opaque actors whose property has lighting on. An actor whose property has
/// lighting off (colour-mapped fields, widget handles, glyphs in their own
/// colour) is drawn unlit by VTK, as without the pass, and a translucent one
/// with VTK's lighting.
bool isLitOpaqueActor(vtkActor* actor);

/// The polydata the pass lights: isLitOpaqueActor's, drawn by an OpenGL polydata mapper.
bool isOurs(vtkAbstractMapper* mapper, vtkProp* prop);

/// Whether VTK's fragment shader @p fragmentShader colours the surface with
/// point or cell scalars (a colour attribute, a colour texture map or a cell
/// colour buffer): then VTK's ambientColor and diffuseColor are the scalar
/// colour times the property's intensities, in place of its colours.
bool drawsScalarColours(const std::string& fragmentShader);

/// Whether VTK's fragment shader @p fragmentShader samples the actor's
/// texture (vtkActor::SetTexture) at the mesh's texture coordinates.
bool hasActorTexture(const std::string& fragmentShader);

/// Whether @p prop's texture colours only faces seen from the front
/// (vtkProperty::ShowTexturesOnBackfaceOff()). A change to it modifies the
/// property, which rebuilds the actor's shaders, so it can be compiled in.
bool textureFrontOnly(vtkProp* prop);

/// What the pass needs to know of a built shader program, read from its
/// fragment shader's source once (the source is fixed once compiled, and
/// copying it for every actor of every frame would cost in scenes of many
/// actors).
struct ProgramFacts
{
  bool scalarColours = false; ///< drawsScalarColours()
  bool backface = false;      ///< a Variant::backface program (slMatBack)
};

} // namespace slLightingPassQueries

#endif
