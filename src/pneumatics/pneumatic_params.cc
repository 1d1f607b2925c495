// pneumatic_params.cc: TOML loader and validation for PneumaticParams (see the header).
#include "pneumatics/pneumatic_params.h"

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/enum_names.h"
#include "base/format.h"
#include "base/file_changes.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "base/units.h"

namespace pamsim {
namespace {

// one numeric key: allowed interval in the file's units and the conversion to SI
struct NumberKey {
  const char* name;
  double lo;
  double hi;
  bool lo_open;
  bool hi_open;
  double to_si;
  double* target;
  std::optional<double>* optional_target = nullptr;   // a key whose absence means "unset"
};

struct StringKey {
  const char* name;
  std::vector<std::string> allowed;
  std::function<void(const std::string&)> set;
};

struct Table {
  const char* name;
  std::vector<NumberKey> numbers;
  std::vector<StringKey> strings;
};

std::string interval(const NumberKey& k) {
  std::string lo = k.lo_open ? "(" : "[";
  std::string hi = k.hi_open ? ")" : "]";
  std::string hi_value = std::isinf(k.hi) ? "inf" : format_value(k.hi);
  return lo + format_value(k.lo) + ", " + hi_value + hi;
}

void read_number(const std::string& path, const std::string& table, const NumberKey& k,
                 const toml::node& node) {
  const std::string key = table + "." + k.name;
  if (!node.is_number()) {
    std::ostringstream type;
    type << node.type();
    throw file_key_error(path, key, "must be a number, got a " + type.str());
  }
  const double v = node.value<double>().value();
  const bool ok = std::isfinite(v) && (k.lo_open ? v > k.lo : v >= k.lo) &&
                  (k.hi_open ? v < k.hi : v <= k.hi);
  if (!ok) {
    throw file_key_error(path, key,
                         "value " + format_value(v) + " out of range, allowed " + interval(k));
  }
  if (k.optional_target != nullptr) {
    *k.optional_target = v * k.to_si;
  } else {
    *k.target = v * k.to_si;
  }
}

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
  require(finite(p.regulator_outlet_volume_m3) && p.regulator_outlet_volume_m3 > 0.0,
          "regulator outlet volume must be > 0 m^3, got " +
              format_value(p.regulator_outlet_volume_m3));
}

}  // namespace

namespace {
constexpr EnumName<RegulatorFeedback> kFeedbackNames[] = {
    {RegulatorFeedback::kInstant, "instant"}, {RegulatorFeedback::kDelayed, "delayed"}};
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
          "sonic conductance must be >= 0, got " +
              format_value(p.sonic_conductance_m3_per_s_pa));
  require(p.critical_pressure_ratio >= 0.0 && p.critical_pressure_ratio < 1.0,
          "critical pressure ratio must be in [0, 1), got " +
              format_value(p.critical_pressure_ratio));
  require(p.laminar_ratio > p.critical_pressure_ratio && p.laminar_ratio < 1.0,
          "laminar ratio must be in (critical ratio, 1), got " + format_value(p.laminar_ratio));
  require(finite(p.regulator_time_constant_s) && p.regulator_time_constant_s > 0.0,
          "regulator time constant must be > 0 s, got " +
              format_value(p.regulator_time_constant_s));
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

