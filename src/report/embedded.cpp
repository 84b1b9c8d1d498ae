#include "report/embedded.hpp"

// The build defines these from report/vendor (see src/report/embed_plotly.cmake).
#if !defined(TRIBOLAB_PLOTLY_JS_PATH) || !defined(TRIBOLAB_PLOTLY_VERSION) || \
    !defined(TRIBOLAB_PLOTLY_SHA384) || !defined(TRIBOLAB_PLOTLY_PACKAGE) || !defined(TRIBOLAB_PLOTLY_FILE) || \
    !defined(TRIBOLAB_VERSION)
#error "build through CMake: src/report/embed_plotly.cmake defines the vendored Plotly.js path"
#endif

// The assembler copies the file into read-only data: no 1.5 MB C array for the compiler to
// parse, and the build re-runs when the file changes (OBJECT_DEPENDS in CMake).
asm(".section .rodata\n"
    ".balign 16\n"
    ".globl tribolab_plotly_js_begin\n"
    ".hidden tribolab_plotly_js_begin\n"
    "tribolab_plotly_js_begin:\n"
    ".incbin \"" TRIBOLAB_PLOTLY_JS_PATH "\"\n"
    ".globl tribolab_plotly_js_end\n"
    ".hidden tribolab_plotly_js_end\n"
    "tribolab_plotly_js_end:\n"
    ".byte 0\n"
    ".previous\n");

extern "C" const char tribolab_plotly_js_begin[];
extern "C" const char tribolab_plotly_js_end[];

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
