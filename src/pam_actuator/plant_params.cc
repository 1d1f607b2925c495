// plant_params.cc: read and validate a plant file (see plant_params.h). Every key is a row:
// the law's parameters in avbdl_keys.h, the file's own (name, source, law, the bladder's
// material, the series' lists) here; the reader then applies what joins keys.
#include "pam_actuator/plant_params.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "base/file_changes.h"
#include "base/input_error.h"
#include "base/key_table.h"
#include "base/toml_file.h"
#include "base/units.h"
#include "pam_actuator/avbdl_keys.h"

namespace pamsim {
namespace {

// What a plant file fills: the plant, and the keys that only mean something with others.
struct PlantFile {
  PlantParams plant;
  std::string material;  // bladder.material: "" for the law's constants given
  std::vector<double> relaxation_times_s, relaxation_weights, breakaway_m, slip_weights;
};

KeyTable& table_named(std::vector<KeyTable>& tables, const std::string& name) {
  return *std::find_if(tables.begin(), tables.end(),
                       [&](const KeyTable& t) { return t.name == name; });
}

std::vector<KeyTable> plant_key_tables(PlantFile* f) {
  std::vector<KeyTable> tables = avbdl_key_tables(&f->plant.avbdl);
  KeyTable top{"", {}, {}};
  top.choices = {{"law",
                  {"avbdl"},
                  "the plant's force law: AVBDL (Pipan et al. 2025)",
                  [](const std::string&) {},
                  [] { return std::string("avbdl"); }}};
  top.texts = {{"name", "the muscle's name", &f->plant.name},
               {"source", "where the numbers come from", &f->plant.source}};
  tables.insert(tables.begin(), top);
  const auto count = [](int n) { return static_cast<std::size_t>(n); };
  KeyTable& bladder = table_named(tables, "bladder");
  bladder.choices.push_back({"material",
                             {"natural_rubber", "silicone"},
                             "a material whose constants the law takes (silicone: Mooney-Rivlin "
                             "only), or give the law's constants",
                             [f](const std::string& v) { f->material = v; },
                             [f] { return f->material; }});
  bladder.lists = {
      {"relaxation_times_s", "s", 1.0, kPositiveRange, count(kMaxRelaxationTerms),
       "the rubber's rate term, a Prony series: its times tau_i", &f->relaxation_times_s},
      {"relaxation_weights", "", 1.0, kNonNegativeRange, count(kMaxRelaxationTerms),
       "the Prony series' g_i, one per relaxation_times_s", &f->relaxation_weights}};
  table_named(tables, "friction").lists = {
      {"breakaway_mm", "mm", units::kMPerMm, kPositiveRange, count(kMaxSlipElements),
       "model = \"maxwell_slip\": the elements' breakaway travels", &f->breakaway_m, "", 1},
      {"weights",
       "",
       1.0,
       {0.0, 1.0, true},
       count(kMaxSlipElements),
       "model = \"maxwell_slip\": the elements' shares of the friction, summing to 1",
       &f->slip_weights}};
  return tables;
}

// the file's checks that join keys; `has` says whether the file gives a key
template <typename Has, typename Fail>
void apply_bladder(PlantFile* f, const Has& has, const Fail& fail) {
  AvbdlParams& a = f->plant.avbdl;
  const bool gent = a.bladder_law == BladderLaw::kGentGent;
  const std::vector<std::string> own =
      gent ? std::vector<std::string>{"mu_MPa", "C2_MPa", "Jm"}
           : std::vector<std::string>{"C10_MPa", "C01_MPa", "C20_MPa"};
  const std::vector<std::string> other =
      gent ? std::vector<std::string>{"C10_MPa", "C01_MPa", "C20_MPa"}
           : std::vector<std::string>{"mu_MPa", "C2_MPa", "Jm"};
  const std::string law = gent ? "\"gent_gent\"" : "\"mooney_rivlin\"";
  for (const std::string& k : other) {
    if (has("bladder." + k)) fail("bladder." + k, "is not a constant of law = " + law);
  }
  if (!f->material.empty()) {
    for (const std::string& k : own) {
      if (has("bladder." + k))
        fail("bladder.material", "and the law's constants are given both: give one");
    }
    if (gent && f->material != "natural_rubber") {
      fail("bladder.material",
           "has no Gent-Gent fit but \"natural_rubber\" (or give mu_MPa, "
           "C2_MPa, Jm), got \"" +
               f->material + "\"");
    }
    a.bladder = f->material == "silicone" ? kSiliconeElastosilM4601 : kNaturalRubberTreloar;
    a.bladder_gent = kNaturalRubberTreloarGentGent;
  } else {
    for (const std::string& k : own) {
      if (!has("bladder." + k)) fail("bladder." + k, "is required (or give bladder.material)");
    }
  }
  if (f->relaxation_weights.size() != f->relaxation_times_s.size()) {
    fail("bladder.relaxation_weights", "must list one weight per relaxation_times_s (" +
                                           std::to_string(f->relaxation_times_s.size()) +
                                           "), got " +
                                           std::to_string(f->relaxation_weights.size()));
  }
  a.relaxation.count = static_cast<int>(f->relaxation_times_s.size());
  std::copy(f->relaxation_times_s.begin(), f->relaxation_times_s.end(),
            a.relaxation.time_s.begin());
  std::copy(f->relaxation_weights.begin(), f->relaxation_weights.end(),
            a.relaxation.weight.begin());
}

template <typename Has, typename Fail>
void apply_friction(PlantFile* f, const Has& has, const Fail& fail) {
  AvbdlFriction& fr = f->plant.avbdl.friction;
  if (fr.model == FrictionModel::kSmooth) {
    for (const char* k : {"friction.breakaway_mm", "friction.weights"}) {
      if (has(k)) fail(k, "belongs to model = \"maxwell_slip\" (this friction is \"smooth\")");
    }
    if (has("friction") && !has("friction.velocity_scale_mm_s")) {
      fail("friction.velocity_scale_mm_s", "is required for model = \"smooth\"");
    }
    return;
  }
  if (f->breakaway_m.empty()) {
    fail("friction.breakaway_mm", "must list 1 to " + std::to_string(kMaxSlipElements) +
                                      " breakaway travels for model = \"maxwell_slip\"");
  }
  if (f->slip_weights.size() != f->breakaway_m.size()) {
    fail("friction.weights", "must list one weight per breakaway_mm (" +
                                 std::to_string(f->breakaway_m.size()) + "), got " +
                                 std::to_string(f->slip_weights.size()));
  }
  fr.slip.count = static_cast<int>(f->breakaway_m.size());
  std::copy(f->breakaway_m.begin(), f->breakaway_m.end(), fr.slip.breakaway_m.begin());
  std::copy(f->slip_weights.begin(), f->slip_weights.end(), fr.slip.weight.begin());
}

// The plant as `root` gives it; `path` names it in errors.
PlantParams read_plant(const toml::table& root, const std::string& path) {
  PlantFile f;
  const std::vector<std::string> given = read_key_tables(root, path, plant_key_tables(&f));
  const auto has = [&](const std::string& key) {
    return std::find(given.begin(), given.end(), key) != given.end();
  };
  const auto fail = [&](const std::string& key, const std::string& problem) {
    throw file_key_error(path, key, problem);
  };
  if (!has("law")) fail("law", "is required: \"avbdl\" (Pipan et al. 2025)");
  apply_bladder(&f, has, fail);
  apply_friction(&f, has, fail);
  AvbdlParams& a = f.plant.avbdl;
  // the end regions: given, or the DMSP-20's in proportion (to the length; to the radius for
  // Table I's tube, whose ends are where the braid flares from the fitting)
  if (!has("geometry.end_length_mm")) {
    a.end_length_m = a.bladder_diameter_m > 0.0 ? kAvbdlEndPerRadius * 0.5 * a.diameter_m
                                                : kAvbdlEndFraction * a.length_m;
  }
  try {  // the law's checks that join keys, named by the same keys
    validate_avbdl_params(a, "");
  } catch (const InputError& e) {
    throw file_key_error(path, e.parts().key, e.parts().problem);
  }
  return f.plant;
}

}  // namespace

PlantParams load_plant_params(const std::string& path) {
  return read_plant(parse_toml_file(path), path);
}

PlantParams load_plant_params(const std::string& path, const toml::table& changes,
                              const std::string& prefix) {
  return read_with_changes(path, changes, prefix, read_plant);
}

std::vector<KeyDoc> plant_key_docs() {
  PlantFile f;
  return key_table_docs(plant_key_tables(&f));
}

}  // namespace pamsim
