// sweep.cc: see sweep.h: a sweep definition's points, trials, shards and canonical form
// (sweep_file.cc reads it from its file).
#include "sim/sweep/sweep.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "base/enum_names.h"
#include "base/portable_random.h"
#include "base/input_error.h"

namespace pamsim {

std::int64_t grid_points(const std::vector<SweepAxis>& axes, std::int64_t cap) {
  std::int64_t n = 1;
  for (const auto& a : axes) {
    const auto levels = static_cast<std::int64_t>(a.values.size());
    if (levels > cap / n) return -1;
    n *= levels;
  }
  return n;
}

void make_points(SweepDefinition* def) {
  const std::size_t n_axes = def->axes.size();
  std::vector<AxisValue>& out = def->point_values;
  if (def->design == SweepDesign::kGrid) {
    const std::int64_t n = grid_points(def->axes, std::numeric_limits<std::int64_t>::max());
    out.resize(static_cast<std::size_t>(n) * n_axes);
    for (std::int64_t p = 0; p < n; ++p) {  // row-major: the first axis varies slowest
      std::int64_t rest = p;
      for (std::size_t a = n_axes; a-- > 0;) {
        const auto levels = static_cast<std::int64_t>(def->axes[a].values.size());
        out[p * n_axes + a] = def->axes[a].values[rest % levels];
        rest /= levels;
      }
    }
    return;
  }
  const std::int64_t n = def->samples;
  out.resize(static_cast<std::size_t>(n) * n_axes);
  std::mt19937_64 rng(def->design_seed);
  for (std::size_t a = 0; a < n_axes; ++a) {
    // Latin hypercube: each of the n strata of every axis holds exactly one point
    std::vector<std::int64_t> stratum(n);
    for (std::int64_t i = 0; i < n; ++i) stratum[i] = i;
    if (def->design == SweepDesign::kLatinHypercube) {
      for (std::int64_t i = n - 1; i > 0; --i) {  // Fisher-Yates with a portable draw
        std::swap(stratum[i], stratum[rng() % static_cast<std::uint64_t>(i + 1)]);
      }
    }
    for (std::int64_t p = 0; p < n; ++p) {
      const double u = def->design == SweepDesign::kLatinHypercube
                           ? (stratum[p] + unit_uniform(rng)) / static_cast<double>(n)
                           : unit_uniform(rng);
      out[p * n_axes + a].number = def->axes[a].at(u);
    }
  }
}

double SweepAxis::at(double u) const {
  if (log_scale) return std::exp(std::log(from) + u * (std::log(to) - std::log(from)));
  return from + u * (to - from);
}

namespace {
constexpr EnumName<SweepDesign> kDesignNames[] = {{SweepDesign::kGrid, "grid"},
                                                  {SweepDesign::kRandom, "random"},
                                                  {SweepDesign::kLatinHypercube, "lhs"}};
}  // namespace

const char* sweep_design_name(SweepDesign design) { return name_of(kDesignNames, design); }

SweepDesign parse_sweep_design(const std::string& name, const std::string& context) {
  return parse_name(kDesignNames, name, context);
}

std::string AxisValue::toml() const {
  switch (kind) {
    case Kind::kString: {
      std::ostringstream os;
      os << toml::value<std::string>(text);  // quoted and escaped as TOML
      return os.str();
    }
    case Kind::kBool:
      return flag ? "true" : "false";
    case Kind::kInteger:
      return std::to_string(static_cast<std::int64_t>(number));
    case Kind::kNumber:
      break;
  }
  if (!std::isfinite(number)) return std::isnan(number) ? "nan" : number > 0 ? "inf" : "-inf";
  char buf[40];
  const auto end = std::to_chars(buf, buf + sizeof(buf), number).ptr;  // shortest exact form
  std::string s(buf, end);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";  // stay a float in TOML
  return s;
}

std::string SweepShard::text() const { return std::to_string(index) + "/" + std::to_string(count); }

SweepShard parse_sweep_shard(const std::string& text, const std::string& source) {
  const auto bad = [&] {
    return InputError(source + " must be I/N with 0 <= I < N, got '" + text + "'");
  };
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) throw bad();
  // a decimal integer that fills its part of the text, or -1
  const auto number = [](const std::string& part) -> std::int64_t {
    std::int64_t value = -1;
    const char* end = part.data() + part.size();
    const auto [ptr, ec] = std::from_chars(part.data(), end, value);
    return part.empty() || ec != std::errc() || ptr != end ? -1 : value;
  };
  SweepShard shard;
  shard.index = number(text.substr(0, slash));
  shard.count = number(text.substr(slash + 1));
  if (shard.index < 0 || shard.count < 1 || shard.index >= shard.count) throw bad();
  return shard;
}

std::int64_t SweepDefinition::points() const {
  return axes.empty() ? 0 : static_cast<std::int64_t>(point_values.size() / axes.size());
}

const AxisValue& SweepDefinition::value(std::int64_t point, std::size_t axis) const {
  return point_values[static_cast<std::size_t>(point) * axes.size() + axis];
}

std::vector<std::string> SweepAxis::overrides_of(const AxisValue& v) const {
  if (!is_cases()) return {key + "=" + v.toml()};
  for (std::size_t c = 0; c < values.size(); ++c) {
    if (values[c].text == v.text) return case_sets[c];
  }
  throw std::logic_error("axis " + key + " has no case " + v.text);
}

std::vector<std::string> SweepDefinition::overrides(std::int64_t point) const {
  std::vector<std::string> out = fixed;
  for (std::size_t a = 0; a < axes.size(); ++a) {
    const std::vector<std::string> set = axes[a].overrides_of(value(point, a));
    out.insert(out.end(), set.begin(), set.end());
  }
  return out;
}

std::uint64_t SweepDefinition::seed_of(std::int64_t trial) const {
  return base_seed + static_cast<std::uint64_t>(trial % seeds);
}

std::vector<double> SweepDefinition::draws(std::int64_t trial) const {
  return draw_values(randomize, randomize_seed, trial % seeds);
}

std::vector<std::string> SweepDefinition::trial_overrides(std::int64_t trial) const {
  std::vector<std::string> out = overrides(trial / seeds);
  append_draws(randomize, randomize_seed, trial % seeds, &out);
  return out;
}

std::string SweepDefinition::canonical_json() const {
  nlohmann::json axes_json = nlohmann::json::array();
  for (const auto& a : axes) {
    nlohmann::json j = {{"key", a.key}};
    if (a.is_range) j["range"] = {{"from", a.from}, {"to", a.to}, {"log", a.log_scale}};
    nlohmann::json values = nlohmann::json::array();
    for (const auto& v : a.values) values.push_back(v.toml());
    j["values"] = values;
    if (a.is_cases()) j["cases"] = a.case_sets;  // (absent on a key's axis, as before cases)
    axes_json.push_back(j);
  }
  nlohmann::json j = {{"base_scenario", base_text},
                      {"fixed", fixed},
                      {"axes", axes_json},
                      {"design", sweep_design_name(design)},
                      {"samples", samples},
                      {"design_seed", design_seed},
                      {"seeds", seeds},
                      {"metrics", metric_names}};
  if (!randomize.empty()) {  // (a sweep without draws is described as before they existed)
    j["randomize"] = randomizations_json(randomize);
    j["randomize_seed"] = randomize_seed;
  }
  return j.dump();
}

}  // namespace pamsim
