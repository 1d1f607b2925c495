// units.h: the only place where the papers' units (MPa, mm, bar, cm) meet SI.
// Inside pamsim everything is SI (Pa, m, N, s); files and the command line use the
// papers' units, named in keys and column headers, and convert here once.
#pragma once

namespace pamsim::units {

inline constexpr double kPaPerMPa = 1e6;
inline constexpr double kPaPerBar = 1e5;
inline constexpr double kMPerMm = 1e-3;
inline constexpr double kMPerCm = 1e-2;
inline constexpr double kPi = 3.14159265358979323846;

inline constexpr double mpa_to_pa(double p_mpa) { return p_mpa * kPaPerMPa; }
inline constexpr double pa_to_mpa(double p_pa) { return p_pa / kPaPerMPa; }
inline constexpr double mm_to_m(double x_mm) { return x_mm * kMPerMm; }
inline constexpr double m_to_mm(double x_m) { return x_m / kMPerMm; }
inline constexpr double mm2_to_m2(double a_mm2) { return a_mm2 * 1e-6; }
inline constexpr double deg_to_rad(double a_deg) { return a_deg * kPi / 180.0; }
inline constexpr double rad_to_deg(double a_rad) { return a_rad * 180.0 / kPi; }

}  // namespace pamsim::units
