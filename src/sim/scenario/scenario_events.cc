// scenario_events.cc: what happens when: bodies.<body>.mass_kg, holds.<body>, events.<name>,
// and the pamsim 0.1 drop.* shorthand that expands into them.
#include <algorithm>
#include <cmath>
#include <utility>

#include "base/units.h"
#include "sim/scenario/scenario_reading.h"
#include "sim/scenario/scenario_key_tables.h"

namespace pamsim {
namespace {

// action and after; body with release and add_mass; mass_kg with add_mass (the rows:
// scenario_key_tables.h)
void read_event_keys(ConfigReader& in, EventSpec* e) {
  KeyTable table = event_key_table(e);
  table.name = e->key;
  read_key_rows(in, rows_named(table, {"action", "after"}));
  if (e->action == EventAction::kRelease || e->action == EventAction::kAddMass) {
    read_key_rows(in, rows_named(table, {"body"}));
    in.check(!e->body.empty(), e->key + ".body", "is required for this action");
  }
  if (e->action == EventAction::kAddMass) read_key_rows(in, rows_named(table, {"mass_kg"}));
  if (e->action == EventAction::kSet) {
    read_key_rows(in, rows_named(table, {"set"}));
    in.check(!e->set.empty(), e->key + ".set", "is required for this action");
  }
}

// when.joint with exactly one threshold: the condition's kind and its threshold in SI
void set_joint_threshold(ConfigReader& in, const std::string& key, const EventThresholds& t,
                         ConditionSpec* c) {
  const std::pair<const std::optional<double>*, ConditionKind> given[] = {
      {&t.below_rad, ConditionKind::kJointBelow},
      {&t.above_rad, ConditionKind::kJointAbove},
      {&t.below_m, ConditionKind::kJointBelow},
      {&t.above_m, ConditionKind::kJointAbove}};
  int n = 0;
  for (const auto& [value, kind] : given) {
    if (!value->has_value()) continue;
    ++n;
    c->threshold = **value;
    c->kind = kind;
  }
  in.check(n == 1, key, "with joint must give one of below_deg, above_deg, below_mm, above_mm");
}

// when.*: exactly one of at_s, contact, joint (with a threshold), body (with below_z_m)
void read_condition(ConfigReader& in, const Scenario& sc, EventSpec* e) {
  const std::string key = e->key + ".when";
  ConditionSpec& c = e->when;
  const int given = in.has(key + ".at_s") + in.has(key + ".contact") + in.has(key + ".joint") +
                    in.has(key + ".body");
  in.check(given == 1, key, "must give one of at_s, contact, joint or body");
  EventThresholds thresholds;
  KeyTable table = event_when_key_table(e, &thresholds);
  table.name = key;
  if (in.has(key + ".at_s")) {
    c.kind = ConditionKind::kTime;
    read_key_rows(in, rows_named(table, {"at_s"}));
    in.check(c.at_s < sc.duration_s, key + ".at_s",
             "must be before the end of the trial (" +
                 in.described("sim.duration_s", sc.duration_s) + " s), got " +
                 format_value(c.at_s));
  } else if (in.has(key + ".contact")) {
    c.kind = ConditionKind::kContact;
    read_key_rows(in, rows_named(table, {"contact"}));
    const std::vector<std::string>& bodies = thresholds.contact;
    in.check(bodies.size() == 2, key + ".contact", "must name two bodies");
    c.body_a = bodies[0];
    c.body_b = bodies[1];
  } else if (in.has(key + ".joint")) {
    read_key_rows(in, rows_given(in, rows_named(table, {"joint", "below_deg", "above_deg",
                                                        "below_mm", "above_mm"})));
    set_joint_threshold(in, key, thresholds, &c);
  } else {
    c.kind = ConditionKind::kBodyBelow;
    read_key_rows(in, rows_named(table, {"body", "below_z_m"}));
    c.threshold = *thresholds.below_z_m;
  }
}

}  // namespace

void read_drop(ConfigReader& in, Scenario* sc, bool implied) {
  if (!in.is_table("drop") && !implied) return;
  DropShorthand drop;
  read_key_rows(in, drop_key_table(&drop));
  in.check(drop.time_s < sc->duration_s, "drop.time_s",
           "must be in [0, sim.duration_s): " + in.described("drop.time_s", drop.time_s) +
               " with " + in.described("sim.duration_s", sc->duration_s) +
               "; set the other too (--set drop.time_s=...)");
  const std::string& body = drop.body;

  // the mass, held above the basket floor, released at time_s; the impact marked
  sc->body_masses.push_back({"drop.mass_kg", body, drop.mass_kg});
  HoldSpec hold;
  hold.key = "drop";
  hold.body = body;
  hold.above_site = drop.site;
  hold.height_m = drop.height_m;
  sc->holds.push_back(hold);
  EventSpec release;
  release.key = "drop";
  release.name = "release";
  release.action = EventAction::kRelease;
  release.body = body;
  release.when.at_s = drop.enabled ? drop.time_s : INFINITY;
  sc->events.push_back(release);
  EventSpec impact;
  impact.key = "drop";
  impact.name = "impact";
  impact.when.kind = ConditionKind::kContact;
  impact.when.body_a = body;
  impact.when.body_b = drop.basket;
  impact.when.after = "release";
  sc->events.push_back(impact);
}

// bodies.<body>: a mass, moments of inertia, or both (the rows: scenario_key_tables.h); the
// moments must be three that a rigid body can have (each at most the sum of the other two,
// as MuJoCo's compiler demands)
void read_bodies(ConfigReader& in, Scenario* sc) {
  for (const std::string& body : in.child_keys("bodies")) {
    BodyKeys keys;
    KeyTable table = body_key_table(&keys);
    table.name = "bodies." + body;
    read_key_rows(in, rows_given(in, table));
    const std::string key = table.name + ".mass_kg", inertia_key = table.name + ".inertia_kg_m2";
    in.check(keys.mass_kg || in.has(inertia_key), key, "is required (or inertia_kg_m2)");
    BodyMassSpec spec{keys.mass_kg ? key : inertia_key, body, keys.mass_kg.value_or(0.0), {}};
    if (in.has(inertia_key)) {
      const std::vector<double>& i = keys.inertia_kg_m2;  // three (its row)
      for (int k = 0; k < 3; ++k) {
        in.check(i[k] <= i[(k + 1) % 3] + i[(k + 2) % 3], inertia_key,
                 "is no rigid body's: each moment must be at most the sum of the other two");
        spec.inertia_kg_m2[k] = i[k];
      }
    }
    for (const BodyMassSpec& other : sc->body_masses) {
      in.check(other.body != body || other.mass_kg == 0 || spec.mass_kg == 0, key,
               "sets body '" + body + "', already set by " + other.key);
    }
    sc->body_masses.push_back(spec);
  }
}

// holds.<body>: above a site (and a height) or at a position (the rows: scenario_key_tables.h)
void read_bodies_and_holds(ConfigReader& in, Scenario* sc) {
  read_bodies(in, sc);
  for (const std::string& body : in.child_keys("holds")) {
    HoldSpec h;
    h.key = "holds." + body;
    h.body = body;
    std::vector<double> position;
    KeyTable table = hold_key_table(&h, &position);
    table.name = h.key;
    read_key_rows(in, rows_given(in, table));
    h.at_position = in.has(h.key + ".position_m");
    if (h.at_position) {
      h.position_m = {position[0], position[1], position[2]};  // three (its row)
      in.check(!in.has(h.key + ".above_site") && !in.has(h.key + ".height_m"), h.key,
               "gives position_m and above_site or height_m; give one");
    } else {
      in.check(!h.above_site.empty(), h.key, "must give above_site (with height_m) or position_m");
    }
    for (const HoldSpec& other : sc->holds) {
      in.check(other.body != body, h.key,
               "holds body '" + body + "', already held by " + other.key);
    }
    sc->holds.push_back(h);
  }
}

void read_events(ConfigReader& in, Scenario* sc) {
  for (const std::string& name : in.child_keys("events")) {
    EventSpec e;
    e.key = "events." + name;
    e.name = name;
    in.check(sc->event(name) == nullptr, e.key,
             "repeats the name of an event the [drop] table makes");
    read_event_keys(in, &e);
    read_condition(in, *sc, &e);
    sc->events.push_back(e);
  }
  // `after` names another event
  for (const EventSpec& e : sc->events) {
    if (e.when.after.empty()) continue;
    in.check(sc->event(e.when.after) != nullptr && e.when.after != e.name, e.key + ".after",
             "names no other event: \"" + e.when.after + "\"");
  }
}

}  // namespace pamsim
