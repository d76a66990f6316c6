# Compiler flags for every pond target, applied through the interface target pond::flags.
#
# Exact math: GPU and CPU agree bit for bit only if no compiler contracts a*b+c into an FMA, nothing
# reorders float arithmetic and the x87 unit is never used. So: -ffp-contract=off, no fast-math, and
# -mfpmath=sse with SSE2 on IA-32. Wider instruction sets (AVX2) are enabled per source file for the
# backend that uses them, never for the whole build, and FMA is never enabled.
add_library(pond_flags INTERFACE)
add_library(pond::flags ALIAS pond_flags)
target_compile_options(pond_flags INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
  -ffp-contract=off -fno-fast-math)
# GCC 12 reports false -Wrestrict positives inside libstdc++ for string concatenation (GCC bug
# 105651); the warning says nothing about our code there.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(pond_flags INTERFACE -Wno-restrict)
endif()
# In a unity build (CMAKE_UNITY_BUILD, the presets' default) GCC takes each batched source file
# for a header, and warns about every class of it with a member of an anonymous-namespace type.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_UNITY_BUILD)
  target_compile_options(pond_flags INTERFACE -Wno-subobject-linkage)
endif()

# GCC on aarch64 notes that passing a std::pair<float, float> changed in GCC 10.1: a note about
# linking with code built by GCC 9 and before, which pond never is.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_SYSTEM_PROCESSOR MATCHES "^(aarch64|arm64)$")
  target_compile_options(pond_flags INTERFACE -Wno-psabi)
endif()

if(POND_IA32)
  target_compile_options(pond_flags INTERFACE -m32 -msse2 -mfpmath=sse)
  target_link_options(pond_flags INTERFACE -m32)
endif()

if(POND_SANITIZE)
  target_compile_options(pond_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                              -fno-sanitize-recover=all)
  target_link_options(pond_flags INTERFACE -fsanitize=address,undefined)
endif()
if(POND_FUZZ)
  target_compile_options(pond_flags INTERFACE -fsanitize=fuzzer-no-link)  # libFuzzer's coverage
endif()

# The wide backends of the build's target, its baseline first (every CPU of the target has it):
# x86-64 sse2 avx2 avx512, IA-32 sse2, aarch64 neon. The sim kernels (kernel_<isa>.cpp) and the LOD's
# copies are built per backend through pond_isa_sources().
if(POND_IA32)
  set(POND_WIDE_BACKENDS sse2)
elseif(CMAKE_SYSTEM_PROCESSOR MATCHES "^(aarch64|arm64|ARM64)$")
  set(POND_WIDE_BACKENDS neon)
elseif(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(POND_WIDE_BACKENDS sse2 avx2 avx512)
else()
  message(FATAL_ERROR "pond builds for x86-64, IA-32 (-DPOND_IA32=ON) and aarch64, not ${CMAKE_SYSTEM_PROCESSOR}")
endif()
# The CPU solvers of this build, as `--solver` and `pond --version` name them (sse2's is sse).
set(POND_CPU_SOLVERS scalar)
foreach(isa IN LISTS POND_WIDE_BACKENDS)
  string(REPLACE "sse2" "sse" solver ${isa})
  list(APPEND POND_CPU_SOLVERS ${solver})
endforeach()

# Per-file flags for the AVX2 and AVX-512 backends, deliberately without -mfma. (-mavx512f makes
# FMA instructions available, but no FMA intrinsic is used and -ffp-contract=off forbids the
# compiler to fuse a*b+c, so the backend's bits equal the scalar ones; the tests check it.) The
# baselines, SSE2 and NEON, need none.
set(POND_SSE2_FLAGS "")
set(POND_AVX2_FLAGS -mavx2)
set(POND_AVX512_FLAGS -mavx512f)
set(POND_NEON_FLAGS "")

# Builds `sources` (of the calling directory) for one wide backend: its flags and, where it has
# flags, its own inline namespace for the code they inline (sim/isa_namespace.h). Appends to the
# files' other options.
function(pond_isa_sources isa)
  string(TOUPPER "${isa}" upper)
  if(NOT DEFINED POND_${upper}_FLAGS)
    message(FATAL_ERROR "pond_isa_sources: no backend ${isa}")
  endif()
  if(POND_${upper}_FLAGS)
    set_property(SOURCE ${ARGN} APPEND PROPERTY COMPILE_OPTIONS ${POND_${upper}_FLAGS})
    set_property(SOURCE ${ARGN} APPEND PROPERTY COMPILE_DEFINITIONS POND_ISA=isa_${isa})
  endif()
endfunction()
