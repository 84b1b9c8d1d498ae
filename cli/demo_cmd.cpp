// `tribolab demo`: commands are added here as the demo area grows.
#include "app.hpp"

namespace tribolab::cli {

void register_demo(CLI::App& root) {
  auto* area = root.add_subcommand("demo", "demo commands");
  area->require_subcommand(0);
}

}  // namespace tribolab::cli
