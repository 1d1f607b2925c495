// pneumatic_params.cc: TOML loader and validation for PneumaticParams (see the header).
#include "pneumatics/pneumatic_params.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/enum_names.h"
#include "base/format.h"
#include "base/file_changes.h"
#include "base/input_error.h"
#include "base/key_table.h"
#include "base/toml_file.h"
#include "base/units.h"

namespace pamsim {
namespace {

// the regulator loop's feedback, sense and restrictions ([regulator]); `require` throws
template <typename Require>
void validate_regulator_loop(const PneumaticParams& p, const Require& require) {
  const auto finite = [](double v) { return std::isfinite(v); };
  require(finite(p.regulator_sample_period_s) && p.regulator_sample_period_s > 0.0 &&
              p.regulator_sample_period_s <= 0.1,
          "regulator sample period must be in (0, 0.1] s, got " +
              format_value(p.regulator_sample_period_s));
  // a restriction that must pass air: C > 0, b below the laminar ratio
  const auto restriction = [&](const char* what, double c, double b) {
    require(finite(c) && c > 0.0,
            std::string(what) + " sonic conductance must be > 0, got " + format_value(c));
    require(b >= 0.0 && b < p.laminar_ratio,
            std::string(what) + " critical pressure ratio must be in [0, laminar ratio), got " +
                format_value(b));
  };
  if (p.regulator_supply_conductance_m3_per_s_pa || p.regulator_supply_critical_ratio) {
    restriction("regulator supply", regulator_supply_conductance(p),
                regulator_supply_critical_ratio(p));
  }
  if (p.regulator_exhaust_conductance_m3_per_s_pa || p.regulator_exhaust_critical_ratio) {
    restriction("regulator exhaust", regulator_exhaust_conductance(p),
                regulator_exhaust_critical_ratio(p));
  }
  restriction("tube", p.tube_conductance_m3_per_s_pa, p.tube_critical_ratio);
  require(
      finite(p.regulator_outlet_volume_m3) && p.regulator_outlet_volume_m3 > 0.0,
      "regulator outlet volume must be > 0 m^3, got " + format_value(p.regulator_outlet_volume_m3));
}

}  // namespace

namespace {
constexpr EnumName<RegulatorFeedback> kFeedbackNames[] = {{RegulatorFeedback::kInstant, "instant"},
                                                          {RegulatorFeedback::kDelayed, "delayed"}};
constexpr EnumName<RegulatorSense> kSenseNames[] = {{RegulatorSense::kChamber, "chamber"},
                                                    {RegulatorSense::kOutlet, "outlet"}};
}  // namespace

RegulatorFeedback parse_regulator_feedback(const std::string& name, const std::string& context) {
  return parse_name(kFeedbackNames, name, context);
}
const char* regulator_feedback_name(RegulatorFeedback feedback) {
  return name_of(kFeedbackNames, feedback);
}
RegulatorSense parse_regulator_sense(const std::string& name, const std::string& context) {
  return parse_name(kSenseNames, name, context);
}
const char* regulator_sense_name(RegulatorSense sense) { return name_of(kSenseNames, sense); }

double regulator_supply_conductance(const PneumaticParams& p) {
  return p.regulator_supply_conductance_m3_per_s_pa.value_or(p.sonic_conductance_m3_per_s_pa);
}
double regulator_supply_critical_ratio(const PneumaticParams& p) {
  return p.regulator_supply_critical_ratio.value_or(p.critical_pressure_ratio);
}
double regulator_exhaust_conductance(const PneumaticParams& p) {
  return p.regulator_exhaust_conductance_m3_per_s_pa.value_or(p.sonic_conductance_m3_per_s_pa);
}
double regulator_exhaust_critical_ratio(const PneumaticParams& p) {
  return p.regulator_exhaust_critical_ratio.value_or(p.critical_pressure_ratio);
}

void validate_pneumatic_params(const PneumaticParams& p, const std::string& context) {
  auto require = [&](bool ok, const std::string& what) {
    if (!ok) throw InputError(context + ": " + what);
  };
  auto finite = [](double v) { return std::isfinite(v); };
  require(finite(p.supply_gauge_pa) && p.supply_gauge_pa > 0.0,
          "supply pressure must be > 0 Pa, got " + format_value(p.supply_gauge_pa));
  require(finite(p.atmospheric_pa) && p.atmospheric_pa > 0.0,
          "atmospheric pressure must be > 0 Pa, got " + format_value(p.atmospheric_pa));
  require(finite(p.gas_constant_j_per_kg_k) && p.gas_constant_j_per_kg_k > 0.0,
          "gas constant must be > 0, got " + format_value(p.gas_constant_j_per_kg_k));
  require(finite(p.temperature_k) && p.temperature_k > 0.0,
          "temperature must be > 0 K, got " + format_value(p.temperature_k));
  require(p.polytropic_index >= 1.0 && p.polytropic_index <= 1.4,
          "polytropic index must be in [1, 1.4], got " + format_value(p.polytropic_index));
  require(finite(p.sonic_conductance_m3_per_s_pa) && p.sonic_conductance_m3_per_s_pa >= 0.0,
          "sonic conductance must be >= 0, got " + format_value(p.sonic_conductance_m3_per_s_pa));
  require(
      p.critical_pressure_ratio >= 0.0 && p.critical_pressure_ratio < 1.0,
      "critical pressure ratio must be in [0, 1), got " + format_value(p.critical_pressure_ratio));
  require(p.laminar_ratio > p.critical_pressure_ratio && p.laminar_ratio < 1.0,
          "laminar ratio must be in (critical ratio, 1), got " + format_value(p.laminar_ratio));
  require(
      finite(p.regulator_time_constant_s) && p.regulator_time_constant_s > 0.0,
      "regulator time constant must be > 0 s, got " + format_value(p.regulator_time_constant_s));
  require(p.command_min_gauge_pa >= 0.0 && p.command_min_gauge_pa < p.command_max_gauge_pa &&
              p.command_max_gauge_pa <= p.supply_gauge_pa,
          "command range must satisfy 0 <= min < max <= supply, got [" +
              format_value(p.command_min_gauge_pa) + ", " + format_value(p.command_max_gauge_pa) +
              "] Pa with supply " + format_value(p.supply_gauge_pa) + " Pa");
  require(finite(p.tube_dead_volume_m3) && p.tube_dead_volume_m3 >= 0.0,
          "tube dead volume must be >= 0 m^3, got " + format_value(p.tube_dead_volume_m3));
  require(finite(p.first_order_time_constant_s) && p.first_order_time_constant_s > 0.0,
          "first-order time constant must be > 0 s, got " +
              format_value(p.first_order_time_constant_s));
  require(finite(p.regulator_dead_time_s) && p.regulator_dead_time_s >= 0.0,
          "regulator dead time must be >= 0 s, got " + format_value(p.regulator_dead_time_s));
  require(finite(p.regulator_valve_time_constant_s) && p.regulator_valve_time_constant_s > 0.0,
          "regulator valve time constant must be > 0 s, got " +
              format_value(p.regulator_valve_time_constant_s));
  require(finite(p.regulator_proportional_band_pa) && p.regulator_proportional_band_pa > 0.0,
          "regulator proportional band must be > 0 Pa, got " +
              format_value(p.regulator_proportional_band_pa));
  validate_regulator_loop(p, require);
  require(p.solver.relative_tolerance > 0.0 && p.solver.relative_tolerance <= 1e-2,
          "solver relative tolerance must be in (0, 1e-2], got " +
              format_value(p.solver.relative_tolerance));
  require(finite(p.solver.absolute_tolerance_pa) && p.solver.absolute_tolerance_pa > 0.0,
          "solver absolute tolerance must be > 0 Pa, got " +
              format_value(p.solver.absolute_tolerance_pa));
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDm3PerSBar = 1e-3 / units::kPaPerBar;  // dm^3/(s bar) -> m^3/(s Pa)
const char* const kDm3PerSBarUnit = "dm^3/(s bar)";

// a choice between two policies of the solver at a discontinuity
ChoiceRow policy_row(const char* name, const char* doc, CommandChangePolicy* field) {
  return {
      name,
      {"warm", "reinit"},
      doc,
      [field](const std::string& v) {
        *field = v == "warm" ? CommandChangePolicy::kWarm : CommandChangePolicy::kReinit;
      },
      [field] { return std::string(*field == CommandChangePolicy::kWarm ? "warm" : "reinit"); }};
}

}  // namespace

// clang-format off
KeyTable pneumatic_regulator_table(PneumaticParams* params) {
  PneumaticParams& p = *params;
  return {"regulator",
          {{"dead_time_ms", "ms", 1e-3, {0.0, 1000.0, false, false},
            "the dead time before a command (and a delayed loop's sample) acts",
            &p.regulator_dead_time_s},
           {"valve_time_constant_ms", "ms", 1e-3, {0.0, 10000.0, true, false},
            "the main valve's first-order lag", &p.regulator_valve_time_constant_s},
           {"proportional_band_kPa", "kPa", 1e3, {0.0, 2000.0, true, false},
            "the pressure error that opens the main valve fully",
            &p.regulator_proportional_band_pa},
           {"sample_period_ms", "ms", 1e-3, {0.0, 100.0, true, false},
            "how often a delayed loop samples its sensed pressure (feedback = \"delayed\")",
            &p.regulator_sample_period_s},
           {"supply_sonic_conductance_dm3_per_s_bar", kDm3PerSBarUnit, kDm3PerSBar,
            {0.0, 100.0, true, false}, "ISO 6358 C of the filling path (unset: [valve]'s)",
            nullptr, &p.regulator_supply_conductance_m3_per_s_pa},
           {"supply_critical_pressure_ratio", "", 1.0, {0.0, 1.0, false, true},
            "ISO 6358 b of the filling path (unset: [valve]'s)", nullptr,
            &p.regulator_supply_critical_ratio},
           {"exhaust_sonic_conductance_dm3_per_s_bar", kDm3PerSBarUnit, kDm3PerSBar,
            {0.0, 100.0, true, false}, "ISO 6358 C of the venting path (unset: [valve]'s)",
            nullptr, &p.regulator_exhaust_conductance_m3_per_s_pa},
           {"exhaust_critical_pressure_ratio", "", 1.0, {0.0, 1.0, false, true},
            "ISO 6358 b of the venting path (unset: [valve]'s)", nullptr,
            &p.regulator_exhaust_critical_ratio},
           {"outlet_volume_cm3", "cm^3", 1e-6, {0.0, 1000.0, true, false},
            "the gas volume at the regulator's outlet port (sense = \"outlet\")",
            &p.regulator_outlet_volume_m3},
           {"tube_sonic_conductance_dm3_per_s_bar", kDm3PerSBarUnit, kDm3PerSBar,
            {0.0, 100.0, true, false},
            "ISO 6358 C of the tube and fittings from the outlet to the chamber",
            &p.tube_conductance_m3_per_s_pa},
           {"tube_critical_pressure_ratio", "", 1.0, {0.0, 1.0, false, true},
            "ISO 6358 b of that tube", &p.tube_critical_ratio}},
          {{"feedback", {"instant", "delayed"},
            "the loop acts on its sensed pressure as it is, or as sampled one dead time ago",
            [params](const std::string& v) {
              params->regulator_feedback = parse_regulator_feedback(v, "regulator.feedback");
            },
            [params] { return std::string(regulator_feedback_name(params->regulator_feedback)); }},
           {"sense", {"chamber", "outlet"},
            "where the loop senses: in the chamber, or at its own outlet port",
            [params](const std::string& v) {
              params->regulator_sense = parse_regulator_sense(v, "regulator.sense");
            },
            [params] { return std::string(regulator_sense_name(params->regulator_sense)); }}}};
}
// clang-format on

namespace {

// [solver]: CVODE's settings
KeyTable solver_table(PneumaticSolverParams* solver) {
  return {
      "solver",
      {{"relative_tolerance",
        "",
        1.0,
        {0.0, 1e-2, true, false},
        "CVODE's relative tolerance",
        &solver->relative_tolerance},
       {"absolute_tolerance_Pa",
        "Pa",
        1.0,
        {0.0, 1e4, true, false},
        "CVODE's absolute tolerance on the pressures",
        &solver->absolute_tolerance_pa}},
      {{"method",
        {"bdf", "adams"},
        "CVODE's linear multistep method",
        [solver](const std::string& v) {
          solver->method = v == "bdf" ? CvodeMethod::kBdf : CvodeMethod::kAdams;
        },
        [solver] { return std::string(solver->method == CvodeMethod::kBdf ? "bdf" : "adams"); }},
       policy_row("on_command_change",
                  "at a change of valve command, keep CVODE's history or restart it",
                  &solver->on_command_change),
       policy_row("on_loop_action", "the same at each action of a delayed regulator loop",
                  &solver->on_loop_action)}};
}

}  // namespace

// clang-format off
std::vector<KeyTable> pneumatic_key_table(PneumaticParams* params) {
  PneumaticParams& p = *params;
  const double mpa = units::kPaPerMPa;
  return {
      {"supply",
       {{"supply_MPa", "MPa", mpa, {0.0, 2.0, true, false}, "the regulator's supply, gauge",
         &p.supply_gauge_pa},
        {"atmospheric_kPa", "kPa", 1e3, {50.0, 120.0, false, false}, "the atmosphere, absolute",
         &p.atmospheric_pa}},
       {}},
      {"gas",
       {{"gas_constant_J_per_kg_K", "J/(kg K)", 1.0, {0.0, kInf, true, true},
         "the working gas's specific gas constant", &p.gas_constant_j_per_kg_k},
        {"temperature_K", "K", 1.0, {200.0, 400.0, false, false},
         "the supply's and the chamber's gas temperature", &p.temperature_k},
        {"polytropic_index", "", 1.0, {1.0, 1.4, false, false},
         "n of the chamber's p V^n (1 isothermal, 1.4 adiabatic)", &p.polytropic_index}},
       {}},
      {"valve",
       {{"sonic_conductance_dm3_per_s_bar", kDm3PerSBarUnit, kDm3PerSBar,
         {0.0, 100.0, false, false},
         "ISO 6358 C of the restriction between regulator and chamber (0: closed)",
         &p.sonic_conductance_m3_per_s_pa},
        {"critical_pressure_ratio", "", 1.0, {0.0, 1.0, false, true},
         "ISO 6358 b of that restriction", &p.critical_pressure_ratio},
        {"laminar_ratio", "", 1.0, {0.9, 1.0, false, true},
         "the pressure ratio above which the flow is taken as linear to zero at 1",
         &p.laminar_ratio},
        {"regulator_time_constant_ms", "ms", 1e-3, {0.0, 10000.0, true, false},
         "the regulated pressure's first-order lag (valve.model = \"iso6358\")",
         &p.regulator_time_constant_s},
        {"command_min_MPa", "MPa", mpa, {0.0, 2.0, false, false},
         "the lowest command, gauge (commands are clamped to [min, max])",
         &p.command_min_gauge_pa},
        {"command_max_MPa", "MPa", mpa, {0.0, 2.0, true, false},
         "the highest command, gauge (at most the supply)", &p.command_max_gauge_pa}},
       {}},
      {"chamber",
       {{"tube_dead_volume_cm3", "cm^3", 1e-6, {0.0, 10000.0, false, false},
         "the tube's and fittings' volume between the valve and the muscle",
         &p.tube_dead_volume_m3}},
       {}},
      {"first_order",
       {{"time_constant_ms", "ms", 1e-3, {0.0, 100000.0, true, false},
         "tau of the first-order valve (valve.model = \"first_order\")",
         &p.first_order_time_constant_s}},
       {}},
      pneumatic_regulator_table(params),
      solver_table(&p.solver),
  };
}
// clang-format on

namespace {

// The parameters as `doc` gives them; `path` names it in errors.
PneumaticParams read_pneumatics(const toml::table& doc, const std::string& path) {
  PneumaticParams p;
  read_key_tables(doc, path, pneumatic_key_table(&p));
  // cross-field checks (command range within supply, laminar ratio above b)
  validate_pneumatic_params(p, path);
  return p;
}

}  // namespace

std::vector<KeyDoc> pneumatic_key_docs() {
  PneumaticParams defaults;
  return key_table_docs(pneumatic_key_table(&defaults));
}

PneumaticParams load_pneumatic_params(const std::string& path) {
  return read_pneumatics(parse_toml_file(path), path);
}

PneumaticParams load_pneumatic_params(const std::string& path, const toml::table& changes,
                                      const std::string& prefix) {
  return read_with_changes(path, changes, prefix, read_pneumatics);
}

}  // namespace pamsim
