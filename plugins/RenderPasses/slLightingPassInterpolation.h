#ifndef slLightingPassInterpolation_h
#define slLightingPassInterpolation_h
/**
 * @file slLightingPassInterpolation.h
 * @brief What slLightingPass keeps to give its actors' interpolation back:
 * the changes it made, and the renderers it watches for its removal.
 * Internal to ShadeLab::RenderPasses.
 *
 * The pass sets each lit actor's interpolation to what its frequency needs
 * (see the caveat of slLightingPass.h) and gives the user's back when it is
 * taken out of a renderer, released or freed. slLightingPassInterpolation.cxx
 * holds this bookkeeping and the pass's member functions that do it
 * (MatchInterpolation, RestoreInterpolations, WatchRenderer,
 * RendererModified): apart from the pass's lighting, which it does not touch.
 */

#include "slPassObjectMap.h"

#include <vtkProperty.h>

class vtkRenderPass;
class vtkRenderWindow;

namespace slLightingPassInterpolation
{

/// A property's interpolation as the pass found it (the user's) and as the
/// pass set it (MatchInterpolation), to give the user's back.
struct InterpolationChange
{
  int found = VTK_PHONG;
  int set = VTK_PHONG;
};

/// The properties whose interpolation the pass changed.
using InterpolationChanges = slPassObjectMap<vtkProperty, InterpolationChange>;

/// Gives each property of @p changes still alive the interpolation the pass
/// found, where it still has the one the pass set (a value the user gave
/// since stays), once @p window has drawn its frame.
/// During a frame a mapper stamps its shaders after it has read the
/// property: a change made then (by a pass freed in a mapper, which holds
/// the last passes it drew with until it draws again) would never rebuild
/// them, and the picture would keep the old interpolation.
void restoreAfterFrame(vtkRenderWindow* window, InterpolationChanges changes);

/// A renderer the pass has drawn, watched for a change of its pass.
struct DrawnRenderer
{
  /// The renderer's pass when the pass last drew it (the pass itself, or a
  /// pass around it), by address: only a change of it counts.
  const vtkRenderPass* top = nullptr;
  unsigned long observer = 0; ///< the tag of the pass's ModifiedEvent observer
  bool givenBack = false;     ///< the interpolations were given back on a change of its pass
  /// Whether a change of the renderer's pass is taken for the pass's
  /// removal. Off once the pass draws the renderer again, after one, under
  /// another pass: a program that changes the passes around this one every
  /// frame must not have the interpolations given back and set again (and
  /// VTK's shaders rebuilt) every frame.
  bool changeRemoves = true;
};

} // namespace slLightingPassInterpolation

#endif
