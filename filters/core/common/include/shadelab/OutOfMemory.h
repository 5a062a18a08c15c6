#ifndef shadelab_OutOfMemory_h
#define shadelab_OutOfMemory_h
/**
 * @file OutOfMemory.h
 * @brief The one test of whether an exception means the process ran out of
 * memory, so that every place that reports one says "out of memory".
 *
 * Memory runs out in more forms than std::bad_alloc: under an address-space
 * limit (ulimit -v, a container's) a thread pool's worker may find no room
 * for its stack. oneTBB, which runs vtkSMPTools on Debian, then throws a
 * std::runtime_error "pthread_create has failed: Resource temporarily
 * unavailable" (its handle_perror()), and std::thread a std::system_error
 * with resource_unavailable_try_again. Both are the same condition as a
 * failed allocation, and a user should read the same line for them.
 */

#include <exception>

namespace shadelab
{

/// True if @p e is a std::bad_alloc, a std::system_error for EAGAIN or
/// ENOMEM (a thread or resource that could not be had), or oneTBB's
/// std::runtime_error for a worker thread it could not start for either
/// reason.
bool isOutOfMemory(const std::exception& e) noexcept;

} // namespace shadelab

#endif
