// gauge_contact.h: where the fishing line bears on the gauge's board, and whether it still
// does: a contact point that moves and sticks, and a line able to lose that contact by
// geometry (Yoshida and Hosoda, Sec. IV-B: "the voltage values fluctuated significantly due
// to slight positional shifts of the fishing line", and the agonist's signal was lost as its
// muscle contracted). The geometry is told at contact_rest_position_m, its figures at
// GaugeContactParams.
#pragma once

#include <string>

#include "sensing/gauge_board.h"

namespace pamsim {

// The figures (each a key, sensors.gauge.contact.*) are an ASSUMPTION, a row of docs/physics.md's
// departures: the paper gives no geometry of its gauges. D = 2 mm (an assembly's lateral
// tolerance), d1 = 20 mm (the board at the fitting), d2 = 250 mm (the MJCF's 0.4 m from anchor to
// shaft less the muscle), theta = 30 deg, mu = 0.3 (nylon on acrylic, the usual 0.2-0.4 of polymer
// pairs), and the board 5 mm longer than the contact position. With them the contact sticks over
// the arm's whole stroke (w about 2.9 mm, y* moving about 0.2 mm): docs/physics.md says what it
// would take to lose it.
struct GaugeContactParams {
  bool sliding = true;                // sensors.gauge.contact.model: "fixed" | "sliding"
  double misalignment_m = 0.002;      // D, misalignment_mm (either sign)
  double fitting_distance_m = 0.020;  // d1, fitting_distance_mm >= 1
  double shaft_distance_m = 0.250;    // d2, shaft_distance_mm > 0
  double wrap_deg = 30.0;             // theta, wrap_deg in (0, 180)
  double friction_coefficient = 0.3;  // mu >= 0
  // reseat_mm: the contact's shift along the edge between the gauge's static calibration
  // and the trial (the paper's "slight positional shifts of the fishing line", Sec. IV-B),
  // which scales the trial's reading by the lever's change, (y0 + shift - y_g) / (y0 - y_g).
  // A line re-laid on the board rests anywhere its stick band holds it: +-w of y*.
  double reseat_m = 0.0;
  // lost_at_shortening_mm: 0, the misalignment as given; > 0, a calibration to an observed
  // signal loss: D solved (misalignment_for_loss_m) so that the line leaves the board's free
  // end once the muscle has shortened this far from the trial's start.
  double lost_at_shortening_m = 0.0;
};

// The line runs from the muscle's end fitting over the board's edge (the cantilever of
// gauge_board.h, clamped at y = 0, free at y = L_b) on to the arm's shaft. Along the edge,
// the shaft lies a misalignment D beside the fitting. Unfolded into a plane, the line's
// shortest path crosses the edge where similar triangles put it (the reflection law):
//   y* = y_p + D L1 / (L1 + L2),
// L1 the fitting's distance to the edge, L2 the edge's to the shaft. The fitting moves away
// from the board as the muscle shortens by s (L1 = d1 + s), so y* moves; y_p is such that
// y* is the board's contact position y0 at the start. The line's pull drags it toward y*
// with the lateral force T (1/L1 + 1/L2) (y* - y), and its bend theta over the edge presses
// it on with 2 T sin(theta / 2), whose friction mu holds it: the contact sticks while
//   |y* - y| <= w = 2 mu sin(theta / 2) / (1/L1 + 1/L2)
// (the pull cancels: a play of half-width w), and slides to the play's edge beyond. A slack
// line rests where it lies. A contact past the board's free end has slid off it: the gauge
// is unloaded from then on, whatever the line pulls (the paper's "failure to send voltage
// signals"). The reading follows the pull times the lever y - y_g (gauge_board.h).
//
// y* [m] once the muscle has shortened by s [m] from the start (negative: lengthened).
double contact_rest_position_m(const GaugeContactParams& c, double y0_m, double shortening_m);
// w [m], the half-width of the band in which the contact sticks.
double contact_stick_band_m(const GaugeContactParams& c, double shortening_m);
// The misalignment D [m] at which a line that sticks from the start, the muscle shortening
// steadily, leaves the board's free end (margin_m beyond the start's contact) once the muscle
// has shortened by s: the contact slides off where y* - w = y0 + margin, so
//   D = (margin + w(s)) / (L1 / (L1 + d2) - d1 / (d1 + d2)),  L1 = d1 + s,  s > 0.
double misalignment_for_loss_m(const GaugeContactParams& c, double margin_m, double shortening_m);

class GaugeContact {
 public:
  GaugeContact(const GaugeContactParams& c, const GaugeBoardParams& board);

  // One control tick with the muscle at length_m, its line pulling f_n [N]. The first call
  // fixes the start length (the contact at the board's contact position).
  void follow(double length_m, double f_n);
  double position_m() const { return y_m_; }
  // Moves the contact, and the position it rests at, by shift_m along the edge (past the
  // free end: lost).
  void reseat(double shift_m);
  bool lost() const { return lost_; }

 private:
  GaugeContactParams params_;
  double free_end_m_ = 0.0;  // L_b
  double y0_m_ = 0.0;
  double y_m_ = 0.0;
  double start_length_m_ = 0.0;
  bool started_ = false;
  bool lost_ = false;
};

}  // namespace pamsim
