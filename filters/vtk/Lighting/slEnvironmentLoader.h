#ifndef slEnvironmentLoader_h
#define slEnvironmentLoader_h
/**
 * @file slEnvironmentLoader.h
 * @brief Internal: an environment map from a file (through slImageReader /
 * OpenImageIO) or a vtkImageData, checked for an equirectangular layout.
 * Not wrapped; slRadianceReference runs it through slRunCore().
 */

#include "shadelab/EnvironmentMap.h"

#include <string>

class vtkImageData;

namespace shadelab
{

/// Fills @p out from @p image (float or 8-bit scalars with at least 3
/// components, width = 2 x height). @p name stands for the image in messages.
/// Throws shadelab::Error with a one-line reason naming it.
void environmentFromImage(vtkImageData* image, const std::string& name, EnvironmentMap& out);

/// Reads @p fileName and fills @p out. Throws shadelab::Error with a one-line
/// reason naming the file.
void environmentFromFile(const std::string& fileName, EnvironmentMap& out);

} // namespace shadelab

#endif
