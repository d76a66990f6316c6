# The tests of the IA-32 build (-DPOND_IA32=ON): the Vulkan-free unit tests, the `pond` command
# line and the fuzz replay (tests/CMakeLists.txt lists the parts), built with -m32 -msse2
# -mfpmath=sse like everything else in that build. Debian's libgtest-dev is 64-bit only, so
# GoogleTest is compiled here from the sources it ships in /usr/src/googletest. The tests run
# natively where the kernel runs 32-bit programs, else under qemu-i386 (user-mode emulation, as in
# tests/cli/ia32_golden_test.sh). POND_BUILD_TESTS defaults to ON when both are possible and to
# OFF, with a message saying why, when not; the benchmarks are never built for IA-32 (no 32-bit
# Google Benchmark).
#
# Sets POND_IA32_EMULATOR (the command that runs a 32-bit program, empty when they run natively)
# and, with tests on, builds the targets GTest::gtest and GTest::gtest_main.
include(${CMAKE_CURRENT_LIST_DIR}/GTestFromSource.cmake)
set(POND_IA32_EMULATOR "")

if(NOT DEFINED CACHE{POND_BUILD_TESTS} OR POND_BUILD_TESTS)
  set(can_test ON)
  set(why "")
  if(NOT EXISTS ${POND_GTEST_SOURCE_DIR}/CMakeLists.txt)
    set(can_test OFF)
    set(why "no GoogleTest sources in ${POND_GTEST_SOURCE_DIR} (install googletest)")
  else()
    # Can this kernel run a 32-bit program? (Some x86-64 kernels have no IA-32 emulation.)
    set(probe ${CMAKE_BINARY_DIR}/CMakeFiles/pond_ia32_probe.cpp)
    file(WRITE ${probe} "#include <emmintrin.h>\nint main() { return _mm_cvtsi128_si32(_mm_set1_epi32(0)); }\n")
    try_run(POND_IA32_RUNS_NATIVELY POND_IA32_PROBE_BUILDS ${CMAKE_BINARY_DIR}/CMakeFiles/pond_ia32_probe
            ${probe} COMPILE_DEFINITIONS -m32 -msse2 LINK_OPTIONS -m32)
    if(NOT POND_IA32_PROBE_BUILDS)
      set(can_test OFF)
      set(why "cannot build -m32 programs (install g++-multilib)")
    elseif(NOT POND_IA32_RUNS_NATIVELY STREQUAL "0")
      find_program(POND_QEMU_I386 qemu-i386)
      if(POND_QEMU_I386)
        set(POND_IA32_EMULATOR ${POND_QEMU_I386})
        message(STATUS "IA-32: this kernel cannot run 32-bit programs; the tests run under ${POND_QEMU_I386}")
      else()
        set(can_test OFF)
        set(why "this kernel cannot run 32-bit programs and qemu-i386 is missing (install qemu-user)")
      endif()
    endif()
  endif()
endif()

pond_tests_from_source(IA-32 can_test "${why}" -m32 -msse2 -mfpmath=sse)
if(POND_BUILD_TESTS)
  # Every executable made from here on runs through the emulator in add_test and in
  # gtest_discover_tests (CROSSCOMPILING_EMULATOR), whether or not CMake calls this cross-compiling.
  if(POND_IA32_EMULATOR)
    set(CMAKE_CROSSCOMPILING_EMULATOR ${POND_IA32_EMULATOR})
  endif()
endif()
unset(can_test)
unset(why)
unset(probe)
