# The installed CMake package: find_package(ShadeLab REQUIRED COMPONENTS
# Normals Lighting ...) gives the imported targets ShadeLab::<Component>
# (Common, IO, Scene, Normals, Lighting, RenderPasses, Rendering, and the
# VTK-free CommonCore, LightingCore and GeometryCore) and finds VTK
# with the modules they use.
include(CMakePackageConfigHelpers)

# The VTK modules the ShadeLab modules depend on, read from their vtk.module
# files, so the list lives in one place.
set(SHADELAB_PACKAGE_VTK_COMPONENTS)
foreach(module IN LISTS SHADELAB_MODULES)
  foreach(kind IN ITEMS depends private_depends)
    vtk_module_get_property("${module}" PROPERTY "INTERFACE_vtk_module_${kind}" VARIABLE deps)
    foreach(dep IN LISTS deps)
      if(dep MATCHES "^VTK::(.+)$")
        list(APPEND SHADELAB_PACKAGE_VTK_COMPONENTS "${CMAKE_MATCH_1}")
      endif()
    endforeach()
  endforeach()
endforeach()
list(REMOVE_DUPLICATES SHADELAB_PACKAGE_VTK_COMPONENTS)
list(SORT SHADELAB_PACKAGE_VTK_COMPONENTS)
if(NOT SHADELAB_PACKAGE_VTK_COMPONENTS)
  message(FATAL_ERROR "no VTK dependencies found for ${SHADELAB_MODULES}")
endif()

set(SHADELAB_PACKAGE_COMPONENTS CommonCore LightingCore GeometryCore)
foreach(module IN LISTS SHADELAB_MODULES)
  string(REPLACE "ShadeLab::" "" component "${module}")
  list(APPEND SHADELAB_PACKAGE_COMPONENTS "${component}")
endforeach()

configure_package_config_file(cmake/ShadeLabConfig.cmake.in
  "${CMAKE_BINARY_DIR}/${SHADELAB_CMAKE_DIR}/ShadeLabConfig.cmake"
  INSTALL_DESTINATION "${SHADELAB_CMAKE_DIR}")
write_basic_package_version_file(
  "${CMAKE_BINARY_DIR}/${SHADELAB_CMAKE_DIR}/ShadeLabConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES
  "${CMAKE_BINARY_DIR}/${SHADELAB_CMAKE_DIR}/ShadeLabConfig.cmake"
  "${CMAKE_BINARY_DIR}/${SHADELAB_CMAKE_DIR}/ShadeLabConfigVersion.cmake"
  DESTINATION "${SHADELAB_CMAKE_DIR}" COMPONENT development)