// [regulator]: the closed-loop regulator's keys (valve.model = "regulator")
Table regulator_table(PneumaticParams* params, double dm3_per_s_bar) {
  PneumaticParams& p = *params;
  return {"regulator",
          {{"dead_time_ms", 0.0, 1000.0, false, false, 1e-3, &p.regulator_dead_time_s},
           {"valve_time_constant_ms", 0.0, 10000.0, true, false, 1e-3,
            &p.regulator_valve_time_constant_s},
           {"proportional_band_kPa", 0.0, 2000.0, true, false, 1e3,
            &p.regulator_proportional_band_pa},
           {"sample_period_ms", 0.0, 100.0, true, false, 1e-3, &p.regulator_sample_period_s},
           {"supply_sonic_conductance_dm3_per_s_bar", 0.0, 100.0, true, false, dm3_per_s_bar,
            nullptr, &p.regulator_supply_conductance_m3_per_s_pa},
           {"supply_critical_pressure_ratio", 0.0, 1.0, false, true, 1.0, nullptr,
            &p.regulator_supply_critical_ratio},
           {"exhaust_sonic_conductance_dm3_per_s_bar", 0.0, 100.0, true, false, dm3_per_s_bar,
            nullptr, &p.regulator_exhaust_conductance_m3_per_s_pa},
           {"exhaust_critical_pressure_ratio", 0.0, 1.0, false, true, 1.0, nullptr,
            &p.regulator_exhaust_critical_ratio},
           {"outlet_volume_cm3", 0.0, 1000.0, true, false, 1e-6, &p.regulator_outlet_volume_m3},
           {"tube_sonic_conductance_dm3_per_s_bar", 0.0, 100.0, true, false, dm3_per_s_bar,
            &p.tube_conductance_m3_per_s_pa},
           {"tube_critical_pressure_ratio", 0.0, 1.0, false, true, 1.0, &p.tube_critical_ratio}},
          {{"feedback",
            {"instant", "delayed"},
            [params](const std::string& v) {
              params->regulator_feedback = parse_regulator_feedback(v, "regulator.feedback");
            }},
           {"sense",
            {"chamber", "outlet"},
            [params](const std::string& v) {
              params->regulator_sense = parse_regulator_sense(v, "regulator.sense");
            }}}};
}

// The file's schema: table, key (unit in the name), allowed interval, factor to SI; each
// key writes its field of *params.
std::vector<Table> pneumatic_schema(PneumaticParams* params) {
  PneumaticParams& p = *params;
  PneumaticSolverParams* solver = &p.solver;
  const double inf = std::numeric_limits<double>::infinity();
  const double kDm3PerSBar = 1e-3 / units::kPaPerBar;   // dm^3/(s bar) -> m^3/(s Pa)
  return {
      {"supply",
       {{"supply_MPa", 0.0, 2.0, true, false, units::kPaPerMPa, &p.supply_gauge_pa},
        {"atmospheric_kPa", 50.0, 120.0, false, false, 1e3, &p.atmospheric_pa}},
       {}},
      {"gas",
       {{"gas_constant_J_per_kg_K", 0.0, inf, true, true, 1.0, &p.gas_constant_j_per_kg_k},
        {"temperature_K", 200.0, 400.0, false, false, 1.0, &p.temperature_k},
        {"polytropic_index", 1.0, 1.4, false, false, 1.0, &p.polytropic_index}},
       {}},
      {"valve",
       {{"sonic_conductance_dm3_per_s_bar", 0.0, 100.0, false, false, kDm3PerSBar,
         &p.sonic_conductance_m3_per_s_pa},
        {"critical_pressure_ratio", 0.0, 1.0, false, true, 1.0, &p.critical_pressure_ratio},
        {"laminar_ratio", 0.9, 1.0, false, true, 1.0, &p.laminar_ratio},
        {"regulator_time_constant_ms", 0.0, 10000.0, true, false, 1e-3,
         &p.regulator_time_constant_s},
        {"command_min_MPa", 0.0, 2.0, false, false, units::kPaPerMPa, &p.command_min_gauge_pa},
        {"command_max_MPa", 0.0, 2.0, true, false, units::kPaPerMPa,
         &p.command_max_gauge_pa}},
       {}},
      {"chamber",
       {{"tube_dead_volume_cm3", 0.0, 10000.0, false, false, 1e-6, &p.tube_dead_volume_m3}},
       {}},
      {"first_order",
       {{"time_constant_ms", 0.0, 100000.0, true, false, 1e-3,
         &p.first_order_time_constant_s}},
       {}},
      regulator_table(params, kDm3PerSBar),
      {"solver",
       {{"relative_tolerance", 0.0, 1e-2, true, false, 1.0, &solver->relative_tolerance},
        {"absolute_tolerance_Pa", 0.0, 1e4, true, false, 1.0, &solver->absolute_tolerance_pa}},
       {{"method",
         {"bdf", "adams"},
         [solver](const std::string& v) {
           solver->method = v == "bdf" ? CvodeMethod::kBdf : CvodeMethod::kAdams;
         }},
        {"on_command_change",
         {"warm", "reinit"},
         [solver](const std::string& v) {
           solver->on_command_change =
               v == "warm" ? CommandChangePolicy::kWarm : CommandChangePolicy::kReinit;
         }},
        {"on_loop_action",
         {"warm", "reinit"},
         [solver](const std::string& v) {
           solver->on_loop_action =
               v == "warm" ? CommandChangePolicy::kWarm : CommandChangePolicy::kReinit;
         }}}},
  };
}

