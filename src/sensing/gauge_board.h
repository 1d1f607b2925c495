// gauge_board.h: the board a strain gauge is bonded to, as the paper builds its force
// sensors (Yoshida and Hosoda, Sec. IV-B: foil gauges on acrylic boards, the line pulling on the
// board; "the gauge voltage fluctuates with slight positional shifts of the line"). The
// board is a cantilever of rectangular section clamped at x = 0; the line pulls across it
// at the contact point x_c; the gauge sits on its surface at x_g < x_c. Euler-Bernoulli
// bending gives the surface strain under the gauge
//   eps = M c / (E I) = 6 F (x_c - x_g) / (E w t^2),
// so the reading follows the force times the lever x_c - x_g: a contact point that shifts
// by dx changes the reading as a force change of F dx / (x_c - x_g) would (where the contact
// sits and how it moves: gauge_contact.h).
#pragma once

#include <string>

namespace pamsim {

struct GaugeBoardParams {
  // E > 0 [Pa]. PMMA (cast acrylic sheet): about 3.3 GPa in short-term tension (Evonik
  // PLEXIGLAS GS technical data, ISO 527); the board's creep is a separate term.
  double youngs_modulus_pa = 3.3e9;
  double width_m = 0.0;             // w > 0
  double thickness_m = 0.0;         // t > 0
  double gauge_position_m = 0.0;    // x_g >= 0, from the clamp to the gauge's centre
  double contact_position_m = 0.0;  // x_c > x_g, from the clamp to where the line bears
  double length_m = 0.0;            // L_b >= x_c, the free end; 0: the board ends at x_c
};

// L_b, or x_c where the board ends at its contact.
inline double board_free_length_m(const GaugeBoardParams& b) {
  return b.length_m > 0.0 ? b.length_m : b.contact_position_m;
}

// What joins the board's keys (each key's own range is its row, sensing/instrument_keys.h):
// throws InputError "<prefix><key> must be ..., got <value>" for a contact_position_mm not
// beyond gauge_position_mm, or a length_mm neither 0 nor at least contact_position_mm.
void validate_gauge_board(const GaugeBoardParams& board, const std::string& prefix);

// The surface strain under the gauge with the line's pull f_n [N] at contact_m [m] (the
// contact point of this moment; the board's own value when it has not moved). Tension only:
// a slack line (f <= 0) bends nothing.
double gauge_board_strain(const GaugeBoardParams& board, double f_n, double contact_m);

}  // namespace pamsim
