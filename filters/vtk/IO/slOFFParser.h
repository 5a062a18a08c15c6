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

#include <istream>
#include <string>

class vtkPolyData;

/// Fills @p output from the OFF text in @p in. Returns "" on success,
/// otherwise "line N: problem".
std::string slParseOFF(std::istream& in, vtkPolyData* output);

#endif
