// `tribolab bounce render`: film a simulated throw (flight, bounce, flight) to a video with
// its truth (docs/cli.md#bounce-render, docs/theory.md#rendering). The workflow is
// app::bounce_render (src/app/bounce/bounce_render.cpp); this file binds its options to flags.
#include "bounce_render_cmd.hpp"
#include "declared_options.hpp"
#include "app/common/result_keys.hpp"

#include "app.hpp"

#include "app/bounce/bounce_synth.hpp"

#include <memory>

namespace tribolab::cli {

void register_bounce_render(CLI::App* area) {
  struct Opts {
    BounceRenderOptions o;
    bool json = false;
  };
  auto opts = std::make_shared<Opts>();
  auto& o = opts->o;
  auto* cmd = area->add_subcommand("render", "film a simulated throw (flight, bounce, flight) to a video with its truth");
  add_declared_options(*cmd, o, bounce_render_fields(), bounce_render_result_keys());
  add_json_flag(*cmd, opts->json);
  cmd->callback([opts, cmd] { print_declared(*cmd, bounce_render(opts->o).json, opts->json); });
}

}  // namespace tribolab::cli
