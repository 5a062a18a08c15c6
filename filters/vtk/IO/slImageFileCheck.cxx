#include "slImageFileCheck.h"

std::string slBytesRemain(unsigned long long count)
{
  return std::to_string(count) + (count == 1 ? " byte remains" : " bytes remain") + " in the file";
}

std::string slTooManyValues(const std::string& what, double width, double height, double channels)
{
  if (width * height * channels <= kMostImageValues)
  {
    return "";
  }
  const auto count = [](double value) { return std::to_string(static_cast<long long>(value)); };
  return what + count(width) + "x" + count(height) + " pixels of " + count(channels) +
    (channels == 1 ? " channel" : " channels") + ", more than ShadeLab reads (2^28 values)";
}

std::string slImageFileProblem(const std::string& fileName)
{
  std::string problem = slPNGProblem(fileName);
  if (problem.empty())
  {
    problem = slEXRProblem(fileName);
  }
  return problem;
}
