#ifndef slRenderNormals_h
#define slRenderNormals_h
/**
 * @file slRenderNormals.h
 * @brief Normals for meshes that arrive without them, as ShadeLab's
 * renderers compute them. C++ only (not wrapped); shadelab-viewer computes
 * its fields on the same normals as its view.
 */

#include "ShadeLabRenderPassesModule.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

/// How renderers compute normals; the defaults are what every ShadeLab
/// renderer uses unless told otherwise.
struct slRenderNormalsOptions
{
  int weighting = 2;          ///< an slPolyDataNormals::WeightingType; 2 = ANGLE
  bool splitting = true;      ///< keep edges sharper than featureAngle sharp
  double featureAngle = 30.0; ///< degrees
  bool replace = false;       ///< recompute even when the mesh has point normals
};

/// @p mesh itself if it has point normals (and !options.replace); otherwise a
/// copy with point and cell "Normals" from slPolyDataNormals with @p options,
/// consistent orientation, and coincident points welded for the computation
/// (texture seams and unwelded patches do not show as creases). Throws
/// shadelab::Error with slPolyDataNormals' reason if the normals cannot be
/// computed.
SHADELABRENDERPASSES_EXPORT vtkSmartPointer<vtkPolyData> slWithRenderNormals(
  vtkPolyData* mesh, const slRenderNormalsOptions& options = slRenderNormalsOptions());

#endif
