// trial_model_identity.cc: same_trial_model (trial_model.h): whether two scenarios build
// the same trial model, by comparing everything load_trial_model reads, as text (doubles by
// their bits).
#include <sstream>

#include "base/double_bits.h"
#include "sim/core/trial_model.h"

namespace pamsim {
namespace {

void append_bits(std::ostringstream& os, double v) { os << double_bits(v) << ';'; }

}  // namespace

bool same_trial_model(const Scenario& a, const Scenario& b) {
  // everything load_trial_model reads, as text
  auto fingerprint = [](const Scenario& sc) {
    std::ostringstream os;
    os << sc.model_file << ';' << sc.joint << ';' << sc.has_start_position << ';';
    append_bits(os, sc.start_position);
    append_bits(os, sc.timestep_s);
    append_bits(os, sc.antagonist_deformation_m.value_or(0.0));   // re-solves two lines
    for (int k = 0; k < 2; ++k) {
      os << sc.calibrated_pair[k] << ';';
      append_bits(os, sc.calibrated_pressure_pa[k]);
    }
    for (const MuscleSpec& mu : sc.muscles) {
      os << mu.actuator << ';' << mu.label << ';' << mu.params_file << ';' << mu.plant_file << ';'
         << mu.plant_changes << ';' << static_cast<int>(mu.line) << ';';
      append_bits(os, mu.line_length_m);
      append_bits(os, mu.line_axial_stiffness_n);
      append_bits(os, mu.line_creep);
      append_bits(os, mu.line_creep_time_s);
      append_bits(os, mu.command.at(0.0));
      for (const std::string& joint : mu.spans) os << joint << ',';   // checked when bound
    }
    for (const std::string& set : sc.metrics) os << set << ',';   // names checked when bound
    for (const BodyMassSpec& bm : sc.body_masses) {
      os << bm.body << ';';
      append_bits(os, bm.mass_kg);
      for (double i : bm.inertia_kg_m2) append_bits(os, i);
    }
    for (const JointSpec& j : sc.joints) {
      os << j.joint << ';';
      append_bits(os, j.damping);
      append_bits(os, j.frictionloss);
      append_bits(os, j.start);
    }
    for (const HoldSpec& h : sc.holds) os << h.body << ';' << h.above_site << ';';
    for (const EventSpec& e : sc.events) {
      os << e.name << ';' << static_cast<int>(e.action) << ';' << e.body << ';'
         << static_cast<int>(e.when.kind) << ';' << e.when.body_a << ';' << e.when.body_b << ';'
         << e.when.joint << ';' << e.when.after << ';';
    }
    for (const auto& pair : sc.controller_pairs()) os << pair[0] << ',' << pair[1] << ';';
    return os.str();
  };
  return fingerprint(a) == fingerprint(b);
}

}  // namespace pamsim
