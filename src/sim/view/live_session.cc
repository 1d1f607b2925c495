// live_session.cc: see live_session.h. The changes applied and written as scenario keys, and
// the settings' values read from the scenario as its keys give them; the record: live_record.cc.
#include "sim/view/live_session.h"

#include <cmath>

#include "base/format.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "reflex/controller_registry.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

// the scenario's first release event, or nullptr
const EventSpec* release_event(const Scenario& sc) {
  for (const EventSpec& e : sc.events) {
    if (e.action == EventAction::kRelease) return &e;
  }
  return nullptr;
}

// The key that moves `release` to a time, or "" with *why_not saying why none can.
std::string release_time_key(const EventSpec& release, std::string* why_not) {
  if (!release.when.after.empty()) {
    *why_not = release.key + " waits for event " + release.when.after + " first";
  } else if (release.key == "drop") {
    return "drop.time_s";
  } else if (release.when.kind == ConditionKind::kTime) {
    return release.key + ".when.at_s";
  } else {
    *why_not = release.key + " fires on a condition, which a scenario cannot move to a time";
  }
  return "";
}

// the controller's live settings with their units and values as the scenario gives them
std::vector<LiveSettingValue> scenario_settings(const std::string& path,
                                                const std::vector<std::string>& overrides,
                                                const std::string& kind_name) {
  const ControllerKind* kind = find_controller_kind(kind_name);
  std::vector<LiveSettingValue> out;
  if (!kind || kind->live.empty()) return out;
  const std::vector<ScenarioKeyValue> values = scenario_key_values(path, overrides);
  for (const LiveSetting& s : kind->live) {
    LiveSettingValue v{s.key, "", s.slider_min, s.slider_max, 0.0};
    for (const KeyDoc& doc : kind->docs) {
      if (doc.key == s.key) v.unit = doc.unit;
    }
    for (const ScenarioKeyValue& kv : values) {
      if (kv.key == s.key && !kv.value.empty()) v.value = std::stod(kv.value);
    }
    out.push_back(v);
  }
  return out;
}

}  // namespace

LiveSession::LiveSession(const std::string& scenario_path,
                         const std::vector<std::string>& overrides)
    : path_(scenario_path), text_(read_text_file(scenario_path)), overrides_(overrides) {
  scenario_ = load_scenario_text(text_, path_, overrides_);
  model_ = std::make_unique<TrialModel>(load_trial_model(scenario_));
  seed_ = scenario_.seed;
  trial_ = std::make_unique<SteppedTrial>(*model_, scenario_, seed_);
  settings_ = scenario_settings(path_, overrides_, scenario_.controller_kind);
}

LiveSession::~LiveSession() = default;

bool LiveSession::step() { return trial_->step(); }

std::string LiveSession::event_key() const { return "events.view_" + std::to_string(next_event_); }

void LiveSession::record(const std::string& what, std::vector<std::string> keys,
                         std::string why_not) {
  LiveChange c;
  c.time_s = time_s();
  c.tick = std::lround(c.time_s * scenario_.control_hz);
  c.what = what;
  c.keys = std::move(keys);
  c.why_not = std::move(why_not);
  changes_.push_back(std::move(c));
  ++next_event_;
}

void LiveSession::restart(std::uint64_t seed) {
  const bool reflex = reflex_on();
  const std::vector<LiveSettingValue> settings = settings_;
  seed_ = seed;
  trial_->reset(seed);
  changes_.clear();
  next_event_ = 0;
  settings_ = scenario_settings(path_, overrides_, scenario_.controller_kind);
  if (!reflex) set_reflex(false);
  for (const LiveSettingValue& s : settings) {
    for (const LiveSettingValue& now : settings_) {
      if (now.key == s.key && now.value != s.value) set_setting(s.key, s.value, "restart");
    }
  }
}

bool LiveSession::has_mass_to_drop() const { return release_event(scenario_) != nullptr; }

bool LiveSession::drop_now() {
  const EventSpec* release = release_event(scenario_);
  if (!release || !trial_->fire_event(release->name)) return false;
  std::string why_not;
  const std::string key = release_time_key(*release, &why_not);
  // the time is the tick's (it fires before that tick's step, as a timed event there does)
  std::vector<std::string> keys;
  if (!key.empty()) keys.push_back(key + "=" + format_shortest(time_s()));
  if (release->key == "drop") keys.push_back("drop.enabled=true");  // (false: never drops)
  record("drop", keys, why_not);
  return true;
}

void LiveSession::set_reflex(bool on) {
  if (on == reflex_on()) return;
  trial_->set_controller_enabled(on);
  const std::string e = event_key();
  record(on ? "reflex on" : "reflex off",
         {e + ".action=" + (on ? "controller_on" : "controller_off"),
          e + ".when.at_s=" + format_shortest(time_s())});
}

std::vector<std::string> LiveSession::setting_assignments(const std::string& key,
                                                          double value) const {
  std::vector<std::string> out;
  bool known = false;
  for (const LiveSettingValue& s : settings_) {
    known |= s.key == key;
    out.push_back(s.key + "=" + format_shortest(s.key == key ? value : s.value));
  }
  if (!known) out.push_back(key + "=" + format_shortest(value));  // refused by the reader
  return out;
}

void LiveSession::check_setting(const std::string& key, double value,
                                const std::string& where) const {
  load_controller_settings(text_, path_, overrides_, setting_assignments(key, value), where);
}

void LiveSession::set_setting(const std::string& key, double value, const std::string& where) {
  const std::vector<std::string> assignments = setting_assignments(key, value);
  const auto config = load_controller_settings(text_, path_, overrides_, assignments, where);
  trial_->retune_controller(*config);
  for (LiveSettingValue& s : settings_) {
    if (s.key == key) s.value = value;
  }
  std::string list;
  for (const std::string& a : assignments)
    list += (list.empty() ? "" : ", ") + toml_value_text(toml::value<std::string>(a));
  const std::string e = event_key();
  record("set " + key + "=" + format_shortest(value),
         {e + ".action=set", e + ".when.at_s=" + format_shortest(time_s()),
          e + ".set=[" + list + "]"});
}

}  // namespace pamsim
