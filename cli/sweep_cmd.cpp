#include "sweep_cmd.hpp"

#include <cstdio>

namespace tribolab::cli {

void print_progress(std::ostream& out, const sweep::Progress& p) {
  const double pct =
      p.total > 0 ? 100.0 * static_cast<double>(p.done) / static_cast<double>(p.total) : 100;
  const double left = p.rate > 0 ? static_cast<double>(p.total - p.done) / p.rate : 0;
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "\rsweep: %lld/%lld cells (%5.1f%%)  %.4g cells/s  %.1f s  ETA %.0f s   ",
                static_cast<long long>(p.done), static_cast<long long>(p.total), pct, p.rate,
                p.elapsed_s, left);
  out << buf << std::flush;
}

}  // namespace tribolab::cli
