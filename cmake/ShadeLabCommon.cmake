# What every build of ShadeLab's sources needs, whichever VTK it builds
# against: the main build (top-level CMakeLists.txt, Debian's VTK 9.1) and the
# ParaView plugin (plugins/ParaView, ParaView 5.11's VTK 9.2).

set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)
if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()

# Programs in bin/, libraries in lib/ of the build tree, as when installed.
include(GNUInstallDirs)
set(CMAKE_RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_BINDIR}")
set(CMAKE_LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CMAKE_ARCHIVE_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")

# Warnings for ShadeLab's own code (generated wrapper code is left alone).
set(SHADELAB_WARNING_FLAGS -Wall -Wextra)
option(SHADELAB_WERROR "Treat warnings in ShadeLab's own code as errors" OFF)
if(SHADELAB_WERROR)
  list(APPEND SHADELAB_WARNING_FLAGS -Werror)
endif()

find_package(glm REQUIRED CONFIG)
find_package(nlohmann_json 3.10 REQUIRED CONFIG)
find_package(OpenImageIO REQUIRED CONFIG)
# Debian's OpenImageIO config lists /usr/include/opencv4 as an include folder
# although libopenimageio-dev does not depend on OpenCV; drop what is absent.
foreach(target IN ITEMS OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
  get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
  list(FILTER dirs EXCLUDE REGEX "opencv")
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${dirs}")
endforeach()

# Compile options for code that uses the 8-lane batch types
# (shadelab/SIMDFloat8.h): the radiance loop, and the test of the batch
# built-ins, which must exercise the same instructions. AVX2 + FMA when the
# building machine has them (ShadeLab's machines do), two SSE halves otherwise.
# -Wno-psabi: 32-byte vector arguments would change the calling convention
# without AVX, which does not matter for inline-only types.
set(SHADELAB_BATCH_OPTIONS -Wno-psabi)
option(SHADELAB_LIGHTING_AVX2 "Compile the CPU radiance loop for AVX2 + FMA" ON)
if(SHADELAB_LIGHTING_AVX2 AND EXISTS /proc/cpuinfo)
  file(READ /proc/cpuinfo cpuinfo)
  if(cpuinfo MATCHES " avx2" AND cpuinfo MATCHES " fma")
    list(APPEND SHADELAB_BATCH_OPTIONS -mavx2 -mfma)
  endif()
endif()
