#include "series_cmd.hpp"

#include "app.hpp"
#include "text_listing.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>

#include <unistd.h>

namespace tribolab::cli {
namespace {

std::string cell(const nlohmann::json& v) {
  if (v.is_null()) return "-";
  if (v.is_number_float()) return fmt::format("{:.6g}", v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

}  // namespace

std::vector<std::string> per_file_values(const std::string& text, std::size_t n_files, const std::string& option) {
  if (text.empty()) return std::vector<std::string>(n_files);
  std::vector<std::string> values;
  for (const auto& v : io::split(text, ',')) values.emplace_back(io::trim(v));
  if (values.size() == 1) return std::vector<std::string>(n_files, values.front());
  if (values.size() != n_files)
    throw InputError(option, "gives " + std::to_string(values.size()) + " values for " + std::to_string(n_files) +
                                 (n_files == 1 ? " file" : " files") + " (give one value for all, or one per file)");
  return values;
}

analysis::SeriesOptions cli_series_options(const std::string& what) {
  analysis::SeriesOptions o;
  if (::isatty(STDERR_FILENO)) {
    o.progress = [what](const analysis::SeriesProgress& p) {
      std::cerr << fmt::format("\ranalysed {}/{} {}{}", p.done, p.total, what,
                               p.failed ? fmt::format(", {} failed", p.failed) : std::string());
      if (p.done == p.total) std::cerr << '\n';
      std::cerr.flush();
    };
  }
  return o;
}

void print_series(const nlohmann::json& raw_rows, const nlohmann::json& raw_summary, bool as_json,
                  const std::vector<std::string>& columns, const app::ResultKeys& row_keys,
                  const app::ResultKeys& summary_keys) {
  const nlohmann::json rows = spelled_for_cli(raw_rows), summary = spelled_for_cli(raw_summary);  // --floor-y
  // Each run's warnings on stderr with its file, whatever the output format; the summary's
  // own below (print_result, or here for --json).
  for (const auto& row : rows)
    if (row.is_object() && row.contains("warnings") && row["warnings"].is_array())
      for (const auto& w : row["warnings"])
        if (w.is_string())
          diagnostics() << "tribolab: warning: " << row.value("file", "") << ": " << one_line(w.get<std::string>()) << '\n';
  if (as_json) {
    if (summary.is_object() && summary.contains("warnings") && summary["warnings"].is_array())
      for (const auto& w : summary["warnings"])
        if (w.is_string()) diagnostics() << "tribolab: warning: " << one_line(w.get<std::string>()) << '\n';
    std::cout << nlohmann::json{{"runs", rows}, {"summary", summary}}.dump() << '\n';
    return;
  }
  std::vector<std::string> header{"file"};
  for (const auto& c : columns) {
    // "/normal_friction/verdict" is the declared key "normal_friction.verdict", shown as "verdict".
    std::string path = c.empty() || c[0] != '/' ? c : c.substr(1);
    std::replace(path.begin(), path.end(), '/', '.');
    const app::ResultKey* k = app::find_result_key(row_keys, path);
    header.push_back(column_label(path.substr(path.rfind('.') + 1), k ? k->unit : ""));
  }
  std::vector<std::vector<std::string>> table;
  for (const auto& row : rows) {
    std::vector<std::string> line{row.value("file", "")};
    if (row.contains("error")) {
      line.push_back("error: " + row["error"].get<std::string>());
    } else {
      for (const auto& c : columns) {
        const nlohmann::json::json_pointer ptr(c.empty() || c[0] != '/' ? "/" + c : c);
        line.push_back(row.contains(ptr) ? cell(row[ptr]) : "-");
      }
    }
    table.push_back(std::move(line));
  }
  std::vector<std::size_t> width(header.size(), 0);
  for (std::size_t k = 0; k < header.size(); ++k) width[k] = header[k].size();
  for (const auto& line : table)
    if (line.size() == header.size())
      for (std::size_t k = 0; k < line.size(); ++k) width[k] = std::max(width[k], line[k].size());
  auto print_line = [&](const std::vector<std::string>& line) {
    std::string out;
    for (std::size_t k = 0; k < line.size(); ++k) {
      const bool last = k + 1 == line.size();
      out += last ? line[k] : fmt::format("{:<{}}  ", line[k], width[k]);
    }
    std::cout << out << '\n';
  };
  print_line(header);
  for (const auto& line : table) print_line(line);
  std::cout << "\nsummary\n";
  print_result(summary, false, summary_keys);
}

void finish_series(std::size_t n_runs, const std::vector<std::string>& errors) {
  if (errors.empty()) return;
  std::string msg = std::to_string(errors.size()) + " of " + std::to_string(n_runs) + " runs failed (" +
                    errors.front() + (errors.size() > 1 ? "; ..." : "") + "); the others' results are printed";
  throw InputError(msg);
}

}  // namespace tribolab::cli
