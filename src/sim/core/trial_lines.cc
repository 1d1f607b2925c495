// trial_lines.cc: see trial_lines.h.
#include "sim/core/trial_lines.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/calibration.h"
#include "sim/core/muscle_law.h"
#include "sim/core/pam_callback.h"

namespace pamsim::detail {
namespace {

// Extensible lines (muscles.<m>.line_diameter_mm): each line's length so far is its length
// at the start, under the start's tension F0. A creeping line (line_creep g > 0) has held F0
// long before the trial (its creep state q = F0, pam_start_line_creep in pam_callback.h), so it
// stretches by (1 + g) F0 / (E A) per unit length there; its unstretched length is
// L / (1 + (1 + g) F0 / (E A)), so the start state stays as calibrated. The creep states
// take d->userdata from `creep_index` on, one per creeping line.
void make_lines_extensible(const Scenario& sc, TrialModel* tm, int creep_index) {
  mjModel* m = tm->model.get();
  const auto extensible = [&](const BoundMuscle& b) {
    return sc.muscles[b.spec].line_axial_stiffness_n > 0.0;
  };
  if (std::none_of(tm->muscles.begin(), tm->muscles.end(), extensible)) return;
  MjDataPtr data = start_state(sc, *tm);  // the inextensible lines' tensions at the start
  for (std::size_t k = 0; k < tm->muscles.size(); ++k) {
    BoundMuscle& b = tm->muscles[k];
    if (!extensible(b)) continue;
    const MuscleSpec& spec = sc.muscles[b.spec];
    LineBinding line;
    line.axial_stiffness_n = spec.line_axial_stiffness_n;
    line.creep = spec.line_creep;
    line.creep_time_s = spec.line_creep_time_s;
    line.start_tension_n = -data->actuator_force[b.actuator];
    line.creep_index = spec.line_creep > 0.0 ? creep_index++ : -1;
    b.line_length_m /= 1.0 + (1.0 + line.creep) * line.start_tension_n / line.axial_stiffness_n;
    store_pam_in_model(m, b.actuator, spec.pam.spring, b.line_length_m, static_cast<int>(k),
                       sc.model_file.c_str());
    store_line_in_model(m, b.actuator, line, sc.model_file.c_str());
  }
}

// the one muscle's line that holds the start state, given the others' (set_lines)
void solve_line(const Scenario& sc, TrialModel* tm, int solved) {
  mjModel* m = tm->model.get();
  // the tension that balances the start state on the degree of freedom it moves most
  BoundMuscle& b = tm->muscles[solved];
  const MuscleSpec& spec = sc.muscles[b.spec];
  MjDataPtr data = start_state(sc, *tm);
  const mjData* d = data.get();
  const mjtNum* moment = d->actuator_moment + static_cast<long>(b.actuator) * m->nv;
  int dof = 0;
  for (int v = 1; v < m->nv; ++v) dof = std::fabs(moment[v]) > std::fabs(moment[dof]) ? v : dof;
  const double others = d->qfrc_actuator[dof] + d->qfrc_passive[dof];
  const double f = m->nv > 0 && moment[dof] != 0 ? (others - d->qfrc_bias[dof]) / moment[dof] : 0.0;
  const double p0 = spec.command.at(0.0);
  const double pam_length_m = plant_length_at_force(spec, p0, f);
  if (!(pam_length_m > 0)) {
    char buf[160];
    std::snprintf(buf, sizeof(buf), "cannot hold the start state: it needs %.4g N at %.4g MPa", f,
                  units::pa_to_mpa(p0));
    fail(sc, spec.key + ".line", std::string("= \"equilibrium\" ") + buf);
  }
  b.line_length_m = d->actuator_length[b.actuator] - pam_length_m;
  if (!(b.line_length_m > 0)) {
    fail(sc, spec.key + ".line",
         "= \"equilibrium\" gives a line <= 0: the tendon is shorter "
         "than the PAM it holds");
  }
  store_pam_in_model(m, b.actuator, spec.pam.spring, b.line_length_m, solved,
                     sc.model_file.c_str());
}

// model.antagonist_deformation_mm: the calibration's two lines solved again at its start
// angle and pressures with this pre-stretch (calibration.h), in place of the file's
void recalibrate_lines(const Scenario& sc, TrialModel* tm) {
  const std::string key = "model.antagonist_deformation_mm";
  const ReflexPair pair = tm->pair_of(sc, sc.calibrated_pair, key);  // model.calibration's
  CalibrationRequest req;
  req.start_angle_rad = sc.start_position;
  req.pressure_agonist_pa = sc.calibrated_pressure_pa[0];
  req.pressure_antagonist_pa = sc.calibrated_pressure_pa[1];
  req.antagonist_deformation_m = *sc.antagonist_deformation_m;
  req.where = sc.path + ": " + key;
  const ArmCalibration c = solve_calibration(*tm, sc, pair, req);
  for (int k : {pair.agonist, pair.antagonist}) {
    BoundMuscle& b = tm->muscles[k];
    b.line_length_m = c.lines[k == pair.agonist ? 0 : 1].line_length_m;
    store_pam_in_model(tm->model.get(), b.actuator, sc.muscles[b.spec].pam.spring, b.line_length_m,
                       k, sc.model_file.c_str());
  }
}

}  // namespace

void fail(const Scenario& sc, const std::string& key, const std::string& problem) {
  throw InputError(sc.path + ": " + key + " " + problem);
}

// the start state: the joint at its start position, held bodies in place, at rest
MjDataPtr start_state(const Scenario& sc, const TrialModel& tm) {
  const mjModel* m = tm.model.get();
  MjDataPtr data = make_data(m);
  tm.place_at_start(sc, data.get());
  for (std::size_t k = 0; k < tm.muscles.size(); ++k) {
    const int slot = pam_userdata_index(m, tm.muscles[k].actuator);  // the binding's
    data->userdata[slot] = sc.muscles[tm.muscles[k].spec].command.at(0.0);
  }
  mj_forward(m, data.get());
  return data;
}

void set_lines(const Scenario& sc, TrialModel* tm) {
  mjModel* m = tm->model.get();
  int solved = -1;
  int history_index = static_cast<int>(tm->muscles.size());  // after the pressures
  for (std::size_t k = 0; k < tm->muscles.size(); ++k) {
    BoundMuscle& b = tm->muscles[k];
    const MuscleSpec& spec = sc.muscles[b.spec];
    b.line_length_m = spec.line_length_m;
    if (spec.line == LineSource::kEquilibrium) {
      if (solved >= 0)
        fail(sc, spec.key + ".line", "\"equilibrium\" is allowed for one muscle only");
      solved = static_cast<int>(k);
      b.line_length_m = 1e3;  // slack while the others' forces are computed
    }
    store_pam_in_model(m, b.actuator, spec.pam.spring, b.line_length_m, static_cast<int>(k),
                       sc.model_file.c_str());
    if (!spec.plant_file.empty()) {
      store_plant_in_model(m, b.actuator, spec.plant, history_index, sc.model_file.c_str());
      history_index += pam_history_size(spec.plant);
    }
  }
  if (solved >= 0) solve_line(sc, tm, solved);
  if (sc.antagonist_deformation_m) recalibrate_lines(sc, tm);
  make_lines_extensible(sc, tm, history_index);
}

}  // namespace pamsim::detail
