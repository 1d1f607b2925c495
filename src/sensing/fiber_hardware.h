// fiber_hardware.h: the conductive-fiber sensor as hardware (sensors.fiber.model = "fabric")
// instead of a rate read exactly plus white noise. The sensor of Hitzmann et al. (Advanced
// Robotics 2021; ref. [17] of Yoshida and Hosoda) is a conductive fabric wrapped round the
// PAM: its resistance follows the muscle's diameter, and the lab converts that linearly into
// a rate of length change, calibrated to the linear encoder at the start (Yoshida and
// Hosoda, Sec. IV-C). Two errors of such a fabric, its nonlinearity and its drift
// (FiberHardware), make the integrated length drift for a reason.
#pragma once

#include <string>
#include <vector>

#include "sensing/prony_creep.h"

namespace pamsim {

// Figures: Hitzmann et al.'s own calibration curves and drift figures could not be
// retrieved, so both are ASSUMPTIONS (docs/physics.md, departures), sized from knitted and
// stitched conductive strain sensors in the literature: a linear fit of R^2 = 0.984 with 6.25 %
// hysteresis (Tangsirinaruenart & Stylios, "A novel textile stitch-based strain sensor for
// wearable end users", 2019, art. 1469), 0.3 % nonlinearity but 12.5 % hysteresis and large
// drift in weft knits (preprints.org 202308.0816, "Advancing smart textiles: structural
// evolution of knitted piezoresistive strain sensors", 2023), low hysteresis only with the
// conductive yarn inside (Bozali et al., Sensors 22(19):7688, 2022), and a gauge factor that
// changes over a test's cycles (Isaia et al., "Effect of mechanical preconditioning on the
// electrical properties of knitted conductive textiles during cyclic loading"). Taken here:
// N = 5 % at S = 20 mm (about the arm's muscles' stroke) and one creep term of 5 % with a
// 10 s retardation time (the order of the reaching task's 12 s).
//
// Keys sensors.fiber.* (read in sim/io; SI inside).
struct FiberHardwareConfig {
  bool enabled = false;           // sensors.fiber.model: "ideal" | "fabric"
  double nonlinearity_pct = 5.0;  // sensors.fiber.nonlinearity_pct, within (-100, 100)
  double span_m = 0.020;          // sensors.fiber.span_mm, > 0
  // sensors.fiber.creep_weights, creep_times_s (two lists of one length)
  // (one term, built without an initializer list: GCC 12 warns on one in a member default)
  std::vector<PronyTerm> creep = std::vector<PronyTerm>(1, PronyTerm{0.05, 10.0});
};

// Throws InputError "<key> must be ..., got <value>" naming the sensors.fiber.* key.
void validate(const FiberHardwareConfig& config);

// The fabric's two errors:
//   1. nonlinearity: the resistance is not linear in the strain it is calibrated on, so the
//      linear conversion reads a displacement u = l - l_0 from the calibration length as
//        u_nl = u (1 + (N / 100) u / S),
//      N % of the reading at a displacement of S (sensors.fiber.nonlinearity_pct, span_mm);
//      the sign of N says whether the fabric over- or under-reads a stretch;
//   2. drift: the knit relaxes under a held strain (its fibres slip and settle), so the
//      reading creeps after every change of length and recovers after it: the same Prony
//      series as the gauge's board (prony_creep.h) on u_nl, with weights g_i and times tau_i
//      (sensors.fiber.creep_weights, creep_times_s): a held displacement reads
//      u_nl (1 + sum g_i (1 - exp(-t / tau_i))).
// The rate the sensor reports is the change of that reading over the tick (then the white
// noise of sensors.fiber_noise_mm_s, as for the ideal sensor).
class FiberHardware {
 public:
  // config must have passed validate (asserted); sample_period_s > 0. The fabric starts at
  // rest at its calibration length.
  FiberHardware(const FiberHardwareConfig& config, double sample_period_s);
  // The displacement the fabric reads at the end of a tick over which the muscle was
  // displaced by u_m from its calibration length.
  double reading_m(double u_m);

 private:
  double quadratic_per_m_ = 0.0;  // N / (100 S)
  PronyCreep creep_;
};

}  // namespace pamsim
