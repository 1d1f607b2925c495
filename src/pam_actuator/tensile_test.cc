// tensile_test.cc: the virtual static tensile test, see tensile_test.h.
#include "pam_actuator/tensile_test.h"

#include <array>
#include <cmath>
#include <random>
#include <string>

#include "base/format.h"
#include "base/input_error.h"
#include "base/units.h"

namespace pamsim {
namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw InputError(message);
}

// deformation set points of one pressure: up in steps to max, then back down to 0;
// the turning point is recorded on both strokes (once reached while loading, again
// after the reversal), so every set point has a loading and an unloading sample
std::vector<std::pair<double, StrokeDirection>> stroke(double step, double max) {
  std::vector<double> up;
  for (int k = 0; k * step < max - 1e-9 * step; ++k) up.push_back(k * step);
  up.push_back(max);
  std::vector<std::pair<double, StrokeDirection>> out;
  for (double d : up) out.emplace_back(d, StrokeDirection::kLoading);
  for (int k = static_cast<int>(up.size()) - 1; k >= 0; --k) {
    out.emplace_back(up[k], StrokeDirection::kUnloading);
  }
  return out;
}

}  // namespace

const char* to_string(StrokeDirection direction) {
  return direction == StrokeDirection::kLoading ? "loading" : "unloading";
}

void validate_tensile_options(const TensileTestOptions& o) {
  require(!o.pressures_mpa.empty(), "tensile test: pressures_MPa: the list is empty");
  for (double p : o.pressures_mpa) {
    require(
        std::isfinite(p) && p > 0.0,
        "tensile test: pressures_MPa: every pressure must be > 0 MPa, got " + std::to_string(p));
  }
  require(std::isfinite(o.step_mm) && o.step_mm > 0.0,
          "tensile test: step_mm must be > 0, got " + std::to_string(o.step_mm));
  require(std::isfinite(o.max_deformation_mm) && o.max_deformation_mm >= o.step_mm,
          "tensile test: max_deformation_mm must be >= the step (" + std::to_string(o.step_mm) +
              " mm), got " + std::to_string(o.max_deformation_mm));
  require(std::isfinite(o.hysteresis) && o.hysteresis >= 0.0 && o.hysteresis < 0.5,
          "tensile test: hysteresis must be in [0, 0.5), got " + std::to_string(o.hysteresis));
  const std::pair<const char*, double> noises[] = {{"noise_pressure_MPa", o.noise_pressure_mpa},
                                                   {"noise_force_N", o.noise_force_n},
                                                   {"noise_length_mm", o.noise_length_mm}};
  for (const auto& [name, sd] : noises) {
    require(std::isfinite(sd) && sd >= 0.0, std::string("tensile test: ") + name +
                                                " must be a finite standard deviation >= 0, "
                                                "got " +
                                                std::to_string(sd));
  }
}

std::vector<TensileRow> run_tensile_test(const ForceLaw& force, const NaturalLengthLaw& l_n,
                                         const TensileTestOptions& options) {
  return run_tensile_test([&force](double p, double d, StrokeDirection) { return force(p, d); },
                          l_n, options);
}

std::vector<TensileRow> run_tensile_test(const AvbdlParams& plant,
                                         const TensileTestOptions& options) {
  // every set point within the lengths the law holds for
  validate_tensile_options(options);
  for (double p_mpa : options.pressures_mpa) {
    const double free_m = avbdl_free_length(plant, units::mpa_to_pa(p_mpa));
    const double room_mm = units::m_to_mm(avbdl_max_length(plant) - free_m);
    require(options.max_deformation_mm <= room_mm,
            "tensile test: max_deformation_mm must be <= " + format_value(room_mm) + " mm (at " +
                format_value(p_mpa) + " MPa the plant reaches its fibre length), got " +
                format_value(options.max_deformation_mm));
  }
  const auto l_n = [&plant](double p) { return avbdl_free_length(plant, p); };
  PlantStroke pulled(plant);
  const auto force = [&](double p, double d, StrokeDirection stroke) {
    return pulled.force(p, avbdl_free_length(plant, p) + d, stroke,
                        d == 0.0 && stroke == StrokeDirection::kLoading);
  };
  return run_tensile_test(StrokeForceLaw(force), l_n, options);
}

double PlantStroke::force(double p, double l, StrokeDirection stroke, bool start) {
  // Maxwell-slip elements follow the stroke set point by set point (the law is rate
  // independent, so the steps' size does not matter), unloaded at each loading start
  if (plant_.friction.model == FrictionModel::kMaxwellSlip) {
    if (start) {
      slip_.fill(0.0);
    } else {
      maxwell_slip_advance(plant_.friction.slip, l - last_l_, slip_.data());
    }
    last_l_ = l;
    return avbdl_static_force(plant_, p, l) + avbdl_slip_friction_force(plant_, p, l, slip_.data());
  }
  const StretchDirection motion = stroke == StrokeDirection::kLoading
                                      ? StretchDirection::kExtension
                                      : StretchDirection::kContraction;
  return avbdl_static_force(plant_, p, l) + avbdl_friction_force(plant_, p, l, motion);
}

std::vector<double> plant_forces_along(const AvbdlParams& plant,
                                       const std::vector<TensileRow>& rows) {
  PlantStroke pulled(plant);
  std::vector<double> forces;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const TensileRow& r = rows[i];
    // a loading stroke starts at the first row and after an unloading one
    const bool start = r.direction == StrokeDirection::kLoading &&
                       (i == 0 || rows[i - 1].direction == StrokeDirection::kUnloading);
    forces.push_back(pulled.force(units::mpa_to_pa(r.pressure_mpa), units::mm_to_m(r.length_mm),
                                  r.direction, start));
  }
  return forces;
}

std::vector<TensileRow> run_tensile_test(const StrokeForceLaw& force, const NaturalLengthLaw& l_n,
                                         const TensileTestOptions& options) {
  validate_tensile_options(options);
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> unit_normal(0.0, 1.0);
  const auto noise = [&](double sd) { return sd > 0.0 ? sd * unit_normal(rng) : 0.0; };

  std::vector<TensileRow> rows;
  for (double p_mpa : options.pressures_mpa) {
    const double p_pa = units::mpa_to_pa(p_mpa);
    const double l_n_mm = units::m_to_mm(l_n(p_pa));
    for (const auto& [d_mm, direction] : stroke(options.step_mm, options.max_deformation_mm)) {
      // true force with friction hysteresis: higher while loading, lower while unloading
      const double sign = direction == StrokeDirection::kLoading ? 1.0 : -1.0;
      const double f =
          force(p_pa, units::mm_to_m(d_mm), direction) * (1.0 + sign * options.hysteresis);

      // sensors: pressure gauge, force gauge, length encoder
      TensileRow row;
      row.direction = direction;
      row.pressure_mpa = p_mpa + noise(options.noise_pressure_mpa);
      row.force_n = f + noise(options.noise_force_n);
      const double e_l = noise(options.noise_length_mm);
      row.deformation_mm = d_mm + e_l;
      row.length_mm = l_n_mm + d_mm + e_l;  // Eq. (1)
      rows.push_back(row);
    }
  }
  return rows;
}

std::vector<TensileRow> run_tensile_test(const SpringModel& model,
                                         const TensileTestOptions& options) {
  return run_tensile_test([&model](double p, double d) { return spring_force(model, p, d); },
                          [&model](double p) { return natural_length(model, p); }, options);
}

}  // namespace pamsim
