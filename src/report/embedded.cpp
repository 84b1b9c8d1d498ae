#include "report/embedded.hpp"
#include "report/incbin.hpp"

// The build defines these from report/vendor (see src/report/embed_plotly.cmake).
#if !defined(TRIBOLAB_PLOTLY_JS_PATH) || !defined(TRIBOLAB_PLOTLY_VERSION) || \
    !defined(TRIBOLAB_PLOTLY_SHA384) || !defined(TRIBOLAB_PLOTLY_PACKAGE) || !defined(TRIBOLAB_PLOTLY_FILE) || \
    !defined(TRIBOLAB_VERSION)
#error "build through CMake: src/report/embed_plotly.cmake defines the vendored Plotly.js path"
#endif

// The assembler copies the file into read-only data; the build re-runs when the file changes
// (OBJECT_DEPENDS in CMake).
TRIBOLAB_INCBIN(tribolab_plotly_js, TRIBOLAB_PLOTLY_JS_PATH);

namespace tribolab::report {

std::string_view plotly_js() {
  return {tribolab_plotly_js_begin,
          static_cast<std::size_t>(tribolab_plotly_js_end - tribolab_plotly_js_begin)};
}

std::string_view plotly_version() { return TRIBOLAB_PLOTLY_VERSION; }

std::string_view plotly_sha384_hex() { return TRIBOLAB_PLOTLY_SHA384; }

std::string_view plotly_package() { return TRIBOLAB_PLOTLY_PACKAGE; }

std::string_view plotly_package_file() { return TRIBOLAB_PLOTLY_FILE; }

std::string_view tribolab_version() { return TRIBOLAB_VERSION; }

}  // namespace tribolab::report
