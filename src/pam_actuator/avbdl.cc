// avbdl.cc: the AVBDL plant force law of Pipan et al., see avbdl.h: the volume, the bladder's
// work and their slopes (Eq. (9)-(25)); its checks are in avbdl_validation.cc, its friction
// term in avbdl_friction.cc.
#include "pam_actuator/avbdl.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <boost/math/tools/roots.hpp>

namespace pamsim {
namespace {

constexpr double kPi = units::kPi;

// 8-point Gauss-Legendre rule on [-1, 1] (Abramowitz & Stegun, Table 25.4): positive nodes
// and their weights; the rule is symmetric
constexpr std::array<double, 4> kGaussNodes = {0.1834346424956498, 0.5255324099163290,
                                               0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kGaussWeights = {0.3626837833783620, 0.3137066458778873,
                                                 0.2223810344533745, 0.1012285362903763};

// coefficients of eta(s) = sum c[i] s^i, the normalised end profile (avbdl.h)
std::array<double, 4> profile_coefficients(double a) { return {0.0, a, 3.0 - 2.0 * a, a - 2.0}; }

double profile(const std::array<double, 4>& c, double s) {
  return ((c[3] * s + c[2]) * s + c[1]) * s;
}

// integrals of eta and eta^2 over s in [0, 1]
using ProfileMoments = AvbdlProfileMoments;

ProfileMoments profile_moments(double a) {
  const std::array<double, 4> c = profile_coefficients(a);
  ProfileMoments m;
  for (int i = 0; i < 4; ++i) {
    m.i1 += c[i] / (i + 1);
    for (int j = 0; j < 4; ++j) m.i2 += c[i] * c[j] / (i + j + 1);
  }
  return m;
}

// the braid's middle radius squared, R^2 = (b^2 - L^2) / (2 pi n)^2, and its slope in L
double radius_squared(const BraidGeometry& g, double length_m) {
  const double k = 2.0 * kPi * g.turns;
  return (g.fibre_length_m * g.fibre_length_m - length_m * length_m) / (k * k);
}

double dradius_squared_dlength(const BraidGeometry& g, double length_m) {
  const double k = 2.0 * kPi * g.turns;
  return -2.0 * length_m / (k * k);
}

// sum over the 8 Gauss nodes in s in [0, 1] of weight * f(s): integral of f over [0, 1]
template <typename F>
double integrate_unit_interval(const F& f) {
  double sum = 0.0;
  for (std::size_t k = 0; k < kGaussNodes.size(); ++k) {
    sum += kGaussWeights[k] * (f(0.5 - 0.5 * kGaussNodes[k]) + f(0.5 + 0.5 * kGaussNodes[k]));
  }
  return 0.5 * sum;
}

// reference (unstrained) bladder volume per unit length: an annulus from R0 out to R0 + t.
// A reading of Eq. (24), which multiplies by "the bladder volume" without placing the wall;
// a bladder inside the braid (R0 - t to R0) would hold (2 R0 - t) / (2 R0 + t) of this
// rubber, two thirds for plant_agonist.toml (docs/physics.md, departures)
// With a tube (bladder_diameter_m > 0): the annulus Db / 2 - t to Db / 2, 2 pi rb t.
double bladder_area(const AvbdlParams& p) {
  if (p.bladder_diameter_m > 0.0) {
    return 2.0 * kPi * avbdl_bladder_reference_radius(p) * p.wall_thickness_m;
  }
  const double r0 = 0.5 * p.diameter_m;
  return kPi * p.wall_thickness_m * (2.0 * r0 + p.wall_thickness_m);
}

using Shape = AvbdlShape;

// The length [m] at which a Gent-Gent bladder reaches 0.999 of its limit, I1 - 3 = Jm (the
// braid cannot contract past it: the bladder would have to stretch without bound); 0 when
// the braid's full contraction comes first, or for the Mooney-Rivlin law.
double bladder_limit_length(const AvbdlParams& p, const BraidGeometry& g, double rb) {
  if (p.bladder_law != BladderLaw::kGentGent) return 0.0;
  // lambda^2 + 2 / lambda - 3 = 0.999 Jm, by Newton from sqrt(Jm + 3) (a few steps: the
  // 2 / lambda term is small beyond a stretch of 3)
  const double target = 0.999 * p.bladder_gent.jm + 3.0;
  double l = std::sqrt(target);
  for (int i = 0; i < 8; ++i) l -= (l * l + 2.0 / l - target) / (2.0 * l - 2.0 / (l * l));
  const double k = 2.0 * kPi * g.turns * l * rb;  // 2 pi n R at that stretch
  const double b = g.fibre_length_m;
  return k < b ? std::sqrt(b * b - k * k) : 0.0;  // k >= b: wider than the braid ever is
}

}  // namespace

AvbdlShape avbdl_shape(const AvbdlParams& p) {
  Shape s;
  s.braid = braid_from_initial_shape(p.length_m, p.diameter_m, p.braid_angle_rad);
  s.r0 = 0.5 * p.diameter_m;
  s.rb = avbdl_bladder_reference_radius(p);
  s.profile = profile_coefficients(p.end_slope);
  s.moments = profile_moments(p.end_slope);
  s.bladder_area = bladder_area(p);
  s.min_length =
      std::max(s.braid.fibre_length_m / std::sqrt(3.0), bladder_limit_length(p, s.braid, s.rb));
  return s;
}

namespace {

Shape shape_of(const AvbdlParams& p) { return avbdl_shape(p); }

// the lengths the law holds for (avbdl_min_length, avbdl_max_length)
double min_length(const Shape& shape) { return shape.min_length; }
double max_length(const Shape& shape) { return kAvbdlMaxStretch * shape.braid.fibre_length_m; }

double dvolume_dlength(const AvbdlParams& p, const Shape& shape, double length_m) {
  const BraidGeometry& g = shape.braid;
  const double ld = p.end_length_m;
  const double r0 = shape.r0;
  const double r_sq = radius_squared(g, length_m);
  const double dr_sq = dradius_squared_dlength(g, length_m);
  const ProfileMoments& m = shape.moments;

  // dA/dL: the end region's shape moves with R(L); dR/dL = d(R^2)/dL / (2 R)
  double da = 0.0;
  if (ld > 0.0) {
    const double r = std::sqrt(r_sq);
    da = ld * (r0 * m.i1 + (r - r0) * m.i2) * dr_sq / (2.0 * r);
  }
  // dB/dL: the straight part widens and shortens
  const double db = 0.25 * (dr_sq * (length_m - 2.0 * ld) + r_sq);
  // Eq. (18) uses F = P dV/dDL with DL = L0 - L: dV/dDL = -dV/dL
  return 4.0 * kPi * (da + db);
}

double dbladder_energy_dlength(const AvbdlParams& p, const Shape& shape, double length_m) {
  const double r0 = shape.r0, rb = shape.rb;
  const double r = std::sqrt(radius_squared(shape.braid, length_m));
  const double area = shape.bladder_area;
  const std::array<double, 4>& c = shape.profile;
  const double dr = dradius_squared_dlength(shape.braid, length_m) / (2.0 * r);

  // Eq. (21): dW/dlambda = sigma; the middle's stretch R / rb moves with dR/dL
  const double dw_mid = area * (p.length_m - 2.0 * p.end_length_m) * bladder_stress(p, r / rb) / rb;
  // at s the end radius moves by eta(s) dR/dL
  const double per_end = integrate_unit_interval([&](double s) {
    const double eta = profile(c, s);
    return bladder_stress(p, (r0 + (r - r0) * eta) / rb) * eta / rb;
  });
  return (dw_mid + 2.0 * area * p.end_length_m * per_end) * dr;
}

double static_force(const AvbdlParams& p, const Shape& shape, double p_pa, double length_m) {
  // the shape's memo: the same (p, L) again (the force callback's, then the step's length)
  if (p_pa == shape.memo_pressure_pa && length_m == shape.memo_length_m) return shape.memo_force_n;
  // Eq. (19): F dDL = p dV - dW_def with dDL = -dL, so Eq. (25) reads
  // F = -p dV/dL + dW_def/dL; the text lost (25)'s fraction bars and sign, this is the
  // sign for which the bladder's work lowers the pull of a contracted muscle
  const double f =
      -p_pa * dvolume_dlength(p, shape, length_m) + dbladder_energy_dlength(p, shape, length_m);
  shape.memo_pressure_pa = p_pa;
  shape.memo_length_m = length_m;
  shape.memo_force_n = f;
  return f;
}

// the free length's root to 2^-45; the tracked search's first step and its widenings
constexpr int kFreeLengthBits = 45;
constexpr double kFreeLengthFirstStep_m = 1e-6;
constexpr int kFreeLengthWidenings = 16;

double free_length(const AvbdlParams& p, const Shape& shape, double p_pa) {
  if (std::isnan(p_pa)) return p_pa;  // no length for no pressure: the trial diverges
  if (!(p_pa > 0.0)) return p.length_m;
  double lo = min_length(shape);
  const auto force = [&](double l) { return static_force(p, shape, p_pa, l); };
  if (force(lo) >= 0.0) return lo;  // still pulling at the braid's limit
  double hi = p.length_m;
  if (force(hi) <= 0.0) {
    // a tube bladder below the pressure at which it meets the braid at L0: the braid must
    // be stretched past L0 until it narrows onto the tube (the law's bladder, the braid's,
    // stays stretched at L0 and so never gets here)
    if (p.bladder_diameter_m == 0.0 || force(max_length(shape)) <= 0.0) return p.length_m;
    lo = hi;
    hi = max_length(shape);
  }
  std::uintmax_t iterations = 100;
  const auto [a, b] = boost::math::tools::toms748_solve(
      force, lo, hi, boost::math::tools::eps_tolerance<double>(kFreeLengthBits), iterations);
  return 0.5 * (a + b);
}

// free_length searched from `near` (a trial's last root, FreeLengthTrack): outwards in
// steps growing eightfold until the pull changes sign (it grows with the length), then TOMS
// 748 in that bracket; the whole stroke's search where the steps leave the range it spans
double free_length_near(const AvbdlParams& p, const Shape& shape, double p_pa, double near) {
  const double lo = min_length(shape);
  const double hi = p.bladder_diameter_m > 0.0 ? max_length(shape) : p.length_m;
  if (!(p_pa > 0.0) || !(near > lo && near < hi)) return free_length(p, shape, p_pa);
  const auto force = [&](double l) { return static_force(p, shape, p_pa, l); };
  double a = near, fa = force(a);
  const double direction = fa > 0.0 ? -1.0 : 1.0;  // a pull: the root is shorter
  double step = kFreeLengthFirstStep_m;
  for (int k = 0; k < kFreeLengthWidenings && fa != 0.0; ++k, step *= 8.0) {
    const double b = a + direction * step;
    if (!(b > lo && b < hi)) break;
    const double fb = force(b);
    if ((fb > 0.0) == (fa > 0.0) && fb != 0.0) {
      a = b;
      fa = fb;
      continue;
    }
    std::uintmax_t iterations = 100;
    const boost::math::tools::eps_tolerance<double> tolerance(kFreeLengthBits);
    const auto [x, y] =
        direction < 0.0
            ? boost::math::tools::toms748_solve(force, b, a, fb, fa, tolerance, iterations)
            : boost::math::tools::toms748_solve(force, a, b, fa, fb, tolerance, iterations);
    return 0.5 * (x + y);
  }
  return fa == 0.0 ? a : free_length(p, shape, p_pa);
}

}  // namespace

BraidGeometry avbdl_braid(const AvbdlParams& p) {
  return braid_from_initial_shape(p.length_m, p.diameter_m, p.braid_angle_rad);
}

double avbdl_min_length(const AvbdlParams& p) { return min_length(shape_of(p)); }

double avbdl_max_length(const AvbdlParams& p) { return max_length(shape_of(p)); }

double avbdl_middle_radius(const AvbdlParams& p, double length_m) {
  // the braid's diameter sqrt(b^2 - L^2) / (pi n), in place of Eq. (26)
  const BraidGeometry g = avbdl_braid(p);
  assert(length_m > 0.0 && length_m < g.fibre_length_m);
  return std::sqrt(radius_squared(g, length_m));
}

double avbdl_end_radius(const AvbdlParams& p, double x_m, double length_m) {
  assert(x_m >= 0.0 && x_m <= p.end_length_m);
  // Eq. (27): the normalised profile scaled from the fitting radius R0 to the middle R(L);
  // in Eq. (6)'s terms p4 = R0, p3 = a dR / Ld, p2 = (3 - 2a) dR / Ld^2, p1 = (a - 2) dR / Ld^3
  const double r0 = 0.5 * p.diameter_m;
  const double dr = avbdl_middle_radius(p, length_m) - r0;
  return r0 + dr * profile(profile_coefficients(p.end_slope), x_m / p.end_length_m);
}

double avbdl_volume(const AvbdlParams& p, double length_m) {
  return avbdl_volume(p, shape_of(p), length_m);
}

double avbdl_volume(const AvbdlParams& p, const AvbdlShape& shape, double length_m) {
  const BraidGeometry& g = shape.braid;
  const double ld = p.end_length_m;
  assert(length_m >= 2.0 * ld && length_m < g.fibre_length_m);
  const double r0 = shape.r0;
  const double r_sq = radius_squared(g, length_m);
  const double r = std::sqrt(r_sq);
  const double dr = r - r0;
  const ProfileMoments& m = shape.moments;

  // Eq. (12), (14): A = y_d A_d = 1/2 integral of y^2 over the end region [0, Ld]
  const double a_ends = 0.5 * ld * (r0 * r0 + 2.0 * r0 * dr * m.i1 + dr * dr * m.i2);
  // Eq. (13), (15): B = y_r A_r with y_r = R / 2 and A_r = R (L0 - 2 Ld - DL) / 2, the
  // straight part of one half; the text lost (15)'s typesetting, this reading is the one
  // that gives the cylinder V = pi R^2 L at Ld = 0
  const double b_middle = (0.5 * r) * (r * 0.5 * (length_m - 2.0 * ld));
  // Eq. (16)-(17): Guldin's rule (9) on one half's profile area, both halves: 4 pi (A + B)
  return 4.0 * kPi * (a_ends + b_middle);
}

double avbdl_dvolume_dlength(const AvbdlParams& p, double length_m) {
  return dvolume_dlength(p, shape_of(p), length_m);
}

double avbdl_dvolume_dlength(const AvbdlParams& p, const AvbdlShape& shape, double length_m) {
  return dvolume_dlength(p, shape, length_m);
}

double avbdl_bladder_energy(const AvbdlParams& p, double length_m) {
  const double r0 = 0.5 * p.diameter_m;
  const double rb = avbdl_bladder_reference_radius(p);
  const double r = avbdl_middle_radius(p, length_m);
  const double area = bladder_area(p);
  const std::array<double, 4> c = profile_coefficients(p.end_slope);

  // Eq. (23)-(24), middle: V_bl(Lr) W_def(R / rb), with the bladder's reference (material)
  // volume of the straight part, so that W depends on L only through the stretch (a tube
  // is stretched at L0 already: W is then counted from its unstretched state, which moves
  // no force, only the energy's zero)
  const double w_mid =
      area * (p.length_m - 2.0 * p.end_length_m) * bladder_energy_density(p, r / rb);
  // Eq. (24), ends: the paper's sum over x slices, as a Gauss rule over s = x / Ld
  const double per_end = integrate_unit_interval(
      [&](double s) { return bladder_energy_density(p, (r0 + (r - r0) * profile(c, s)) / rb); });
  return w_mid + 2.0 * area * p.end_length_m * per_end;
}

double avbdl_dbladder_energy_dlength(const AvbdlParams& p, double length_m) {
  return dbladder_energy_dlength(p, shape_of(p), length_m);
}

double avbdl_dbladder_energy_dlength(const AvbdlParams& p, const AvbdlShape& shape,
                                     double length_m) {
  return dbladder_energy_dlength(p, shape, length_m);
}

double avbdl_static_force(const AvbdlParams& p, double p_pa, double length_m) {
  return static_force(p, shape_of(p), p_pa, length_m);
}

double avbdl_free_length(const AvbdlParams& p, double p_pa) {
  return free_length(p, shape_of(p), p_pa);
}

double avbdl_length_at_force(const AvbdlParams& p, double p_pa, double f_n) {
  const Shape shape = shape_of(p);
  const double lo = free_length(p, shape, p_pa);
  const double hi = max_length(shape);
  const auto excess = [&](double l) { return static_force(p, shape, p_pa, l) - f_n; };
  if (!(f_n > 0.0) || excess(hi) < 0.0) return -1.0;
  if (excess(lo) >= 0.0) return lo;
  std::uintmax_t iterations = 100;
  const auto [a, b] = boost::math::tools::toms748_solve(
      excess, lo, hi, boost::math::tools::eps_tolerance<double>(45), iterations);
  return 0.5 * (a + b);
}

double avbdl_force(const AvbdlParams& p, double p_pa, double length_m, double length_rate_m_per_s) {
  return static_force(p, shape_of(p), p_pa, length_m) +
         avbdl_smooth_friction_force(p, p_pa, length_m, length_rate_m_per_s);
}

double avbdl_line_pull(const AvbdlParams& p, double p_pa, double taut_length_m,
                       const FrictionInput& friction) {
  return avbdl_line_pull(p, shape_of(p), p_pa, taut_length_m, friction);
}

double avbdl_line_pull(const AvbdlParams& p, const AvbdlShape& shape, double p_pa,
                       double taut_length_m, const FrictionInput& friction) {
  // Eq. (25) plus the friction term at the line's length, held at the law's last length
  // past avbdl_max_length; a muscle at its full contraction (or pushing) pulls nothing
  const double l = std::min(taut_length_m, max_length(shape));
  if (l <= min_length(shape)) return 0.0;
  const double f = static_force(p, shape, p_pa, l) + avbdl_friction(p, p_pa, l, friction);
  return std::max(f, 0.0);
}

double avbdl_line_muscle_length(const AvbdlParams& p, double p_pa, double taut_length_m) {
  return avbdl_line_muscle_length(p, shape_of(p), p_pa, taut_length_m);
}

double avbdl_line_muscle_length(const AvbdlParams& p, const AvbdlShape& shape, double p_pa,
                                double taut_length_m) {
  FreeLengthTrack none;  // no last root: the search over the whole stroke
  return avbdl_line_muscle_length(p, shape, p_pa, taut_length_m, &none);
}

double avbdl_line_muscle_length(const AvbdlParams& p, const AvbdlShape& shape, double p_pa,
                                double taut_length_m, FreeLengthTrack* track) {
  // while Eq. (25) pulls at the line's length the muscle is that long; otherwise the line
  // is slack and the muscle has contracted to where Eq. (25) is zero (a root solve, so
  // only then)
  const double l = std::min(taut_length_m, max_length(shape));
  if (static_force(p, shape, p_pa, l) > 0.0) return taut_length_m;
  if (!(p_pa == track->pressure_pa)) {
    track->length_m = std::isnan(track->length_m)
                          ? free_length(p, shape, p_pa)
                          : free_length_near(p, shape, p_pa, track->length_m);
    track->pressure_pa = p_pa;
  }
  return std::max(taut_length_m, track->length_m);
}

}  // namespace pamsim
