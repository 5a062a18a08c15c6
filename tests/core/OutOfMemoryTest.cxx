// shadelab::isOutOfMemory(): the exceptions that mean memory ran out.
#include "shadelab/Error.h"
#include "shadelab/OutOfMemory.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <new>
#include <stdexcept>
#include <system_error>

TEST(OutOfMemory, FailedAllocationsAre)
{
  EXPECT_TRUE(shadelab::isOutOfMemory(std::bad_alloc()));
  EXPECT_TRUE(shadelab::isOutOfMemory(std::bad_array_new_length()));
}

TEST(OutOfMemory, ThreadsThatCouldNotStartForWantOfResourcesAre)
{
  // What std::thread throws when pthread_create fails.
  EXPECT_TRUE(shadelab::isOutOfMemory(std::system_error(EAGAIN, std::generic_category())));
  EXPECT_TRUE(shadelab::isOutOfMemory(std::system_error(ENOMEM, std::generic_category())));
  // oneTBB's line, as `shadelab lobe` printed it under `ulimit -v 185000`
  // reading a 2M-triangle VTP.
  EXPECT_TRUE(
    shadelab::isOutOfMemory(std::runtime_error("pthread_create has failed: Resource temporarily unavailable")));
  EXPECT_TRUE(shadelab::isOutOfMemory(std::runtime_error("pthread_create has failed: Cannot allocate memory")));
}

TEST(OutOfMemory, OtherFailuresAreNot)
{
  EXPECT_FALSE(shadelab::isOutOfMemory(std::system_error(ENOENT, std::generic_category())));
  EXPECT_FALSE(shadelab::isOutOfMemory(std::runtime_error("pthread_create has failed: Invalid argument")));
  EXPECT_FALSE(shadelab::isOutOfMemory(std::runtime_error("pthread_create has failed: Resource temporarily")));
  EXPECT_FALSE(shadelab::isOutOfMemory(std::runtime_error("Resource temporarily unavailable")));
  EXPECT_FALSE(shadelab::isOutOfMemory(shadelab::Error("mesh.ply: line 3: out of memory is not a number")));
  EXPECT_FALSE(shadelab::isOutOfMemory(std::logic_error("pthread_create")));
}
