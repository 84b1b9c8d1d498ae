// `tribolab studio [file_or_folder] [--port N] [--open]`: the browser workbench
// (docs/cli.md#studio). Serves the folder (src/studio/) on 127.0.0.1 and prints the page's URL
// with its secret token; runs until interrupted (every action is already autosaved).
#include "app.hpp"
#include "declared_options.hpp"

#include "numerics/error.hpp"
#include "report/embedded.hpp"
#include "studio/guard.hpp"
#include "studio/handler.hpp"
#include "studio/page.hpp"
#include "studio/server.hpp"
#include "studio/studio_options.hpp"
#include "studio/workbench.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>

namespace tribolab::cli {

void register_studio(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "studio", "The browser workbench: open a video or Tracker project from a folder, calibrate and track "
                "by clicking, run the analyses, save CSV and .trk (a local web server on 127.0.0.1)");
  auto opt = std::make_shared<studio::StudioOptions>();
  add_declared_options(*cmd, *opt, studio::studio_fields(), studio::studio_result_keys());
  cmd->callback([opt] {
    app::check_ranges(*opt, studio::studio_fields());
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path given(opt->file_or_folder);
    if (!fs::exists(given, ec)) throw InputError(opt->file_or_folder, "no such file or folder");
    const bool folder = fs::is_directory(given, ec);
    const fs::path root = fs::canonical(folder ? given : (given.has_parent_path() ? given.parent_path() : fs::path(".")));
    studio::Workbench workbench(root);
    if (!folder) workbench.open(fs::canonical(given));  // a bad video fails here, before serving
    const std::string token = studio::make_token();
    studio::Server server(opt->port, studio::AccessRules{}.max_body_bytes, [&](int bound) {
      return std::make_unique<studio::Handler>(root, studio::AccessRules{token, bound},
                                               studio::Assets{studio::page_html(), report::plotly_js()}, workbench);
    });
    const std::string url = "http://127.0.0.1:" + std::to_string(server.port()) + "/?token=" + token;
    std::cout << "tribolab studio: serving " << root.string() << "\n" << url << "\n(Ctrl-C stops; every action is saved)"
              << std::endl;
    if (opt->open) {
      // The URL holds digits, hex and punctuation only: nothing the shell would interpret.
      const std::string command = "xdg-open '" + url + "' >/dev/null 2>&1 &";
      if (std::system(command.c_str()) != 0) diagnostics() << "tribolab: warning: could not start a browser; open the URL above\n";
    }
    server.run();
  });
}

}  // namespace tribolab::cli
