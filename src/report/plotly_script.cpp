#include "report/plotly_script.hpp"

#include "io/atomic_file.hpp"
#include "numerics/error.hpp"
#include "report/embedded.hpp"
#include "report/format.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace tribolab::report {

std::string_view to_string(PlotlyMode mode) {
  switch (mode) {
    case PlotlyMode::embed: return "embed";
    case PlotlyMode::cdn: return "cdn";
    case PlotlyMode::file: return "file";
  }
  return "embed";
}

PlotlyMode parse_plotly_mode(std::string_view text) {
  for (PlotlyMode m : {PlotlyMode::embed, PlotlyMode::cdn, PlotlyMode::file}) {
    if (text == to_string(m)) return m;
  }
  throw InputError(field("plotly"), "'" + std::string(text) + "' is not one of embed, cdn, file");
}

std::string plotly_file_name() { return "plotly-" + std::string(plotly_version()) + ".min.js"; }

std::string plotly_cdn_url() {
  return "https://cdn.jsdelivr.net/npm/" + std::string(plotly_package()) + "@" + std::string(plotly_version()) + "/" +
         std::string(plotly_package_file());
}

std::string plotly_integrity() {
  const std::string_view hex = plotly_sha384_hex();
  if (hex.size() != 96) throw std::logic_error("the build's SHA-384 of Plotly.js is not 96 hex digits");
  auto nibble = [](char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    throw std::logic_error("the build's SHA-384 of Plotly.js is not hex");
  };
  std::string bytes;
  for (std::size_t i = 0; i < hex.size(); i += 2) bytes += static_cast<char>(nibble(hex[i]) * 16 + nibble(hex[i + 1]));
  return "sha384-" + base64(bytes);
}

std::string write_plotly_script(const std::string& dir) {
  namespace fs = std::filesystem;
  const std::string path = (fs::path(dir.empty() ? "." : dir) / plotly_file_name()).string();
  const std::string_view js = plotly_js();
  std::error_code ec;
  if (fs::file_size(path, ec) == js.size() && !ec) {
    std::ifstream in(path, std::ios::binary);
    const std::string have((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (have == js) return path;  // already there: not rewritten (its time stamp stays)
  }
  io::AtomicFile file(path);
  file.stream().write(js.data(), static_cast<std::streamsize>(js.size()));
  file.commit();
  return path;
}

}  // namespace tribolab::report
