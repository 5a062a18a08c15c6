# Debian packages through CPack: `cpack -G DEB` in the build folder (or
# scripts/package.sh) writes three packages, split as Debian does:
#   shadelab          the programs, shared libraries, example mesh and scenes
#   shadelab-dev      headers, the static lighting core, the CMake package
#   python3-shadelab  `import shadelab` for Debian's python3
# Library dependencies are read off the binaries by dpkg-shlibdeps; the rest
# are declared here.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME shadelab)
set(CPACK_PACKAGE_VENDOR ShadeLab)
set(CPACK_PACKAGE_CONTACT "ShadeLab developers <shadelab@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "VTK filters, render passes and apps for local lighting")
set(CPACK_PACKAGE_DESCRIPTION
  "Lambert, Phong and Blinn-Phong with every light type of the classic lighting equation, normal generation, and flat / Gouraud / Phong shading as VTK filters and a render pass, with the shadelab command-line tool and the shadelab-viewer Qt viewer.")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# ShadeLab's own libraries are in the package being built, not installed yet.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CPACK_COMPONENTS_ALL runtime development python)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME shadelab)
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION "${CPACK_PACKAGE_DESCRIPTION}")
# Offscreen rendering without a display: Debian's VTK renders through X11 only.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SUGGESTS "xvfb, xauth")

set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME shadelab-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_COMPONENT_DEVELOPMENT_DEPENDS runtime)
set(CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION
  "ShadeLab headers and CMake package: find_package(ShadeLab COMPONENTS ...).")
# What find_package(ShadeLab) finds in turn (ShadeLabConfig.cmake).
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "libvtk9-dev (>= 9.1), libglm-dev, nlohmann-json3-dev")

set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-shadelab)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
set(CPACK_COMPONENT_PYTHON_DEPENDS runtime)
set(CPACK_COMPONENT_PYTHON_DESCRIPTION "ShadeLab for Python 3: import shadelab (with python3-vtk9).")
# The extension modules are built for this Python's ABI.
math(EXPR python_next_minor "${Python3_VERSION_MINOR} + 1")
set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
  "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}), python3 (<< ${Python3_VERSION_MAJOR}.${python_next_minor}), python3-vtk9")

include(CPack)
