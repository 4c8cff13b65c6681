include(GNUInstallDirs)

# Warning and sanitizer flags shared by every dynpos target.
add_library(dynpos_warnings INTERFACE)
target_compile_options(dynpos_warnings INTERFACE -Wall -Wextra -Wpedantic
  $<$<BOOL:${DYNPOS_WERROR}>:-Werror>)
if(DYNPOS_SANITIZE)
  target_compile_options(dynpos_warnings INTERFACE -fsanitize=address,undefined
    -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(dynpos_warnings INTERFACE -fsanitize=address,undefined)
endif()
# The fuzz build (clang): every module instrumented for libFuzzer's coverage, the fuzz targets
# (fuzz/) linked with its driver.
if(DYNPOS_FUZZ)
  target_compile_options(dynpos_warnings INTERFACE -fsanitize=fuzzer-no-link)
endif()

# dynpos_add_module(NAME DEPS targets...)
# One static library per module from src/NAME/*.cpp, public headers in include/dynpos/NAME.
# A module links only to the modules it names, so a wrong include fails to build.
# The library is installed and exported as dynpos::NAME (cmake/DynposInstall.cmake); its
# private headers in src/NAME stay in the source tree.
function(dynpos_add_module name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${name}/*.cpp)
  set(headers $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  if(NOT sources)  # a header-only module
    add_library(dynpos_${name} INTERFACE)
    target_include_directories(dynpos_${name} INTERFACE ${headers})
    target_link_libraries(dynpos_${name} INTERFACE ${ARG_DEPS})
  else()
    add_library(dynpos_${name} STATIC ${sources})
    target_include_directories(dynpos_${name} PUBLIC ${headers}
      PRIVATE ${PROJECT_SOURCE_DIR}/src/${name})
    # The warning flags are the build's own business: a static library exports even its
    # private links ($<LINK_ONLY:...>), so the installed package must not name this target.
    target_link_libraries(dynpos_${name} PUBLIC ${ARG_DEPS}
      PRIVATE $<BUILD_INTERFACE:dynpos_warnings>)
    # Eigen, fmt and the standard library are most of a source's parse time; every module has
    # them through core. Precompiled per module, so each keeps its own flags and definitions.
    target_precompile_headers(dynpos_${name} PRIVATE <Eigen/Dense> <fmt/format.h> <algorithm>
      <cmath> <filesystem> <functional> <map> <optional> <string> <string_view> <vector>)
    # GCC 12 then reports its known false bounds warnings on inlined std::string copies and
    # moves (GCC bugs 105651, 105329), which it hides while <string> is parsed as a system
    # header rather than loaded from a precompiled one. Real out-of-bounds accesses are the
    # sanitizer pass's job.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
      target_compile_options(dynpos_${name} PRIVATE -Wno-array-bounds -Wno-stringop-overread
        -Wno-stringop-overflow -Wno-restrict)
    endif()
    # Code compiled with the sanitizers needs their runtimes wherever it is linked.
    if(DYNPOS_SANITIZE)
      target_link_options(dynpos_${name} INTERFACE
        $<INSTALL_INTERFACE:-fsanitize=address,undefined>)
    endif()
  endif()
  # The static module libraries end up in the Python extension, a shared object.
  if(DYNPOS_BUILD_PYTHON AND TARGET dynpos_${name})
    get_target_property(type dynpos_${name} TYPE)
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      set_target_properties(dynpos_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    endif()
  endif()
  add_library(dynpos::${name} ALIAS dynpos_${name})
  set_target_properties(dynpos_${name} PROPERTIES EXPORT_NAME ${name})
  install(TARGETS dynpos_${name} EXPORT dynposTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
endfunction()

# dynpos_add_test(NAME SOURCE LIBS...): one GoogleTest executable registered with CTest.
function(dynpos_add_test name source)
  add_executable(${name} ${source})
  target_link_libraries(${name} PRIVATE ${ARGN} GTest::gtest GTest::gmock GTest::gtest_main
    dynpos_test_source_dir dynpos_warnings)
  if(TARGET dynpos_test_pch)
    target_precompile_headers(${name} REUSE_FROM dynpos_test_pch)
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 TEST_PREFIX "${name}."
    PROPERTIES ENVIRONMENT "DYNPOS_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
endfunction()
