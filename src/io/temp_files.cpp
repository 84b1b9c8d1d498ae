#include "io/temp_files.hpp"

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

#include <signal.h>
#include <unistd.h>

namespace tribolab::io {
namespace {

constexpr int kSlots = 64;
constexpr std::size_t kMaxPath = 4096;

/// A slot is claimed (state 1) while its path is copied, published (state 2) once the
/// handler may read it, and freed (0) by the destructor after unpublishing.
struct Slot {
  std::atomic<int> state{0};
  char path[kMaxPath] = {};
};
static_assert(std::atomic<int>::is_always_lock_free);

std::array<Slot, kSlots> g_slots;

extern "C" void cleanup_and_die(int sig) {
  remove_registered_temps();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

TempRegistration::TempRegistration(const std::string& path) {
  if (path.size() >= kMaxPath) return;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (g_slots[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
      g_slots[i].state.store(2, std::memory_order_release);
      slot_ = i;
      return;
    }
  }
}

TempRegistration::~TempRegistration() {
  if (slot_ >= 0) g_slots[slot_].state.store(0, std::memory_order_release);
}

void remove_registered_temps() noexcept {
  for (Slot& s : g_slots) {
    if (s.state.load(std::memory_order_acquire) == 2) ::unlink(s.path);
  }
}

void install_temp_cleanup_on_signals() {
  struct sigaction sa {};
  sa.sa_handler = cleanup_and_die;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    // A signal the caller ignores (nohup, a shell's background job) stays ignored.
    if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    sigaction(sig, &sa, nullptr);
  }
}

}  // namespace tribolab::io
