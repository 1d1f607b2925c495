// plant_params.cc: read and validate a plant file (see plant_params.h).
#include "pam_actuator/plant_params.h"

#include <cmath>

#include "base/input_error.h"
#include "base/toml_file.h"
#include "base/toml_section.h"
#include "base/units.h"

namespace pamsim {
namespace {

MooneyRivlinConstants read_bladder(const Section& bladder) {
  if (bladder.has("material")) {
    bladder.reject_unknown({"material"});
    const std::string material = bladder.text("material", "");
    if (material == "natural_rubber") return kNaturalRubberTreloar;
    if (material == "silicone") return kSiliconeElastosilM4601;
    bladder.fail("material", "must be \"natural_rubber\" or \"silicone\" (or give C10_MPa, "
                             "C01_MPa, C20_MPa), got \"" + material + "\"");
  }
  bladder.reject_unknown({"C01_MPa", "C10_MPa", "C20_MPa"});
  return {units::mpa_to_pa(bladder.number("C10_MPa")), units::mpa_to_pa(bladder.number("C01_MPa")),
          units::mpa_to_pa(bladder.non_negative("C20_MPa", "MPa"))};
}

AvbdlFrictionCoefficients read_stroke(const Section& stroke) {
  stroke.reject_unknown({"A0_mm2", "A1_mm2", "F0_N"});
  return {stroke.non_negative("F0_N", "N"), units::mm2_to_m2(stroke.non_negative("A0_mm2", "mm^2")),
          units::mm2_to_m2(stroke.non_negative("A1_mm2", "mm^2"))};
}

AvbdlFriction read_friction(const Section& friction) {
  friction.reject_unknown({"contraction", "extension", "velocity_scale_mm_s"});
  AvbdlFriction f;
  f.extension = read_stroke(friction.sub("extension"));
  f.contraction = read_stroke(friction.sub("contraction"));
  f.velocity_scale_m_per_s = units::mm_to_m(friction.positive("velocity_scale_mm_s", "mm/s"));
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

}  // namespace

PlantParams load_plant_params(const std::string& path) {
  const toml::table root = parse_toml_file(path);
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
  a.end_length_m = kAvbdlEndFraction * length_m;
  if (geo.has("end_length_mm")) {
    a.end_length_m = units::mm_to_m(geo.non_negative("end_length_mm", "mm"));
  }
  if (geo.has("end_slope")) a.end_slope = geo.number("end_slope");
  a.bladder = read_bladder(top.sub("bladder"));
  a.friction = top.has("friction") ? read_friction(top.sub("friction")) : AvbdlFriction{};

  // the model's own checks, reported with the file's keys
  try {
    validate_avbdl_params(a, "");
  } catch (const InputError& e) {
    const std::string what = e.what();
    const auto space = what.find(' ');
    throw InputError(path + ": " + file_key(what.substr(0, space)) + ":" + what.substr(space));
  }
  return plant;
}

}  // namespace pamsim
