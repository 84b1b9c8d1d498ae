// libFuzzer target: any bytes as a .trz file through tribolab::io::parse_tracks.
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return tribolab::fuzz::run(data, size, "fuzz.trz");
}
