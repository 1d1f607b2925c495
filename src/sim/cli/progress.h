// progress.h: progress of a long job on stderr. On a terminal, one bar redrawn in place
// ("[#####.....]  1234/2000  61.7%  93.1 trials/s  ETA 0:08"), at most ten times a second;
// otherwise (a log file, CI) a plain line every 10 % or 30 s, whichever comes first; with
// --quiet, nothing. The rate counts only this run's work (a resumed job's earlier trials are
// not in it).
#pragma once

#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>

namespace pamsim {

enum class ProgressStyle { kTerminal, kLog, kQuiet };

// kQuiet with --quiet, else kTerminal when stderr is a terminal, else kLog.
ProgressStyle progress_style(bool quiet);

class ProgressReporter {
 public:
  // `unit` names what is counted in the rate ("trials/s", "evaluations/s").
  ProgressReporter(std::string label, std::int64_t total, std::int64_t already_done,
                   std::ostream& out, ProgressStyle style, std::string unit = "trials");
  void update(std::int64_t done);  // throttled
  void finish(std::int64_t done);  // always prints the last state

 private:
  void print(std::int64_t done, bool last);

  std::string label_;
  std::string unit_;
  std::int64_t total_;
  std::int64_t already_done_;
  std::ostream& out_;
  ProgressStyle style_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  std::int64_t last_done_printed_;
};

// "1:02:03" or "2:03" for a duration in seconds; "--:--" if not finite.
std::string format_duration(double seconds);

}  // namespace pamsim
