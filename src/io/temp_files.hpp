// Temporary files that a signal must not leave behind: AtomicFile's `.OUT.tmpPID`, a video
// being rendered, a video extracted from a .trz. Each is registered while it exists; on
// SIGINT, SIGTERM or SIGHUP the command line's handler (install_temp_cleanup_on_signals)
// unlinks every registered path, then dies of the signal as it would have.
#pragma once

#include <string>

namespace tribolab::io {

/// Registers `path` (copied) for removal on a signal, until the object is destroyed. A path
/// longer than 4095 bytes, or more than 64 at once, is not registered (kept on a signal).
class TempRegistration {
 public:
  explicit TempRegistration(const std::string& path);
  TempRegistration(const TempRegistration&) = delete;
  TempRegistration& operator=(const TempRegistration&) = delete;
  ~TempRegistration();

 private:
  int slot_ = -1;
};

/// Unlinks every registered path. Async-signal-safe (only atomics and unlink()).
void remove_registered_temps() noexcept;

/// SIGINT, SIGTERM, SIGHUP: remove_registered_temps(), then the default action of the signal
/// (the exit status still says which signal ended the process). For the command line; a
/// handler installed later (bounce sweep's) calls remove_registered_temps() itself.
void install_temp_cleanup_on_signals();

}  // namespace tribolab::io
