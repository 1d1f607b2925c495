// bands.cc: the brackets read and checked, the drawn rigs' runs, the sensitivity runs and
// the statistics; the tables are written in bands_tables.cc.
#include "sim/validate/bands.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "base/format.h"
#include "base/input_error.h"
#include "sim/validate/table_cells.h"
#include "sim/scenario/randomize.h"

namespace pamsim {
namespace {

void check_bracket_name(const TableEntry& e, const std::string& name,
                        const std::vector<Bracket>& before) {
  check_cell_name(e, name);
  for (const Bracket& b : before) {
    e.in.check(b.name != name, e.where + "name", "repeats another bracket's, \"" + name + "\"");
    e.in.check(b.key != e.text("key", true), e.where + "key",
               "repeats bracket \"" + b.name + "\"'s key");
  }
}

double required_number(const TableEntry& e, const char* key) {
  const std::optional<double> v = e.number(key);
  e.in.check(v.has_value(), e.where + key, "is required (a number)");
  return *v;
}

// The cells' names of a run, checked against the first run's.
void check_same_cells(const std::vector<std::string>& names, const std::vector<BandCell>& cells) {
  bool same = names.size() == cells.size();
  for (std::size_t c = 0; same && c < cells.size(); ++c) same = names[c] == cells[c].name;
  if (!same) throw std::logic_error("bands: a run gave other cells than the first");
}

double quantile(const std::vector<double>& sorted, double q) {
  const double h = (sorted.size() - 1) * q;
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - lo) * (sorted[hi] - sorted[lo]);
}

}  // namespace

const std::vector<EntryKey>& bracket_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"name", "", "a plain name, unique", "(required)", "the unknown, as the outputs name it",
       EntryType::kText},
      {"key", "", "a numeric scenario key, unique", "(required)", "the key a rig's draw sets",
       EntryType::kText},
      {"from", "(the key's)", "below to", "(required)", "the bracket's lower end",
       EntryType::kNumber},
      {"to", "(the key's)", "", "(required)", "the bracket's upper end", EntryType::kNumber},
      {"source", "", "a citation", "(required)", "where the bracket comes from", EntryType::kText},
      {"assumption", "", "", "false",
       "no published source sizes it: drawn only with --assumptions, never in the headline "
       "count",
       EntryType::kBool}};
  return keys;
}

std::vector<Bracket> read_brackets(ConfigReader& in, std::uint64_t* seed) {
  const std::int64_t s = in.get_int("bracket_seed", 1);
  in.check(s >= 0, "bracket_seed", "must be >= 0, got " + std::to_string(s));
  *seed = static_cast<std::uint64_t>(s);
  std::vector<Bracket> brackets;
  const TableArray tables(in, "bracket");
  for (const TableEntry& e : tables.entries(bracket_entry_keys())) {
    Bracket b;
    b.name = e.text("name", true);
    check_bracket_name(e, b.name, brackets);
    b.key = e.text("key", true);
    e.in.check(!b.key.empty() && b.key.find_first_of("=,\"") == std::string::npos, e.where + "key",
               "must be a scenario key, got \"" + b.key + "\"");
    b.from = required_number(e, "from");
    b.to = required_number(e, "to");
    e.in.check(b.from < b.to, e.where + "from",
               "must be below to, got " + format_value(b.from) + " and " + format_value(b.to));
    b.source = e.text("source", true);
    e.in.check(!b.source.empty(), e.where + "source", "must cite where the bracket comes from");
    b.assumption = e.table["assumption"].value_or(false);  // true or false, by its row
    brackets.push_back(std::move(b));
  }
  in.check(static_cast<int>(brackets.size()) <= kMaxBrackets, "bracket",
           "may hold at most " + std::to_string(kMaxBrackets) + " brackets, got " +
               std::to_string(brackets.size()));
  return brackets;
}

std::vector<Bracket> drawn_brackets(const std::vector<Bracket>& brackets, bool assumptions) {
  std::vector<Bracket> drawn;
  for (const Bracket& b : brackets) {
    if (assumptions || !b.assumption) drawn.push_back(b);
  }
  return drawn;
}

std::vector<double> bracket_draws(const std::vector<Bracket>& brackets, std::uint64_t seed,
                                  int rig) {
  std::vector<Randomization> uniform;
  for (const Bracket& b : brackets)
    uniform.push_back({b.key, Distribution::kUniform, b.from, b.to});
  return draw_values(uniform, seed, rig);
}

std::vector<std::string> bracket_overrides(const std::vector<Bracket>& brackets,
                                           const std::vector<double>& values) {
  std::vector<std::string> out;
  for (std::size_t b = 0; b < brackets.size(); ++b) {
    out.push_back(brackets[b].key + "=" + format_number(values[b]));
  }
  return out;
}

