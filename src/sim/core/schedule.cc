// schedule.cc: see schedule.h.
#include "sim/core/schedule.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <utility>

#include "base/input_error.h"
#include "base/units.h"

namespace pamsim {
namespace {

constexpr double kTwoPi = 2.0 * units::kPi;

std::string mpa_text(double pa) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.6g", units::pa_to_mpa(pa));
  return buf;
}

// index of the last time <= t, or -1 before the first
long segment(const std::vector<double>& times, double t) {
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  return static_cast<long>(it - times.begin()) - 1;
}

}  // namespace

const char* to_string(ScheduleKind kind) {
  switch (kind) {
    case ScheduleKind::kConstant:
      return "constant";
    case ScheduleKind::kRamp:
      return "ramp";
    case ScheduleKind::kSine:
      return "sine";
    case ScheduleKind::kSteps:
      return "steps";
    case ScheduleKind::kTable:
      return "table";
  }
  return "?";
}

const std::vector<ScheduleKind>& schedule_kinds() {
  static const std::vector<ScheduleKind> kinds = {ScheduleKind::kConstant, ScheduleKind::kRamp,
                                                  ScheduleKind::kSine, ScheduleKind::kSteps,
                                                  ScheduleKind::kTable};
  return kinds;
}

ScheduleKind parse_schedule_kind(const std::string& name, const std::string& key) {
  for (ScheduleKind k : schedule_kinds()) {
    if (name == to_string(k)) return k;
  }
  throw InputError(key +
                   " must be one of \"constant\", \"ramp\", \"sine\", \"steps\", "
                   "\"table\", got \"" +
                   name + "\"");
}

double PressureSchedule::at(double t) const {
  switch (kind) {
    case ScheduleKind::kConstant:
      return p0_pa;
    case ScheduleKind::kRamp: {
      const double s = std::clamp((t - start_s) / duration_s, 0.0, 1.0);
      return p0_pa + (p1_pa - p0_pa) * s;
    }
    case ScheduleKind::kSine:
      if (t < start_s) return p0_pa;
      return p0_pa + amplitude_pa * std::sin(kTwoPi * (t - start_s) / period_s + phase_rad);
    case ScheduleKind::kSteps: {
      const long i = segment(times_s, t);
      return values_pa[i < 0 ? 0 : static_cast<std::size_t>(i)];
    }
    case ScheduleKind::kTable: {
      const long i = segment(times_s, hold ? t + kHoldToleranceS : t);
      if (i < 0) return values_pa.front();
      if (hold) return values_pa[static_cast<std::size_t>(i)];
      const std::size_t k = static_cast<std::size_t>(i);
      if (k + 1 >= times_s.size()) return values_pa.back();
      const double w = (t - times_s[k]) / (times_s[k + 1] - times_s[k]);
      return values_pa[k] + (values_pa[k + 1] - values_pa[k]) * w;
    }
  }
  return p0_pa;
}

double PressureSchedule::min_pa() const {
  switch (kind) {
    case ScheduleKind::kRamp:
      return std::min(p0_pa, p1_pa);
    case ScheduleKind::kSine:
      return std::min(p0_pa, p0_pa - std::fabs(amplitude_pa));
    case ScheduleKind::kSteps:
    case ScheduleKind::kTable:
      return *std::min_element(values_pa.begin(), values_pa.end());
    default:
      return p0_pa;
  }
}

double PressureSchedule::max_pa() const {
  switch (kind) {
    case ScheduleKind::kRamp:
      return std::max(p0_pa, p1_pa);
    case ScheduleKind::kSine:
      return std::max(p0_pa, p0_pa + std::fabs(amplitude_pa));
    case ScheduleKind::kSteps:
    case ScheduleKind::kTable:
      return *std::max_element(values_pa.begin(), values_pa.end());
    default:
      return p0_pa;
  }
}

PressureSchedule table_schedule(std::vector<double> times_s, std::vector<double> values_pa,
                                std::string source) {
  assert(!times_s.empty() && times_s.size() == values_pa.size());
  PressureSchedule s;
  s.kind = ScheduleKind::kTable;
  s.source = std::move(source);
  s.times_s = std::move(times_s);
  s.values_pa = std::move(values_pa);
  s.p0_pa = s.values_pa.front();
  return s;
}

void validate(const PressureSchedule& s, const std::string& key, double max_pa) {
  auto fail = [&](const std::string& field, const std::string& problem) {
    const std::string where = key + (field.empty() ? "" : "." + field);
    throw InputError(where + " " + problem, {"", where, problem});
  };
  for (double v :
       {s.p0_pa, s.p1_pa, s.amplitude_pa, s.period_s, s.phase_rad, s.start_s, s.duration_s}) {
    if (!std::isfinite(v)) fail("", "must have finite values");
  }
  if (s.kind == ScheduleKind::kSine && !(s.period_s > 0)) fail("period_s", "must be > 0");
  if (s.kind == ScheduleKind::kRamp && !(s.duration_s > 0)) fail("duration_s", "must be > 0");
  if (s.kind == ScheduleKind::kSteps || s.kind == ScheduleKind::kTable) {
    if (s.times_s.empty() || s.times_s.size() != s.values_pa.size()) {
      fail(s.kind == ScheduleKind::kSteps ? "times_s" : "file",
           "must give one pressure per time, at least one");
    }
    for (std::size_t i = 1; i < s.times_s.size(); ++i) {
      if (!(s.times_s[i] > s.times_s[i - 1])) fail("times_s", "must increase strictly");
    }
  }
  if (!(s.min_pa() >= 0.0 && s.max_pa() <= max_pa)) {
    fail("", "must stay within [0, " + mpa_text(max_pa) + "] MPa (the valve's range), goes from " +
                 mpa_text(s.min_pa()) + " to " + mpa_text(s.max_pa()) + " MPa");
  }
}

}  // namespace pamsim
