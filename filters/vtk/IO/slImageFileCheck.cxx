#include "slImageFileCheck.h"

std::string slBytesRemain(unsigned long long count)
{
  return std::to_string(count) + (count == 1 ? " byte remains" : " bytes remain") + " in the file";
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
