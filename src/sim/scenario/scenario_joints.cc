// scenario_joints.cc: joints.<joint>.*, a joint's damping and friction loss in place of the
// model's (scenario.h, JointSpec): a hinge's in N m s/rad and N m, a slide's in N s/m and N;
// and its position at the start (start_deg, start_mm: set in the trial's start state, so a
// leg starts crouched or a trunk high above the ground).
// Whether the joint exists, and is of the kind its keys' units say, is checked when the
// model is bound (trial_model.cc).
#include "base/key_table.h"
#include "sim/scenario/scenario_key_tables.h"
#include "sim/scenario/scenario_reading.h"

namespace pamsim {

void read_joints(ConfigReader& in, Scenario* sc) {
  for (const std::string& name : in.child_keys("joints")) {
    JointSpec j;
    j.key = "joints." + name;
    j.joint = name;
    KeyTable hinge = hinge_key_table(&j), slide = slide_key_table(&j);
    hinge.name = slide.name = j.key;
    const auto gives = [&](const KeyTable& t) { return !rows_given(in, t).numbers.empty(); };
    const auto list = [](const KeyTable& t) {
      std::string names;
      for (const NumberRow& row : t.numbers) names += (names.empty() ? "" : ", ") + row.name;
      return names;
    };
    const bool is_hinge = gives(hinge), is_slide = gives(slide);
    in.check(!(is_hinge && is_slide), j.key,
             "mixes a hinge's keys (" + list(hinge) + ") with a slide's (" + list(slide) + ")");
    in.check(is_hinge || is_slide, j.key,
             "gives none of " + list(hinge) + " (a hinge), " + list(slide) + " (a slide)");
    j.rotational = is_hinge;
    read_key_rows(in, rows_given(in, is_hinge ? hinge : slide));
    sc->joints.push_back(j);
  }
}

}  // namespace pamsim
