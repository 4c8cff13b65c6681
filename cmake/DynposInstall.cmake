# What `cmake --install` puts under the prefix besides the CLI and its data (apps/dynpos):
#   include/dynpos/**          the public headers
#   lib/libdynpos_*.a          every module's static library (dynpos_add_module installs them)
#   lib/cmake/dynpos/          the CMake package: find_package(dynpos CONFIG) gives the target
#                              dynpos::dynpos (every module) and dynpos::MODULE for each one
include(CMakePackageConfigHelpers)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/dynpos DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp")
install(TARGETS dynpos EXPORT dynposTargets)

set(DYNPOS_CONFIG_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/dynpos)
install(EXPORT dynposTargets NAMESPACE dynpos:: DESTINATION ${DYNPOS_CONFIG_DIR})

# The installed config finds GeographicLib as this build did: through the find module that the
# distribution ships outside CMake's own module path, when there is one.
find_file(DYNPOS_GEOGRAPHICLIB_FIND_MODULE FindGeographicLib.cmake PATHS ${CMAKE_MODULE_PATH}
  NO_DEFAULT_PATH NO_CACHE)
set(DYNPOS_GEOGRAPHICLIB_MODULE_DIR "")
if(DYNPOS_GEOGRAPHICLIB_FIND_MODULE)
  get_filename_component(DYNPOS_GEOGRAPHICLIB_MODULE_DIR ${DYNPOS_GEOGRAPHICLIB_FIND_MODULE}
    DIRECTORY)
endif()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/dynposConfig.cmake.in
  ${PROJECT_BINARY_DIR}/dynposConfig.cmake INSTALL_DESTINATION ${DYNPOS_CONFIG_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dynposConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/dynposConfig.cmake
  ${PROJECT_BINARY_DIR}/dynposConfigVersion.cmake DESTINATION ${DYNPOS_CONFIG_DIR})
