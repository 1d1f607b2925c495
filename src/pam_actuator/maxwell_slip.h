// maxwell_slip.h: rate-independent hysteresis with memory, as the Maxwell-slip model (Iwan's
// parallel spring-slider elements; Lampaert, Al-Bender & Swevers, IEEE PhysCon 2003, give its
// rate-dependent generalization, not modelled here; used for the hysteresis of PAMs by
// Vo-Minh et al., IEEE/ASME Trans. Mechatronics 16(1), 2011): N
// elements, each a linear spring k_i in series with a Coulomb block that slips once its
// spring holds more than F_i. The model sticks (a small reversal is elastic, no energy
// lost), slips beyond the band, and remembers where in the loop it rests: what the smooth
// tanh(v / v_s) friction of avbdl_friction.cc cannot do (issue 25, item 2).
//
// Slip forces may grow with pressure, as braid friction does (the contact load is the
// pressure on the fibres): F_i(p) = F0_i + a_i p. The elements' deflections are the state;
// a lower slip force (pressure falling) clips them at once.
#pragma once

#include <string>
#include <vector>

namespace pamsim {

struct MaxwellSlipElement {
  double stiffness_n_per_m = 0.0;     // k_i > 0
  double slip_force_n = 0.0;          // F0_i >= 0, at zero gauge pressure
  double slip_force_per_pa_n = 0.0;   // a_i >= 0 [N/Pa]: F_i(p) = F0_i + a_i p
};

// Throws InputError "<prefix>elements[i].<field> must be ..., got <value>" for a
// non-positive stiffness or a negative (or non-finite) slip force or slope.
void validate_maxwell_slip(const std::vector<MaxwellSlipElement>& elements,
                           const std::string& prefix);

class MaxwellSlip {
 public:
  // Elements must have passed validate_maxwell_slip (asserted). All start unloaded.
  explicit MaxwellSlip(std::vector<MaxwellSlipElement> elements);

  // Moves the input to position_m at gauge pressure p_pa and returns the total force
  // sum k_i z_i [N], positive when the position has been pushed up (resisting the push).
  // The first call sets the reference position (the elements stay unloaded).
  double update(double position_m, double p_pa);
  double force_n() const;
  // The largest force the elements can hold at p_pa: sum F_i(p) (the loop's half height).
  double max_force_n(double p_pa) const;

 private:
  std::vector<MaxwellSlipElement> elements_;
  std::vector<double> deflection_m_;   // z_i
  double position_m_ = 0.0;
  bool started_ = false;
};

}  // namespace pamsim
