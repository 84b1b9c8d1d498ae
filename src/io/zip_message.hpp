// The text of a libzip error, shared by the .trz reader and writer.
#pragma once

#include <zip.h>

#include <string>

namespace tribolab::io {

/// libzip's message for `e`, which is released (zip_error_fini) after reading it.
inline std::string zip_message(zip_error_t* e) {
  std::string m = zip_error_strerror(e);
  zip_error_fini(e);
  return m;
}

}  // namespace tribolab::io
