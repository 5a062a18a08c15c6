#ifndef shadelab_tests_ImageComparison_h
#define shadelab_tests_ImageComparison_h
/**
 * @file ImageComparison.h
 * @brief The image regression metric, through OpenImageIO.
 *
 * A pixel fails when any channel differs from the baseline by more than
 * PixelThresholdLevels of 255, counted in whole 8-bit levels; an image
 * passes when at most AllowedFailingFraction of its pixels fail and its
 * size matches.
 */

#include <string>

class vtkImageData;

namespace regression
{

constexpr int PixelThresholdLevels = 2;
constexpr double AllowedFailingFraction = 0.002;

struct Verdict
{
  bool passed = false;
  long failingPixels = 0;
  long pixels = 0;
  double maxError = 0.0;
  std::string message; ///< one line: why it failed, or the figures
};

/// Compares @p candidate (RGB, row 0 at the bottom) with the PNG at
/// @p baselinePath. On failure writes CANDIDATE.png and DIFF.png (the
/// absolute difference, amplified 8 times) into @p failureFolder, named
/// after @p name.
Verdict compareWithBaseline(vtkImageData* candidate, const std::string& baselinePath,
  const std::string& failureFolder, const std::string& name);

/// Writes @p candidate as the new baseline (all or nothing). Returns "" or an error.
std::string writeBaseline(vtkImageData* candidate, const std::string& baselinePath);

} // namespace regression

#endif
