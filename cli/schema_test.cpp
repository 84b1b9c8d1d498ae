// `tribolab schema` and the option declarations as the command line spells them
// (cli/declared_options.hpp): every declared field is a flag and every flag a declared field;
// every number a declared command prints has a declared key, and its listing shows the
// declared unit; docs/cli.md documents every declared flag with its unit.
#include "cli_test_util.hpp"

#include "app.hpp"
#include "text_listing.hpp"

#include "app/common/option_fields.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <regex>
#include <set>

namespace tribolab::cli {
namespace {

using namespace tribolab::cli::testing;
using nlohmann::json;

const json& schema() {
  static const json s = [] {
    const RunResult r = run_tribolab("schema --json");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return json::parse(r.out)["commands"];
  }();
  return s;
}

/// The declared keys of a command of the schema: its results, or with `which` its
/// "series_results" (the summary of several files).
app::ResultKeys keys_of(const json& c, const char* which = "results") {
  app::ResultKeys k;
  for (const json& r : c[which]) k.push_back({r["key"], r["unit"], r["help"]});
  return k;
}

/// A small, quick run of each command with declared result keys: `setup` (run first, its JSON
/// passed to `args`) makes the inputs a command needs. A command declared without an entry here
/// fails Schema.EveryCommandWithDeclaredResultsHasASampleRun.
struct SampleRun {
  using Args = std::function<std::string(const std::string& dir, const json& setup)>;
  SampleRun(Args a, std::string s = "") : args(std::move(a)), setup(std::move(s)) {}
  SampleRun(std::string s, Args a) : args(std::move(a)), setup(std::move(s)) {}  ///< setup first, for long setups
  Args args;
  std::string setup;  ///< run first (with {dir} replaced), or empty
};

const std::map<std::string, SampleRun>& sample_runs() {
  static const std::string src = TRIBOLAB_SOURCE_DIR;
  static const std::string throw_txt = "'" + src + "/data/demo/bounce/ordinary.txt'";
  static const std::map<std::string, SampleRun> m = {
      {"bounce contact-time", {[](auto&, auto&) { return "bounce contact-time --height 0.5 --omega 3 --theta-deg 20"; }}},
      {"bounce simulate", {[](auto&, auto&) { return "bounce simulate --vy -4 --omega 5 --theta-deg 30"; }}},
      {"bounce drop", {[](auto&, auto&) { return "bounce drop --height 0.6 --omega -40 --bounces 2"; }}},
      {"incline predict", {[](auto&, auto&) { return "incline predict --mu 0.634 --phi-deg 20.96 --v0 2.62"; }}},
      {"incline simulate",
       {[](const std::string& dir, auto&) {
          return "incline simulate --mu 0.634 --phi-deg 20.96 --v0 2.62 --method numeric --out '" + dir + "/s.csv'";
        }}},
      {"incline mu-from-stop",
       {[](auto&, auto&) {
          return "incline mu-from-stop --phi-deg 10.37 --x-stop 0.214 --y-stop -0.036 --sigma-phi-deg 0.1 --sigma-pos 0.002 "
                 "--plate-size 1";
        }}},
      {"incline synth",
       {[](const std::string& dir, auto&) {
          return "incline synth --mu 0.634 --phi-deg 20.96 --v0 2.62 --seed 3 --out '" + dir + "/r.txt'";
        }}},
      {"bounce synth-video",
       {[](const std::string& dir, auto&) { return "bounce synth-video --height 0.5 --fps 120 --out '" + dir + "/v.txt'"; }}},
      {"bounce synth-table", {[](const std::string& dir, auto&) { return "bounce synth-table --rows 5 --out '" + dir + "/t.csv'"; }}},
      {"bounce merge",
       {[](const std::string& dir, auto&) {
          return "bounce merge '" + dir + "/s0.csv' '" + dir + "/s1.csv' --out '" + dir + "/m.csv'";
        },
        "bounce sweep --theta-deg 100:120:2 --omega 30:40:2 --shard 0/2 --out {dir}/s0.csv && "
        "bounce sweep --theta-deg 100:120:2 --omega 30:40:2 --shard 1/2 --out {dir}/s1.csv"}},
      {"bounce analyze",
       {[](auto&, auto&) { return "bounce analyze " + throw_txt + " --track-a A --track-b B --time-scale 0.125 --floor-y 0"; }}},
      {"track kinematics",
       {[](const std::string& dir, auto&) { return "track kinematics " + throw_txt + " --track A --out '" + dir + "/k.csv'"; }}},
      {"incline mu-from-slide",
       {[](const std::string& dir, auto&) { return "incline mu-from-slide '" + dir + "/slide.txt' --phi-deg 41.09"; },
        "incline synth --mu 0.634 --phi-deg 41.09 --v0 0 --fps 240 --duration 0.7 --seed 41 --out {dir}/slide.txt"}},
      {"bounce render",
       {[](const std::string& dir, auto&) {
          return "bounce render --size 160x120 --fps 100 --height 0.3 --after 0.05 --supersample 1 --out '" + dir + "/r.avi'";
        }}},
      {"incline render",
       {[](const std::string& dir, auto&) {
          return "incline render --mu 0.45 --phi-deg 20 --v0 1.2 --size 160x120 --duration 0.2 --supersample 1 --out '" + dir +
                 "/r.avi'";
        }}},
      {"track video",
       {[](const std::string& dir, const json& film) {
          return fmt::format("track video '{}/v.avi' --ellipse ball={},{}@0 --scale {} --out '{}/t.csv'", dir,
                             film["ball_start_px"][0].get<double>(), film["ball_start_px"][1].get<double>(),
                             film["scale_m_per_px"].get<double>(), dir);
        },
        "bounce render --size 160x120 --fps 100 --height 0.3 --after 0.05 --supersample 1 --out {dir}/v.avi"}},
      {"track import", {[](auto&, auto&) { return "track import " + throw_txt; }}},
      {"track rigid-body",
       {[](auto&, auto&) { return "track rigid-body " + throw_txt + " --track-a A --track-b B --time-scale 0.125"; }}},
      {"track rotation",  // the ball's tip A about a given point: the fitted pivot needs a turning mark
       {[](auto&, auto&) { return "track rotation " + throw_txt + " --track A --time-scale 0.125 --pivot-x 0.1 --pivot-y 0.5"; }}},
      {"incline families",
       {[](const std::string& dir, auto&) {
          return "incline families --mu 0.6 --phi-deg 20 --v0 2 --vary v0 --values 1,2 --samples 50 --out '" + dir + "/f.csv'";
        }}},
      {"incline analyze",
       {[](const std::string& dir, auto&) { return "incline analyze '" + dir + "/run.txt' --phi-deg 20.96"; },
        "incline synth --mu 0.634 --phi-deg 20.96 --v0 2.62 --seed 3 --out {dir}/run.txt"}},
      {"incline normal-friction-test",
       {[](const std::string& dir, auto&) {
          return "incline normal-friction-test '" + dir + "/r15.txt' '" + dir + "/r20.txt' '" + dir + "/r25.txt' --phi-deg 15,20,25";
        },
        "incline synth --mu 0.634 --phi-deg 15 --v0 2.62 --seed 3 --out {dir}/r15.txt && "
        "incline synth --mu 0.634 --phi-deg 20 --v0 2.62 --seed 4 --out {dir}/r20.txt && "
        "incline synth --mu 0.634 --phi-deg 25 --v0 2.62 --seed 5 --out {dir}/r25.txt"}},
      {"bounce fit",
       {[](const std::string& dir, auto&) { return "bounce fit '" + dir + "/t.csv'"; },
        "bounce synth-table --rows 8 --out {dir}/t.csv"}},
      {"bounce sweep",
       {[](const std::string& dir, auto&) {
          return "bounce sweep --theta-deg 100:120:3 --omega 30:40:3 --threads 1 --out '" + dir + "/s.csv' --contour '" + dir +
                 "/c.csv' --threshold '" + dir + "/h.csv'";
        }}},
  };
  return m;
}

/// Commands whose listing has no sample run here, and why: each is run by its own tests.
const std::map<std::string, std::string>& without_sample_run() {
  static const std::map<std::string, std::string> m = {
      {"demo", "runs every case study (5 s; minutes under ASan): cli/demo_test.cpp runs it; its four keys are "
               "checked by Schema.TheDemoListingIsDeclared"},
      {"studio", "serves a page until interrupted and prints its URL, no result (src/studio/server_test.cpp starts the "
                 "real server, tests/browser/studio_e2e.py the command; ExitCodes.* its bad options)"},
      {"schema", "its one key, commands, is what every Schema.* test reads"},
  };
  return m;
}

/// The arguments of `name`'s sample run, its setup done in a fresh folder.
/// The arguments of run `s` (named `name`), its setup done in a fresh folder "<prefix><name>":
/// the setup's commands, separated by " && ", run in order; the last one's JSON is kept.
std::string args_after_setup(const SampleRun& s, const std::string& prefix, const std::string& name) {
  std::string slug = name;
  for (char& c : slug) if (c == ' ' || c == '-' || c == '@') c = '_';
  const std::string dir = temp_dir(prefix + slug);
  json setup;
  for (std::size_t start = 0; start < s.setup.size();) {
    const std::size_t end = std::min(s.setup.find(" && ", start), s.setup.size());
    std::string cmd = s.setup.substr(start, end - start);
    for (std::size_t p; (p = cmd.find("{dir}")) != std::string::npos;) cmd.replace(p, 5, "'" + dir + "'");
    setup = run_json(cmd);
    start = end + 4;
  }
  return s.args(dir, setup);
}

std::string sample_args(const std::string& name) { return args_after_setup(sample_runs().at(name), "schema_", name); }

/// The commands with declared result keys, and their sample runs' JSON and listing (run once).
struct Listed {
  json command;
  json result;
  std::string listing;
};
const std::vector<Listed>& listed() {
  // Each command runs once (--json); its listing is what print_result prints for that JSON with
  // the declared keys (Schema.TheCommandPrintsTheListingOfItsDeclaredKeys checks that the
  // program does print exactly that).
  static const std::vector<Listed> l = [] {
    std::vector<Listed> out;
    for (const json& c : schema()) {
      if (!c.contains("results") || !sample_runs().count(c["command"])) continue;
      const json j = run_json(sample_args(c["command"]));
      const app::ResultKeys keys = keys_of(c);
      out.push_back({c, j, text_listing(spelled_for_cli(j), keys)});
    }
    return out;
  }();
  return l;
}

std::vector<json> declared() {
  std::vector<json> out;
  for (const json& c : schema())
    if (c["declared"].get<bool>()) out.push_back(c);
  return out;
}

/// Every leaf of `j` as its dotted path (lists of objects: the element's keys under the list's).
void schema_leaves(const json& j, const std::string& path, std::vector<std::string>& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) schema_leaves(v, path.empty() ? k : path + "." + k, out);
  } else if (j.is_array() && !j.empty() && j[0].is_object()) {
    for (const json& e : j) schema_leaves(e, path, out);
  } else {
    out.push_back(path);
  }
}

