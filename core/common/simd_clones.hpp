// AVX2 clones of hot loops, chosen at load time (GNU ifunc); elsewhere (other
// architectures, other compilers) the one portable version. A clone must do
// the same operations per element as the baseline (AVX2 without FMA: no
// contraction), so that both give the same bits. Not under ThreadSanitizer:
// its instrumented ifunc resolver runs while the loader relocates, before the
// sanitizer is set up, and crashes.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_THREAD__)
#define MCMD_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define MCMD_AVX2_CLONES
#endif
