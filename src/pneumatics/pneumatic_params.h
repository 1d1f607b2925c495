// pneumatic_params.h: parameters of the valve (proportional pressure regulator + ISO 6358
// restriction), the muscle chamber gas and the CVODE solver, read from one TOML file
// (models/pams/pneumatics.toml). The file uses named practical units (MPa, kPa,
// dm^3/(s bar), cm^3, ms); this struct is SI (Pa, m^3, s, K) and is filled once by
// load_pneumatic_params(), which validates every value.
#pragma once

#include <optional>
#include <string>

#include <toml++/toml.h>

#include "base/key_table.h"
#include "pneumatics/ode_system.h"

namespace pamsim {

// How the integrator treats a change of valve command (a jump in the regulator's
// derivative): keep CVODE's history (warm) or re-initialise it at the change (reinit).
enum class CommandChangePolicy { kWarm, kReinit };

// What the "regulator" valve model's loop acts on ([regulator] feedback, chamber_ode.h):
// the sensed pressure as it is now (kInstant), or as the regulator sampled it one dead time
// ago (kDelayed, a sampled-data controller; pneumatics.h).
enum class RegulatorFeedback { kInstant, kDelayed };
// Where its loop senses ([regulator] sense): in the chamber (kChamber: one gas volume behind
// the valve, the path's restriction lumped into the valve), or at its own outlet port
// (kOutlet: outlet volume -> tube/fitting restriction -> chamber, as an SMC ITV senses).
enum class RegulatorSense { kChamber, kOutlet };

struct PneumaticSolverParams {
  CvodeMethod method = CvodeMethod::kBdf;
  double relative_tolerance = 1e-4;    // [-], (0, 1e-2]
  double absolute_tolerance_pa = 1.0;  // [Pa], > 0
  CommandChangePolicy on_command_change = CommandChangePolicy::kReinit;
  // The same for an action of the delayed regulator loop (the held sensed pressure steps
  // by what the pressure moved in one sample period: a small jump every sample). A file
  // that does not say restarts there, as before the key; the shipped file says "warm".
  CommandChangePolicy on_loop_action = CommandChangePolicy::kReinit;
};

struct PneumaticParams {
  // supply and ambient
  double supply_gauge_pa = 0.7e6;    // regulator inlet, gauge [Pa], > 0
  double atmospheric_pa = 101325.0;  // absolute [Pa], > 0
  // gas
  double gas_constant_j_per_kg_k = 287.0;  // air [J/(kg K)]
  double temperature_k = 293.15;           // supply and chamber gas [K]
  double polytropic_index = 1.2;           // n in [1.0, 1.4]
  // valve: ISO 6358 restriction between regulator and chamber
  double sonic_conductance_m3_per_s_pa = 1e-8;  // C [m^3/(s Pa)], >= 0 (0 = closed)
  double critical_pressure_ratio = 0.3;         // b in [0, 1)
  double laminar_ratio = 0.999;  // r above which psi(r) is linearised to 0 at r = 1; (b, 1)
  // regulator: command -> regulated pressure, first order
  double regulator_time_constant_s = 0.02;  // > 0
  double command_min_gauge_pa = 0.0;        // commands are clamped to [min, max]
  double command_max_gauge_pa = 0.7e6;      // <= supply
  // chamber: tube between valve and muscle
  double tube_dead_volume_m3 = 12.566e-6;  // >= 0
  // first-order valve option: dp/dt = (p_cmd - p) / tau
  double first_order_time_constant_s = 0.1;  // > 0
  // closed-loop regulator option (valve.model = "regulator", chamber_ode.h): the command
  // reaches the regulator after a dead time; its main valve opens toward
  // (p_cmd - p_sensed) / proportional band with a first-order lag, filling from the supply
  // or venting to the atmosphere through its supply or exhaust restriction
  double regulator_dead_time_s = 0.005;            // >= 0
  double regulator_valve_time_constant_s = 0.010;  // > 0
  double regulator_proportional_band_pa = 20.0e3;  // > 0
  RegulatorFeedback regulator_feedback = RegulatorFeedback::kInstant;
  RegulatorSense regulator_sense = RegulatorSense::kChamber;
  // kDelayed: the loop samples its sensed pressure every sample period and acts on each
  // sample one dead time later (the dead time above, which also delays the command)
  double regulator_sample_period_s = 1e-3;  // (0, 0.1]
  // ISO 6358 C [m^3/(s Pa)] and b of the regulator's supply (filling) and exhaust (venting)
  // paths; unset: the [valve] restriction's C and b for both (the model before they were
  // separate). Given: C > 0, b in [0, laminar ratio).
  std::optional<double> regulator_supply_conductance_m3_per_s_pa;
  std::optional<double> regulator_supply_critical_ratio;
  std::optional<double> regulator_exhaust_conductance_m3_per_s_pa;
  std::optional<double> regulator_exhaust_critical_ratio;
  // kOutlet: the gas volume at the regulator's outlet port [m^3], > 0, and the ISO 6358
  // restriction of the tube and fittings from it to the chamber (C > 0, b in [0, laminar
  // ratio)); the tube's volume stays with the chamber (tube_dead_volume_m3)
  double regulator_outlet_volume_m3 = 2e-6;
  double tube_conductance_m3_per_s_pa = 1.3e-8;
  double tube_critical_ratio = 0.4;
  PneumaticSolverParams solver;
};

// ISO 6358-1 reference conditions (ANR: 20 degC, 100 kPa, 65 % RH): the sonic conductance
// C is defined with the density rho0 and temperature T0 below.
inline constexpr double kIso6358ReferenceDensityKgM3 = 1.185;
inline constexpr double kIso6358ReferenceTemperatureK = 293.15;

// Reads and validates `path`. Every key is optional (missing keys keep the defaults
// above). Throws InputError with a one-line message "<path>: <table.key>: <problem>" for a
// missing or unreadable file, a TOML syntax error, an unknown table or key, a value of the
// wrong type, or a non-finite / out-of-range value.
PneumaticParams load_pneumatic_params(const std::string& path);
// The same with `changes` (tables and values of the file's own layout and units, e.g.
// chamber.tube_dead_volume_cm3) written over the file's, each validated as the file's own: a
// scenario's pneumatics.<table>.<field> keys. A refused change is named
// "<prefix><table>.<field>: <problem>" (prefix "pneumatics."); base/file_changes.h.
PneumaticParams load_pneumatic_params(const std::string& path, const toml::table& changes,
                                      const std::string& prefix);

// The file's key table: each key's unit, factor to SI, range and meaning, and the field of
// *params it writes (whose value before a file is read is the key's default). The reader
// reads by it; so do the key reference and the tests' bad values.
std::vector<KeyTable> pneumatic_key_table(PneumaticParams* params);
// Its [regulator] table alone: the closed-loop regulator's keys (valve.model = "regulator"),
// which a scenario's valve.<key> also reads, for a rig's own point of the file's bracket.
KeyTable pneumatic_regulator_table(PneumaticParams* params);
// Every key of the file (its table, unit, default, range and meaning): the file's key
// reference (`pamsim keys --pneumatics`).
std::vector<KeyDoc> pneumatic_key_docs();

// "instant" | "delayed" and "chamber" | "outlet", both ways; parse_* throws InputError
// "<context> must be \"a\" or \"b\", got \"x\"".
RegulatorFeedback parse_regulator_feedback(const std::string& name, const std::string& context);
const char* regulator_feedback_name(RegulatorFeedback feedback);
RegulatorSense parse_regulator_sense(const std::string& name, const std::string& context);
const char* regulator_sense_name(RegulatorSense sense);

// The regulator's supply and exhaust restrictions: the given C and b, else [valve]'s.
double regulator_supply_conductance(const PneumaticParams& params);
double regulator_supply_critical_ratio(const PneumaticParams& params);
double regulator_exhaust_conductance(const PneumaticParams& params);
double regulator_exhaust_critical_ratio(const PneumaticParams& params);

// Checks the cross-field and range constraints listed above; `context` prefixes the
// messages (a file name, or "pneumatic parameters"). Throws InputError.
void validate_pneumatic_params(const PneumaticParams& params, const std::string& context);

}  // namespace pamsim
