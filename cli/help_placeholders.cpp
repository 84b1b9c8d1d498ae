#include "help_placeholders.hpp"

#include <cctype>
#include <regex>
#include <string>

namespace tribolab::cli {
namespace {

/// An option whose value is a file to write or read: its help says so in its first words
/// ("Write ... to this CSV", "Output CSV", "CSV with columns ...") or its name is an output.
bool names_a_file(const CLI::Option& opt) {
  std::string d = opt.get_description();
  for (char& c : d) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* start : {"write", "also write", "output", "csv", "merged output"}) {
    if (d.rfind(start, 0) == 0) return true;
  }
  if (d.find("to this csv") != std::string::npos || d.find("to this file") != std::string::npos) return true;
  const std::string n = opt.get_name(false, true);
  return n == "--out" || (n.size() > 4 && n.compare(n.size() - 4, 4, "-out") == 0);
}

/// "hooke|hertz|hunt-crossley" from a description such as "normal law: hooke|hertz|... (default x)".
std::string listed_choices(const std::string& description) {
  static const std::regex choices(R"(([a-z][a-z0-9_-]*(?:\|[a-z][a-z0-9_-]*)+))");
  std::smatch m;
  if (!std::regex_search(description, m, choices)) return {};
  return m.str(1).size() <= 48 ? m.str(1) : "NAME";  // too many to list: see the help text
}

/// The help shows each option's default as CLI11 captured it from the option struct
/// (`--g NUM=9.8`), so no help text repeats a default by hand. A required option has no
/// default to show, nor has an empty list or an empty text (an output not written), nor a
/// non-finite number: NaN or an infinity is the struct's "not given" (`--pivot-x`, `--from`),
/// which the help text says in words ("when not given: ...").
void tidy_default(CLI::Option& opt) {
  const std::string d = opt.get_default_str();
  const bool not_given = d == "nan" || d == "-nan" || d == "inf" || d == "-inf";
  if (opt.get_required() || d == "[]" || d == "\"\"" || not_given) opt.default_str("");
}

void tidy(CLI::Option& opt) {
  tidy_default(opt);
  const std::string type = opt.get_type_name();
  if (opt.get_positional() && !opt.nonpositional()) {
    // "FILE FILE ..." or "files TEXT ...": the name says it; keep only the repetition.
    opt.type_name("");
    return;
  }
  if (type == "FLOAT") {
    // a list split at commas (add_number on a vector): one value, or several
    opt.type_name(opt.get_delimiter() == ',' ? "NUM[,NUM...]" : "NUM");
  } else if (type == "UINT") {
    opt.type_name("INT");
  } else if (type == "TEXT") {
    const std::string d = opt.get_description();
    if (d.find("NAME=VALUE") != std::string::npos) {
      opt.type_name("NAME=VALUE");
    } else if (d.find("i of N") != std::string::npos) {
      opt.type_name("I/N");
    } else if (d.find("lo:hi:count") != std::string::npos) {
      opt.type_name("LO:HI:N");
    } else if (std::string c = listed_choices(d); !c.empty()) {
      opt.type_name(c);
    } else if (names_a_file(opt)) {
      opt.type_name("FILE");
    } else if (d.find("name") != std::string::npos || d.rfind("Track", 0) == 0 || d.rfind("track ", 0) == 0 ||
               d.find("this track") != std::string::npos || d.find(".trk inside") != std::string::npos) {
      opt.type_name("NAME");
    } else if (d.find("comma separated") != std::string::npos) {
      opt.type_name("NUM[,NUM...]");
    } else if (d.find("Unit of") != std::string::npos || d.find("unit of") != std::string::npos) {
      opt.type_name("UNIT");
    }
  }
}

}  // namespace

void tidy_placeholders(CLI::App& app) {
  for (CLI::Option* opt : app.get_options()) tidy(*opt);
  for (CLI::App* sub : app.get_subcommands({})) tidy_placeholders(*sub);
}

}  // namespace tribolab::cli
