// protocol_bands.cc: see protocol_bands.h.
#include "sim/validate/protocol_bands.h"

#include <filesystem>
#include <functional>
#include <system_error>

#include "base/format.h"
#include "base/input_error.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

// every budget source's `on`, in the sources' order (the budget's "all" run)
std::vector<std::string> all_sources_on(const std::vector<BudgetSource>& sources) {
  std::vector<std::string> on;
  for (const BudgetSource& s : sources) on.insert(on.end(), s.on.begin(), s.on.end());
  return on;
}

// A protocol run with `extra` overrides after the sources' and the user's, seeded for run
// `index` (`per_run` seeds each), its progress counted among `total` trials.
std::vector<BandCell> run_one(
    const ValidationOptions& options, const std::vector<std::string>& sources_on,
    const std::vector<std::string>& extra, int index, int per_run, int total,
    const std::function<std::vector<BandCell>(const ValidationOptions&)>& run_protocol) {
  ValidationOptions v = options;
  v.started = nullptr;
  v.overrides = sources_on;
  v.overrides.insert(v.overrides.end(), options.overrides.begin(), options.overrides.end());
  v.overrides.insert(v.overrides.end(), extra.begin(), extra.end());
  v.seed = options.seed.value_or(1) + static_cast<std::uint64_t>(index) * per_run;
  v.progress = [&options, index, per_run, total](int done, int) {
    if (options.progress) options.progress(index * per_run + done, total);
  };
  return run_protocol(v);
}

std::vector<BandCell> length_cells(const LengthValidationSpec& spec, const ValidationOptions& v) {
  const LengthValidationResult result = run_length_validation(spec, v);
  std::error_code ec;
  std::filesystem::remove_all(result.fits_dir, ec);  // a band keeps no fitted files
  std::vector<BandCell> cells;
  for (const DynamicRow& row : result.rows) {
    cells.push_back(
        {"PAM-" + row.pam + " " + to_string(row.law) + " " + format_value(row.weight_kg) + " kg",
         row.sim, row.paper});
  }
  return cells;
}

std::vector<BandCell> reaching_cells(const ReachingValidationSpec& spec,
                                     const ValidationOptions& v) {
  const ReachingValidationResult result = run_reaching_validation(spec, v);
  std::vector<BandCell> cells;
  for (const ReachingRow& row : result.rows) {
    cells.push_back({row.muscle + " " + row.method + " " + row.part, row.sim, row.paper});
  }
  return cells;
}

void check_length_brackets(const LengthValidationSpec& spec, const ValidationOptions& options) {
  const std::vector<std::string> on = all_sources_on(spec.budget);
  check_brackets(spec.brackets, options.overrides, spec.file,
                 [&](const std::vector<std::string>& end) {
                   std::vector<std::string> all = spec.overrides;
                   all.insert(all.end(), on.begin(), on.end());
                   all.insert(all.end(), options.overrides.begin(), options.overrides.end());
                   all.insert(all.end(), end.begin(), end.end());
                   with_plant_changes(spec, &all);  // a PAM's plant: checked by its file
                   load_scenario(spec.rig_file, all);
                 });
}

void check_reaching_brackets(const ReachingValidationSpec& spec, const ValidationOptions& options) {
  const std::vector<std::string> on = all_sources_on(spec.budget);
  check_brackets(spec.brackets, options.overrides, spec.file,
                 [&](const std::vector<std::string>& end) {
                   std::vector<std::string> all = on;
                   all.insert(all.end(), options.overrides.begin(), options.overrides.end());
                   all.insert(all.end(), end.begin(), end.end());
                   load_scenario(spec.scenario_file, all);
                 });
}

std::string length_cases(const LengthValidationSpec& spec) {
  return "each PAM's estimate by each fitted law and weight on the pulley rig (" +
         std::to_string(spec.pams.size()) + " PAMs)";
}

std::string reaching_cases(const ReachingValidationSpec& spec) {
  return "each muscle's model estimate and fiber sensor over " + format_value(spec.window_start_s) +
         "-" + format_value(spec.window_end_s) + " s and before / after its slack episode, " +
         std::to_string(spec.trials) + " trials per rig";
}

