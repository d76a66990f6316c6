# The Vulkan device the GPU tests run on, by name substring: POND_DEVICE in their environment (the
# variable every pond command reads when --device is not given). lavapipe by default, so runs are
# the same everywhere; scripts/test.sh passes $POND_DEVICE, so `POND_DEVICE=radeon scripts/test.sh`
# tests a real GPU.
set(POND_TEST_DEVICE "llvmpipe" CACHE STRING "Vulkan device (name substring) for the GPU tests")
# pond_add_test(NAME SOURCES ... LIBS ... LABELS ...): one GoogleTest executable registered with
# CTest, every test case of it a CTest test (gtest_discover_tests) carrying the labels.
include(GoogleTest)
function(pond_add_test name)
  cmake_parse_arguments(T "" "" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/tests)
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main pond::flags)
  gtest_discover_tests(${name} PROPERTIES LABELS "${T_LABELS}" DISCOVERY_TIMEOUT 60
                       WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endfunction()

# pond_test_command(VAR TARGET): how a shell test runs the executable TARGET: its path, or where
# programs run under an emulator (CMAKE_CROSSCOMPILING_EMULATOR: IA-32 on a kernel that cannot run
# 32-bit programs, a cross build) a wrapper script beside it that runs it there.
function(pond_test_command var target)
  if(NOT CMAKE_CROSSCOMPILING_EMULATOR)
    set(${var} $<TARGET_FILE:${target}> PARENT_SCOPE)
    return()
  endif()
  set(wrapper ${CMAKE_CURRENT_BINARY_DIR}/${target}_under_emulator.sh)
  list(JOIN CMAKE_CROSSCOMPILING_EMULATOR "\" \"" emulator)
  file(GENERATE OUTPUT ${wrapper}
       CONTENT "#!/bin/sh\nexec \"${emulator}\" \"$<TARGET_FILE:${target}>\" \"$@\"\n"
       FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
  set(${var} ${wrapper} PARENT_SCOPE)
endfunction()
