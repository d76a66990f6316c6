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

# Per-file flags for the AVX2 and AVX-512 backends, deliberately without -mfma. (-mavx512f makes
# FMA instructions available, but no FMA intrinsic is used and -ffp-contract=off forbids the
# compiler to fuse a*b+c, so the backend's bits equal the scalar ones; the tests check it.)
set(POND_AVX2_FLAGS -mavx2)
set(POND_AVX512_FLAGS -mavx512f)

# Builds `sources` (of the calling directory) for one wide backend, avx2 or avx512: its flags, and
# its own inline namespace for the kernel code they inline (sim/isa_namespace.h).
function(pond_isa_sources isa)
  string(TOUPPER "${isa}" upper)
  set_source_files_properties(${ARGN} PROPERTIES
    COMPILE_OPTIONS "${POND_${upper}_FLAGS}" COMPILE_DEFINITIONS "POND_ISA=isa_${isa}")
endfunction()
