// trial_model_identity.cc: same_trial_model (trial_model.h): which scenarios share a trial
// model, by their model_keys (the scenario less the keys whose rows say only the trial reads
// them, scenario_key_docs.h: trial_only_key); everything else is compared, so that a key added
// to the scenario, or a new use of one when the model is bound, can only cost a model load.
#include <algorithm>
#include <string>
#include <vector>

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

}  // namespace pamsim
