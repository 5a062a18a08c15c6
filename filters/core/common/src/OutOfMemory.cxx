#include "shadelab/OutOfMemory.h"

#include <cerrno>
#include <cstring>
#include <new>
#include <string>
#include <system_error>

namespace shadelab
{

bool isOutOfMemory(const std::exception& e) noexcept
{
  if (dynamic_cast<const std::bad_alloc*>(&e))
  {
    return true;
  }
  if (const auto* system = dynamic_cast<const std::system_error*>(&e))
  {
    return system->code() == std::errc::resource_unavailable_try_again ||
      system->code() == std::errc::not_enough_memory;
  }
  // oneTBB's handle_perror(): "WHAT: " followed by strerror() of the code.
  static const char prefix[] = "pthread_create has failed: ";
  const char* what = e.what();
  if (std::strncmp(what, prefix, sizeof(prefix) - 1) != 0)
  {
    return false;
  }
  const char* reason = what + sizeof(prefix) - 1;
  return std::strcmp(reason, std::strerror(EAGAIN)) == 0 || std::strcmp(reason, std::strerror(ENOMEM)) == 0;
}

} // namespace shadelab