TEST(Schema, ListsEveryCommandAndEveryOneIsDeclared) {
  std::set<std::string> names, with_fields;
  for (const json& c : schema()) {
    names.insert(c["command"]);
    if (c["declared"].get<bool>()) with_fields.insert(c["command"]);
  }
  for (const char* c : {"incline predict", "bounce simulate", "track video", "demo", "schema"}) EXPECT_TRUE(names.count(c)) << c;
  // Issue 23: every command's options declared once, every front end bound from it.
  for (const std::string& c : names) EXPECT_TRUE(with_fields.count(c)) << c << ": its options are not bound from a declaration";
  for (const char* c : {"bounce sweep", "track video", "track import", "track rotation", "track kinematics", "incline analyze",
                        "studio", "schema"})
    EXPECT_TRUE(with_fields.count(c)) << c;
}

TEST(Schema, SweepFieldsHaveTheirTypesAndDefaults) {
  // A range, a number or a range and a shard are types of their own in the schema (a form
  // needs lo, hi, count), with the struct's defaults: speed 4, mu 0.5, the whole grid 0/1.
  for (const json& c : schema()) {
    if (c["command"] != "bounce sweep") continue;
    std::map<std::string, json> by_name;
    for (const json& f : c["fields"]) by_name[f["name"]] = f;
    EXPECT_EQ(by_name["theta_deg"]["type"], "range");
    EXPECT_TRUE(by_name["theta_deg"]["required"].get<bool>());
    EXPECT_EQ(by_name["theta_deg"]["unit"], "deg");
    EXPECT_EQ(by_name["omega"]["type"], "range");
    EXPECT_TRUE(by_name["omega"]["default"].is_null());
    EXPECT_EQ(by_name["speed"]["type"], "number or range");
    EXPECT_EQ(by_name["speed"]["default"], 4.0);
    EXPECT_EQ(by_name["mu"]["default"], 0.5);
    EXPECT_EQ(by_name["shard"]["type"], "shard");
    EXPECT_EQ(by_name["shard"]["default"], json::array({0, 1}));
    EXPECT_EQ(by_name.count("a") + by_name.count("model") + by_name.count("tol"), 3u);  // the cell's physics
  }
}

