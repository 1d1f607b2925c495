// live_session.h: a trial run live (`pamsim view`), without any window: the scenario's trial
// stepped one control period at a time, the changes a person makes while it runs (drop the
// mass now, the reflex on or off, a controller setting), each applied from the next control
// tick, and their list. Every change that a scenario can hold is also written as the keys
// that hold it (a drop is drop.time_s, the reflex switched is a controller_off/on event, a
// setting is a `set` event): the record (`--record DIR`) is a run folder whose scenario.toml
// has them, so `pamsim run --from DIR` runs the same trial, bit for bit. A change no scenario
// can hold (dropping a mass whose release waits on a condition) is listed as such, and
// `run --from` names it.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sim/core/trial.h"
#include "sim/core/trial_model.h"

namespace pamsim {

// One live change, as the record lists it (view_changes.json).
struct LiveChange {
  long tick = 0;      // the control tick it applies from (0 at t = 0)
  double time_s = 0;  // that tick's time
  std::string what;   // "drop", "reflex off", "set reflex.v_thr_mm_s=50"
  // the scenario keys that hold it (--set form); empty where none can (`why_not` says)
  std::vector<std::string> keys;
  std::string why_not;
};

// The file of a record that lists the live changes, and its reader for `run --from`: one
// line per change no scenario can hold ("<DIR>: the change at t = 0.5 s (drop) is not
// reproduced: <why>"); none when the folder has no such file.
inline constexpr const char* kLiveChangesFile = "view_changes.json";
std::vector<std::string> unreproduced_live_changes(const std::string& dir);

// A setting the controller lets change during a trial (ControllerKind::live), with its value
// now in the key's unit.
struct LiveSettingValue {
  std::string key;
  std::string unit;
  double slider_min = 0, slider_max = 1;
  double value = 0;
};

class LiveSession {
 public:
  // Reads the scenario (`overrides` applied) and loads its model. Throws InputError as
  // load_scenario and load_trial_model do.
  LiveSession(const std::string& scenario_path, const std::vector<std::string>& overrides);
  ~LiveSession();

  const Scenario& scenario() const { return scenario_; }
  const TrialModel& model() const { return *model_; }
  SteppedTrial& trial() { return *trial_; }
  std::uint64_t seed() const { return seed_; }
  double time_s() const { return trial_->time_s(); }
  bool done() const { return trial_->done(); }
  double control_period_s() const { return 1.0 / scenario_.control_hz; }

  // One control period; false once the trial has ended.
  bool step();
  // Starts again at t = 0 with `seed`, the reflex switch and settings kept as they are (each
  // a change at tick 0 where it differs from the scenario's).
  void restart(std::uint64_t seed);
  // Drops the mass now (fires the scenario's first release event); false when there is none
  // left to drop (released already, or the scenario holds no mass).
  bool drop_now();
  bool has_mass_to_drop() const;  // the scenario holds a release event (the leg's do not)
  void set_reflex(bool on);
  bool reflex_on() const { return trial_->controller_enabled(); }
  // A controller setting (`key` of settings(), `value` in its unit). Throws InputError
  // "<where>: ..." when the key cannot change or the value is refused.
  void set_setting(const std::string& key, double value, const std::string& where);
  // Checks a setting without applying it (what a script's line is checked by).
  void check_setting(const std::string& key, double value, const std::string& where) const;
  const std::vector<LiveSettingValue>& settings() const { return settings_; }

  const std::vector<LiveChange>& changes() const { return changes_; }
  // The trial so far (ended early if not done) written as a run folder `dir` (trajectory.csv,
  // summary.json, scenario.toml with the changes' keys, provenance.json, view_changes.csv),
  // atomically. Ends the trial: restart() to run another.
  void write_record(const std::string& dir);

 private:
  void record(const std::string& what, std::vector<std::string> keys, std::string why_not = "");
  std::vector<std::string> setting_assignments(const std::string& key, double value) const;
  std::string event_key() const;  // "events.view_<n>"

  std::string path_, text_;
  std::vector<std::string> overrides_;
  Scenario scenario_;
  std::unique_ptr<TrialModel> model_;
  std::unique_ptr<SteppedTrial> trial_;
  std::uint64_t seed_ = 1;
  std::vector<LiveSettingValue> settings_;
  std::vector<LiveChange> changes_;
  int next_event_ = 0;
};

}  // namespace pamsim
