// randomize.cc: see randomize.h.
#include "sim/sweep/randomize.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <set>

#include "base/enum_names.h"
#include "base/format.h"
#include "base/input_error.h"
#include "sim/sweep/sweep_file_fields.h"

namespace pamsim {
namespace {

// Draws outside [min, max] before a truncated distribution gives up; with at least 1 % of it
// inside (checked when read) all of them miss with a probability below 1e-40.
constexpr int kMaxRedraws = 10000;
constexpr double kMinKeptShare = 0.01;

constexpr EnumName<Distribution> kDistributions[] = {{Distribution::kUniform, "uniform"},
                                                     {Distribution::kNormal, "normal"},
                                                     {Distribution::kLogNormal, "lognormal"}};

Distribution parse_distribution(const toml::table& t, const SweepFileWhere& where) {
  const std::optional<std::string> name = t["distribution"].value<std::string>();
  where.check(name.has_value(), "distribution", "is required: " + quoted_choices(kDistributions));
  return parse_name(kDistributions, *name, where.file + ": " + where.prefix + "distribution");
}

// The parameters a distribution takes, and their checks.
void read_parameters(const toml::table& t, const SweepFileWhere& where, Randomization* r) {
  const char* names[3][2] = {{"from", "to"}, {"mean", "stddev"}, {"median", "sigma"}};
  const auto& [first, second] = names[static_cast<int>(r->distribution)];
  static const std::set<std::string> any = {"key", "distribution", "min", "max"};
  for (const auto& [k, _] : t) {
    const std::string key(k.str());
    where.check(any.count(key) || key == first || key == second, key,
                "is not a key of this distribution (" + std::string(first) + ", " + second +
                    (r->distribution == Distribution::kUniform ? "" : ", min, max") + ")");
  }
  r->a = sweep_number(t, first, where);
  r->b = sweep_number(t, second, where);
  if (r->distribution == Distribution::kUniform) {
    where.check(r->a < r->b, "from", "must be below to, got " + format_value(r->a) + " and " +
                                         format_value(r->b));
    where.check(!t.contains("min") && !t.contains("max"), "min",
                "and max are for normal and lognormal draws (uniform's range is from, to)");
    return;
  }
  where.check(r->b > 0, second, "must be > 0, got " + format_value(r->b));
  if (r->distribution == Distribution::kLogNormal) {
    where.check(r->a > 0, first, "must be > 0, got " + format_value(r->a));
  }
  if (t.contains("min")) r->min = sweep_number(t, "min", where);
  if (t.contains("max")) r->max = sweep_number(t, "max", where);
  where.check(r->min < r->max, "min", "must be below max");
  where.check(r->kept_share() >= kMinKeptShare, "min",
              "and max keep " + format_value(100 * r->kept_share()) +
                  " % of the distribution; at least 1 % is needed");
}

Randomization read_one(const toml::table& t, std::size_t index, const std::string& file) {
  const SweepFileWhere where{file, "randomize[" + std::to_string(index) + "]."};
  Randomization r;
  const std::optional<std::string> key = t["key"].value<std::string>();
  where.check(key.has_value() && !key->empty(), "key",
              "is required (a numeric scenario key, e.g. \"muscles.agonist.plant.geometry."
              "wall_thickness_mm\")");
  r.key = *key;
  where.check(r.key != "seed", "key", "cannot be \"seed\": use the sweep's `seeds`");
  r.distribution = parse_distribution(t, where);
  read_parameters(t, where, &r);
  return r;
}

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

}  // namespace

double Randomization::draw(std::mt19937_64& rng) const {
  if (distribution == Distribution::kUniform) {
    const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;   // [0, 1), portable
    return a + (b - a) * u;
  }
  for (int i = 0; i < kMaxRedraws; ++i) {
    std::normal_distribution<double> normal(0.0, 1.0);
    const double z = normal(rng);
    const double v = distribution == Distribution::kNormal ? a + b * z : a * std::exp(b * z);
    if (v >= min && v <= max) return v;
  }
  throw std::runtime_error("randomize " + key + ": no draw inside [min, max] in " +
                           std::to_string(kMaxRedraws) + " tries");
}

double Randomization::kept_share() const {
  if (distribution == Distribution::kUniform) return 1.0;
  const auto z = [&](double x) {
    if (distribution == Distribution::kNormal) return (x - a) / b;
    return x <= 0 ? -std::numeric_limits<double>::infinity() : std::log(x / a) / b;
  };
  return normal_cdf(z(max)) - normal_cdf(z(min));
}

std::vector<Randomization> read_randomizations(const toml::node* node, const std::string& file) {
  std::vector<Randomization> out;
  if (!node) return out;
  const toml::array* list = node->as_array();
  if (!list) throw InputError(file + ": randomize must be [[randomize]] tables");
  std::set<std::string> keys;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::table* t = (*list)[i].as_table();
    if (!t) throw InputError(file + ": randomize must be [[randomize]] tables");
    out.push_back(read_one(*t, i, file));
    if (!keys.insert(out.back().key).second) {
      throw InputError(file + ": randomize names " + out.back().key + " twice");
    }
  }
  return out;
}

std::vector<double> draw_values(const std::vector<Randomization>& randomize,
                                std::uint64_t randomize_seed, std::int64_t seed_index) {
  const auto index = static_cast<std::uint64_t>(seed_index);
  std::seed_seq seq{static_cast<std::uint32_t>(randomize_seed), static_cast<std::uint32_t>(randomize_seed >> 32),
                    static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(index >> 32)};
  std::mt19937_64 rng(seq);
  std::vector<double> values;
  for (const Randomization& r : randomize) values.push_back(r.draw(rng));
  return values;
}

nlohmann::json randomizations_json(const std::vector<Randomization>& randomize) {
  nlohmann::json out = nlohmann::json::array();
  for (const Randomization& r : randomize) {
    nlohmann::json j = {{"key", r.key}, {"distribution", name_of(kDistributions, r.distribution)},
                        {"a", r.a}, {"b", r.b}};
    if (std::isfinite(r.min)) j["min"] = r.min;
    if (std::isfinite(r.max)) j["max"] = r.max;
    out.push_back(j);
  }
  return out;
}

}  // namespace pamsim
