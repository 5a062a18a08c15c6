#ifndef slEnvironmentLoader_h
#define slEnvironmentLoader_h
/**
 * @file slEnvironmentLoader.h
 * @brief Internal: an environment map from a file (through slImageReader /
 * OpenImageIO) or a vtkImageData, checked for an equirectangular layout.
 * Not wrapped.
 */

#include "shadelab/EnvironmentMap.h"

#include <string>

class vtkImageData;

namespace shadelab
{

/// Fills @p out from @p image (float or 8-bit scalars with at least 3
/// components, width = 2 x height). @p name stands for the image in messages.
/// Returns "" or a one-line reason naming it.
std::string environmentFromImage(vtkImageData* image, const std::string& name, EnvironmentMap& out);

/// Reads @p fileName and fills @p out. Returns "" or a one-line reason naming the file.
std::string environmentFromFile(const std::string& fileName, EnvironmentMap& out);

} // namespace shadelab

#endif
