// `tribolab bounce`: commands are added here as the bounce area grows.
#include "app.hpp"

namespace tribolab::cli {

void register_bounce(CLI::App& root) {
  auto* area = root.add_subcommand("bounce", "bounce commands");
  area->require_subcommand(0);
}

}  // namespace tribolab::cli
