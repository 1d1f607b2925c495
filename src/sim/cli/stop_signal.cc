// stop_signal.cc: see stop_signal.h.
#include "sim/cli/stop_signal.h"

namespace pamsim {
namespace {

std::atomic<bool> g_stop_requested{false};
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "set from a signal handler");

extern "C" void request_stop(int signal_number) {
  g_stop_signal = signal_number;
  g_stop_requested = true;
}

}  // namespace

std::atomic<bool>& stop_requested() { return g_stop_requested; }
int stop_signal() { return g_stop_signal.load(); }

StopOnSignal::StopOnSignal() {
  g_stop_requested = false;
  g_stop_signal = 0;
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, &old_int_);
  sigaction(SIGTERM, &action, &old_term_);
}

StopOnSignal::~StopOnSignal() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
}

}  // namespace pamsim
