// randomize.cc: see randomize.h.
#include "sim/scenario/randomize.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <set>

#include "base/config_reader.h"
#include "base/enum_names.h"
#include "base/format.h"
#include "base/portable_random.h"
#include "base/input_error.h"

namespace pamsim {
namespace {

// Draws outside [min, max] before a truncated distribution gives up; with at least 1 % of it
// inside (checked when read) all of them miss with a probability below 1e-40.
constexpr int kMaxRedraws = 10000;
constexpr double kMinKeptShare = 0.01;

constexpr EnumName<Distribution> kDistributions[] = {{Distribution::kUniform, "uniform"},
                                                     {Distribution::kNormal, "normal"},
                                                     {Distribution::kLogNormal, "lognormal"}};

double required(const TableEntry& t, const char* key) {
  const std::optional<double> v = t.number(key);
  if (!v) t.in.fail(t.where + key, "is required (a number)");
  return *v;
}

// The parameters a distribution takes, and their checks.
void read_parameters(const TableEntry& t, Randomization* r) {
  const char* names[3][2] = {{"from", "to"}, {"mean", "stddev"}, {"median", "sigma"}};
  const auto& [first, second] = names[static_cast<int>(r->distribution)];
  const auto fail = [&](const std::string& key, const std::string& problem) {
    t.in.fail(t.where + key, problem);
  };
  for (const auto& [k, _] : t.table) {
    const std::string key(k.str());
    const bool truncation =
        r->distribution != Distribution::kUniform && (key == "min" || key == "max");
    if (key != "key" && key != "distribution" && key != first && key != second && !truncation) {
      fail(key, "is not a key of a " + std::string(name_of(kDistributions, r->distribution)) +
                    " draw (" + first + ", " + second +
                    (r->distribution == Distribution::kUniform ? ")" : ", min, max)"));
    }
  }
  r->a = required(t, first);
  r->b = required(t, second);
  if (r->distribution == Distribution::kUniform) {
    if (!(r->a < r->b))
      fail("from", "must be below to, got " + format_value(r->a) + " and " + format_value(r->b));
    return;
  }
  // stddev, median and sigma are > 0 by their rows
  r->min = t.number("min").value_or(r->min);
  r->max = t.number("max").value_or(r->max);
  if (!(r->min < r->max)) fail("min", "must be below max");
  if (r->kept_share() < kMinKeptShare) {
    fail("min", "and max keep " + format_value(100 * r->kept_share()) +
                    " % of the distribution; at least 1 % is needed");
  }
}

Randomization read_one(const TableEntry& t) {
  Randomization r;
  r.key = t.text("key", true);
  if (r.key.empty()) t.in.fail(t.where + "key", "is required (a numeric scenario key)");
  if (r.key == "seed") t.in.fail(t.where + "key", "cannot be \"seed\": seeds are the file's own");
  r.distribution = parse_name(kDistributions, t.text("distribution", true),
                              t.in.where(t.where + "distribution"));
  read_parameters(t, &r);
  return r;
}

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

}  // namespace

double Randomization::draw(std::mt19937_64& rng) const {
  if (distribution == Distribution::kUniform) {
    const double u = unit_uniform(rng);
    return a + (b - a) * u;
  }
  for (int i = 0; i < kMaxRedraws; ++i) {
    const double z = portable_standard_normal(rng);  // the same draws with any library
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

const std::vector<EntryKey>& randomize_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"key", "", "a numeric scenario key, not seed", "(required)", "the scenario key drawn",
       EntryType::kText},
      {"distribution",
       "",
       "",
       "(required)",
       "how it is drawn, once per seed",
       EntryType::kChoice,
       {},
       enum_name_list(kDistributions)},
      {"from", "(the key's)", "uniform: below to", "(required)", "a uniform draw's lower end",
       EntryType::kNumber},
      {"to", "(the key's)", "uniform", "(required)", "a uniform draw's upper end",
       EntryType::kNumber},
      {"mean", "(the key's)", "normal", "(required)", "a normal draw's mean", EntryType::kNumber},
      {"stddev", "(the key's)", "normal", "(required)", "a normal draw's standard deviation",
       EntryType::kNumber, kPositiveRange},
      {"median", "(the key's)", "lognormal", "(required)", "a lognormal draw's median",
       EntryType::kNumber, kPositiveRange},
      {"sigma", "", "lognormal", "(required)", "a lognormal draw's log standard deviation",
       EntryType::kNumber, kPositiveRange},
      {"min", "(the key's)", "normal, lognormal: below max, keeping at least 1 %", "(none)",
       "truncation: draws below are drawn again", EntryType::kNumber},
      {"max", "(the key's)", "normal, lognormal", "(none)",
       "truncation: draws above are drawn again", EntryType::kNumber}};
  return keys;
}