TEST(Schema, DeclaredSweepOptionsReadTheirTextAsBefore) {
  // The declared --theta-deg, --speed and --shard read LO:HI:N, a number or a range, and i/N
  // with the messages the hand-bound options gave (src/app/sweep/sweep_text.hpp).
  const std::string dir = temp_dir("schema_sweep_text");
  const auto error_of = [&](const std::string& args) {
    const RunResult r = run_tribolab("bounce sweep --out '" + dir + "/s.csv' " + args);
    EXPECT_NE(r.exit_code, 0) << args;
    return r.err;
  };
  EXPECT_NE(error_of("--theta-deg 100:170 --omega 30:50:3").find("--theta-deg: expected a range lo:hi:count"),
            std::string::npos);
  EXPECT_NE(error_of("--theta-deg 100:170:3 --omega 30:50:3 --speed 0").find("--speed: the incoming speed must be > 0"),
            std::string::npos);
  EXPECT_NE(error_of("--theta-deg 100:170:3 --omega 30:50:3 --shard 2/2").find("--shard: shard index must be in 0..1"),
            std::string::npos);
  const json j = run_json("bounce sweep --theta-deg 100:120:2 --omega 30:40:2 --speed 3:5:2 --mu 0.4 --shard 1/2 --threads 1 "
                          "--out '" + dir + "/s.csv'");
  EXPECT_EQ(j["cells_grid"], 8);
  EXPECT_EQ(j["cells_shard"], 4);
  const std::string header = slurp(dir + "/s.csv").substr(0, 200);
  EXPECT_NE(header.find("shard 1/2"), std::string::npos) << header;
  EXPECT_NE(header.find("speed=3:5:2"), std::string::npos) << header;
  EXPECT_NE(header.find("mu=0.4"), std::string::npos) << header;
}

