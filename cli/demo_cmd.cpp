// `tribolab demo --out DIR`: runs the case studies and writes DIR/report.html (src/app/demo/demo.hpp).
#include "app.hpp"
#include "declared_options.hpp"
#include "app/demo/demo.hpp"
#include "app/common/result_keys.hpp"

#include <iostream>
#include <sstream>

namespace tribolab::cli {

void register_demo(CLI::App& root) {
  struct DemoOptions {
    std::string out = "demo-out";  ///< folder for report.html (created if needed)
    bool json = false;
  };
  auto opt = std::make_shared<DemoOptions>();
  auto* cmd = root.add_subcommand(
      "demo",
      "Run both studies end to end on shipped data and write an offline HTML report "
      "(DIR/report.html)");
  cmd->add_option("--out", opt->out, "Folder for report.html, created if needed")
      ->type_name("DIR")
      ->capture_default_str();
  add_json_flag(*cmd, opt->json);
  declare_results(*cmd, app::demo_result_keys());
  cmd->callback([opt] {
    std::ostringstream quiet;
    const DemoSummary s = run_demo(opt->out, opt->json ? static_cast<std::ostream&>(quiet) : std::cout);
    print_result({{"report", s.report},
                  {"case_studies", s.case_studies},
                  {"sections", s.sections},
                  {"figures", s.figures}},
                 opt->json, app::demo_result_keys());
  });
}

}  // namespace tribolab::cli
