# GoogleTest compiled from the sources Debian's googletest package ships (/usr/src/googletest), for
# builds whose target Debian's libgtest-dev does not serve: IA-32 (cmake/Ia32Tests.cmake) and the
# aarch64 cross build (cmake/CrossTests.cmake).
set(POND_GTEST_SOURCE_DIR /usr/src/googletest/googletest CACHE PATH
    "GoogleTest's sources, compiled for the target where Debian's libgtest-dev is not for it")


# pond_tests_from_source(BUILD NAME CAN_TEST WHY [OPTIONS...]): the option POND_BUILD_TESTS for such
# a build (NAME: "IA-32", ...), defaulting to CAN_TEST, with WHY said once where it cannot and an
# error where asked for anyway; with it on, gtest and gtest_main (GoogleTest's CMake names them
# GTest::gtest, GTest::gtest_main) built in BUILD/googletest-NAME, only when a test needs them, with
# OPTIONS (the target's code generation; not pond::flags: GoogleTest keeps its own warnings).
macro(pond_tests_from_source name can_test why)
  if(NOT DEFINED CACHE{POND_BUILD_TESTS} AND NOT ${can_test})
    message(STATUS "${name}: the tests are off (POND_BUILD_TESTS=OFF): ${why}")
  endif()
  option(POND_BUILD_TESTS "Build the GoogleTest suite (${name}: the Vulkan-free unit and CLI tests)" ${${can_test}})
  if(POND_BUILD_TESTS)
    if(NOT ${can_test})
      message(FATAL_ERROR "POND_BUILD_TESTS in the ${name} build: ${why}")
    endif()
    add_subdirectory(${POND_GTEST_SOURCE_DIR} ${CMAKE_BINARY_DIR}/googletest-${name} EXCLUDE_FROM_ALL)
    foreach(lib gtest gtest_main)
      target_compile_options(${lib} PRIVATE ${ARGN})
      if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
        target_compile_options(${lib} PRIVATE -Wno-restrict)  # GCC bug 105651, as in CompilerFlags.cmake
      endif()
    endforeach()
  endif()
endmacro()
