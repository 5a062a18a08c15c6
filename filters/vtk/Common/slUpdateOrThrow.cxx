#include "slUpdateOrThrow.h"

#include <vtkAlgorithm.h>
#include <vtkExecutive.h>

void slUpdateOrThrow(vtkAlgorithm* algorithm, const std::string& context)
{
  slCallOrThrow(algorithm, [algorithm] { return algorithm->GetExecutive()->Update() != 0; }, context);
}
