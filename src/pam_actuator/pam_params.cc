// pam_params.cc: read, validate and write one PAM's parameter file (see pam_params.h).
#include "pam_actuator/pam_params.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include <toml++/toml.h>

#include "base/input_error.h"
#include "base/toml_file.h"
#include "base/toml_section.h"
#include "base/units.h"

namespace pamsim {
namespace {

// spring.units must name the paper's units exactly
void check_units(const Section& spring) {
  const Section u = spring.sub("units");
  u.reject_unknown({"force", "length", "pressure"});
  const std::pair<const char*, const char*> expected[] = {
      {"pressure", "MPa"}, {"length", "mm"}, {"force", "N"}};
  for (const auto& [k, unit] : expected) {
    const std::string got = u.text(k, "");
    if (got != unit) {
      u.fail(k, "must be \"" + std::string(unit) + "\" (the paper's units), got \"" + got +
                    "\"");
    }
  }
}

SpringModel read_spring(const Section& spring) {
  const SpringLaw law = parse_spring_law(spring.text("law", ""), spring.file + ": spring.law");

  // keys allowed for this law
  std::set<std::string> allowed = {"law", "units", "m", "h"};
  for (int k = 0; k < coefficient_count(law); ++k) allowed.insert(coefficient_name(law, k));
  spring.reject_unknown(allowed);
  check_units(spring);

  // Eq. (2) and the law's coefficients, in paper units
  const double m = spring.number("m");
  const double h = spring.positive("h", "mm");
  std::array<double, 6> coef{};
  for (int k = 0; k < coefficient_count(law); ++k) {
    coef[k] = spring.number(coefficient_name(law, k));
  }
  return spring_model_from_paper_units(law, m, h, coef);
}

StrainGaugeParams read_strain_gauge(const Section& gauge) {
  gauge.reject_unknown({"V_base_V", "q_V_per_N"});
  StrainGaugeParams out;
  out.q_v_per_n = gauge.positive("q_V_per_N", "V/N");
  out.v_base_v = gauge.has("V_base_V") ? gauge.number("V_base_V") : 0.0;
  return out;
}

PamGeometry read_geometry(const Section& geo) {
  geo.reject_unknown(
      {"braid_angle_deg", "bladder_diameter_mm", "length_mm", "sleeve_diameter_mm"});
  PamGeometry out;
  out.length_m = units::mm_to_m(geo.positive("length_mm", "mm"));
  out.sleeve_diameter_m = units::mm_to_m(geo.positive("sleeve_diameter_mm", "mm"));
  out.bladder_diameter_m = units::mm_to_m(geo.positive("bladder_diameter_mm", "mm"));
  const double angle = geo.number("braid_angle_deg");
  if (!(angle > 0.0 && angle < 90.0)) {
    geo.fail("braid_angle_deg", "must be in (0, 90) deg, got " + format_number(angle));
  }
  out.braid_angle_rad = units::deg_to_rad(angle);
  return out;
}

std::string quoted(const std::string& s) {
  std::ostringstream out;
  out << toml::value<std::string>(s);
  return out.str();
}

}  // namespace

PamParams load_pam_params(const std::string& path) {
  const toml::table root = parse_toml_file(path);
  const Section top{path, "", root};
  top.reject_unknown({"geometry", "name", "source", "spring", "strain_gauge"});

  PamParams params;
  params.name = top.text("name", "");
  params.source = top.text("source", "");
  params.spring = read_spring(top.sub("spring"));
  if (top.has("strain_gauge")) params.strain_gauge = read_strain_gauge(top.sub("strain_gauge"));
  if (top.has("geometry")) params.geometry = read_geometry(top.sub("geometry"));
  return params;
}

std::string pam_params_to_toml(const PamParams& params) {
  std::ostringstream out;
  out << "# PAM parameter file (pamsim); units are the paper's (seeds/000): p MPa, d mm, f N\n";
  out << "name = " << quoted(params.name) << "\n";
  out << "source = " << quoted(params.source) << "\n";

  // spring model, Eq. (2)-(5)
  double m = 0.0, h = 0.0;
  std::array<double, 6> coef{};
  spring_model_to_paper_units(params.spring, &m, &h, &coef);
  out << "\n[spring]\n";
  out << "law = \"" << to_string(params.spring.law) << "\"\n";
  out << "units = { pressure = \"MPa\", length = \"mm\", force = \"N\" }\n";
  out << "m = " << format_number(m) << "   # Eq. (2) slope [mm/MPa]\n";
  out << "h = " << format_number(h) << "   # Eq. (2) intercept [mm]\n";
  for (int k = 0; k < coefficient_count(params.spring.law); ++k) {
    out << coefficient_name(params.spring.law, k) << " = " << format_number(coef[k]) << "\n";
  }

  // optional sections
  if (params.strain_gauge) {
    out << "\n[strain_gauge]   # Eq. (8)\n";
    out << "q_V_per_N = " << format_number(params.strain_gauge->q_v_per_n) << "\n";
    out << "V_base_V = " << format_number(params.strain_gauge->v_base_v) << "\n";
  }
  if (params.geometry) {
    const PamGeometry& g = *params.geometry;
    out << "\n[geometry]\n";
    out << "length_mm = " << format_number(units::m_to_mm(g.length_m)) << "\n";
    out << "sleeve_diameter_mm = " << format_number(units::m_to_mm(g.sleeve_diameter_m))
        << "\n";
    out << "bladder_diameter_mm = " << format_number(units::m_to_mm(g.bladder_diameter_m))
        << "\n";
    out << "braid_angle_deg = " << format_number(units::rad_to_deg(g.braid_angle_rad)) << "\n";
  }
  return out.str();
}

}  // namespace pamsim
