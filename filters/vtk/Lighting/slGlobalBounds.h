#ifndef slGlobalBounds_h
#define slGlobalBounds_h
/**
 * @file slGlobalBounds.h
 * @brief Internal: the bounds of a data set over every process of VTK's
 * global vtkMultiProcessController (the MPI ranks of ParaView's pvbatch or
 * pvserver), so that a camera fitted to them is the same on every rank and
 * the same as on one process. Not wrapped.
 */

class vtkDataSet;

namespace shadelab
{

/// Writes (xmin, xmax, ymin, ymax, zmin, zmax) of @p data united over all
/// processes of vtkMultiProcessController::GetGlobalController() into
/// @p bounds; with no controller or one process, @p data's own bounds. A
/// process with no points contributes nothing (its bounds are empty,
/// min > max). Every process must call it (a collective operation).
void globalBounds(vtkDataSet* data, double bounds[6]);

} // namespace shadelab

#endif
