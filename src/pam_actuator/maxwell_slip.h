// maxwell_slip.h: rate-independent hysteresis with memory, as the Maxwell-slip model (Iwan's
// parallel spring-slider elements; Lampaert, Al-Bender & Swevers, IEEE PhysCon 2003, give its
// rate-dependent generalization, not modelled here; used for the hysteresis of PAMs by
// Vo-Minh et al., IEEE/ASME Trans. Mechatronics 16(1), 2011, and, with different slip forces
// in the two directions, by Capace et al., Actuators 8(2), 49, 2019): elements, each a linear
// spring in series with a Coulomb block that slips once its spring holds its slip force. The
// model sticks (a small reversal is elastic, no energy lost), slips beyond the band, and
// remembers where in the loop it rests: what the smooth tanh(v / v_s) friction of
// avbdl_friction.cc cannot do.
#pragma once

#include <array>
#include <string>

namespace pamsim {

inline constexpr int kMaxSlipElements = 4;

// Element i is given by its share w_i of the total slip force (sum w_i = 1) and its
// breakaway travel delta_i, the travel over which its spring takes up its share. Its state
// is the normalised deflection s_i = z_i / delta_i in [-1, 1]. With a total slip force F_up
// for positive deflection and F_down for negative (braid friction differs while lengthening
// and while shortening, and both grow with the contact load, i.e. with pressure: avbdl.h),
// element i holds
//   f_i = w_i s_i F_up   (s_i >= 0),     f_i = w_i s_i F_down   (s_i < 0),
// a spring of stiffness w_i F / delta_i. The breakaway travels stay fixed as the slip forces
// change, so the springs stiffen with the load as tangential contact stiffness does (Mindlin;
// the LuGre model's bristles likewise deflect sigma_0^-1 F_c at sliding): a falling pressure
// scales the held force down at once and a rising one up, with no jump in state.
struct MaxwellSlipParams {
  int count = 0;                                       // 1..kMaxSlipElements when used
  std::array<double, kMaxSlipElements> weight{};       // w_i > 0, summing to 1
  std::array<double, kMaxSlipElements> breakaway_m{};  // delta_i > 0 [m]
};

// Throws InputError "<prefix><key> must be ..., got <value>" (keys in the plant file's
// units: "breakaway_mm[i]", "weights[i]", "weights" for the sum, "breakaway_mm" for the
// count) for a count outside 1..kMaxSlipElements, a non-positive or non-finite value, or
// weights whose sum is not 1 (within 1e-6).
void validate_maxwell_slip(const MaxwellSlipParams& params, const std::string& prefix);

// Moves the elements' common input by step_m [m]: each sticks (its spring takes the step)
// until its state reaches +-1, then slips. `state` holds params.count values in [-1, 1];
// all zero is the unloaded model.
void maxwell_slip_advance(const MaxwellSlipParams& params, double step_m, double* state);

// The elements' total force [N] in `state` for slip forces up_n, down_n >= 0 (see above):
// positive after the input has been pushed up (resisting the push). Closed forms (tested):
// on the virgin branch F(x) = F_up sum w_i min(x / delta_i, 1); a loop of amplitude
// A >= max delta_i is F_up + F_down wide and encloses 2 (F_up + F_down) sum w_i (A - delta_i).
double maxwell_slip_force(const MaxwellSlipParams& params, const double* state, double up_n,
                          double down_n);

}  // namespace pamsim