// "a | b": the values a string key allows
std::string allowed_values(const StringKey& k) {
  std::string allowed;
  for (const std::string& a : k.allowed) allowed += (allowed.empty() ? "" : " | ") + a;
  return allowed;
}

// One string key: one of the values it allows, handed to its setter.
void read_string(const std::string& path, const std::string& table, const StringKey& k,
                 const toml::node& node) {
  const std::string allowed = allowed_values(k);
  const auto value = node.value<std::string>();
  if (!value) {
    throw file_key_error(path, table + "." + k.name, "must be a string, allowed " + allowed);
  }
  bool ok = false;
  for (const std::string& a : k.allowed) ok = ok || *value == a;
  if (!ok) {
    throw file_key_error(path, table + "." + k.name,
                         "unknown value \"" + *value + "\", allowed " + allowed);
  }
  k.set(*value);
}

// One key of a table: read by the schema, or refused with the keys the table has.
void read_key(const std::string& path, const std::string& table_name, const Table& table,
              const std::string& key_name, const toml::node& node) {
  bool known = false;
  for (const NumberKey& k : table.numbers) {
    if (key_name == k.name) {
      read_number(path, table_name, k, node);
      known = true;
    }
  }
  for (const StringKey& k : table.strings) {
    if (key_name != k.name) continue;
    known = true;
    read_string(path, table_name, k, node);
  }
  if (!known) {
    std::string allowed;
    for (const NumberKey& k : table.numbers) allowed += std::string(allowed.empty() ? "" : ", ") + k.name;
    for (const StringKey& k : table.strings) allowed += std::string(allowed.empty() ? "" : ", ") + k.name;
    throw file_key_error(path, table_name + "." + key_name, "unknown key (allowed: " + allowed + ")");
  }
}

// The parameters as `doc` gives them; `path` names it in errors.
PneumaticParams read_pneumatics(const toml::table& doc, const std::string& path) {
  PneumaticParams p;
  const std::vector<Table> schema = pneumatic_schema(&p);

  // walk the document: every table and key must be in the schema
  for (const auto& [table_key, table_node] : doc) {
    const std::string table_name(table_key.str());
    const Table* table = nullptr;
    for (const Table& t : schema) {
      if (table_name == t.name) table = &t;
    }
    if (table == nullptr) {
      throw file_key_error(path, table_name,
                           "unknown table (allowed: supply, gas, valve, chamber, first_order, "
                           "regulator, solver)");
    }
    const toml::table* tbl = table_node.as_table();
    if (tbl == nullptr) {
      throw file_key_error(path, table_name, "must be a table");
    }
    for (const auto& [key, node] : *tbl) {
      read_key(path, table_name, *table, std::string(key.str()), node);
    }
  }

  // cross-field checks (command range within supply, laminar ratio above b)
  validate_pneumatic_params(p, path);
  return p;
}

}  // namespace

PneumaticParams load_pneumatic_params(const std::string& path) {
  return read_pneumatics(parse_toml_file(path), path);
}

PneumaticParams load_pneumatic_params(const std::string& path, const toml::table& changes,
                                      const std::string& prefix) {
  return read_with_changes(path, changes, prefix, read_pneumatics);
}

}  // namespace pamsim
