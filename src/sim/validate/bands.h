// bands.h: a validation protocol (length_estimation.h, reaching.h) reported as bands over
// what an unsized rig may be. The paper leaves several parts of its rig unnamed (the
// gauge's board, the fishing line, where the line bears on the board); each is a bracket
// of published values, and `pamsim validate ... --bands N` runs the protocol on N rigs
// drawn from the brackets, every hardware source of [[budget_source]] on (the budget's
// "all" run), and reports each cell of the paper's table as median and 5-95 % range over
// the rigs, with the paper's value beside, inside or outside that range. With
// --sensitivity, each bracket is instead set alone to its ends (the others at their
// brackets' middles), so a lab reads which part of its rig to measure first.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "base/config_reader.h"
#include "sim/validate/validation_options.h"

namespace pamsim {

// The brackets are data, a protocol file's [[bracket]] tables:
//   name     what is unknown ("board creep"), unique; no comma, quote, bar, tab or newline
//   key      the scenario key it sets (any numeric key of the rig's scenario)
//   from, to the bracket, from < to, in the key's unit; drawn uniformly
//   source   where the bracket comes from (a datasheet, a material's data), required
//   assumption  true: no published source sizes it (`source` says what it rests on); drawn
//            only when asked (--assumptions) and never in the headline count; default false
// and bracket_seed (>= 0, default 1) fixes the draws: rig r's values depend on it and r alone.
struct Bracket {
  std::string name, key, source;
  double from = 0.0, to = 0.0;
  bool assumption = false;
};

// The brackets a band or sensitivity run draws: the sourced ones, and the assumptions too
// when `assumptions` is set.
std::vector<Bracket> drawn_brackets(const std::vector<Bracket>& brackets, bool assumptions);

// A [[bracket]] table's keys, as the reader takes them and the key reference lists them.
const std::vector<EntryKey>& bracket_entry_keys();

// Reads and checks [[bracket]] and bracket_seed; empty if the file has none.
inline constexpr int kMaxBrackets = 32;
std::vector<Bracket> read_brackets(ConfigReader& in, std::uint64_t* seed);

// Rig r's draws, one per bracket, and as "key=value" overrides.
std::vector<double> bracket_draws(const std::vector<Bracket>& brackets, std::uint64_t seed,
                                  int rig);
std::vector<std::string> bracket_overrides(const std::vector<Bracket>& brackets,
                                           const std::vector<double>& values);
// Each bracket's middle, (from + to) / 2: where the sensitivity holds the other unknowns.
std::vector<double> bracket_middles(const std::vector<Bracket>& brackets);

// A cell of the protocol's table as one run gives it, and the paper's (where published).
struct BandCell {
  std::string name;  // "PAM-A eq3 5 kg", "agonist model all"
  ErrorPct error;
  std::optional<ErrorPct> paper;
};

// Median, quantiles (linear between order statistics, R's type 7) and extremes of the finite
// values; n counts them (0: every value NaN).
struct BandStats {
  int n = 0;
  double median = 0.0, p5 = 0.0, p95 = 0.0, min = 0.0, max = 0.0;
};
BandStats band_stats(std::vector<double> values);
inline constexpr double kBandLow = 0.05, kBandHigh = 0.95;

// Runs' cells: the names and the paper's values from the first run that ran, errors
// [run][cell], and per run the reason the protocol refused it ("" where it ran; its cells
// NaN): a drawn rig may be one the protocol cannot test (a PAM whose wall is so thick that it
// cannot reach the tensile test's deformation), which is a finding, not an input error.
struct RunCells {
  std::vector<std::string> cells;
  std::vector<std::optional<ErrorPct>> paper;  // per cell
  std::vector<std::vector<ErrorPct>> errors;   // [run][cell]
  std::vector<std::string> refused;            // [run]
  int refused_count() const;
};

// Runs `run(k)` for k = 0 .. runs - 1, an InputError of a run kept as its refusal. Throws
// the first refusal when every run was refused, std::logic_error when two runs give other
// cells.
RunCells gather_runs(int runs, const std::function<std::vector<BandCell>(int)>& run);

struct Bands {
  std::string protocol;           // "length-estimation", "reaching"
  std::string cases_are;          // what a run's cells are, for the Markdown
  std::vector<Bracket> brackets;  // those drawn
  std::vector<Bracket> held;      // assumptions not drawn: the scenario's values
  std::uint64_t seed = 1;
  std::vector<std::vector<double>> draws;  // [rig][bracket]
  RunCells runs;                           // one run per rig
};

// Runs `run(rig, overrides)` (one protocol run) for rigs 0 .. rigs - 1, each with its draws
// as overrides (gather_runs).
Bands run_bands(
    const std::vector<Bracket>& brackets, std::uint64_t seed, int rigs,
    const std::function<std::vector<BandCell>(int rig, const std::vector<std::string>&)>& run);

// The sensitivity, one unknown at a time about the brackets' middles: run once with every
// bracket at its middle, then per bracket at `from` and at `to`, the others at their
// middles; runs in that order (1 + 2 brackets).
struct Sensitivity {
  std::string protocol, cases_are;
  std::vector<Bracket> brackets;
  RunCells runs;
  // the RMSE's swing of bracket b on cell c: its range over the runs at from, the middle and
  // to, a refused run left out (a rig whose line breaks at one end); NaN where under two ran
  double swing(std::size_t b, std::size_t c) const;
};
Sensitivity run_sensitivity(
    const std::vector<Bracket>& brackets,
    const std::function<std::vector<BandCell>(const std::vector<std::string>&)>& run);

// Refuses (InputError "<what>: bracket "<name>" ...") a file without brackets, a bracket
// whose key the rig refuses at either end, the others at their middles (`check(overrides)`
// loads it), and a --set of a bracket's key.
void check_brackets(const std::vector<Bracket>& brackets,
                    const std::vector<std::string>& user_overrides, const std::string& what,
                    const std::function<void(const std::vector<std::string>&)>& check);

// bands.csv, bands.md, draws.csv (bands_tables.cc); sensitivity.csv, sensitivity.md.
std::string bands_csv(const Bands& bands);
std::string bands_markdown(const Bands& bands);
std::string draws_csv(const Bands& bands);
std::string sensitivity_csv(const Sensitivity& s);
std::string sensitivity_markdown(const Sensitivity& s);
// out_dir/bands.csv, bands.md, draws.csv and, with `draw`, bands.png (per cell the 5-95 %
// range of the RMSE, its median and the paper's value); each whole or not at all.
void write_bands(const Bands& bands, const std::string& out_dir, bool draw);
void write_sensitivity(const Sensitivity& s, const std::string& out_dir);

}  // namespace pamsim
