#ifndef slAtomicMinimum_h
#define slAtomicMinimum_h
/**
 * @file slAtomicMinimum.h
 * @brief Lowers a shared value to a candidate from any thread: how parallel
 * loops find the first bad point (a NaN coordinate, a normal without a
 * direction) whatever order their ranges run in. C++ only, not wrapped.
 */

#include <atomic>

/// Sets @p value to @p candidate if the candidate is smaller, atomically.
template <typename T>
void slAtomicMinimum(std::atomic<T>& value, T candidate)
{
  T current = value.load();
  while (candidate < current && !value.compare_exchange_weak(current, candidate))
  {
  }
}

#endif