TEST(Schema, EveryDeclaredFieldIsAFlagAndEveryFlagADeclaredField) {
  for (const json& c : declared()) {
    std::set<std::string> flags, fields;
    for (const json& o : c["options"])
      if (o["name"] != "--json") flags.insert(o["name"]);
    for (const json& f : c["fields"]) {
      if (!f["flag"].is_null()) fields.insert(f["flag"]);
      if (f["required"].get<bool>()) {
        bool required_flag = false;
        for (const json& o : c["options"])
          if (o["name"] == f["flag"]) required_flag = o["required"].get<bool>();
        EXPECT_TRUE(required_flag) << c["command"] << " " << f["flag"];
      }
    }
    EXPECT_EQ(flags, fields) << c["command"];
  }
}

TEST(Schema, TheHelpShowsTheDeclaredUnitAndTheStructsDefault) {
  for (const json& c : declared()) {
    for (const json& f : c["fields"]) {
      if (f["flag"].is_null()) continue;
      for (const json& o : c["options"]) {
        if (o["name"] != f["flag"] || f["unit"].get<std::string>().empty()) continue;
        const std::string help = o["help"];
        EXPECT_NE(help.find(", " + f["unit"].get<std::string>()), std::string::npos) << c["command"] << " " << help;
      }
    }
  }
  const std::string help = run_tribolab("bounce simulate --help").out;
  EXPECT_NE(help.find("--inertia"), std::string::npos) << help;
  EXPECT_NE(help.find("0.0041"), std::string::npos) << help;  // bounce::Ball's default, shown
}

