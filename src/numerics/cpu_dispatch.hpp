// CPU dispatch for the hot kernels (docs/design.md, "CPU dispatch"). A portable build targets the
// x86-64 baseline (SSE2, no FMA); a kernel whose body is an always-inline function is also
// compiled, in the same translation unit, into a second function with the target attribute
// TRIBOLAB_TARGET_X86_64_V3 (AVX2, FMA: every x86-64 CPU since 2013-2015), and a dispatcher picks
// one at run time with cpu_level(). Only the two kernel functions themselves differ by target:
// everything they call out of line is the baseline code, so no baseline-only CPU ever runs an
// instruction it lacks (which a second translation unit compiled with -march could not promise:
// inline functions and templates it emits are merged with everyone else's by the linker).
#pragma once

#include <string_view>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define TRIBOLAB_HAVE_X86_64_V3 1
#define TRIBOLAB_TARGET_X86_64_V3 __attribute__((target("arch=x86-64-v3")))
#else
#define TRIBOLAB_HAVE_X86_64_V3 0
#define TRIBOLAB_TARGET_X86_64_V3
#endif

namespace tribolab::numerics {

enum class CpuLevel {
  baseline,   ///< the build's own target (x86-64: SSE2)
  x86_64_v3,  ///< AVX2, FMA, BMI2 (x86-64 microarchitecture level 3)
};

/// The level the dispatched kernels run at: x86_64_v3 when this build has such kernels and the
/// CPU and operating system support them, unless the environment variable TRIBOLAB_CPU is
/// "baseline" (to reproduce a baseline machine's numbers to the last bit). Decided once.
CpuLevel cpu_level();

/// The highest level this CPU supports for this build, ignoring TRIBOLAB_CPU.
CpuLevel cpu_level_supported();

/// "baseline" or "x86-64-v3".
std::string_view to_string(CpuLevel level);

}  // namespace tribolab::numerics