std::vector<double> bracket_middles(const std::vector<Bracket>& brackets) {
  std::vector<double> middles;
  for (const Bracket& b : brackets) middles.push_back(0.5 * (b.from + b.to));
  return middles;
}

BandStats band_stats(std::vector<double> values) {
  values.erase(
      std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
      values.end());
  BandStats s;
  s.n = static_cast<int>(values.size());
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  s.median = quantile(values, 0.5);
  s.p5 = quantile(values, kBandLow);
  s.p95 = quantile(values, kBandHigh);
  s.min = values.front();
  s.max = values.back();
  return s;
}

Bands run_bands(
    const std::vector<Bracket>& brackets, std::uint64_t seed, int rigs,
    const std::function<std::vector<BandCell>(int rig, const std::vector<std::string>&)>& run) {
  Bands bands;
  bands.brackets = brackets;
  bands.seed = seed;
  for (int rig = 0; rig < rigs; ++rig) bands.draws.push_back(bracket_draws(brackets, seed, rig));
  bands.runs = gather_runs(
      rigs, [&](int rig) { return run(rig, bracket_overrides(brackets, bands.draws[rig])); });
  return bands;
}

double Sensitivity::swing(std::size_t b, std::size_t c) const {
  double lo = INFINITY, hi = -INFINITY;
  int ran = 0;
  for (std::size_t run : {std::size_t{0}, 2 * b + 1, 2 * b + 2}) {  // middle, from, to
    const double rmse = runs.errors[run][c].rmse_pct;
    if (!std::isfinite(rmse)) continue;
    lo = std::min(lo, rmse);
    hi = std::max(hi, rmse);
    ++ran;
  }
  return ran >= 2 ? hi - lo : NAN;
}

Sensitivity run_sensitivity(
    const std::vector<Bracket>& brackets,
    const std::function<std::vector<BandCell>(const std::vector<std::string>&)>& run) {
  Sensitivity s;
  s.brackets = brackets;
  std::vector<std::vector<double>> settings = {bracket_middles(brackets)};
  for (std::size_t b = 0; b < brackets.size(); ++b) {
    for (double end : {brackets[b].from, brackets[b].to}) {
      settings.push_back(bracket_middles(brackets));
      settings.back()[b] = end;
    }
  }
  s.runs = gather_runs(static_cast<int>(settings.size()),
                       [&](int k) { return run(bracket_overrides(brackets, settings[k])); });
  return s;
}

int RunCells::refused_count() const {
  return static_cast<int>(std::count_if(refused.begin(), refused.end(),
                                        [](const std::string& r) { return !r.empty(); }));
}

RunCells gather_runs(int runs, const std::function<std::vector<BandCell>(int)>& run) {
  RunCells out;
  std::vector<std::optional<std::vector<BandCell>>> ran(runs);
  out.refused.resize(runs);
  for (int k = 0; k < runs; ++k) {
    try {
      ran[k] = run(k);
    } catch (const InputError& e) {
      out.refused[k] = e.what();
    }
  }
  const auto first =
      std::find_if(ran.begin(), ran.end(), [](const auto& r) { return r.has_value(); });
  if (first == ran.end()) throw InputError(out.refused.front());
  for (const BandCell& c : **first) {
    out.cells.push_back(c.name);
    out.paper.push_back(c.paper);
  }
  for (const auto& r : ran) {
    std::vector<ErrorPct> errors(out.cells.size(), ErrorPct{NAN, NAN});
    if (r) {
      check_same_cells(out.cells, *r);
      for (std::size_t c = 0; c < r->size(); ++c) errors[c] = (*r)[c].error;
    }
    out.errors.push_back(errors);
  }
  return out;
}

void check_brackets(const std::vector<Bracket>& brackets,
                    const std::vector<std::string>& user_overrides, const std::string& what,
                    const std::function<void(const std::vector<std::string>&)>& check) {
  if (brackets.empty()) {
    throw InputError(what +
                     ": bracket: --bands and --sensitivity need at least one [[bracket]] table");
  }
  for (std::size_t k = 0; k < brackets.size(); ++k) {
    const Bracket& b = brackets[k];
    for (const std::string& o : user_overrides) {
      if (o.rfind(b.key + "=", 0) == 0) {
        throw InputError("--set " + o + ": " + b.key + " is drawn by " + what + "'s bracket \"" +
                         b.name + "\"");
      }
    }
    for (double end : {b.from, b.to}) {
      std::vector<double> values = bracket_middles(brackets);
      values[k] = end;
      try {
        check(bracket_overrides(brackets, values));
      } catch (const InputError& e) {
        throw InputError(what + ": bracket \"" + b.name + "\" (" + b.key + " = " +
                         format_value(end) + "): " + e.what());
      }
    }
  }
}

}  // namespace pamsim