TEST(Schema, EveryCommandWithDeclaredResultsHasASampleRun) {
  std::size_t n = 0;
  for (const json& c : schema()) {
    if (!c.contains("results")) continue;
    ++n;
    EXPECT_TRUE(sample_runs().count(c["command"]) || without_sample_run().count(c["command"])) << c["command"];
  }
  EXPECT_EQ(n, sample_runs().size() + without_sample_run().size());  // no sample run of a command that declares nothing
}

TEST(Schema, EveryCommandThatPrintsAListingDeclaresItsResults) {
  // Issue 27: the listing's units come from each key's declaration, never from its name; a
  // command without declared keys would print its numbers without units. `schema` prints the
  // declarations themselves, not a result; `studio` prints its URL and serves the page, where
  // each analysis shows that command's own declared listing.
  for (const json& c : schema()) {
    if (c["command"] == "schema" || c["command"] == "studio") continue;
    EXPECT_TRUE(c.contains("results")) << c["command"] << " prints a listing but declares no result keys";
  }
}

TEST(Schema, TheDemoListingIsDeclared) {
  // demo's result is the four keys cli/demo_cmd.cpp prints (no sample run: see without_sample_run).
  for (const json& c : schema()) {
    if (c["command"] != "demo") continue;
    const app::ResultKeys keys = keys_of(c);
    for (const char* k : {"report", "case_studies", "sections", "figures"})
      EXPECT_NE(app::find_result_key(keys, k), nullptr) << k;
  }
}

TEST(Schema, TheCommandPrintsTheListingOfItsDeclaredKeys) {
  // The program's own listing of a sample run is the declared-keys listing of its JSON.
  const std::string args = sample_args("bounce drop");
  const json j = run_json(args);
  for (const json& c : schema()) {
    if (c["command"] != "bounce drop") continue;
    const app::ResultKeys keys = keys_of(c);
    EXPECT_EQ(run_tribolab(args).out, text_listing(j, keys));
  }
}

TEST(Schema, EveryKeyACommandPrintsIsDeclared) {
  // The listing's units come only from these declarations: an undeclared key would print
  // without a unit.
  ASSERT_EQ(listed().size(), sample_runs().size());
  for (const Listed& l : listed()) {
    const app::ResultKeys keys = keys_of(l.command);
    std::vector<std::string> paths;
    schema_leaves(l.result, "", paths);
    ASSERT_FALSE(paths.empty()) << l.command["command"];
    for (const std::string& p : paths)
      EXPECT_NE(app::find_result_key(keys, p), nullptr) << l.command["command"] << ": key " << p << " is not declared";
  }
}

std::string regex_quote(const std::string& s) { return std::regex_replace(s, std::regex(R"([\^$.|?*+()\[\]{}])"), R"(\$&)"); }

TEST(Schema, ListingsPrintTheDeclaredUnits) {
  for (const Listed& l : listed()) {
    const app::ResultKeys keys = keys_of(l.command);
    // Each top-level number's row: "key  value[ ± sigma][ unit]", the unit the declared one.
    for (const auto& [k, v] : l.result.items()) {
      if (!v.is_number() || k.rfind("sigma_", 0) == 0) continue;
      const app::ResultKey* d = app::find_result_key(keys, k);
      ASSERT_NE(d, nullptr) << k;
      const std::regex row("(^|\\n)" + k + " +\\S+( ± \\S+)?" + (d->unit.empty() ? "" : " " + regex_quote(d->unit)) + "(\\n|  )");
      EXPECT_TRUE(std::regex_search(l.listing, row)) << l.command["command"] << ": " << k << " [" << d->unit << "]\n" << l.listing;
    }
  }
}