using CellsOf = std::function<std::vector<BandCell>(const ValidationOptions&)>;

// What the bands and the sensitivity need of a protocol: its brackets and sources, its
// trials per run, what its cells are, and a run's cells
struct Protocol {
  std::vector<Bracket> brackets;  // all of the file's; drawn_brackets picks a run's
  std::uint64_t seed;
  const std::vector<BudgetSource>& budget;
  int per_run;
  std::string name, cases_are;
  CellsOf cells;
};

Protocol length_protocol(const LengthValidationSpec& spec) {
  return {spec.brackets,
          spec.bracket_seed,
          spec.budget,
          static_cast<int>(spec.pams.size() * spec.laws.size() * spec.weights_kg.size()),
          "length-estimation",
          length_cases(spec),
          [&spec](const ValidationOptions& v) { return length_cells(spec, v); }};
}

Protocol reaching_protocol(const ReachingValidationSpec& spec) {
  return {spec.brackets,
          spec.bracket_seed,
          spec.budget,
          spec.trials,
          "reaching",
          reaching_cases(spec),
          [&spec](const ValidationOptions& v) { return reaching_cells(spec, v); }};
}

// The bands of a protocol over `rigs` drawn rigs
Bands bands_of(const Protocol& p, const ValidationOptions& options, int rigs) {
  const int total = p.per_run * rigs;
  if (options.started) options.started(total);
  const std::vector<std::string> on = all_sources_on(p.budget);
  Bands bands = run_bands(drawn_brackets(p.brackets, options.assumptions), p.seed, rigs,
                          [&](int rig, const std::vector<std::string>& draws) {
                            return run_one(options, on, draws, rig, p.per_run, total, p.cells);
                          });
  for (const Bracket& b : p.brackets) {
    if (b.assumption && !options.assumptions) bands.held.push_back(b);
  }
  bands.protocol = p.name;
  bands.cases_are = p.cases_are;
  return bands;
}

// Its sensitivity: every run on the same seeds, so that the runs differ only by a bracket
Sensitivity sensitivity_of(const Protocol& p, const ValidationOptions& options) {
  const std::vector<Bracket> drawn = drawn_brackets(p.brackets, options.assumptions);
  const int total = p.per_run * static_cast<int>(1 + 2 * drawn.size());
  if (options.started) options.started(total);
  const std::vector<std::string> on = all_sources_on(p.budget);
  int run = 0;
  Sensitivity s = run_sensitivity(drawn, [&](const std::vector<std::string>& set) {
    ValidationOptions counted = options;
    counted.progress = [&](int done, int) {
      if (options.progress) options.progress(run * p.per_run + done, total);
    };
    std::vector<BandCell> result = run_one(counted, on, set, 0, p.per_run, total, p.cells);
    ++run;
    return result;
  });
  s.protocol = p.name;
  s.cases_are = p.cases_are;
  return s;
}

}  // namespace

void check_band_rigs(int rigs) {
  if (rigs < 1 || rigs > kMaxBandRigs) {
    throw InputError("--bands must be in [1, " + std::to_string(kMaxBandRigs) + "], got " +
                     std::to_string(rigs));
  }
}

Bands run_length_bands(const LengthValidationSpec& spec, const ValidationOptions& options,
                       int rigs) {
  check_band_rigs(rigs);
  check_length_brackets(spec, options);
  return bands_of(length_protocol(spec), options, rigs);
}

Sensitivity run_length_sensitivity(const LengthValidationSpec& spec,
                                   const ValidationOptions& options) {
  check_length_brackets(spec, options);
  return sensitivity_of(length_protocol(spec), options);
}

Bands run_reaching_bands(const ReachingValidationSpec& spec, const ValidationOptions& options,
                         int rigs) {
  check_band_rigs(rigs);
  check_reaching_brackets(spec, options);
  return bands_of(reaching_protocol(spec), options, rigs);
}

Sensitivity run_reaching_sensitivity(const ReachingValidationSpec& spec,
                                     const ValidationOptions& options) {
  check_reaching_brackets(spec, options);
  return sensitivity_of(reaching_protocol(spec), options);
}

}  // namespace pamsim
