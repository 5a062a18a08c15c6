#ifndef slRenderNormals_h
#define slRenderNormals_h
/**
 * @file slRenderNormals.h
 * @brief Normals for meshes that arrive without them, as ShadeLab's
 * renderers compute them. Internal to ShadeLab::RenderPasses.
 */

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

/// @p mesh itself if it has point normals; otherwise a copy with point and
/// cell "Normals" from slPolyDataNormals: angle weighting, feature edges over
/// 30 degrees kept sharp, consistent orientation, and coincident points
/// welded for the computation (texture seams and unwelded patches do not show
/// as creases). Null, with @p error set, if the normals cannot be computed.
vtkSmartPointer<vtkPolyData> slWithRenderNormals(vtkPolyData* mesh, std::string& error);

#endif