TEST(Schema, TheListingsOfIssue27SayTheRightUnits) {
  // Before the declarations the key names gave "height 480 m", "scale_m_per_px 0.00237 px",
  // "accelerations_defined 89 m/s^2", "a_velocity_line 1.765 m/s", "r_squared x 0.9997 m".
  std::map<std::string, std::string> text;
  for (const Listed& l : listed()) text[l.command["command"]] = l.listing;
  EXPECT_TRUE(std::regex_search(text["bounce render"], std::regex("\\nheight +120 px\\n"))) << text["bounce render"];
  EXPECT_TRUE(std::regex_search(text["bounce render"], std::regex("\\nscale_m_per_px +\\S+ m/px\\n")));
  EXPECT_TRUE(std::regex_search(text["track video"], std::regex("\\n +m_per_px +\\S+ m/px\\n"))) << text["track video"];
  EXPECT_TRUE(std::regex_search(text["track kinematics"], std::regex("(^|\\n)accelerations_defined +\\d+\\n"))) << text["track kinematics"];
  EXPECT_TRUE(std::regex_search(text["incline mu-from-slide"], std::regex("\\na_velocity_line +\\S+ ± \\S+ m/s\\^2\\n")))
      << text["incline mu-from-slide"];
  EXPECT_TRUE(std::regex_search(text["bounce analyze"], std::regex("\\n +x +0\\.\\d+\\n"))) << text["bounce analyze"];  // r_squared.x
}

/// A series (several files) of each command that takes them ("command@variant" for a second one).
const std::map<std::string, SampleRun>& series_runs() {
  static const std::map<std::string, SampleRun> m = {
      {"incline analyze",  // one angle, three launch speeds: the stop relations (eqs 7-10)
       {"incline synth --mu 0.634 --phi-deg 20.96 --v0 2.0 --seed 3 --out {dir}/a.txt && "
        "incline synth --mu 0.634 --phi-deg 20.96 --v0 2.62 --seed 4 --out {dir}/b.txt && "
        "incline synth --mu 0.634 --phi-deg 20.96 --v0 2.3 --seed 5 --out {dir}/c.txt",
        [](const std::string& d, const json&) {
          return "incline analyze '" + d + "/a.txt' '" + d + "/b.txt' '" + d + "/c.txt' --phi-deg 20.96";
        }}},
      {"incline analyze@angles",  // three angles: the theta_c test (eq c') instead
       {"incline synth --mu 0.634 --phi-deg 15 --v0 2.0 --seed 3 --out {dir}/a.txt && "
        "incline synth --mu 0.634 --phi-deg 20.96 --v0 2.62 --seed 4 --out {dir}/b.txt && "
        "incline synth --mu 0.634 --phi-deg 25 --v0 2.3 --seed 5 --out {dir}/c.txt",
        [](const std::string& d, const json&) {
          return "incline analyze '" + d + "/a.txt' '" + d + "/b.txt' '" + d + "/c.txt' --phi-deg 15,20.96,25";
        }}},
      {"incline mu-from-slide",
       {"incline synth --mu 0.634 --phi-deg 41.09 --v0 0 --fps 240 --duration 0.7 --seed 41 --out {dir}/a.txt && "
        "incline synth --mu 0.634 --phi-deg 41.09 --v0 0 --fps 240 --duration 0.7 --seed 42 --out {dir}/b.txt",
        [](const std::string& d, const json&) { return "incline mu-from-slide '" + d + "/a.txt' '" + d + "/b.txt' --phi-deg 41.09"; }}},
      {"bounce analyze",
       {"bounce synth-video --height 0.7 --theta-deg 30 --seed 1 --out {dir}/a.txt && "
        "bounce synth-video --height 0.7 --theta-deg 60 --seed 2 --out {dir}/b.txt",
        [](const std::string& d, const json&) {
          return "bounce analyze '" + d + "/a.txt' '" + d + "/b.txt' --track-a A --track-b B --time-scale 0.125 --floor-y 0";
        }}},
      {"track video",  // the same throw rendered twice: one start fits both
       {"bounce render --size 160x120 --fps 100 --height 0.3 --after 0.05 --supersample 1 --out {dir}/a.avi && "
        "bounce render --size 160x120 --fps 100 --height 0.3 --after 0.05 --supersample 1 --out {dir}/b.avi",
        [](const std::string& d, const json& film) {
          return fmt::format("track video '{}/a.avi' '{}/b.avi' --ellipse ball={},{}@0 --scale {} --out '{}'", d, d,
                             film["ball_start_px"][0].get<double>(), film["ball_start_px"][1].get<double>(),
                             film["scale_m_per_px"].get<double>(), d);
        }}},
  };
  return m;
}

