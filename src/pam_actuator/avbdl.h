// avbdl.h: the AVBDL static PAM model of Pipan et al. (Actuators 14(11), 560, 2025),
// "Accurate Volume and Bladder Deformation Loss", as a plant force law, plus the fibre
// friction that the paper names as what it leaves out. Pure functions, SI
// (Pa, m, N, J); p is gauge pressure, L the muscle length between the end fittings, and
// tension (pull) is positive. Equation numbers are Pipan et al.'s, each beside the function
// that implements it: Eq. (3), (18), (19), (25) the force, Eq. (6), (8), (26)-(29) the
// muscle's shape, Eq. (9)-(17) its volume, Eq. (20)-(24) the bladder's work.
// Domain: 2 Ld <= L < b (validate_avbdl_params makes the whole contraction range
// [b/sqrt(3), L0] lie inside it). Outside, results are not physical.
#pragma once

#include <array>
#include <limits>
#include <string>

#include "pam_actuator/bladder_relaxation.h"
#include "pam_actuator/chou_hannaford.h"
#include "pam_actuator/maxwell_slip.h"
#include "base/units.h"
#include "pam_actuator/wickramatunge.h"  // StretchDirection

namespace pamsim {

// Eq. (20): W = C10 (I1 - 3) + C01 (I2 - 3) + C20 (I1 - 3)^2, incompressible [Pa].
struct MooneyRivlinConstants {
  double c10_pa = 0.0;
  double c01_pa = 0.0;
  double c20_pa = 0.0;
};

// Natural rubber: Eq. (20) fitted here (linear least squares on nominal stress) to Treloar's
// uniaxial data for vulcanised natural rubber, L. R. G. Treloar, Trans. Faraday Soc. 40, 59
// (1944), the 9 points with stretch <= 2.42 (a 25 deg braid stretches the bladder's hoop at
// most 1/sin(25 deg) = 2.37); largest residual 0.010 MPa. Data as tabulated in the FElupe
// example ex14_hyperelasticity.py (kgf/cm^2 x 0.0980665 = MPa).
inline constexpr MooneyRivlinConstants kNaturalRubberTreloar{0.0505e6, 0.1771e6, 0.00352e6};
// Silicone rubber (Wacker Elastosil M4601): Yeoh C10 = 0.11 MPa, C20 = 0.02 MPa, i.e. Eq. (20)
// with C01 = 0, from Polygerinos et al., "Modeling of Soft Fiber-Reinforced Bending
// Actuators", IEEE Trans. Robot. 31(3), 778-789 (2015).
inline constexpr MooneyRivlinConstants kSiliconeElastosilM4601{0.11e6, 0.0, 0.02e6};

// The Gent-Gent law, W = -(mu Jm / 2) ln(1 - (I1 - 3) / Jm) + C2 ln(I2 / 3) [Pa] (E. Pucci
// and G. Saccomandi, "A note on the Gent model for rubber-like materials", Rubber Chem.
// Technol. 75, 839 (2002)): Gent's finite extensibility Jm on I1 and a logarithmic I2 term for the
// small-strain softening Gent lacks. mu, C2 >= 0, Jm > 0; defined while I1 - 3 < Jm.
struct GentGentConstants {
  double mu_pa = 0.0;
  double c2_pa = 0.0;
  double jm = 0.0;
};

// Natural rubber: the Gent-Gent law fitted here (least squares on nominal stress, linear in
// mu and C2 for each Jm) to all 25 points of Treloar's uniaxial data (the source of
// kNaturalRubberTreloar), stretch 1 to 7.6: mu = 0.2373 MPa, C2 = 0.2992 MPa, Jm = 77.94;
// every point within 4 % (RMS 0.054 MPa, largest 0.16 MPa at 7.6). Over the stretches a
// Table I tube reaches (4-6) the Mooney-Rivlin fit above is 25-50 % too stiff.
inline constexpr GentGentConstants kNaturalRubberTreloarGentGent{0.23732e6, 0.29918e6, 77.94};

// The bladder's law. Eq. (20)'s Mooney-Rivlin fit holds to a stretch of 2.4; for a tube
// bladder (avbdl_bladder_reference_radius), kGentGent, the Gent-Gent law (Pucci & Saccomandi
// 2002), fitted here to Treloar's whole uniaxial curve (to a stretch of 7.6) within 4 %. Both
// are used as the paper uses Eq. (20): the hoop's nominal uniaxial stress and its work per
// reference volume.
enum class BladderLaw { kMooneyRivlin, kGentGent };

// Friction (pamsim's addition; Pipan et al. Sec. 3 ask for "a pressure- and strain-dependent
// friction term"): dry friction between braid and bladder, proportional to the normal load,
// i.e. to p times a contact area that changes with contraction strain eps = (L0 - L) / L0,
// in the spirit of Tondu & Lopez (2000, ref. [4] of Pipan et al.):
//   F_f = F0 + max(p, 0) max(A0 + A1 eps, 0) >= 0,
// with its own (F0, A0, A1) for lengthening (StretchDirection::kExtension) and shortening
// (kContraction). It opposes motion: +F_f while lengthening, -F_f while shortening, so the
// muscle pulls harder while being stretched than while shortening at the same (p, L).
// Two forms: avbdl_friction_force takes the direction as a state (rate-independent, for
// quasi-static tensile tests); avbdl_smooth_friction_force, used by avbdl_force, is
// tanh(v / v_s) F_f(direction of v): continuous in v (zero at rest, no jump at reversal) for
// ODE solvers and MuJoCo steps; v_s sets how fast it saturates. Its price: no stiction, a
// muscle at rest carries no friction, so it creeps to the friction-free equilibrium. The
// Maxwell-slip form (FrictionModel::kMaxwellSlip, maxwell_slip.h) sticks
// instead: its elements hold their shares of F_f,ext (stretched side) and F_f,con
// (shortened side) as the braid's contacts deflect, slip beyond their breakaway travel,
// and keep what they hold when the muscle stops; their state is the trial's. Friction
// defaults to zero (no published values): fit it from a measured loop, whose width at
// (p, eps) is F_f,ext + F_f,con in both forms.
//
// One stroke direction's friction coefficients, all >= 0.
struct AvbdlFrictionCoefficients {
  double force_n = 0.0;           // F0: friction at p = 0 [N]
  double pressure_area_m2 = 0.0;  // A0: per Pa of gauge pressure at eps = 0 [N/Pa = m^2]
  double strain_area_m2 = 0.0;    // A1: growth of A0 per unit contraction strain [m^2]
};

// How the friction depends on motion: the smooth tanh(v / v_s) of the rate, or Maxwell-slip
// elements whose state is the motion's history.
enum class FrictionModel { kSmooth, kMaxwellSlip };

struct AvbdlFriction {
  AvbdlFrictionCoefficients extension;    // while lengthening
  AvbdlFrictionCoefficients contraction;  // while shortening
  double velocity_scale_m_per_s = 1e-3;   // v_s of the tanh, > 0
  FrictionModel model = FrictionModel::kSmooth;
  MaxwellSlipParams slip;  // the elements, for kMaxwellSlip
};

// Defaults: the Festo DMSP-20 as Pipan et al. Sec. 2.6 print it (D 20 mm, L 200 mm, fibre
// 221 mm, n 1.5, braid 25 deg; b and n follow from L0, D0, alpha0: 220.7 mm, 1.49) and its
// 32 mm end regions (Sec. 2.2). Its wall thickness and fitted Mooney-Rivlin constants are not
// in the text (Table 3 and Fig. 7 are lost): 2 mm is pamsim's assumption and the bladder
// stands in with natural rubber. With Ld = 0 (no end regions) and t = 0 (no bladder) the
// model is Chou-Hannaford exactly.
struct AvbdlParams {
  double length_m = 0.200;                           // L0 at p = 0, > 0
  double diameter_m = 0.020;                         // D0 = 2 R0, > 0
  double braid_angle_rad = units::deg_to_rad(25.0);  // alpha0, in (0, 54.74 deg)
  double wall_thickness_m = 0.002;                   // t >= 0 (R0 to R0 + t); 0: no loss
  MooneyRivlinConstants bladder = kNaturalRubberTreloar;
  BladderLaw bladder_law = BladderLaw::kMooneyRivlin;  // kGentGent: bladder_gent instead
  GentGentConstants bladder_gent = kNaturalRubberTreloarGentGent;
  double bladder_diameter_m = 0.0;  // Db, the tube's outer diameter; 0: the braid's (above)
  BladderRelaxation relaxation;     // the rubber's rate term (bladder_relaxation.h); none
  double end_length_m = 0.032;      // Ld >= 0; 0: no end regions
  double end_slope = 2.0;           // a in [0, 3]; 2: parabolic shoulder
  AvbdlFriction friction;
};

// What the law derives from a muscle's parameters alone, computed once by avbdl_shape: the
// braid, the end profile's coefficients and moments, the bladder's reference radius and
// area, the shortest length. The overloads below that take one skip that work (a
// co-simulation step evaluates the law several times); give them the shape of the same
// parameters. A shape also remembers the last static force it computed (the force callback
// and the step's muscle length ask for the same one): use a shape from one thread at a time.
struct AvbdlProfileMoments {
  double i1 = 0.0;  // integral of eta over [0, 1]
  double i2 = 0.0;  // integral of eta^2
};
struct AvbdlShape {
  BraidGeometry braid;
  double r0 = 0.0;                  // fitting radius D0 / 2
  double rb = 0.0;                  // the bladder's reference radius (its stretch R / rb)
  std::array<double, 4> profile{};  // eta(s) coefficients
  AvbdlProfileMoments moments;
  double bladder_area = 0.0;  // reference wall area per unit length
  double min_length = 0.0;    // avbdl_min_length
  // the memo: static force [N] at (p, L) last computed with this shape (NaN: none)
  mutable double memo_pressure_pa = std::numeric_limits<double>::quiet_NaN();
  mutable double memo_length_m = std::numeric_limits<double>::quiet_NaN();
  mutable double memo_force_n = 0.0;
};

// Throws InputError with one line "<key_prefix><key> must be ..., got <value>" for a value
// outside its key's row (avbdl_keys.h: non-finite, L0 or D0 <= 0, a braid angle outside
// (0, arccos(1/sqrt 3)), t < 0, C20 < 0, a Gent-Gent mu <= 0, C2 < 0 or Jm <= 0, a end slope
// outside [0, 3], a negative friction coefficient, v_s <= 0), and for what joins keys:
// C10 + C01 <= 0 (no initial shear modulus), a bladder diameter not 0 and not in
// (2 t, D0], a Gent-Gent bladder that the braid's full contraction would stretch to its
// limit, 2 Ld >= b / sqrt(3) (both end regions must fit in the fully contracted muscle), a
// bladder relaxation term or Maxwell-slip element out of its rules (bladder_relaxation.h,
// maxwell_slip.h). Keys and values are the plant file's, in its units:
// "geometry.length_mm", "bladder.C10_MPa", "friction.extension.F0_N", ...
void validate_avbdl_params(const AvbdlParams& params, const std::string& key_prefix);

// Eq. (27)-(29) for any muscle: the given geometry and bladder, end regions as long as the
// DMSP-20's relative to its length (Ld = 32/200 L0; Fig. 9 normalises x by the length),
// a = 2, no friction. Validates with `key_prefix` (throws InputError as above).
AvbdlParams avbdl_params_from_geometry(double length_m, double diameter_m, double braid_angle_rad,
                                       double wall_thickness_m,
                                       const MooneyRivlinConstants& bladder,
                                       const std::string& key_prefix = "");

// b and n of the braid from L0, D0, alpha0 (chou_hannaford.h).
BraidGeometry avbdl_braid(const AvbdlParams& params);

// The shape of valid parameters (AvbdlShape above).
AvbdlShape avbdl_shape(const AvbdlParams& params);

// The lengths the law holds for [m]: from the braid's full contraction b / sqrt(3) (or,
// for a Gent-Gent bladder that reaches 0.999 of its limit first, from that length: no
// pressure contracts the muscle past it) to kAvbdlMaxStretch b, just short of the fibre
// length b at which the muscle would have to break (a pamsim cap: Pipan et al. do not model
// a muscle stretched that far).
inline constexpr double kAvbdlMaxStretch = 0.999;
double avbdl_min_length(const AvbdlParams& params);
double avbdl_max_length(const AvbdlParams& params);

// The DMSP-20's end regions relative to its length (32 of 200 mm, Pipan et al. Sec. 2.2), the
// default Ld = kAvbdlEndFraction L0 of any muscle (avbdl_params_from_geometry, plant files).
inline constexpr double kAvbdlEndFraction = 0.032 / 0.200;
// The same end regions relative to the muscle's radius (32 mm at R0 = 10 mm): the default of
// a plant file with Table I's tube (bladder.diameter_mm), whose end regions are where the
// braid flares from the fitting's radius, so they scale with the radius, not the length.
inline constexpr double kAvbdlEndPerRadius = 0.032 / 0.010;

// Radius of the straight middle part [m]: the braid's sqrt(b^2 - L^2) / (2 pi n). In place of
// Eq. (26), D_max = D0 L0 / L_min as read, the middle radius follows the inextensible braid
// (Chou & Hannaford, chou_hannaford.h). For the DMSP-20 the braid reaches D = 38.6 mm at its
// free-contraction length b/sqrt(3) = 127 mm, where Eq. (26) as read gives 31 mm; the paper
// measured D_F20_max = 36 mm.
double avbdl_middle_radius(const AvbdlParams& params, double length_m);

// Eq. (6), (27): radius [m] of the end region at x in [0, Ld] from the fitting.
// The DMSP-20 coefficients of Eq. (6) and Eq. (8)'s data matrix p_n(P, DL) are not printed.
// The end profile keeps Eq. (6)'s four terms (p4 + p3 x + p2 x^2 + p1 x^3) and, as
// Eq. (27)-(29) do, scales one normalised shape affinely onto the muscle:
// y(x) = R0 + (R(L) - R0) eta(x / Ld) with eta(s) = a s + (3 - 2a) s^2 + (a - 2) s^3:
// y(0) = R0 (p4 is the initial radius, Sec. 2.2), y(Ld) = R(L) and y'(Ld) = 0 (it meets the
// straight part without a kink), y'(0) = a (R(L) - R0) / Ld. eta is monotone exactly for a in
// [0, 3]. The profile does not depend on p (the paper's p-dependence comes from fibre
// stretch, absent here). Eq. (28)-(29) (K1, K2) lost their fraction bars; they are read as
// the affine map that sends the DMSP-20's radii [D_F20, D_F20_max] / 2 onto [D, D_max] / 2;
// here that map is applied directly with the muscle's own R0 and R(L).
double avbdl_end_radius(const AvbdlParams& params, double x_m, double length_m);

// Eq. (9)-(17): gas volume [m^3] of the muscle at length L, by Guldin's rule: the deformed
// end regions AR1 (length Ld each) plus the straight middle AR2.
double avbdl_volume(const AvbdlParams& params, double length_m);
double avbdl_volume(const AvbdlParams& params, const AvbdlShape& shape, double length_m);
// dV/dL [m^2], analytic: Eq. (3), (18), the pressure's force F = P dV/dDL = -p dV/dL
// (dDL = -dL).
double avbdl_dvolume_dlength(const AvbdlParams& params, double length_m);
double avbdl_dvolume_dlength(const AvbdlParams& params, const AvbdlShape& shape, double length_m);

// Eq. (20): nominal uniaxial stress [Pa] at stretch lambda > 0.
double mooney_rivlin_stress(const MooneyRivlinConstants& c, double stretch);
// Eq. (21)-(22): its integral from 1 to lambda, work per reference volume [J/m^3].
double mooney_rivlin_energy_density(const MooneyRivlinConstants& c, double stretch);

// The bladder's law at hoop stretch lambda: nominal stress [Pa] and work per reference
// volume [J/m^3] (Eq. (20)-(22) or the Gent-Gent law, whichever params.bladder_law names).
double gent_gent_stress(const GentGentConstants& c, double stretch);
double gent_gent_energy_density(const GentGentConstants& c, double stretch);
double bladder_stress(const AvbdlParams& params, double stretch);
double bladder_energy_density(const AvbdlParams& params, double stretch);

// The bladder's reference. Pipan et al.'s DMSP-20 has a bladder as wide as its braid, and by
// default so does this file's: the wall spans R0 to R0 + t and its hoop stretch is R / R0.
// The papers' own muscles (Yoshida and Hosoda, Table I) are a rubber tube a third to a
// quarter of the sleeve's diameter (the arm's: 4 mm inside 16 mm): with
// bladder_diameter_m > 0 the wall is that tube, Db / 2 - t to Db / 2, its stretch is
// R / rb with rb = Db / 2 - t / 2 (the wall's mid-surface; thin once inflated), so at L0 it
// is already stretched R0 / rb (about 5): the tube inflates freely until it meets the braid,
// and the braid pulls only at pressures above that (avbdl_bladder_free_pressure).
// The bladder's reference radius [m], its stretch being R / that: R0 by default, the tube's
// mid-surface Db / 2 - t / 2 with bladder_diameter_m > 0.
double avbdl_bladder_reference_radius(const AvbdlParams& params);
// The gauge pressure [Pa] that holds the bladder, unconfined, at outer radius r >= its
// reference: the thin tube's p = sigma(lambda) t / (lambda rb) with lambda = r / rb.
// At r = R0 (avbdl_bladder_contact_pressure) the tube meets the braid of the muscle at L0.
double avbdl_bladder_free_pressure(const AvbdlParams& params, double radius_m);
double avbdl_bladder_contact_pressure(const AvbdlParams& params);

// Eq. (23)-(24): work [J] stored in the bladder's radial deformation at length L
// (0 at L0), summed over the end slices and the middle, lambda = R / the reference radius;
// and its slope dW/dL [N].
double avbdl_bladder_energy(const AvbdlParams& params, double length_m);
double avbdl_dbladder_energy_dlength(const AvbdlParams& params, double length_m);
double avbdl_dbladder_energy_dlength(const AvbdlParams& params, const AvbdlShape& shape,
                                     double length_m);

// Eq. (25): the paper's static force [N], -p dV/dL + dW/dL, without friction; with
// Eq. (19), W_out = W_in - W_ob.
double avbdl_static_force(const AvbdlParams& params, double p_pa, double length_m);

// The free length [m] at gauge pressure p: where avbdl_static_force is zero, in
// [avbdl_min_length, L0] (L0 for p <= 0; the minimum if the pull is still positive there;
// NaN for a NaN pressure); for a tube bladder below the pressure at which it meets the
// braid at L0, past L0, where the stretched braid has narrowed onto it. A slack muscle rests there.
// Solved by Boost.Math's TOMS 748 to ~1e-13 relative.
double avbdl_free_length(const AvbdlParams& params, double p_pa);

// The length [m] at which the muscle pulls f > 0 [N] at rest at gauge pressure p, between
// its free length and avbdl_max_length; -1 if it cannot pull that much there.
double avbdl_length_at_force(const AvbdlParams& params, double p_pa, double f_n);

// Friction magnitude F_f >= 0 [N] for a stroke direction (AvbdlFrictionCoefficients).
double avbdl_friction_magnitude(const AvbdlParams& params, double p_pa, double length_m,
                                StretchDirection direction);
// Signed friction [N] with the direction as a state: +F_f lengthening, -F_f shortening.
double avbdl_friction_force(const AvbdlParams& params, double p_pa, double length_m,
                            StretchDirection direction);
// Signed friction [N] from the length rate dL/dt [m/s]: tanh(v / v_s) F_f(direction of v).
double avbdl_smooth_friction_force(const AvbdlParams& params, double p_pa, double length_m,
                                   double length_rate_m_per_s);

// Signed friction [N] of the Maxwell-slip form: the elements in `slip_state` (params.friction
// .slip.count values, maxwell_slip.h) holding their shares of F_f,ext where they are
// stretched and of F_f,con where they are shortened, both at (p, L).
double avbdl_slip_friction_force(const AvbdlParams& params, double p_pa, double length_m,
                                 const double* slip_state);

// What the friction of either form needs at a step: the length rate (kSmooth) and the
// Maxwell-slip elements' state at this length (kMaxwellSlip; null reads as unloaded).
struct FrictionInput {
  double length_rate_m_per_s = 0.0;
  const double* slip_state = nullptr;
};
// Signed friction [N] of the plant's own form.
double avbdl_friction(const AvbdlParams& params, double p_pa, double length_m,
                      const FrictionInput& input);

// The plant force [N]: avbdl_static_force + avbdl_smooth_friction_force.
double avbdl_force(const AvbdlParams& params, double p_pa, double length_m,
                   double length_rate_m_per_s);

// For a muscle on a line whose ends are `taut_length_m` apart (the co-simulation's tendon
// length minus the line): its pull [N] >= 0 (Eq. (25) plus avbdl_friction), zero when it is
// slack (at or below the braid's full contraction, or pulling nothing), the law at
// min(taut, avbdl_max_length) otherwise;
// and its own length [m]: the taut length while it pulls, else its free length (a slack
// muscle rests at avbdl_free_length, whatever the line's ends do). These run at every
// physics step: the co-simulation gives them the muscle's shape (derived once per model),
// whose memo lets the length reuse the pull's static force at the same (p, L).
double avbdl_line_pull(const AvbdlParams& params, double p_pa, double taut_length_m,
                       const FrictionInput& friction);
double avbdl_line_pull(const AvbdlParams& params, const AvbdlShape& shape, double p_pa,
                       double taut_length_m, const FrictionInput& friction);
double avbdl_line_muscle_length(const AvbdlParams& params, double p_pa, double taut_length_m);
double avbdl_line_muscle_length(const AvbdlParams& params, const AvbdlShape& shape, double p_pa,
                                double taut_length_m);

// A trial's last free length of one muscle and the pressure it was solved at.
// Given to the length below, a slack muscle's root is searched from the last one (a
// pressure that moved little in a step moved the root little: a few evaluations of Eq. (25)
// where a bracket over the whole stroke takes a dozen), and the same pressure again returns
// it at once. The root agrees with the untracked one to the solver's tolerance (2^-45), not
// bit for bit; one track per muscle per trial keeps trials deterministic.
struct FreeLengthTrack {
  double pressure_pa = std::numeric_limits<double>::quiet_NaN();
  double length_m = std::numeric_limits<double>::quiet_NaN();
};
double avbdl_line_muscle_length(const AvbdlParams& params, const AvbdlShape& shape, double p_pa,
                                double taut_length_m, FreeLengthTrack* track);

}  // namespace pamsim
