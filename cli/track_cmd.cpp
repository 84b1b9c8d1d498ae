// `tribolab track`: commands are added here as the track area grows.
#include "app.hpp"

namespace tribolab::cli {

void register_track(CLI::App& root) {
  auto* area = root.add_subcommand("track", "track commands");
  area->require_subcommand(0);
}

}  // namespace tribolab::cli
