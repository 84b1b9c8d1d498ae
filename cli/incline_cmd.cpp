// `tribolab incline`: commands are added here as the incline area grows.
#include "app.hpp"

namespace tribolab::cli {

void register_incline(CLI::App& root) {
  auto* area = root.add_subcommand("incline", "incline commands");
  area->require_subcommand(0);
}

}  // namespace tribolab::cli