/// Runs `name`'s series in a fresh folder with `extra` arguments; its stdout.
std::string series_output(const std::string& name, const std::string& extra) {
  const RunResult out = run_tribolab(args_after_setup(series_runs().at(name), "schema_series_", name) + extra);
  EXPECT_EQ(out.exit_code, 0) << name << ": " << out.err;
  return out.out;
}

TEST(Schema, EveryKeyOfASeriesIsDeclared) {
  // The runs' rows carry the one-file command's keys, the summary the series' own: a summary
  // listed with units guessed from key names printed slopes in s^2/m and rms in s without unit.
  std::set<std::string> with_series, run;
  for (const json& c : schema()) {
    if (!c.contains("series_results")) continue;
    with_series.insert(c["command"]);
    ASSERT_TRUE(series_runs().count(c["command"])) << c["command"] << " has no series run in series_runs()";
  }
  for (const auto& [name, r] : series_runs()) {
    const std::string command = name.substr(0, name.find('@'));
    run.insert(command);
    const auto it = std::find_if(schema().begin(), schema().end(), [&](const json& c) { return c["command"] == command; });
    ASSERT_NE(it, schema().end()) << name;
    const json& c = *it;
    ASSERT_TRUE(c.contains("series_results")) << command << " takes several files but declares no summary keys";
    const json j = json::parse(series_output(name, " --json"));
    const app::ResultKeys rows = keys_of(c), summary = keys_of(c, "series_results");
    std::vector<std::string> paths;
    schema_leaves(j["runs"], "", paths);
    for (const std::string& p : paths) EXPECT_NE(app::find_result_key(rows, p), nullptr) << c["command"] << ": row key " << p;
    paths.clear();
    schema_leaves(j["summary"], "", paths);
    ASSERT_GE(paths.size(), 7u) << c["command"];
    for (const std::string& p : paths)
      EXPECT_NE(app::find_result_key(summary, p), nullptr) << c["command"] << ": summary key " << p << " is not declared";
  }
  EXPECT_EQ(with_series, run);
  EXPECT_EQ(with_series, (std::set<std::string>{"incline analyze", "incline mu-from-slide", "bounce analyze", "track video"}));
}

TEST(Schema, SeriesListingsPrintTheDeclaredUnits) {
  const std::string inc = series_output("incline analyze", "");
  // The table's header from the rows' keys, the summary's blocks from the series' keys.
  EXPECT_TRUE(std::regex_search(inc, std::regex("(^|\\n)file +phi_deg +mu +sigma_mu +v0 \\(m/s\\) +rms_residual \\(m\\) +verdict\\n")))
      << inc;
  EXPECT_TRUE(std::regex_search(inc, std::regex("\\n  t_stop_v0:\\n(    .*\\n)*?    rms +\\S+ s\\n"))) << inc;
  EXPECT_TRUE(std::regex_search(inc, std::regex("\\n  x_stop_v0sq:\\n(    .*\\n)*?    slope +\\S+ ± \\S+ s\\^2/m  \\(95 %"))) << inc;
  EXPECT_TRUE(std::regex_search(inc, std::regex("\\n  y_stop_x_stop:\\n(    .*\\n)*?    rms +\\S+ m\\n"))) << inc;
  EXPECT_TRUE(std::regex_search(inc, std::regex("\\n  y_stop_x_stop:\\n(    .*\\n)*?    slope +\\S+ ± \\S+  \\(95 %"))) << inc;
  EXPECT_TRUE(std::regex_search(inc, std::regex("\\nphi_deg +20.96 deg\\n"))) << inc;
  const std::string angles = series_output("incline analyze@angles", "");
  EXPECT_TRUE(std::regex_search(angles, std::regex("\\nphi_deg +none\\n"))) << angles;  // null: several angles
  EXPECT_TRUE(std::regex_search(angles, std::regex("\\ntheta_c_test:\\n(  .*\\n)*?  slope +\\S+ ± \\S+\\n"))) << angles;
  const std::string b = series_output("bounce analyze", "");
  EXPECT_TRUE(std::regex_search(b, std::regex("(^|\\n)file +collision_angle_deg +e_velocity +sigma_e_velocity +e_height +"
                                              "energy_pre \\(J\\) +energy_post \\(J\\) +mean_normal_force \\(N\\)\\n")))
      << b;
  EXPECT_TRUE(std::regex_search(b, std::regex("\\nmean_normal_force:\\n(  .*\\n)*?  sd +\\S+ N\\n"))) << b;
  EXPECT_TRUE(std::regex_search(b, std::regex("\\n    contact_point_speed +\\S+ m/s\\n"))) << b;
  EXPECT_TRUE(std::regex_search(b, std::regex("\\n    centre_deg +\\S+ deg\\n"))) << b;
  const std::string slide = series_output("incline mu-from-slide", "");
  EXPECT_TRUE(std::regex_search(slide, std::regex("(^|\\n)file +phi_deg +a \\(m/s\\^2\\) +sigma_a \\(m/s\\^2\\) +mu +sigma_mu +r_squared\\n")))
      << slide;
}

