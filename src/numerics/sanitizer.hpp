// TRIBOLAB_ASAN: 1 when this translation unit is compiled with AddressSanitizer, else 0. GCC
// defines __SANITIZE_ADDRESS__; clang (the sanitizer tree's compiler, docs/design.md#build-and-ci)
// answers __has_feature(address_sanitizer) instead. Tests that run a long study keep it short
// there: the sanitizer tree runs the same tests several times slower.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define TRIBOLAB_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TRIBOLAB_ASAN 1
#endif
#endif
#ifndef TRIBOLAB_ASAN
#define TRIBOLAB_ASAN 0
#endif
