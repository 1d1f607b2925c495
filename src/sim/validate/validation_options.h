// validation_options.h: what both validation protocols (length_estimation.h, reaching.h) take
// from the command line, and their common result cell: an error in % of length.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pamsim {

// A cell of Table III or V: maximum and RMS error in % of the length.
struct ErrorPct {
  double max_pct = 0.0;
  double rmse_pct = 0.0;
};

struct ValidationOptions {
  std::string out_dir;                 // created if missing
  std::vector<std::string> overrides;  // the user's --set, scenario keys of every trial
  std::optional<std::uint64_t> seed;   // tensile noise and trial seed; default: files'
  int threads = 1;
  bool assumptions = false;  // --assumptions: bands and sensitivity draw assumption brackets too
  std::function<void(int total)> started;             // inputs checked, trials about to run
  std::function<void(int done, int total)> progress;  // called from one thread at a time
};

}  // namespace pamsim
