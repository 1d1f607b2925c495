// progress.cc: see progress.h.
#include "sim/cli/progress.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace pamsim {
namespace {

constexpr int kBarWidth = 30;
constexpr double kTerminalPeriodS = 0.1;
constexpr double kLogPeriodS = 30.0;
constexpr double kLogFraction = 0.1;

}  // namespace

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--";
  const long s = std::lround(seconds);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof(buf), "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof(buf), "%ld:%02ld", s / 60, s % 60);
  return buf;
}

ProgressStyle progress_style(bool quiet) {
  if (quiet) return ProgressStyle::kQuiet;
  return ::isatty(STDERR_FILENO) != 0 ? ProgressStyle::kTerminal : ProgressStyle::kLog;
}

ProgressReporter::ProgressReporter(std::string label, std::int64_t total, std::int64_t already_done,
                                   std::ostream& out, ProgressStyle style, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      already_done_(already_done),
      out_(out),
      style_(style),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_),
      last_done_printed_(already_done) {}

void ProgressReporter::update(std::int64_t done) {
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (style_ == ProgressStyle::kQuiet) return;
  if (style_ == ProgressStyle::kTerminal) {
    if (since >= kTerminalPeriodS) print(done, false);
    return;
  }
  const auto step = static_cast<std::int64_t>(std::ceil(kLogFraction * total_));
  if (since >= kLogPeriodS || done - last_done_printed_ >= step) {
    print(done, false);
  }
}

void ProgressReporter::finish(std::int64_t done) {
  if (style_ == ProgressStyle::kQuiet) return;
  if (style_ == ProgressStyle::kTerminal || done != last_done_printed_) print(done, true);
}

void ProgressReporter::print(std::int64_t done, bool last) {
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? (done - already_done_) / elapsed : NAN;
  const double eta = rate > 0 ? (total_ - done) / rate : NAN;
  const double fraction = total_ > 0 ? static_cast<double>(done) / total_ : 1.0;
  char numbers[160];
  std::snprintf(numbers, sizeof(numbers), "%lld/%lld  %5.1f%%  %.1f %s/s  %s %s",
                static_cast<long long>(done), static_cast<long long>(total_), 100.0 * fraction,
                std::isfinite(rate) ? rate : 0.0, unit_.c_str(), last ? "elapsed" : "ETA",
                format_duration(last ? elapsed : eta).c_str());
  if (style_ == ProgressStyle::kTerminal) {
    const int filled = static_cast<int>(fraction * kBarWidth);
    out_ << "\r" << label_ << " [" << std::string(filled, '#')
         << std::string(kBarWidth - filled, '.') << "]  " << numbers << "\x1b[K"
         << (last ? "\n" : "") << std::flush;
  } else {
    out_ << label_ << ": " << numbers << "\n" << std::flush;
  }
  last_print_ = now;
  last_done_printed_ = done;
}

}  // namespace pamsim
