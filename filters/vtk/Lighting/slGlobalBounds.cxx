#include "slGlobalBounds.h"

#include <vtkCommunicator.h>
#include <vtkDataSet.h>
#include <vtkMultiProcessController.h>

#include <limits>

namespace shadelab
{

void globalBounds(vtkDataSet* data, double bounds[6])
{
  constexpr double inf = std::numeric_limits<double>::infinity();
  // Empty: min = +inf, max = -inf, so that the reduction ignores it.
  double mins[3] = { inf, inf, inf }, maxs[3] = { -inf, -inf, -inf };
  if (data && data->GetNumberOfPoints() > 0)
  {
    double b[6];
    data->GetBounds(b);
    for (int a = 0; a < 3; ++a)
    {
      mins[a] = b[2 * a];
      maxs[a] = b[2 * a + 1];
    }
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    double localMins[3] = { mins[0], mins[1], mins[2] }, localMaxs[3] = { maxs[0], maxs[1], maxs[2] };
    controller->AllReduce(localMins, mins, 3, vtkCommunicator::MIN_OP);
    controller->AllReduce(localMaxs, maxs, 3, vtkCommunicator::MAX_OP);
  }
  for (int a = 0; a < 3; ++a)
  {
    bounds[2 * a] = mins[a];
    bounds[2 * a + 1] = maxs[a];
  }
}

} // namespace shadelab