void read_randomizations(ConfigReader& in, std::vector<Randomization>* randomize,
                         std::uint64_t* randomize_seed) {
  std::set<std::string> keys;
  const TableArray tables(in, "randomize");
  for (const TableEntry& entry : tables.entries(randomize_entry_keys())) {
    randomize->push_back(read_one(entry));
    if (!keys.insert(randomize->back().key).second) {
      in.fail("randomize", "names " + randomize->back().key + " twice");
    }
  }
  const bool has_seed = in.has("randomize_seed");
  const std::int64_t seed = in.get_int("randomize_seed", 1);
  in.check(!randomize->empty() || !has_seed, "randomize_seed",
           "is for files with [[randomize]] tables");
  in.check(seed >= 0, "randomize_seed", "must be >= 0, got " + std::to_string(seed));
  *randomize_seed = static_cast<std::uint64_t>(seed);
}

std::vector<double> draw_values(const std::vector<Randomization>& randomize,
                                std::uint64_t randomize_seed, std::int64_t seed_index) {
  const auto index = static_cast<std::uint64_t>(seed_index);
  std::seed_seq seq{static_cast<std::uint32_t>(randomize_seed),
                    static_cast<std::uint32_t>(randomize_seed >> 32),
                    static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(index >> 32)};
  std::mt19937_64 rng(seq);
  std::vector<double> values;
  for (const Randomization& r : randomize) values.push_back(r.draw(rng));
  return values;
}

void append_draws(const std::vector<Randomization>& randomize, std::uint64_t randomize_seed,
                  std::int64_t seed_index, std::vector<std::string>* overrides) {
  const std::vector<double> values = draw_values(randomize, randomize_seed, seed_index);
  for (std::size_t k = 0; k < values.size(); ++k) {
    overrides->push_back(randomize[k].key + "=" + format_number(values[k]));
  }
}

nlohmann::json randomizations_json(const std::vector<Randomization>& randomize) {
  nlohmann::json out = nlohmann::json::array();
  for (const Randomization& r : randomize) {
    nlohmann::json j = {{"key", r.key},
                        {"distribution", name_of(kDistributions, r.distribution)},
                        {"a", r.a},
                        {"b", r.b}};
    if (std::isfinite(r.min)) j["min"] = r.min;
    if (std::isfinite(r.max)) j["max"] = r.max;
    out.push_back(j);
  }
  return out;
}

std::vector<Randomization> randomizations_from_json(const nlohmann::json& j) {
  std::vector<Randomization> out;
  for (const auto& e : j) {
    Randomization r;
    r.key = e.at("key").get<std::string>();
    r.distribution =
        parse_name(kDistributions, e.at("distribution").get<std::string>(), "randomize");
    r.a = e.at("a").get<double>();
    r.b = e.at("b").get<double>();
    if (e.contains("min")) r.min = e.at("min").get<double>();
    if (e.contains("max")) r.max = e.at("max").get<double>();
    out.push_back(r);
  }
  return out;
}

}  // namespace pamsim
