// gauge_contact.cc: see gauge_contact.h.
#include "sensing/gauge_contact.h"

#include <algorithm>
#include <cmath>

#include "base/units.h"

namespace pamsim {

double contact_rest_position_m(const GaugeContactParams& c, double y0_m, double shortening_m) {
  const double d1 = c.fitting_distance_m, d2 = c.shaft_distance_m;
  const double l1 = d1 + shortening_m;
  return y0_m + c.misalignment_m * (l1 / (l1 + d2) - d1 / (d1 + d2));
}

double contact_stick_band_m(const GaugeContactParams& c, double shortening_m) {
  const double l1 = c.fitting_distance_m + shortening_m;
  return 2.0 * c.friction_coefficient * std::sin(units::deg_to_rad(c.wrap_deg) / 2.0) /
         (1.0 / l1 + 1.0 / c.shaft_distance_m);
}

double misalignment_for_loss_m(const GaugeContactParams& c, double margin_m, double shortening_m) {
  const double d1 = c.fitting_distance_m, d2 = c.shaft_distance_m;
  const double l1 = d1 + shortening_m;
  return (margin_m + contact_stick_band_m(c, shortening_m)) / (l1 / (l1 + d2) - d1 / (d1 + d2));
}

GaugeContact::GaugeContact(const GaugeContactParams& c, const GaugeBoardParams& board)
    : params_(c),
      free_end_m_(board_free_length_m(board)),
      y0_m_(board.contact_position_m),
      y_m_(board.contact_position_m) {}

void GaugeContact::reseat(double shift_m) {
  y0_m_ += shift_m;
  y_m_ = std::max(y_m_ + shift_m, 0.0);
  if (y_m_ > free_end_m_) lost_ = true;
}

void GaugeContact::follow(double length_m, double f_n) {
  if (!started_) {
    start_length_m_ = length_m;
    started_ = true;
    // solved on the contact as the trial starts it (re-seated included)
    if (params_.lost_at_shortening_m > 0.0) {
      params_.misalignment_m =
          misalignment_for_loss_m(params_, free_end_m_ - y0_m_, params_.lost_at_shortening_m);
    }
  }
  // a fixed contact, a line gone, or a slack one (nothing drags it) stays where it is
  if (!params_.sliding || lost_ || !(f_n > 0.0)) return;
  // the fitting cannot pass the board: the span keeps a millimetre
  const double s = std::max(start_length_m_ - length_m, 1e-3 - params_.fitting_distance_m);
  const double rest = contact_rest_position_m(params_, y0_m_, s);
  const double band = contact_stick_band_m(params_, s);
  // the clamp stops it at y = 0; past the free end it has slid off
  y_m_ = std::max(std::clamp(y_m_, rest - band, rest + band), 0.0);
  if (y_m_ > free_end_m_) lost_ = true;
}

}  // namespace pamsim
