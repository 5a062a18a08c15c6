#ifndef shadelab_tests_VTKErrors_h
#define shadelab_tests_VTKErrors_h
/**
 * @file VTKErrors.h
 * @brief The tests' view of a VTK-layer failure: the one-line message
 * slUpdateOrThrow() / slCallOrThrow() give back, "" on success.
 */

#include "slUpdateOrThrow.h"

#include <string>
#include <utility>

/// Updates @p algorithm; its one-line error, or "" if the update succeeds.
inline std::string updateError(vtkAlgorithm* algorithm)
{
  try
  {
    slUpdateOrThrow(algorithm);
    return std::string();
  }
  catch (const shadelab::Error& error)
  {
    return error.what();
  }
}

/// Runs @p call (true on success) on @p object; its one-line error, or "".
template <class Call>
std::string callError(vtkObject* object, Call&& call)
{
  try
  {
    slCallOrThrow(object, std::forward<Call>(call));
    return std::string();
  }
  catch (const shadelab::Error& error)
  {
    return error.what();
  }
}

#endif
