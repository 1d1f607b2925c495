// sampled_delay_line.h: the delay line of a sampled-data controller, as the "regulator"
// valve model's loop uses it with [regulator] feedback = "delayed" (pneumatics.h): the
// controller samples its sensed pressures at t_k = t0 + k T (T the sample period) and acts
// on sample k at t_k + D (D the dead time), holding it until sample k + 1 acts. Why not a
// continuous delay p(t - D): see SampledDelayLine.
#pragma once

#include <deque>
#include <vector>

namespace pamsim {

// Why a sampled-data line and not a continuous delay p(t - D): between two moments the
// loop's input is constant, so the ODE the integrator sees is smooth on each interval and
// CVODE's error control holds unchanged; PneumaticSystem splits its intervals at the
// moments (as it does for delayed commands) and every value acts at an exact, deterministic
// time. A continuous delay p(t - D) would need the past solution's interpolant, kept by
// us (CVodeGetDky reaches only the last internal step), and a delay shorter than a step
// makes the step's right-hand side depend on its own unknown solution: a method-of-steps
// scheme whose interpolation error CVODE's error test never sees. It is also the hardware: an
// ITV-class regulator's control circuit reads its pressure sensor and drives its pilot solenoid
// valves digitally (SMC ITV manual, working principle); as T -> 0 and D -> 0 the line becomes the
// instant loop (tested).
class SampledDelayLine {
 public:
  // `initial` is the sample taken at t0_s and the value held until it acts.
  // period_s > 0, delay_s >= 0 (asserted; PneumaticParams validates the keys).
  SampledDelayLine(double t0_s, double period_s, double delay_s, std::vector<double> initial);

  double next_sample_s() const;  // when the next sample is due
  double next_action_s() const;  // when the oldest pending sample acts; +inf if none
  double next_event_s() const;   // the earlier of the two

  // the sample due at next_sample_s(), one value per channel; it acts `delay` later
  void take_sample(std::vector<double> values);
  // the oldest pending sample becomes the held one (at next_action_s()); returns whether
  // any held value changed
  bool act();
  const std::vector<double>& held() const { return held_; }

 private:
  struct Sample {
    double act_s;
    std::vector<double> values;
  };
  double t0_s_;
  double period_s_;
  double delay_s_;
  long next_k_ = 0;  // index of the next sample (t_k = t0 + k T, not accumulated)
  std::deque<Sample> pending_;
  std::vector<double> held_;
};

}  // namespace pamsim
