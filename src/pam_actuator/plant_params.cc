// plant_params.cc: read and validate a plant file (see plant_params.h).
#include "pam_actuator/plant_params.h"

#include <cmath>
#include <string>
#include <vector>

#include "base/enum_names.h"
#include "base/file_changes.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "base/toml_section.h"
#include "base/units.h"

namespace pamsim {
namespace {

constexpr EnumName<BladderLaw> kBladderLaws[] = {{BladderLaw::kMooneyRivlin, "mooney_rivlin"},
                                                 {BladderLaw::kGentGent, "gent_gent"}};

// The Mooney-Rivlin constants: a material's, or C10_MPa, C01_MPa, C20_MPa
MooneyRivlinConstants read_mooney_rivlin(const Section& bladder) {
  if (bladder.has("material")) {
    const std::string material = bladder.text("material", "");
    if (material == "natural_rubber") return kNaturalRubberTreloar;
    if (material == "silicone") return kSiliconeElastosilM4601;
    bladder.fail("material", "must be \"natural_rubber\" or \"silicone\" (or give C10_MPa, "
                             "C01_MPa, C20_MPa), got \"" + material + "\"");
  }
  return {units::mpa_to_pa(bladder.number("C10_MPa")), units::mpa_to_pa(bladder.number("C01_MPa")),
          units::mpa_to_pa(bladder.non_negative("C20_MPa", "MPa"))};
}

// The Gent-Gent constants: natural rubber's (the one material fitted), or mu_MPa, C2_MPa, Jm
GentGentConstants read_gent_gent(const Section& bladder) {
  if (bladder.has("material")) {
    const std::string material = bladder.text("material", "");
    if (material == "natural_rubber") return kNaturalRubberTreloarGentGent;
    bladder.fail("material", "has no Gent-Gent fit but \"natural_rubber\" (or give mu_MPa, "
                             "C2_MPa, Jm), got \"" + material + "\"");
  }
  return {units::mpa_to_pa(bladder.positive("mu_MPa", "MPa")),
          units::mpa_to_pa(bladder.non_negative("C2_MPa", "MPa")), bladder.positive("Jm", "")};
}

// relaxation_weights = [...] and relaxation_times_s = [...], one per Prony term
BladderRelaxation read_relaxation(const Section& bladder) {
  const std::vector<double> times = bladder.numbers("relaxation_times_s");
  const std::vector<double> weights = bladder.numbers("relaxation_weights");
  if (times.size() > static_cast<std::size_t>(kMaxRelaxationTerms)) {
    bladder.fail("relaxation_times_s", "must list at most " +
                                           std::to_string(kMaxRelaxationTerms) + " terms, got " +
                                           std::to_string(times.size()));
  }
  if (weights.size() != times.size()) {
    bladder.fail("relaxation_weights", "must list one weight per relaxation_times_s (" +
                                           std::to_string(times.size()) + "), got " +
                                           std::to_string(weights.size()));
  }
  BladderRelaxation r;
  r.count = static_cast<int>(times.size());
  for (int i = 0; i < r.count; ++i) {
    const std::string index = "[" + std::to_string(i) + "]";
    if (!(times[i] > 0.0)) {
      bladder.fail("relaxation_times_s", index + " must be > 0 s, got " + format_number(times[i]));
    }
    if (!(weights[i] >= 0.0)) {
      bladder.fail("relaxation_weights", index + " must be >= 0, got " + format_number(weights[i]));
    }
    r.time_s[i] = times[i];
    r.weight[i] = weights[i];
  }
  return r;
}

// [bladder]: its law and material, and its own diameter (a tube inside the sleeve, Table I)
void read_bladder(const Section& bladder, AvbdlParams* a) {
  a->bladder_law = parse_name(kBladderLaws, bladder.text("law", "mooney_rivlin"),
                              bladder.file + ": " + bladder.key("law"));
  if (a->bladder_law == BladderLaw::kGentGent) {
    bladder.reject_unknown({"C2_MPa", "Jm", "diameter_mm", "law", "material", "mu_MPa",
                            "relaxation_times_s", "relaxation_weights"});
    a->bladder_gent = read_gent_gent(bladder);
  } else {
    bladder.reject_unknown({"C01_MPa", "C10_MPa", "C20_MPa", "diameter_mm", "law", "material",
                            "relaxation_times_s", "relaxation_weights"});
    a->bladder = read_mooney_rivlin(bladder);
  }
  if (bladder.has("material") &&
      (bladder.has("C10_MPa") || bladder.has("mu_MPa") || bladder.has("Jm"))) {
    bladder.fail("material", "and the law's constants are given both: give one");
  }
  if (bladder.has("diameter_mm")) {
    a->bladder_diameter_m = units::mm_to_m(bladder.positive("diameter_mm", "mm"));
  }
  if (bladder.has("relaxation_times_s") || bladder.has("relaxation_weights")) {
    a->relaxation = read_relaxation(bladder);
  }
}

AvbdlFrictionCoefficients read_stroke(const Section& stroke) {
  stroke.reject_unknown({"A0_mm2", "A1_mm2", "F0_N"});
  return {stroke.non_negative("F0_N", "N"), units::mm2_to_m2(stroke.non_negative("A0_mm2", "mm^2")),
          units::mm2_to_m2(stroke.non_negative("A1_mm2", "mm^2"))};
}

constexpr EnumName<FrictionModel> kFrictionModels[] = {
    {FrictionModel::kSmooth, "smooth"}, {FrictionModel::kMaxwellSlip, "maxwell_slip"}};

// model = "maxwell_slip" with breakaway_mm = [...] and weights = [...], one per element
MaxwellSlipParams read_slip(const Section& friction) {
  const std::vector<double> breakaway_mm = friction.numbers("breakaway_mm");
  const std::vector<double> weights = friction.numbers("weights");
  if (breakaway_mm.empty() || breakaway_mm.size() > static_cast<std::size_t>(kMaxSlipElements)) {
    friction.fail("breakaway_mm", "must list 1 to " + std::to_string(kMaxSlipElements) +
                                      " breakaway travels for model = \"maxwell_slip\"");
  }
  if (weights.size() != breakaway_mm.size()) {
    friction.fail("weights", "must list one weight per breakaway_mm (" +
                                 std::to_string(breakaway_mm.size()) + "), got " +
                                 std::to_string(weights.size()));
  }
  MaxwellSlipParams slip;
  slip.count = static_cast<int>(breakaway_mm.size());
  for (int i = 0; i < slip.count; ++i) {
    slip.breakaway_m[i] = units::mm_to_m(breakaway_mm[i]);
    slip.weight[i] = weights[i];
  }
  return slip;
}

AvbdlFriction read_friction(const Section& friction) {
  friction.reject_unknown({"breakaway_mm", "contraction", "extension", "model",
                           "velocity_scale_mm_s", "weights"});
  AvbdlFriction f;
  f.extension = read_stroke(friction.sub("extension"));
  f.contraction = read_stroke(friction.sub("contraction"));
  f.model = parse_name(kFrictionModels, friction.text("model", "smooth"),
                       friction.file + ": " + friction.key("model"));
  if (f.model == FrictionModel::kMaxwellSlip) {
    f.slip = read_slip(friction);
  } else if (friction.has("breakaway_mm") || friction.has("weights")) {
    friction.fail(friction.has("weights") ? "weights" : "breakaway_mm",
                  "belongs to model = \"maxwell_slip\" (this friction is \"smooth\")");
  }
  if (f.model == FrictionModel::kSmooth || friction.has("velocity_scale_mm_s")) {
    f.velocity_scale_m_per_s =
        units::mm_to_m(friction.positive("velocity_scale_mm_s", "mm/s"));
  }
  return f;
}

// validate_avbdl_params names SI fields; the file's keys are in paper units
std::string file_key(const std::string& field) {
  const std::pair<const char*, const char*> names[] = {
      {"length_m", "geometry.length_mm"},
      {"diameter_m", "geometry.diameter_mm"},
      {"braid_angle_rad", "geometry.braid_angle_deg"},
      {"wall_thickness_m", "geometry.wall_thickness_mm"},
      {"end_length_m", "geometry.end_length_mm"},
      {"end_slope", "geometry.end_slope"},
      {"bladder.c10_pa", "bladder.C10_MPa"},
      {"bladder.c01_pa", "bladder.C01_MPa"},
      {"bladder.c20_pa", "bladder.C20_MPa"},
      {"bladder_diameter_m", "bladder.diameter_mm"},
      {"bladder.mu_pa", "bladder.mu_MPa"},
      {"bladder.c2_pa", "bladder.C2_MPa"},
      {"bladder.jm", "bladder.Jm"},
      {"friction.velocity_scale_m_per_s", "friction.velocity_scale_mm_s"},
      {"friction.extension.force_n", "friction.extension.F0_N"},
      {"friction.extension.pressure_area_m2", "friction.extension.A0_mm2"},
      {"friction.extension.strain_area_m2", "friction.extension.A1_mm2"},
      {"friction.contraction.force_n", "friction.contraction.F0_N"},
      {"friction.contraction.pressure_area_m2", "friction.contraction.A0_mm2"},
      {"friction.contraction.strain_area_m2", "friction.contraction.A1_mm2"}};
  for (const auto& [si, file] : names) {
    if (field == si) return file;
  }
  return field;
}

// The plant as `root` gives it; `path` names it in errors.
PlantParams read_plant(const toml::table& root, const std::string& path) {
  const Section top{path, "", root};
  top.reject_unknown({"bladder", "friction", "geometry", "law", "name", "source"});
  PlantParams plant;
  plant.name = top.text("name", "");
  plant.source = top.text("source", "");
  const std::string law = top.text("law", "");
  if (law != "avbdl") top.fail("law", "must be \"avbdl\" (seeds/003), got \"" + law + "\"");

  const Section geo = top.sub("geometry");
  geo.reject_unknown({"braid_angle_deg", "diameter_mm", "end_length_mm", "end_slope",
                      "length_mm", "wall_thickness_mm"});
  // each value in the file's units first; the law's cross checks (validate_avbdl_params) after
  const double length_m = units::mm_to_m(geo.positive("length_mm", "mm"));
  AvbdlParams& a = plant.avbdl;
  a.length_m = length_m;
  a.diameter_m = units::mm_to_m(geo.positive("diameter_mm", "mm"));
  // the braid must be able to contract from L0: alpha0 below arccos(1 / sqrt(3))
  const double angle_deg = geo.number("braid_angle_deg");
  const double max_deg = units::rad_to_deg(std::acos(1.0 / std::sqrt(3.0)));
  if (!(angle_deg > 0.0 && angle_deg < max_deg)) {
    geo.fail("braid_angle_deg",
             "must be in (0, 54.7356) deg (a braid at a steeper angle cannot contract), got " +
                 format_number(angle_deg));
  }
  a.braid_angle_rad = units::deg_to_rad(angle_deg);
  a.wall_thickness_m = units::mm_to_m(geo.non_negative("wall_thickness_mm", "mm"));
  if (geo.has("end_slope")) a.end_slope = geo.number("end_slope");
  read_bladder(top.sub("bladder"), &a);
  // the end regions: given, or the DMSP-20's in proportion (to the length; to the radius for
  // Table I's tube, whose ends are where the braid flares from the fitting)
  a.end_length_m = a.bladder_diameter_m > 0.0 ? kAvbdlEndPerRadius * 0.5 * a.diameter_m
                                              : kAvbdlEndFraction * length_m;
  if (geo.has("end_length_mm")) {
    a.end_length_m = units::mm_to_m(geo.non_negative("end_length_mm", "mm"));
  }
  a.friction = top.has("friction") ? read_friction(top.sub("friction")) : AvbdlFriction{};

  // the model's own checks, reported with the file's keys
  try {
    validate_avbdl_params(a, "");
  } catch (const InputError& e) {
    if (e.parts().key.empty()) throw;
    throw file_key_error(path, file_key(e.parts().key), e.parts().problem);
  }
  return plant;
}

}  // namespace

PlantParams load_plant_params(const std::string& path) {
  return read_plant(parse_toml_file(path), path);
}

PlantParams load_plant_params(const std::string& path, const toml::table& changes,
                              const std::string& prefix) {
  return read_with_changes(path, changes, prefix, read_plant);
}

}  // namespace pamsim
