// sampled_delay_line.cc: SampledDelayLine (see the header).
#include "pneumatics/sampled_delay_line.h"

#include <algorithm>
#include <cassert>
#include <limits>
#include <utility>

namespace pamsim {

SampledDelayLine::SampledDelayLine(double t0_s, double period_s, double delay_s,
                                   std::vector<double> initial)
    : t0_s_(t0_s), period_s_(period_s), delay_s_(delay_s), held_(initial) {
  assert(period_s > 0.0 && delay_s >= 0.0);
  take_sample(std::move(initial));
}

double SampledDelayLine::next_sample_s() const {
  return t0_s_ + static_cast<double>(next_k_) * period_s_;
}

double SampledDelayLine::next_action_s() const {
  return pending_.empty() ? std::numeric_limits<double>::infinity() : pending_.front().act_s;
}

double SampledDelayLine::next_event_s() const { return std::min(next_sample_s(), next_action_s()); }

void SampledDelayLine::take_sample(std::vector<double> values) {
  assert(values.size() == held_.size());
  pending_.push_back({next_sample_s() + delay_s_, std::move(values)});
  ++next_k_;
}

bool SampledDelayLine::act() {
  assert(!pending_.empty());
  const bool changed = pending_.front().values != held_;
  held_ = std::move(pending_.front().values);
  pending_.pop_front();
  return changed;
}

}  // namespace pamsim
