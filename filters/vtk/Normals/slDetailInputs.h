#ifndef slDetailInputs_h
#define slDetailInputs_h
/**
 * @file slDetailInputs.h
 * @brief What the surface-detail filters share: reading a texture through
 * slImageReader, and the per-point frames (position, normal, tangent,
 * handedness, UV) of a mesh. Internal to ShadeLab::Normals; the filters
 * run them through slRunCore().
 */

#include "shadelab/slTextureSampling.h"

#include "shadelab/Error.h"

#include <vtkSmartPointer.h>

#include <glm/glm.hpp>

#include <string>
#include <vector>

class vtkPolyData;

/// Reads @p fileName as float texels (0..1 for 8-bit files). Throws
/// shadelab::Error with the one-line problem, which names the file.
void slLoadTexture(const char* fileName, slnormals::Texture& texture);

/// Throws shadelab::Error naming @p fileName and the first pixel (from the
/// top left, as image tools count) whose channel @p channel in @p texture is
/// NaN or infinite, as float images (EXR, TIFF, HDR) can hold: a filter
/// would carry it into the mesh, where it would look like the mesh's fault.
void slCheckFiniteChannel(const slnormals::Texture& texture, int channel, const char* fileName);

/// A mesh's per-point surface frames.
struct slSurfaceFrames
{
  vtkSmartPointer<vtkPolyData> mesh; ///< the input, with normals and tangents added if missing
  std::vector<glm::dvec3> normal, tangent;
  std::vector<double> handedness;
  std::vector<glm::dvec2> uv;
};

/// Fills @p frames from @p input, computing normals (slPolyDataNormals) and
/// tangents (slPolyDataTangents) when absent. Throws shadelab::Error with the
/// problem (e.g. no texture coordinates).
void slGetSurfaceFrames(vtkPolyData* input, bool needTangents, slSurfaceFrames& frames);

/// slGetSurfaceFrames, slLoadTexture, then slCheckFiniteChannel on each of
/// the first @p channelsRead channels the image has (the ones the filter
/// samples). Throws shadelab::Error with the first problem.
void slPrepareDetail(vtkPolyData* input, const char* fileName, bool needTangents, int channelsRead,
  slSurfaceFrames& frames, slnormals::Texture& texture);

/// @p output = @p mesh with its point array "Normals" replaced by @p normals.
void slOutputWithNormals(vtkPolyData* output, vtkPolyData* mesh, const std::vector<glm::dvec3>& normals);
#endif
