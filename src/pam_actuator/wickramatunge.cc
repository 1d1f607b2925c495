// wickramatunge.cc: Eq. (1)-(2) of Wickramatunge and Leephakpreeda and its loader, see
// wickramatunge.h.
#include "pam_actuator/wickramatunge.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "base/input_error.h"
#include "base/toml_file.h"
#include "base/units.h"

namespace pamsim {
namespace {

constexpr const char* kDirectionKey[] = {"extension", "contraction"};
constexpr const char* kRangeKey[] = {"low", "high"};

// Eq. (2) in paper units: K [N/cm] from P [bar], Ls [cm]
double stiffness_paper(const WickramatungeCoefficients& c, double p_bar, double ls_cm) {
  return c.a0 * p_bar * p_bar + c.a1 * p_bar * ls_cm + c.a2 * ls_cm * ls_cm + c.a3;
}

[[noreturn]] void fail(const std::string& file, const std::string& key,
                       const std::string& problem) {
  throw InputError(file + ": " + key + ": " + problem);
}

// every key of `table` must be one of `allowed`
void reject_unknown(const std::string& file, const std::string& prefix, const toml::table& table,
                    const std::string& allowed) {
  for (const auto& [k, v] : table) {
    const std::string name(k.str());
    if (("," + allowed + ",").find("," + name + ",") == std::string::npos) {
      fail(file, prefix + name, "unknown key (allowed here: " + allowed + ")");
    }
  }
}

double read_number(const std::string& file, const std::string& key, const toml::table& t,
                   const std::string& name) {
  const toml::node* n = t.get(name);
  if (n == nullptr) fail(file, key, "missing (a number is required)");
  const std::optional<double> v = n->value<double>();
  if (!v || n->is_boolean()) fail(file, key, "must be a number");
  if (!std::isfinite(*v)) fail(file, key, "must be finite");
  return *v;
}

const toml::table& read_table(const std::string& file, const std::string& key, const toml::table& t,
                              const std::string& name) {
  const toml::node* n = t.get(name);
  if (n == nullptr || !n->is_table()) fail(file, key, "missing table");
  return *n->as_table();
}

void check_units(const std::string& path, const toml::table& root) {
  const toml::table& u = read_table(path, "units", root, "units");
  reject_unknown(path, "units.", u, "pressure,length,stiffness");
  const std::pair<const char*, const char*> expected[] = {
      {"pressure", "bar"}, {"length", "cm"}, {"stiffness", "N/cm"}};
  for (const auto& [k, unit] : expected) {
    const std::string got = u[k].value_or(std::string());
    if (got != unit) {
      fail(path, std::string("units.") + k,
           "must be \"" + std::string(unit) +
               "\" (Table 1 of Wickramatunge and Leephakpreeda), got \"" + got + "\"");
    }
  }
}

}  // namespace

StretchDirection stretch_direction(double ls_dot_m_per_s, StretchDirection previous) {
  if (ls_dot_m_per_s > 0.0) return StretchDirection::kExtension;
  if (ls_dot_m_per_s < 0.0) return StretchDirection::kContraction;
  return previous;
}

double wickramatunge_stiffness(const WickramatungeModel& model, double p_pa, double ls_m,
                               StretchDirection direction) {
  const WickramatungeCoefficients& c = model.coefficients(direction, model.range(p_pa));
  const double k_n_per_cm = stiffness_paper(c, p_pa / units::kPaPerBar, ls_m / units::kMPerCm);
  return k_n_per_cm / units::kMPerCm;
}

double wickramatunge_force(const WickramatungeModel& model, double p_pa, double ls_m,
                           StretchDirection direction) {
  if (!(ls_m > 0.0)) return 0.0;
  // Eq. (1) in paper units: F [N] = K [N/cm] Ls [cm]
  const WickramatungeCoefficients& c = model.coefficients(direction, model.range(p_pa));
  const double p_bar = p_pa / units::kPaPerBar, ls_cm = ls_m / units::kMPerCm;
  return stiffness_paper(c, p_bar, ls_cm) * ls_cm;
}

DeformationEstimate invert_wickramatunge(const WickramatungeModel& model, double p_pa, double f_n,
                                         StretchDirection direction) {
  DeformationEstimate out;
  if (!std::isfinite(p_pa) || !std::isfinite(f_n)) {
    out.status = InversionStatus::kNoPhysicalRoot;
    return out;
  }
  if (f_n <= 0.0) return out;  // slack: Ls = 0

  // Eq. (1)-(2) as a cubic in Ls [cm]: a2 Ls^3 + a1 P Ls^2 + (a0 P^2 + a3) Ls = F
  const WickramatungeCoefficients& c = model.coefficients(direction, model.range(p_pa));
  const double p_bar = p_pa / units::kPaPerBar;
  const double ls_cm = smallest_positive_root(c.a2, c.a1 * p_bar, c.a0 * p_bar * p_bar + c.a3, f_n);
  if (ls_cm > 0.0 && std::isfinite(ls_cm)) {
    out.d_m = ls_cm * units::kMPerCm;
    out.status = InversionStatus::kOk;
  } else {
    out.status = InversionStatus::kNoPhysicalRoot;
  }
  return out;
}

WickramatungeModel load_wickramatunge(const std::string& path) {
  const toml::table root = parse_toml_file(path);
  reject_unknown(path, "", root, "name,source,units,pressure_split_bar,extension,contraction");
  check_units(path, root);

  WickramatungeModel model;
  const double split_bar = read_number(path, "pressure_split_bar", root, "pressure_split_bar");
  if (!(split_bar > 0.0)) fail(path, "pressure_split_bar", "must be > 0 bar");
  model.pressure_split_pa = split_bar * units::kPaPerBar;

  // four coefficient sets of Table 1
  for (int d = 0; d < 2; ++d) {
    const toml::table& dir = read_table(path, kDirectionKey[d], root, kDirectionKey[d]);
    reject_unknown(path, std::string(kDirectionKey[d]) + ".", dir, "low,high");
    for (int r = 0; r < 2; ++r) {
      const std::string prefix = std::string(kDirectionKey[d]) + "." + kRangeKey[r];
      const toml::table& t = read_table(path, prefix, dir, kRangeKey[r]);
      reject_unknown(path, prefix + ".", t, "a0,a1,a2,a3");
      WickramatungeCoefficients& c = model.sets[d][r];
      c.a0 = read_number(path, prefix + ".a0", t, "a0");
      c.a1 = read_number(path, prefix + ".a1", t, "a1");
      c.a2 = read_number(path, prefix + ".a2", t, "a2");
      c.a3 = read_number(path, prefix + ".a3", t, "a3");
    }
  }
  return model;
}

}  // namespace pamsim