/// The cells of a Markdown table row "| a | b |" -> {"a", "b"} (an escaped \\| stays in its cell).
std::vector<std::string> table_cells(const std::string& row) {
  std::vector<std::string> cells;
  std::string cell;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') {
      cell += '|';
      ++i;
    } else if (row[i] == '|') {
      if (i > 0) {
        const auto b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
        cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
      }
      cell.clear();
    } else if (row[i] != '\n') {
      cell += row[i];
    }
  }
  return cells;
}

/// docs/cli.md's text from "### <command>" to the next heading of that level or above.
std::string docs_section(const std::string& doc, const std::string& heading) {
  const auto start = doc.find("\n" + heading + "\n");
  if (start == std::string::npos) return "";
  const auto end = doc.find("\n#", start + heading.size() + 2);
  return doc.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

TEST(Schema, DocsCliMdDocumentsEveryDeclaredFlagWithItsUnit) {
  const std::string doc = slurp(std::string(TRIBOLAB_SOURCE_DIR) + "/docs/cli.md");
  ASSERT_FALSE(doc.empty());
  for (const json& c : declared()) {
    const std::string name = c["command"];
    const std::string area = name.substr(0, name.find(' '));
    // A command of an area has its ### section, a command of its own (demo) its ## section.
    const std::string section = docs_section(doc, (name.find(' ') == std::string::npos ? "## " : "### ") + name);
    ASSERT_FALSE(section.empty()) << "docs/cli.md has no section for " << name;
    // Shared groups (ball, law options) are documented once, in the area's introduction.
    const std::string intro = docs_section(doc, "## " + area);
    for (const json& f : c["fields"]) {
      if (f["flag"].is_null() || f["role"] == "plotly" || f["role"] == "report") continue;  // #reports documents them
      const std::string flag = f["flag"];
      // The command's section, or for options its area shares (ball, contact law, --g) the
      // area's introduction.
      const std::regex mention("(^|[^\\w-])" + flag + "([^\\w-]|$)");
      const bool in_section = std::regex_search(section, mention);
      EXPECT_TRUE(in_section || std::regex_search(intro, mention))
          << "docs/cli.md: " << flag << " of " << name << " is not documented in ### " << name << " nor ## " << area;
      const std::string& where = in_section ? section : intro;
      // Where a table gives the option a unit, it is the declared one.
      std::smatch m;
      const std::regex row("\\n\\| `" + flag + "[ `][^|]*\\|([^\\n]*)\\n");
      if (!std::regex_search(where, m, row)) continue;
      const auto table = where.rfind("\n| option", m.position(0));
      if (table == std::string::npos) continue;
      const std::string header = where.substr(table + 1, where.find('\n', table + 1) - table - 1);
      const std::vector<std::string> cols = table_cells(header);
      std::vector<std::string> cells = table_cells(m[0].str().substr(1));
      for (std::size_t i = 0; i < cols.size() && i < cells.size(); ++i) {
        if (cols[i] != "unit") continue;
        if (cells[i] == "1") cells[i].clear();  // the incline tables write a pure number's unit as 1
        const std::string unit = f["unit"];
        EXPECT_EQ(cells[i].substr(0, unit.size()), unit) << "docs/cli.md " << flag << ": unit '" << cells[i] << "'";
        if (unit.empty()) {
          EXPECT_TRUE(cells[i].empty()) << "docs/cli.md " << flag << ": unit '" << cells[i] << "', declared none";
        }
      }
    }
  }
}

}  // namespace
}  // namespace tribolab::cli
