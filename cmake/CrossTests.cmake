# The tests of a cross build (the arm64 preset: cmake/Aarch64Toolchain.cmake): the Vulkan-free unit
# tests, the `pond` command line and the fuzz replay, as in the IA-32 build (tests/CMakeLists.txt
# lists the parts), run under the toolchain's emulator (CMAKE_CROSSCOMPILING_EMULATOR, qemu-aarch64)
# by add_test and gtest_discover_tests alike. GoogleTest is compiled for the target from its
# sources (cmake/GTestFromSource.cmake). POND_BUILD_TESTS defaults to ON when both are here and to
# OFF, with a message saying why, when not; the benchmarks are not built.
include(${CMAKE_CURRENT_LIST_DIR}/GTestFromSource.cmake)
set(can_test ON)
set(why "")
if(NOT EXISTS ${POND_GTEST_SOURCE_DIR}/CMakeLists.txt)
  set(can_test OFF)
  set(why "no GoogleTest sources in ${POND_GTEST_SOURCE_DIR} (install googletest)")
elseif(NOT CMAKE_CROSSCOMPILING_EMULATOR)
  set(can_test OFF)
  set(why "no emulator for ${CMAKE_SYSTEM_PROCESSOR} programs (install qemu-user)")
endif()
pond_tests_from_source(${CMAKE_SYSTEM_PROCESSOR} can_test "${why}")
unset(can_test)
unset(why)
