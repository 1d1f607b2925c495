// pam_params.cc: read, validate and write one PAM's parameter file (see pam_params.h).
#include "pam_actuator/pam_params.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <set>
#include <limits>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <vector>
#include <sstream>

#include <toml++/toml.h>

#include "base/format.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "base/key_table.h"
#include "base/units.h"

namespace pamsim {
namespace {

constexpr SpringLaw kLaws[] = {SpringLaw::kEq3, SpringLaw::kEq4, SpringLaw::kEq5};

// What a parameter file fills, in its own units where the conversion joins keys (the spring
// law's coefficients), and the optional tables before the file says whether it has them.
struct PamFile {
  PamParams params;
  SpringLaw law = SpringLaw::kEq3;
  std::string pressure_unit = "MPa", length_unit = "mm", force_unit = "N";
  double m_mm_per_mpa = 0.0, h_mm = 0.0;
  std::array<std::array<double, 6>, 3> coef{};  // each law's, paper order
  StrainGaugeParams gauge;
  PamGeometry geometry;
};

ChoiceRow unit_row(const char* name, const char* unit, std::string* field) {
  return {name,
          {unit},
          "the file's " + std::string(name) + " unit: the paper's",
          [field](const std::string& v) { *field = v; },
          [field] { return *field; }};
}

std::vector<KeyTable> pam_key_tables(PamFile* f) {
  KeyTable top{"", {}, {}};
  top.texts = {{"name", "the muscle's name", &f->params.name},
               {"source", "where the numbers come from", &f->params.source}};
  KeyTable spring{"spring", {}, {}};
  spring.choices = {{"law",
                     {"eq3", "eq4", "eq5"},
                     "the spring law the estimator inverts: Eq. (3), (4) or (5) (Yoshida and "
                     "Hosoda)",
                     [f](const std::string& v) { f->law = parse_spring_law(v, "spring.law"); },
                     [f] { return std::string(to_string(f->law)); }}};
  spring.numbers = {{"m", "mm/MPa", 1.0, kAnyRange, "Eq. (2)'s slope of the natural length",
                     &f->m_mm_per_mpa, nullptr, true},
                    {"h", "mm", 1.0, kPositiveRange, "Eq. (2)'s natural length at p = 0", &f->h_mm,
                     nullptr, true}};
  for (std::size_t l = 0; l < 3; ++l) {
    for (int k = 0; k < coefficient_count(kLaws[l]); ++k) {
      spring.numbers.push_back({coefficient_name(kLaws[l], k), "", 1.0, kAnyRange,
                                std::string("law = \"") + to_string(kLaws[l]) +
                                    "\": a coefficient (f in N from p in MPa, d in mm)",
                                &f->coef[l][static_cast<std::size_t>(k)]});
    }
  }
  KeyTable units{"spring.units", {}, {}};
  units.choices = {unit_row("pressure", "MPa", &f->pressure_unit),
                   unit_row("length", "mm", &f->length_unit),
                   unit_row("force", "N", &f->force_unit)};
  KeyTable gauge{"strain_gauge", {}, {}};
  gauge.optional = true;
  gauge.numbers = {{"q_V_per_N", "V/N", 1.0, kPositiveRange, "Eq. (8)'s slope q",
                    &f->gauge.q_v_per_n, nullptr, true},
                   {"V_base_V", "V", 1.0, kAnyRange, "Eq. (8)'s offset", &f->gauge.v_base_v}};
  KeyTable geometry{"geometry", {}, {}};
  geometry.optional = true;
  geometry.numbers = {{"length_mm", "mm", units::kMPerMm, kPositiveRange,
                       "L0, unpressurised (Table I)", &f->geometry.length_m, nullptr, true},
                      {"sleeve_diameter_mm", "mm", units::kMPerMm, kPositiveRange,
                       "D0, the sleeve's (Table I)", &f->geometry.sleeve_diameter_m, nullptr, true},
                      {"bladder_diameter_mm", "mm", units::kMPerMm, kPositiveRange,
                       "the tube's (Table I)", &f->geometry.bladder_diameter_m, nullptr, true},
                      {"braid_angle_deg",
                       "deg",
                       units::kPi,
                       {0.0, 90.0, true, true},
                       "alpha0, the braid's angle to the axis",
                       &f->geometry.braid_angle_rad,
                       nullptr,
                       true,
                       "",
                       180.0}};
  return {top, spring, units, gauge, geometry};
}

std::string quoted(const std::string& s) {
  std::ostringstream out;
  out << toml::value<std::string>(s);
  return out.str();
}

// the index of `law` in kLaws
std::size_t law_index(SpringLaw law) {
  return static_cast<std::size_t>(std::find(std::begin(kLaws), std::end(kLaws), law) -
                                  std::begin(kLaws));
}

// a table of choices as a TOML inline table: { pressure = "MPa", ... }
std::string inline_choices(const KeyTable& table) {
  std::string text = "{ ";
  for (const ChoiceRow& row : table.choices) {
    text += (text.size() > 2 ? ", " : "") + row.name + " = \"" + row.get() + "\"";
  }
  return text + " }";
}

// whether a row's key names its unit ("length_mm"), or the unit is none
bool unit_in_name(const NumberRow& row) {
  std::string suffix = "_" + row.unit;  // "V/N" as "_V_per_N"
  for (std::size_t at; (at = suffix.find('/')) != std::string::npos;)
    suffix.replace(at, 1, "_per_");
  return row.unit.empty() ||
         (row.name.size() > suffix.size() &&
          row.name.compare(row.name.size() - suffix.size(), suffix.size(), suffix) == 0);
}

}  // namespace

PamParams load_pam_params(const std::string& path) {
  PamFile f;
  const std::vector<std::string> given =
      read_key_tables(parse_toml_file(path), path, pam_key_tables(&f));
  const auto has = [&](const std::string& key) {
    return std::find(given.begin(), given.end(), key) != given.end();
  };
  for (const char* k :
       {"spring.law", "spring.units.pressure", "spring.units.length", "spring.units.force"}) {
    if (!has(k)) throw file_key_error(path, k, "is required");
  }
  const std::size_t law = law_index(f.law);
  for (std::size_t l = 0; l < 3; ++l) {
    for (int k = 0; k < coefficient_count(kLaws[l]); ++k) {
      const std::string key = "spring." + coefficient_name(kLaws[l], k);
      if (l == law && !has(key)) throw file_key_error(path, key, "is required");
      if (l != law && has(key)) {
        throw file_key_error(
            path, key, std::string("is not a coefficient of law = \"") + to_string(f.law) + "\"");
      }
    }
  }
  f.params.spring = spring_model_from_paper_units(f.law, f.m_mm_per_mpa, f.h_mm, f.coef[law]);
  if (has("strain_gauge")) f.params.strain_gauge = f.gauge;
  if (has("geometry")) f.params.geometry = f.geometry;
  return f.params;
}

void validate_pam_params(const SpringModel& spring, const StrainGaugeParams& gauge,
                         const std::string& key_prefix) {
  PamFile f;
  f.law = spring.law;
  spring_model_to_paper_units(spring, &f.m_mm_per_mpa, &f.h_mm, &f.coef[law_index(f.law)]);
  f.gauge = gauge;
  const std::vector<KeyTable> tables = pam_key_tables(&f);
  for (const char* name : {"strain_gauge", "spring"}) {  // the gauge first, as a reader meets it
    for (KeyTable table : tables) {
      if (table.name != name) continue;
      table.name = key_prefix + "." + table.name;
      check_key_rows(table);
    }
  }
}

std::vector<KeyDoc> pam_key_docs() {
  PamFile f;
  return key_table_docs(pam_key_tables(&f));
}

std::string pam_params_to_toml(const PamParams& params) {
  PamFile f;
  f.params = params;
  f.law = params.spring.law;
  spring_model_to_paper_units(params.spring, &f.m_mm_per_mpa, &f.h_mm, &f.coef[law_index(f.law)]);
  if (params.strain_gauge) f.gauge = *params.strain_gauge;
  if (params.geometry) f.geometry = *params.geometry;
  // the tables the parameters have ([spring.units] is written inline in [spring]), and the
  // other laws' coefficients, which are not written
  std::set<std::string> written = {"", "spring"};
  if (params.strain_gauge) written.insert("strain_gauge");
  if (params.geometry) written.insert("geometry");
  std::set<std::string> other_laws;
  for (SpringLaw law : kLaws) {
    for (int k = 0; law != f.law && k < coefficient_count(law); ++k) {
      other_laws.insert(coefficient_name(law, k));
    }
  }
  const std::vector<KeyTable> tables = pam_key_tables(&f);
  const auto table = [&](const std::string& name) {
    return *std::find_if(tables.begin(), tables.end(),
                         [&](const KeyTable& t) { return t.name == name; });
  };

  std::ostringstream out;
  out << "# PAM parameter file (pamsim), every key from its row; units are the paper's: p MPa, "
         "d mm, f N\n";
  for (const KeyTable& t : tables) {
    if (!written.count(t.name)) continue;
    if (!t.name.empty()) out << "\n[" << t.name << "]\n";
    for (const TextRow& row : t.texts) out << row.name << " = " << quoted(*row.target) << "\n";
    for (const ChoiceRow& row : t.choices) out << row.name << " = \"" << row.get() << "\"\n";
    if (t.name == "spring") out << "units = " << inline_choices(table("spring.units")) << "\n";
    for (const NumberRow& row : t.numbers) {
      if (other_laws.count(row.name)) continue;
      out << row.name << " = " << format_number(from_si(row, *row.target));
      if (!unit_in_name(row)) out << "   # " << row.unit;
      out << "\n";
    }
  }
  return out.str();
}

}  // namespace pamsim
