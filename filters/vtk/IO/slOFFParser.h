#ifndef slOFFParser_h
#define slOFFParser_h
/**
 * @file slOFFParser.h
 * @brief Parses Object File Format (OFF) text into vtkPolyData.
 *
 * Accepts "OFF" and "COFF"/"NOFF"-free plain OFF with '#' comments, n-gon
 * faces, and optional per-face colours (ignored). Non-manifold faces are kept,
 * unlike half-edge readers that must drop them. Internal to ShadeLab::IO.
 */

#include "shadelab/Error.h"

#include <istream>
#include <string>

class vtkPolyData;

/// Fills @p output from the OFF text in @p in, read from @p fileName. Throws
/// shadelab::Error "FILE: line N: problem" for text that is not OFF.
void slParseOFF(std::istream& in, const std::string& fileName, vtkPolyData* output);

#endif
