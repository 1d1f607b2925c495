// stop_signal.h: SIGINT / SIGTERM as a request to stop a long job (sweep, tune) cleanly:
// work in flight finishes and is stored, nothing new starts, and the command then exits
// with the shell's code for the signal (128 + its number). The handler is one-shot
// (SA_RESETHAND): a second Ctrl-C kills the process at once, which loses nothing stored.
#pragma once

#include <signal.h>

#include <atomic>

namespace pamsim {

// Set by the handler while a StopOnSignal is alive.
std::atomic<bool>& stop_requested();
// The signal that asked, 0 if none.
int stop_signal();

class StopOnSignal {
 public:
  StopOnSignal();
  ~StopOnSignal();
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

}  // namespace pamsim
