// What the report writer carries inside the tribolab binary: the Plotly.js library, copied
// from report/vendor/node_modules at compile time (embed_plotly.cmake), so the program writes
// complete offline reports anywhere, without the source tree or a network.
#pragma once

#include <string_view>

namespace tribolab::report {

/// The minified Plotly.js source (Plotly's cartesian partial bundle, about 1.5 MB), exactly as
/// vendored by `npm ci`.
std::string_view plotly_js();

/// Plotly.js version, from the vendored package.json (e.g. "4.1.1").
std::string_view plotly_version();

/// The npm package vendored ("plotly.js-cartesian-dist-min") and its file ("plotly-cartesian.min.js").
std::string_view plotly_package();
std::string_view plotly_package_file();

/// SHA-384 of plotly_js() as 96 lower-case hex digits, computed by CMake from the vendored
/// file (embed_plotly.cmake); the integrity attribute of the `cdn` mode (PlotlyMode) is made from it.
std::string_view plotly_sha384_hex();

/// tribolab version (the CMake project version, e.g. "0.1.0").
std::string_view tribolab_version();

}  // namespace tribolab::report
