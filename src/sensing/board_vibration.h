// board_vibration.h: the gauge board's first bending mode, so that a sharp change of the
// line's pull (the mass landing in the basket) rings the acrylic board and the gauge samples
// the ringing (an impact-excited vibration of line and board; the paper's mistrips and
// self-retriggering came from a noisy velocity estimate, Yoshida and Hosoda, Sec. IV).
#pragma once

#include <string>

#include "sensing/gauge_board.h"

namespace pamsim {

// The figures (each a key, sensors.gauge.board.*): PMMA's density 1190 kg/m^3 (Evonik
// PLEXIGLAS GS/XT technical data, ISO 1183); its loss factor 0.02-0.04 at room temperature
// in the audio range (the material table of Cremer, Heckl & Petersson, Structure-Borne
// Sound, 3rd ed., Springer 2005: "Plexiglas 2-4e-2"), taken as 0.03. The board's own size
// is the assumption of gauge_hardware.h (20 x 5 mm, free 45 mm from the clamp: f1 about
// 660 Hz, a ringing that decays with a time constant of 1 / (zeta w1), about 16 ms).
struct BoardVibrationParams {
  bool enabled = true;            // sensors.gauge.board.vibration
  double density_kg_m3 = 1190.0;  // sensors.gauge.board.density_kg_m3, > 0
  double loss_factor = 0.03;      // sensors.gauge.board.loss_factor, (0, 1)
};

// The board is the cantilever of gauge_board.h, clamped at x = 0, free at L_b and pulled at
// the contact point x_c (the mode's shape taken as the static one's). Its first mode (Euler-
// Bernoulli, a uniform clamped-free beam; Blevins, Formulas for Natural Frequency and Mode
// Shape, Table 8-1: lambda_1 = 1.87510):
//   f1 = lambda_1^2 / (2 pi L^2) sqrt(E I / (rho A)),   I = w t^3 / 12,   A = w t,
// with the material's loss factor eta as a viscous damping ratio zeta = eta / 2 at f1.
// f1 [Hz] of the board clamped at 0 and free at L_b.
double board_first_mode_hz(const GaugeBoardParams& board, const BoardVibrationParams& v);

// The gauge's strain follows the mode's amplitude, written here as the pull F_b that would
// bend the board as far statically:
//   F_b'' + 2 zeta w1 F_b' + w1^2 F_b = w1^2 F(t)     (w1 = 2 pi f1),
// with the line's pull F taken as linear between the physics steps' instants (a first-order
// hold: the line's tension is continuous; MuJoCo's held staircase would itself ring a mode
// above the step's Nyquist frequency, 500 Hz at 1 ms, and make the ringing depend on the
// step). The step is exact for that input: the particular solution F - 2 zeta F' / w1 plus
// the damped oscillator's free response. Each call brings the board to the instant of the
// pull it is given, so a reading between calls is one physics step behind the pull.
// The board's first mode under the line's pull, stepped by a fixed dt.
class BoardVibration {
 public:
  // natural_hz > 0 and finite, 0 < damping_ratio < 1, dt_s > 0 (std::invalid_argument).
  BoardVibration(double natural_hz, double damping_ratio, double dt_s);

  // Advances one dt, the pull going linearly from the last call's to f_n [N]. The first call
  // starts the board at rest under f_n (a trial starts in equilibrium).
  void step(double f_n);
  // The static pull that would bend the board as far as it is bent now [N]; it can be
  // negative while the board rings through its rest shape after a release.
  double equivalent_force_n() const { return force_n_; }
  bool started() const { return started_; }

 private:
  // the free response over dt: [e; v](t + dt) = P [e; v](t), e = F_b - the particular one
  double p11_ = 0.0, p12_ = 0.0, p21_ = 0.0, p22_ = 0.0;
  double dt_s_ = 0.0;
  double lag_s_ = 0.0;     // 2 zeta / w1: the particular solution's lag behind a ramp
  double force_n_ = 0.0;   // F_b
  double rate_n_s_ = 0.0;  // dF_b/dt
  double input_n_ = 0.0;   // the last call's pull
  bool started_ = false;
};

}  // namespace pamsim
