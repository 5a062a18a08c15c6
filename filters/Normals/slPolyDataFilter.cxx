#include "slPolyDataFilter.h"

#include <vtkPolyData.h>

slPolyDataFilter::slPolyDataFilter() = default;
slPolyDataFilter::~slPolyDataFilter() = default;

int slPolyDataFilter::Fail(const std::string& problem, vtkPolyData* output)
{
  output->Initialize();
  this->ErrorMessage = problem;
  vtkErrorMacro(<< problem);
  return 0;
}

void slPolyDataFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
