// wickramatunge.h: the empirical spring model of Wickramatunge & Leephakpreeda
// (IMECS 2009), Eq. (1)-(2):
//   F = K(P, Ls) Ls,   K = a0 P^2 + a1 P Ls + a2 Ls^2 + a3                      (1), (2)
// Ls is the stretched length beyond the unstretched length Lu(P), with separate
// coefficient sets for extension (their "extraction", Ls increasing) and contraction
// (Ls decreasing), and for low (0-2.5 bar) and high (2.5-5 bar) gauge pressure (Table 1).
//
// Units of their Table 1 (not printed in the paper, inferred): P [bar gauge], Ls [cm],
// K [N/cm], F [N]. Check: their Fig. 6 spans Ls 0-7 cm with K ~ 50-150 N/cm, and with
// the high-pressure extension set at 5 bar and Ls = 7 cm, K = 155 N/cm and F = 1080 N,
// matching the 0-1000 N pulling forces of their setup; Ls in mm would give K ~ 1e4.
// The API below is SI (Pa, m, N); conversion happens inside.
#pragma once

#include <array>
#include <string>

#include "pam_actuator/spring_model.h"

namespace pamsim {

enum class StretchDirection { kExtension, kContraction };
enum class PressureRange { kLow, kHigh };

// Branch from the rate of the stretched length [m/s]: > 0 extension, < 0 contraction,
// == 0 keeps `previous` (a PAM at rest stays on the branch it came from).
StretchDirection stretch_direction(double ls_dot_m_per_s, StretchDirection previous);

// Coefficients of Eq. (2) in the paper's units (bar, cm, N/cm).
struct WickramatungeCoefficients {
  double a0 = 0.0;  // [N/(cm bar^2)]
  double a1 = 0.0;  // [N/(cm^2 bar)]
  double a2 = 0.0;  // [N/cm^3]
  double a3 = 0.0;  // [N/cm]
};

struct WickramatungeModel {
  // indexed [direction][range]
  std::array<std::array<WickramatungeCoefficients, 2>, 2> sets{};
  double pressure_split_pa = 2.5e5;  // below: low range, else high (2.5 bar)

  const WickramatungeCoefficients& coefficients(StretchDirection direction,
                                                PressureRange range) const {
    return sets[static_cast<int>(direction)][static_cast<int>(range)];
  }
  PressureRange range(double p_pa) const {
    return p_pa < pressure_split_pa ? PressureRange::kLow : PressureRange::kHigh;
  }
};

// Eq. (2): K [N/m] at gauge pressure p [Pa] and stretched length ls [m].
double wickramatunge_stiffness(const WickramatungeModel& model, double p_pa, double ls_m,
                               StretchDirection direction);

// Eq. (1): F [N]; zero for ls <= 0 (nothing stretched).
double wickramatunge_force(const WickramatungeModel& model, double p_pa, double ls_m,
                           StretchDirection direction);

// Ls [m] from (p, F): the smallest positive root of the cubic
// a2 Ls^3 + a1 P Ls^2 + (a0 P^2 + a3) Ls - F = 0, same statuses as invert_spring_model.
DeformationEstimate invert_wickramatunge(const WickramatungeModel& model, double p_pa, double f_n,
                                         StretchDirection direction);

// Reads models/pams/wickramatunge_table1.toml-style files:
//   units = { pressure = "bar", length = "cm", stiffness = "N/cm" }
//   pressure_split_bar = 2.5
//   [extension.low] a0 = .. a1 = .. a2 = .. a3 = ..   (and extension.high,
//   contraction.low, contraction.high)
// Throws InputError "<file>: <key>: <problem>" like load_pam_params.
WickramatungeModel load_wickramatunge(const std::string& path);

}  // namespace pamsim
