// length_validation_protocol.cc: load_length_validation of length_estimation.h, the
// protocol file read and checked (the rig, the laws, the weights, the tensile test and each
// PAM) before anything runs.
#include <algorithm>
#include <set>

#include "base/config_reader.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/units.h"
#include "sim/validate/length_estimation.h"

namespace pamsim {
namespace {

ValidationPam read_pam(ConfigReader& in, const std::string& name, const TensileTestOptions& base,
                       const std::vector<SpringLaw>& laws) {
  const std::string key = "pams." + name;
  ValidationPam pam;
  pam.name = name;
  pam.plant_file = in.require_path(key + ".plant", "the PAM's plant file");
  try {
    pam.plant = load_plant_params(pam.plant_file);
  } catch (const InputError& e) {
    in.fail(key + ".plant", std::string("(") + e.what() + ")");
  }
  const double bladder_mm = in.require_double(key + ".bladder_diameter_mm");
  in.check(bladder_mm > 0.0, key + ".bladder_diameter_mm",
           "must be > 0 mm, got " + format_value(bladder_mm));
  pam.bladder_diameter_m = units::mm_to_m(bladder_mm);

  pam.tensile = base;
  pam.tensile.pressures_mpa = in.get_double_list(key + ".pressures_MPa", {});
  std::set<double> levels(pam.tensile.pressures_mpa.begin(), pam.tensile.pressures_mpa.end());
  in.check(levels.size() >= 3, key + ".pressures_MPa",
           "needs at least 3 distinct pressures (Eq. (4)'s p^2 term), got " +
               std::to_string(levels.size()));
  pam.tensile.max_deformation_mm = in.require_double(key + ".max_deformation_mm");
  try {
    validate_tensile_options(pam.tensile);
  } catch (const InputError& e) {
    in.fail(key, std::string("(") + e.what() + ")");
  }
  pam.offset_mpa = in.require_double(key + ".offset_MPa");
  in.check(pam.offset_mpa > 0.0 && pam.offset_mpa < 1.0, key + ".offset_MPa",
           "must be in (0, 1) MPa, got " + format_value(pam.offset_mpa));

  // Table III's values, by law
  for (const std::string& law_name : in.child_keys(key + ".paper")) {
    const std::string law_key = key + ".paper." + law_name;
    in.check(std::any_of(laws.begin(), laws.end(),
                         [&](SpringLaw l) { return law_name == to_string(l); }),
             law_key, "names no law of `laws`");
    const std::vector<double> v = in.get_double_list(law_key, {});
    in.check(v.size() == 2 && v[0] >= 0.0 && v[1] >= 0.0, law_key,
             "must be [max, RMSE] in % of length, both >= 0");
    pam.paper[law_name] = {v[0], v[1]};
  }
  in.raw(key + ".paper");  // read (an empty or absent table is fine)
  return pam;
}

// `laws`: the spring laws to fit, at least one
std::vector<SpringLaw> read_laws(ConfigReader& in) {
  std::vector<SpringLaw> laws;
  for (const std::string& name : in.get_string_list("laws", {"eq3", "eq4", "eq5"})) {
    try {
      laws.push_back(parse_spring_law(name, "laws"));
    } catch (const InputError& e) {
      in.fail("laws", std::string("(") + e.what() + ")");
    }
  }
  in.check(!laws.empty(), "laws", "must name at least one law");
  return laws;
}

// `weights_kg`: the hanging weights, each in (0, 1000]
std::vector<double> read_weights(ConfigReader& in) {
  const std::vector<double> weights = in.get_double_list("weights_kg", {5.0, 10.0});
  in.check(!weights.empty(), "weights_kg", "must hold at least one weight");
  for (double w : weights) {
    in.check(w > 0.0 && w <= 1000.0, "weights_kg",
             "must be in (0, 1000] kg, got " + format_value(w));
  }
  return weights;
}

// [tensile]: the options every PAM's test shares, and the strain gauge (spec->gauge_file,
// spec->gauge) the fitted estimators get
TensileTestOptions read_tensile(ConfigReader& in, LengthValidationSpec* spec) {
  TensileTestOptions base;
  base.step_mm = in.get_double("tensile.step_mm", base.step_mm);
  base.noise_pressure_mpa = in.get_double("tensile.noise_pressure_MPa", 0.0);
  base.noise_force_n = in.get_double("tensile.noise_force_N", 0.0);
  base.noise_length_mm = in.get_double("tensile.noise_length_mm", 0.0);
  const std::int64_t seed = in.get_int("tensile.seed", 1);
  in.check(seed >= 0, "tensile.seed", "must be >= 0");
  base.seed = static_cast<std::uint64_t>(seed);
  spec->gauge_file = in.require_path("tensile.sensors_from",
                                     "the strain gauge of the rig's force reading, Eq. (8)");
  try {
    const PamParams sensors = load_pam_params(spec->gauge_file);
    in.check(sensors.strain_gauge.has_value(), "tensile.sensors_from",
             "(" + spec->gauge_file + ") needs a [strain_gauge] table (Eq. (8))");
    spec->gauge = *sensors.strain_gauge;
  } catch (const InputError& e) {
    in.fail("tensile.sensors_from", std::string("(") + e.what() + ")");
  }
  return base;
}

// --pams: each name once, each a PAM of the file (`names`)
void check_pams_asked(const std::vector<std::string>& only, const std::vector<std::string>& names,
                      const std::string& path) {
  for (std::size_t i = 0; i < only.size(); ++i) {
    const std::string& wanted = only[i];
    if (std::find(only.begin(), only.begin() + i, wanted) != only.begin() + i) {
      throw InputError("--pams: " + wanted + " is named twice");
    }
    if (std::find(names.begin(), names.end(), wanted) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      throw InputError("--pams: unknown PAM " + wanted + "; " + path + " has " + list);
    }
  }
}

// The PAMs `only` names, in its order (`only` empty: all, in the file's)
std::vector<ValidationPam> pams_asked(std::vector<ValidationPam> pams,
                                      const std::vector<std::string>& only) {
  if (only.empty()) return pams;
  std::vector<ValidationPam> ordered;
  for (const std::string& wanted : only) {
    for (const ValidationPam& p : pams) {
      if (p.name == wanted) ordered.push_back(p);
    }
  }
  return ordered;
}

}  // namespace

LengthValidationSpec load_length_validation(const std::string& path,
                                            const std::vector<std::string>& only,
                                            const std::vector<std::string>& protocol_overrides) {
  ConfigReader in(path);
  in.apply_overrides(protocol_overrides);
  LengthValidationSpec spec;
  spec.file = path;
  spec.rig_file = in.require_path("rig", "the pulley rig's scenario");
  spec.overrides = in.get_string_list("overrides", {});
  spec.laws = read_laws(in);
  spec.weights_kg = read_weights(in);
  const TensileTestOptions base = read_tensile(in, &spec);

  const std::vector<std::string> names = in.child_keys("pams");
  in.check(!names.empty(), "pams", "must hold at least one [pams.<NAME>] table");
  check_pams_asked(only, names, path);
  spec.pam_names = names;
  std::vector<ValidationPam> pams;
  for (const std::string& name : names) {
    ValidationPam pam = read_pam(in, name, base, spec.laws);  // every PAM validated
    if (only.empty() || std::find(only.begin(), only.end(), name) != only.end()) {
      pams.push_back(std::move(pam));
    }
  }
  spec.pams = pams_asked(std::move(pams), only);
  spec.budget = read_budget_sources(in);
  spec.brackets = read_brackets(in, &spec.bracket_seed);
  in.reject_unknown();
  return spec;
}

LengthValidationSpec with_plant_changes(const LengthValidationSpec& spec,
                                        std::vector<std::string>* overrides) {
  LengthValidationSpec drawn = spec;
  std::vector<std::string> rest;
  for (const std::string& o : *overrides) {
    if (o.rfind("pams.", 0) != 0) {
      rest.push_back(o);
      continue;
    }
    const std::size_t dot = o.find('.', 5);
    const std::string name = o.substr(5, dot == std::string::npos ? std::string::npos : dot - 5);
    const std::string plant = "pams." + name + ".plant.";
    if (o.rfind(plant, 0) != 0 || o.find('=') == std::string::npos) {
      throw InputError("--set " + o +
                       ": only a plant's field, pams.<NAME>.plant.<table>.<field>, "
                       "may be changed");
    }
    if (std::find(spec.pam_names.begin(), spec.pam_names.end(), name) == spec.pam_names.end()) {
      throw InputError("--set " + o + ": " + spec.file + " has no PAM " + name);
    }
    const auto pam = std::find_if(drawn.pams.begin(), drawn.pams.end(),
                                  [&](const ValidationPam& p) { return p.name == name; });
    if (pam != drawn.pams.end()) pam->plant_changes.push_back(o.substr(plant.size()));
  }
  for (ValidationPam& pam : drawn.pams) {
    if (pam.plant_changes.empty()) continue;
    ConfigReader changes("", "pams." + pam.name + ".plant");
    changes.apply_overrides(pam.plant_changes);
    pam.plant =
        load_plant_params(pam.plant_file, changes.document(), "pams." + pam.name + ".plant.");
  }
  *overrides = rest;
  return drawn;
}

}  // namespace pamsim
