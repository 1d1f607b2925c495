// scenario_events.cc: what happens when: bodies.<body>.mass_kg, holds.<body>, events.<name>,
// and the pamsim 0.1 drop.* shorthand that expands into them.
#include <cmath>

#include "base/units.h"
#include "sim/scenario/scenario_reading.h"
#include "sim/scenario/scenario_key_tables.h"

namespace pamsim {
namespace {

EventAction parse_action(ConfigReader& in, const std::string& key) {
  const std::string name = in.get_string(key, "mark");
  const std::pair<const char*, EventAction> actions[] = {
      {"mark", EventAction::kMark},
      {"release", EventAction::kRelease},
      {"add_mass", EventAction::kAddMass},
      {"controller_off", EventAction::kControllerOff},
      {"controller_on", EventAction::kControllerOn},
      {"end", EventAction::kEnd}};
  for (const auto& [text, action] : actions) {
    if (name == text) return action;
  }
  in.fail(key, "must be \"mark\", \"release\", \"add_mass\", \"controller_off\", "
               "\"controller_on\" or \"end\", got \"" + name + "\"");
}

// when.*: exactly one of at_s, contact, joint (with a threshold), body (with below_z_m)
ConditionSpec read_condition(ConfigReader& in, const std::string& key, const Scenario& sc) {
  ConditionSpec c;
  const int given = in.has(key + ".at_s") + in.has(key + ".contact") + in.has(key + ".joint") +
                    in.has(key + ".body");
  in.check(given == 1, key, "must give one of at_s, contact, joint or body");
  if (in.has(key + ".at_s")) {
    c.kind = ConditionKind::kTime;
    c.at_s = in.get_double(key + ".at_s", 0.0);
    in.check(c.at_s >= 0, key + ".at_s", "must be >= 0, got " + format_value(c.at_s));
    in.check(c.at_s < sc.duration_s, key + ".at_s",
             "must be before the end of the trial (" +
                 in.described("sim.duration_s", sc.duration_s) + " s), got " +
                 format_value(c.at_s));
  } else if (in.has(key + ".contact")) {
    c.kind = ConditionKind::kContact;
    const std::vector<std::string> bodies = in.get_string_list(key + ".contact", {});
    in.check(bodies.size() == 2, key + ".contact", "must name two bodies");
    c.body_a = bodies[0];
    c.body_b = bodies[1];
  } else if (in.has(key + ".joint")) {
    c.joint = in.get_string(key + ".joint", "");
    const std::pair<const char*, double> thresholds[] = {
        {"below_deg", units::deg_to_rad(1.0)}, {"above_deg", units::deg_to_rad(1.0)},
        {"below_mm", units::mm_to_m(1.0)}, {"above_mm", units::mm_to_m(1.0)}};
    int n = 0;
    for (const auto& [field, to_si] : thresholds) {
      if (!in.has(key + "." + field)) continue;
      ++n;
      c.threshold = in.get_double(key + "." + field, 0.0) * to_si;
      c.kind = field[0] == 'b' ? ConditionKind::kJointBelow : ConditionKind::kJointAbove;
    }
    in.check(n == 1, key, "with joint must give one of below_deg, above_deg, below_mm, above_mm");
  } else {
    c.kind = ConditionKind::kBodyBelow;
    c.body_a = in.get_string(key + ".body", "");
    in.check(in.has(key + ".below_z_m"), key + ".below_z_m", "is required with body");
    c.threshold = in.get_double(key + ".below_z_m", 0.0);
  }
  return c;
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
  const std::string body = in.get_string("drop.body", "ball");
  const std::string basket = in.get_string("drop.basket", "basket");
  const std::string site = in.get_string("drop.site", "basket_floor");

  // the mass, held above the basket floor, released at time_s; the impact marked
  sc->body_masses.push_back({"drop.mass_kg", body, drop.mass_kg});
  HoldSpec hold;
  hold.key = "drop";
  hold.body = body;
  hold.above_site = site;
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
  impact.when.body_b = basket;
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
      const std::vector<double>& i = keys.inertia_kg_m2;   // three (its row)
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
      h.position_m = {position[0], position[1], position[2]};   // three (its row)
      in.check(!in.has(h.key + ".above_site") && !in.has(h.key + ".height_m"), h.key,
               "gives position_m and above_site or height_m; give one");
    } else {
      in.check(!h.above_site.empty(), h.key, "must give above_site (with height_m) or position_m");
    }
    for (const HoldSpec& other : sc->holds) {
      in.check(other.body != body, h.key, "holds body '" + body + "', already held by " + other.key);
    }
    sc->holds.push_back(h);
  }
}

void read_events(ConfigReader& in, Scenario* sc) {
  for (const std::string& name : in.child_keys("events")) {
    EventSpec e;
    e.key = "events." + name;
    e.name = name;
    in.check(sc->event(name) == nullptr, e.key, "repeats the name of an event the [drop] table makes");
    e.action = parse_action(in, e.key + ".action");
    if (e.action == EventAction::kRelease || e.action == EventAction::kAddMass) {
      e.body = in.get_string(e.key + ".body", "");
      in.check(!e.body.empty(), e.key + ".body", "is required for this action");
    }
    if (e.action == EventAction::kAddMass) {
      e.mass_kg = in.get_double(e.key + ".mass_kg", 0.0);
      in.check(e.mass_kg > 0 && e.mass_kg <= 1000, e.key + ".mass_kg",
               "must be in (0, 1000] kg, got " + format_value(e.mass_kg));
    }
    e.when = read_condition(in, e.key + ".when", *sc);
    e.when.after = in.get_string(e.key + ".after", "");
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
