#pragma once
// The solver kernel is a set of inline templates compiled once per instruction set (kernel_avx2.cpp
// with -mavx2, the others without). To keep the linker from merging an AVX2-compiled copy of an
// inline function into a baseline translation unit (an ODR violation that crashes on CPUs without
// AVX2), all kernel code lives in an inline namespace named per translation unit: POND_ISA is set
// by the build for kernel_avx2.cpp and defaults to isa_base.
#ifndef POND_ISA
#define POND_ISA isa_base
#endif
