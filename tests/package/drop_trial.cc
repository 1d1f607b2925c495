// drop_trial.cc: the installed drop-mass scenario run through pamsim::sim (a short trial);
// prints its status and peak drop; exit 0 when the trial ran ok.
#include <cstdio>

#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"

int main() {
  using namespace pamsim;
  const Scenario sc = load_scenario(PAMSIM_DATA_DIR "/scenarios/drop_mass.toml",
                                    {"sim.duration_s=1.5", "drop.time_s=0.3"});
  const TrialModel model = load_trial_model(sc);
  const TrialResult r = run_trial(model, sc, sc.seed, false);
  std::printf("status %s, peak drop %.3f deg\n", r.summary.status.c_str(),
              r.summary.metric("peak_drop_deg"));
  return r.summary.status == "ok" ? 0 : 1;
}
