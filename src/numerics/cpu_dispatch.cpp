#include "numerics/cpu_dispatch.hpp"

#include <cstdlib>
#include <string_view>

namespace tribolab::numerics {

CpuLevel cpu_level_supported() {
#if TRIBOLAB_HAVE_X86_64_V3
  // libgcc's test covers the operating system's support of the AVX state (XGETBV) too.
  static const bool v3 = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("x86-64-v3") != 0;
  }();
  return v3 ? CpuLevel::x86_64_v3 : CpuLevel::baseline;
#else
  return CpuLevel::baseline;
#endif
}

CpuLevel cpu_level() {
  static const CpuLevel level = [] {
    const char* forced = std::getenv("TRIBOLAB_CPU");
    if (forced && std::string_view(forced) == "baseline") return CpuLevel::baseline;
    return cpu_level_supported();
  }();
  return level;
}

std::string_view to_string(CpuLevel level) {
  switch (level) {
    case CpuLevel::baseline: return "baseline";
    case CpuLevel::x86_64_v3: return "x86-64-v3";
  }
  return "?";
}

}  // namespace tribolab::numerics
