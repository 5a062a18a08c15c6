#ifndef slPointWelding_h
#define slPointWelding_h
/**
 * @file slPointWelding.h
 * @brief Merges points that are identical in position and in every point-data
 * value. Internal to ShadeLab::IO.
 *
 * vtkOBJReader emits one point per face corner; merging only exact duplicates
 * restores the shared vertices while keeping texture and normal seams (points
 * that differ in any attribute stay apart).
 */

class vtkPolyData;

/// Rewrites @p mesh in place; returns how many points were removed.
long long slMergeIdenticalPoints(vtkPolyData* mesh);

#endif
