// `tribolab studio [FILE_OR_FOLDER] [--port N] [--open]`: the browser workbench
// (docs/cli.md#studio). Serves the folder (src/studio/) on 127.0.0.1 and prints the page's URL
// with its secret token; runs until interrupted (every action is already autosaved).
#include "app.hpp"

#include "numerics/error.hpp"
#include "report/embedded.hpp"
#include "studio/guard.hpp"
#include "studio/handler.hpp"
#include "studio/page.hpp"
#include "studio/server.hpp"
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
  auto path = std::make_shared<std::string>(".");
  auto port = std::make_shared<int>(0);
  auto open = std::make_shared<bool>(false);
  cmd->add_option("FILE_OR_FOLDER", *path,
                  "Folder served (every file read or written is inside it), or a video or project in it, "
                  "opened at start (when not given: the current folder)");
  cmd->add_option("--port", *port, "Port on 127.0.0.1 (when not given: a free one)")->check(CLI::Range(0, 65535));
  cmd->add_flag("--open", *open, "Open the page in the desktop's browser (xdg-open)");
  cmd->callback([path, port, open] {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path given(*path);
    if (!fs::exists(given, ec)) throw InputError(*path, "no such file or folder");
    const bool folder = fs::is_directory(given, ec);
    const fs::path root = fs::canonical(folder ? given : (given.has_parent_path() ? given.parent_path() : fs::path(".")));
    studio::Workbench workbench(root);
    if (!folder) workbench.open(fs::canonical(given));  // a bad video fails here, before serving
    const std::string token = studio::make_token();
    studio::Server server(*port, studio::AccessRules{}.max_body_bytes, [&](int bound) {
      return std::make_unique<studio::Handler>(root, studio::AccessRules{token, bound},
                                               studio::Assets{studio::page_html(), report::plotly_js()}, workbench);
    });
    const std::string url = "http://127.0.0.1:" + std::to_string(server.port()) + "/?token=" + token;
    std::cout << "tribolab studio: serving " << root.string() << "\n" << url << "\n(Ctrl-C stops; every action is saved)"
              << std::endl;
    if (*open) {
      // The URL holds digits, hex and punctuation only: nothing the shell would interpret.
      const std::string command = "xdg-open '" + url + "' >/dev/null 2>&1 &";
      if (std::system(command.c_str()) != 0) std::cerr << "tribolab: warning: could not start a browser; open the URL above\n";
    }
    server.run();
  });
}

}  // namespace tribolab::cli
