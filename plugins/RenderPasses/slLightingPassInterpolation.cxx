/**
 * @file slLightingPassInterpolation.cxx
 * @brief The interpolation slLightingPass gives the actors it lights, and
 * gives back: its bookkeeping (slLightingPassInterpolation.h) and the
 * pass's member functions that set it and give it back.
 *
 * Apart from slLightingPass.cxx because it touches nothing of the lighting:
 * only the actors' vtkProperty interpolation and the renderers it watches.
 */
#include "slLightingPassInterpolation.h"

#include "slLightingPassInternals.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkNew.h>
#include <vtkRenderState.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <utility>

namespace slLightingPassInterpolation
{

namespace
{
/// The interpolation a property of interpolation @p given needs for the
/// pass's @p frequency: VTK's mapper supplies face normals under flat
/// interpolation and interpolated point normals under any other, so flat
/// for FLAT, and for GOURAUD and PHONG the user's own unless it is flat
/// (then Phong).
int interpolationFor(int frequency, int given)
{
  if (frequency == slLightingPass::FLAT)
  {
    return VTK_FLAT;
  }
  return given == VTK_FLAT ? VTK_PHONG : given;
}

/// Gives each property of @p changes still alive the interpolation the pass
/// found, where it still has the one the pass set: a value the user gave
/// since stays.
void restoreInterpolations(const InterpolationChanges& changes)
{
  changes.ForEachLive([](vtkProperty* property, const InterpolationChange& change) {
    if (property->GetInterpolation() == change.set)
    {
      property->SetInterpolation(change.found);
    }
  });
}
} // namespace

void restoreAfterFrame(vtkRenderWindow* window, InterpolationChanges changes)
{
  struct Pending
  {
    InterpolationChanges changes;
    vtkCommand* command;
  };
  vtkNew<vtkCallbackCommand> command;
  command->SetClientData(new Pending{ std::move(changes), command.GetPointer() });
  command->SetClientDataDeleteCallback([](void* pending) { delete static_cast<Pending*>(pending); });
  command->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
    auto* pending = static_cast<Pending*>(data);
    restoreInterpolations(pending->changes);
    caller->RemoveObserver(pending->command); // VTK keeps the command alive until it returns
  });
  window->AddObserver(vtkCommand::EndEvent, command);
}

} // namespace slLightingPassInterpolation

using namespace slLightingPassInterpolation;
using slLightingPassQueries::isLitOpaqueActor;

void slLightingPass::MatchInterpolation(const vtkRenderState* s)
{
  // VTK's mapper supplies per-face normals under flat interpolation and
  // interpolated point normals otherwise: make it supply what we need
  // (interpolationFor), and remember the user's value to give it back.
  InterpolationChanges& changes = this->Internal->Interpolations;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkActor* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    if (!isLitOpaqueActor(actor))
    {
      continue; // drawn by VTK as without the pass, in its own interpolation
    }
    vtkProperty* property = actor->GetProperty();
    const int current = property->GetInterpolation();
    const InterpolationChange* change = changes.Find(property);
    // A value other than the one the pass set is the user's, and the one
    // to give back from now on.
    const bool userChanged = change && change->set != current;
    const int given = change && !userChanged ? change->found : current;
    const int wanted = interpolationFor(this->Frequency, given);
    // Only on a change: a property's modification time rebuilds the
    // actor's shaders, so the pass never sets it frame after frame.
    if (wanted != current || userChanged)
    {
      property->SetInterpolation(wanted);
      changes.Insert(property, { given, wanted });
    }
  }
}

void slLightingPass::RestoreInterpolations()
{
  restoreInterpolations(this->Internal->Interpolations);
  this->Internal->Interpolations.Clear();
}

void slLightingPass::WatchRenderer(vtkRenderer* renderer)
{
  slPassObjectMap<vtkRenderer, DrawnRenderer>& renderers = this->Internal->Renderers;
  const DrawnRenderer* known = renderers.Find(renderer);
  if (known && known->top == renderer->GetPass() && !known->givenBack)
  {
    return; // every frame but the first in a renderer
  }
  DrawnRenderer drawn = known ? *known : DrawnRenderer();
  if (!known)
  {
    // vtkRenderer::SetPass() tells no pass, but modifies the renderer.
    drawn.observer = renderer->AddObserver(vtkCommand::ModifiedEvent, this, &slLightingPass::RendererModified);
  }
  // Drawn again after a change of the renderer's pass gave the
  // interpolations back: under the pass it had before, the pass was taken
  // out and put back; under another, that change was one around the pass,
  // not its removal, and such changes are not taken for one again.
  drawn.changeRemoves = drawn.changeRemoves && (!drawn.givenBack || renderer->GetPass() == drawn.top);
  drawn.givenBack = false;
  drawn.top = renderer->GetPass();
  renderers.Insert(renderer, drawn);
}

void slLightingPass::RendererModified(vtkObject* caller, unsigned long, void*)
{
  auto* renderer = static_cast<vtkRenderer*>(caller);
  const DrawnRenderer* drawn = this->Internal->Renderers.Find(renderer);
  if (!drawn || drawn->givenBack || !drawn->changeRemoves || renderer->GetPass() == drawn->top)
  {
    return; // modified for anything but a new pass
  }
  // The renderer's pass changed (vtkRenderer::SetPass): the pass is no
  // longer drawn there, alone or inside the old one. Given back now, before
  // VTK draws a frame without the pass.
  DrawnRenderer givenBack = *drawn;
  givenBack.givenBack = true;
  this->Internal->Renderers.Insert(renderer, givenBack);
  this->RestoreInterpolations();
}
