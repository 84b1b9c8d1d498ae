// `tribolab demo --out DIR`: runs the case studies and writes DIR/report.html (src/app/demo/demo.hpp).
#include "app.hpp"
#include "declared_options.hpp"
#include "app/demo/demo.hpp"
#include "app/demo/demo_options.hpp"
#include "app/common/result_keys.hpp"

#include <iostream>
#include <sstream>

namespace tribolab::cli {

void register_demo(CLI::App& root) {
  auto opt = std::make_shared<app::DemoOptions>();
  auto as_json = std::make_shared<bool>(false);
  auto* cmd = root.add_subcommand(
      "demo",
      "Run both studies end to end on shipped data and write an offline HTML report "
      "(DIR/report.html)");
  add_declared_options(*cmd, *opt, app::demo_fields(), app::demo_result_keys());
  cmd->get_option("--out")->type_name("DIR");
  add_json_flag(*cmd, *as_json);
  cmd->callback([opt, as_json, cmd] {
    std::ostringstream quiet;
    const DemoSummary s = run_demo(opt->out, *as_json ? static_cast<std::ostream&>(quiet) : std::cout);
    print_declared(*cmd,
                   {{"report", s.report}, {"case_studies", s.case_studies}, {"sections", s.sections}, {"figures", s.figures}},
                   *as_json);
  });
}

}  // namespace tribolab::cli
