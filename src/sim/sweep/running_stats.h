// running_stats.h: Welford's running mean and variance of a metric, with its range, as a
// sweep's reports accumulate them (per point over its seeds, per heat-map cell over points).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/sweep/report.h"  // MetricStats

namespace pamsim {

// Welford's running mean and variance, with the range.
struct Accumulator {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  int n = 0;
  double mean = 0, m2 = 0, min = kNaN, max = kNaN;
  void add(double v) {
    ++n;
    const double delta = v - mean;
    mean += delta / n;
    m2 += delta * (v - mean);
    min = n == 1 ? v : std::min(min, v);
    max = n == 1 ? v : std::max(max, v);
  }
  MetricStats stats() const {
    MetricStats s;
    s.count = n;
    s.mean = n ? mean : kNaN;
    s.std = n > 1 ? std::sqrt(m2 / (n - 1)) : kNaN;
    s.min = min;
    s.max = max;
    return s;
  }
};

}  // namespace pamsim
