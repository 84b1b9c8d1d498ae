// The options of `tribolab studio` and their declaration (app/common/option_fields.hpp): the
// command line binds from it and `tribolab schema` lists it; the studio is a server for a
// browser page, not a Python function (python/tests/test_schema.py, NOT_IN_PYTHON). The server
// itself is studio::Server (server.hpp), its requests studio::Handler (handler.hpp).
#pragma once

#include "app/common/option_fields.hpp"

#include <string>

namespace tribolab::studio {

struct StudioOptions {
  std::string file_or_folder = ".";  ///< folder served, or a video or project in it (opened at start)
  int port = 0;              ///< port on 127.0.0.1; 0 = a free one
  bool open = false;         ///< open the page in the desktop's browser
};

/// The TCP ports a user may ask for (0: the system picks a free one).
inline constexpr PhysicalRange kPortRange{0, 65535, ""};

inline const app::Fields<StudioOptions>& studio_fields() {
  using O = StudioOptions;
  static const app::Fields<O> f = [] {
    app::Fields<O> d;
    d.add("file_or_folder", &O::file_or_folder, "",
          "folder served (every file read or written is inside it), or a video or project in it, opened at "
          "start (when not given: the current folder)")
        .as(app::FieldRole::input_files);
    d.add("port", &O::port, "", "port on 127.0.0.1 (when not given: a free one)").in(kPortRange);
    d.add("open", &O::open, "", "open the page in the desktop's browser (xdg-open)");
    return d;
  }();
  return f;
}

/// The studio prints its URL and serves; it has no result to list.
inline const app::ResultKeys& studio_result_keys() {
  static const app::ResultKeys keys;
  return keys;
}

}  // namespace tribolab::studio
