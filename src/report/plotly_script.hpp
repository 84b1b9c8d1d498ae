// How a report gets Plotly.js (the field `plotly`: embed|cdn|file, docs/cli.md#plotly-in-reports):
//
//   embed  the library inside the page (about 4.8 MB): one file that works offline (default);
//   cdn    a <script src> to the same pinned version on jsDelivr, with a sha384 integrity
//          attribute made from the embedded copy: small pages that need the network;
//   file   plotly-<version>.min.js written once beside the report(s) and read through a
//          relative link: a series of reports shares one copy and stays offline.
#pragma once

#include <string>
#include <string_view>

namespace tribolab::report {

enum class PlotlyMode { embed, cdn, file };

/// "embed", "cdn" or "file".
std::string_view to_string(PlotlyMode mode);

/// The mode named `text` ("embed", "cdn", "file"); InputError naming the field `plotly` otherwise.
PlotlyMode parse_plotly_mode(std::string_view text);

/// "plotly-<version>.min.js", the name of the shared script of the `file` mode.
std::string plotly_file_name();

/// The pinned URL of the `cdn` mode: jsDelivr's copy of the npm package the build embeds
/// (plotly.js-dist-min@<version>/plotly.min.js), byte for byte the vendored file.
std::string plotly_cdn_url();

/// The subresource-integrity value of the embedded copy: "sha384-" + base64 of its SHA-384.
std::string plotly_integrity();

/// Writes plotly_file_name() into folder `dir` (atomically) unless a file with exactly the
/// embedded bytes is already there; returns its path. InputError naming the path on failure.
std::string write_plotly_script(const std::string& dir);

}  // namespace tribolab::report
