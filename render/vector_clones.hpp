// ELBOWSIM_VECTOR_CLONES before a function over every pixel of a frame: GCC
// on x86-64 compiles it for AVX2 and for the baseline and picks the version
// at load time (integer loops: both give the same bytes). Elsewhere it is
// nothing.
#pragma once

#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#define ELBOWSIM_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define ELBOWSIM_VECTOR_CLONES
#endif
