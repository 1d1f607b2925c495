// trial_model_identity.cc: same_trial_model and trial_only_key (trial_model.h): which
// scenarios share a trial model, by the keys that may change it. The list here names what
// load_trial_model never reads; everything else is compared, so that a key added to the
// scenario, or a new use of one when the model is bound, can only cost a model load.
#include <algorithm>
#include <string>
#include <vector>

#include "base/config_reader.h"  // split_key
#include "sim/core/trial_model.h"

namespace pamsim {

bool same_trial_model(const Scenario& a, const Scenario& b) {
  return !a.model_keys.empty() && a.model_keys == b.model_keys;
}

std::vector<TrialModel> shared_trial_models(const std::vector<Scenario>& scenarios,
                                            std::vector<std::size_t>* model_of) {
  std::vector<TrialModel> models;
  model_of->assign(scenarios.size(), 0);
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    std::size_t m = 0;  // the first earlier scenario of the same model
    while (m < i && !same_trial_model(scenarios[i], scenarios[m])) ++m;
    if (m == i) {
      (*model_of)[i] = models.size();
      models.push_back(load_trial_model(scenarios[i]));
    } else {
      (*model_of)[i] = (*model_of)[m];
    }
  }
  return models;
}

bool trial_only_key(const std::string& key) {
  // whole tables, then single keys ("*": any one part)
  static const std::vector<std::vector<std::string>> kTables = {
      {"reflex"}, {"sensors"}, {"valve"}, {"pneumatics"}, {"muscles", "*", "gauge"}};
  static const std::vector<std::string> kKeys = {
      "seed",          "sim.duration_s",   "sim.control_hz",
      "sim.max_steps", "model.pneumatics", "controller.p_max_MPa",
      "drop.time_s",   "drop.height_m"};
  if (key == "reflex.pairs") return false;  // the pairs bound to muscle indices
  if (std::find(kKeys.begin(), kKeys.end(), key) != kKeys.end()) return true;
  const std::vector<std::string> parts = split_key(key);
  return std::any_of(kTables.begin(), kTables.end(), [&](const std::vector<std::string>& t) {
    if (parts.size() < t.size()) return false;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] != "*" && t[i] != parts[i]) return false;
    }
    return true;
  });
}

}  // namespace pamsim
