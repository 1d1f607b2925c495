// tensile_test.h: a virtual static tensile test following the protocol of Yoshida and Hosoda,
// Sec. II-B: at each constant pressure the PAM is stretched from its natural length in
// 2.5 mm steps up to a maximum deformation, then relaxed in 2.5 mm steps back to 0;
// pressure, deformation, force and length are recorded at every point. Optional
// hysteresis and Gaussian sensor noise make the data look like a real test.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "pam_actuator/avbdl.h"
#include "pam_actuator/maxwell_slip.h"
#include "pam_actuator/spring_model.h"

namespace pamsim {

enum class StrokeDirection { kLoading, kUnloading };
// "loading", "unloading"
const char* to_string(StrokeDirection direction);

// One measured point in the paper's units.
struct TensileRow {
  double pressure_mpa = 0.0;    // measured gauge pressure p [MPa]
  double deformation_mm = 0.0;  // measured deformation d from l_n [mm]
  double force_n = 0.0;         // measured force f [N]
  double length_mm = 0.0;       // measured length l = l_n + d [mm], Eq. (1)
  StrokeDirection direction = StrokeDirection::kLoading;
};

struct TensileTestOptions {
  std::vector<double> pressures_mpa{0.4, 0.5, 0.6, 0.7, 0.8};  // the paper's PAM A-C set
  double step_mm = 2.5;                                        // > 0
  double max_deformation_mm = 20.0;                            // >= step_mm
  double hysteresis = 0.0;          // in [0, 0.5): loading f (1+h), unloading f (1-h)
  double noise_pressure_mpa = 0.0;  // standard deviations, >= 0
  double noise_force_n = 0.0;
  double noise_length_mm = 0.0;
  std::uint64_t seed = 1;  // std::mt19937_64 seed: same seed, same data
};

// Throws InputError naming the option for an empty or non-positive pressure list, a
// non-positive step, max < step, hysteresis outside [0, 0.5), negative or non-finite noise.
void validate_tensile_options(const TensileTestOptions& options);

// force [N] from gauge pressure [Pa] and deformation [m]
using ForceLaw = std::function<double(double p_pa, double d_m)>;
// the same on a stroke: a law with its own friction pulls harder loading than unloading
using StrokeForceLaw = std::function<double(double p_pa, double d_m, StrokeDirection stroke)>;
// natural length [m] from gauge pressure [Pa]
using NaturalLengthLaw = std::function<double(double p_pa)>;

// Runs the protocol with any force law. Rows are ordered by pressure, then loading
// (d = 0, step, ..., max) and unloading (max, max - step, ..., 0). The paper does not say
// whether the turning point is measured twice; recording it on both strokes keeps the
// two hysteresis branches balanced in a least-squares fit. Noise: one length sample per
// point is added to both the deformation and the length (the encoder reads l).
std::vector<TensileRow> run_tensile_test(const ForceLaw& force, const NaturalLengthLaw& l_n,
                                         const TensileTestOptions& options);

std::vector<TensileRow> run_tensile_test(const StrokeForceLaw& force, const NaturalLengthLaw& l_n,
                                         const TensileTestOptions& options);

// The lab's test on a physical plant (avbdl.h): l_n is the plant's free length, the force
// its static law plus its friction, lengthening while loading and shortening while
// unloading (the `hysteresis` option multiplies on top). What `pamsim fit` then turns into
// the estimator's spring law.
std::vector<TensileRow> run_tensile_test(const AvbdlParams& plant,
                                         const TensileTestOptions& options);

// A plant pulled along a tensile test's set points in order: its static law plus its
// friction on the stroke (tanh friction by the stroke's direction; Maxwell-slip elements
// walked from set point to set point, unloaded where a loading stroke starts from d = 0).
// What run_tensile_test(AvbdlParams) measures, and what `pamsim identify` compares a
// recorded tensile test's forces with.
class PlantStroke {
 public:
  explicit PlantStroke(const AvbdlParams& plant) : plant_(plant) {}
  // The force [N] at gauge pressure p [Pa] and length l [m] on `stroke`; `start`: the first
  // point of a loading stroke (the slip elements unloaded).
  double force(double p_pa, double length_m, StrokeDirection stroke, bool start);

 private:
  const AvbdlParams& plant_;
  std::array<double, kMaxSlipElements> slip_{};
  double last_l_ = 0.0;
};

// The plant's forces [N] at the rows' recorded pressures and lengths, in their order (a
// loading stroke starts at the first row and after an unloading row).
std::vector<double> plant_forces_along(const AvbdlParams& plant,
                                       const std::vector<TensileRow>& rows);

// Same with the spring model's Eq. (2) and Eq. (3)-(5).
std::vector<TensileRow> run_tensile_test(const SpringModel& model,
                                         const TensileTestOptions& options);

}  // namespace pamsim
