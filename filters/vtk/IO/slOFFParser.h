#ifndef slOFFParser_h
#define slOFFParser_h
/**
 * @file slOFFParser.h
 * @brief Parses Object File Format (OFF) text into vtkPolyData.
 *
 * Accepts "OFF", "COFF" (a colour r g b [a] after each vertex's
 * coordinates, read into the unsigned char point scalars "Colors": integers
 * 0-255, or 0-1 when any value in the file is written otherwise) and "NOFF"
 * (a normal after each vertex, read into the point normals "Normals"), with
 * '#' comments and n-gon faces; values after a face's indices (a face
 * colour) are ignored, values after a plain OFF vertex refused. Other forms
 * (STOFF, 4OFF, nOFF, CNOFF) are refused. Non-manifold faces are kept,
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
