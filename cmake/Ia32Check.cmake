# The IA-32 check: the 64-bit build also builds a 32-bit, CPU-only `pond` from the same sources
# (-DPOND_IA32=ON: -m32 -msse2 -mfpmath=sse) as an external project, and tests/cli runs it against
# the golden hash. Needs g++-multilib; without it the check is skipped with a warning, or fails the
# configuration when POND_REQUIRE_IA32 is on (as in CI).
option(POND_IA32_CHECK "Build the 32-bit pond and test its golden hash" ON)
option(POND_REQUIRE_IA32 "Fail the configuration when the IA-32 check cannot be built" OFF)
if(POND_IA32_CHECK AND NOT POND_IA32)
  include(CheckCXXSourceCompiles)
  set(CMAKE_REQUIRED_FLAGS "-m32 -msse2")
  set(CMAKE_REQUIRED_LINK_OPTIONS "-m32")
  check_cxx_source_compiles("#include <thread>\n#include <emmintrin.h>\nint main() { return 0; }"
                            POND_CAN_BUILD_M32)
  unset(CMAKE_REQUIRED_FLAGS)
  unset(CMAKE_REQUIRED_LINK_OPTIONS)
  if(POND_CAN_BUILD_M32)
    include(ExternalProject)
    ExternalProject_Add(pond_ia32
      SOURCE_DIR ${PROJECT_SOURCE_DIR}
      BINARY_DIR ${CMAKE_BINARY_DIR}/ia32
      CMAKE_ARGS -DPOND_IA32=ON -DPOND_BUILD_TESTS=OFF -DPOND_BUILD_BENCH=OFF
                 -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
                 -DCMAKE_UNITY_BUILD=${CMAKE_UNITY_BUILD}
      INSTALL_COMMAND ""
      BUILD_ALWAYS ON
      BUILD_BYPRODUCTS ${CMAKE_BINARY_DIR}/ia32/src/app/pond)
    set(POND_IA32_POND ${CMAKE_BINARY_DIR}/ia32/src/app/pond)
  elseif(POND_REQUIRE_IA32)
    message(FATAL_ERROR "POND_REQUIRE_IA32: cannot build -m32 programs (install g++-multilib)")
  else()
    message(WARNING "IA-32 check skipped: cannot build -m32 programs (install g++-multilib)")
  endif()
endif()
