#ifndef shadelab_DefaultScene_h
#define shadelab_DefaultScene_h
/**
 * @file DefaultScene.h
 * @brief The scene used when none is given: works for any mesh because its
 * lights move with the camera and the camera fits the mesh.
 */

#include "shadelab/Scene.h"

namespace shadelab
{

/// A white key light from the upper left and a dimmer fill light from the
/// right (both directional, in camera space), a faint ambient light, a grey
/// Blinn-Phong material (shininess 32), Phong frequency, 800 x 600 pixels.
Scene defaultScene();

} // namespace shadelab

#endif
