// name_list_keys_test.cc: the scenario's keys that are lists of names or a muscle's name
// (metrics, events.<event>.when.contact, muscles.<actuator>.label and .spans) as rows
// (scenario_key_tables.h) through the scenario reader: a bad value of each is refused in one
// line naming the scenario file and the key; a good one reaches the scenario; each is one row.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "base/input_error.h"
#include "base/key_table_test_util.h"
#include "sim/scenario/scenario_file.h"
#include "sim/scenario/scenario_key_tables.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

using pamsim_test::kDropMass;

// The scenario's name lists (metrics, events.<event>.when.contact): a name the row does not
// allow, an item that is no string and a value that is no list are refused naming the file
// and the key; the names reach the scenario; the reference lists each row once.
TEST(NameListKeysTest, MetricsAndContactRefuseTheirBadValuesAndReachTheScenario) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"metrics", {}}, {"events.e.when.contact", {"events.e.action=\"mark\""}}};
  for (const auto& [key, context] : cases) {
    for (const char* bad : {"[\"drop\", 3]", "\"drop\"", "7"}) {
      std::vector<std::string> set = context;
      set.push_back(key + "=" + bad);
      const InputErrorParts parts =
          refusal_parts([&] { load_scenario(kDropMass, set); }, key + bad);
      EXPECT_EQ(parts.key, key) << bad;
      EXPECT_EQ(parts.file, kDropMass) << bad;
    }
  }
  const InputErrorParts unknown = refusal_parts(
      [&] { load_scenario(kDropMass, {"metrics=[\"drop\", \"speed\"]"}); }, "metrics speed");
  EXPECT_EQ(unknown.key, "metrics");
  EXPECT_NE(unknown.problem.find("holds \"speed\", allowed \"drop\""), std::string::npos)
      << unknown.problem;
  EXPECT_EQ(load_scenario(kDropMass, {"metrics=[\"tracking\", \"drop\"]"}).metrics,
            (std::vector<std::string>{"tracking", "drop"}));
  const Scenario touch = load_scenario(
      kDropMass, {"events.e.action=\"mark\"", "events.e.when.contact=[\"ball\", \"basket\"]"});
  const auto e = std::find_if(touch.events.begin(), touch.events.end(),
                              [](const EventSpec& x) { return x.key == "events.e"; });
  ASSERT_NE(e, touch.events.end());
  EXPECT_EQ(e->when.kind, ConditionKind::kContact);
  EXPECT_EQ(e->when.body_a, "ball");
  EXPECT_EQ(e->when.body_b, "basket");
  EXPECT_EQ(refusal_parts(
                [&] {
                  load_scenario(kDropMass,
                                {"events.e.action=\"mark\"", "events.e.when.contact=[\"ball\"]"});
                },
                "one body")
                .key,
            "events.e.when.contact");
  Scenario sc;
  EventSpec event;
  EventThresholds thresholds;
  const std::map<std::string, int> rows =
      row_keys({metrics_key_table(&sc), event_when_key_table(&event, &thresholds)});
  EXPECT_EQ(rows.at("metrics"), 1);
  EXPECT_EQ(rows.at("events.<event>.when.contact"), 1);
}

// muscles.<actuator>.label and .spans as rows: a value of another type is refused naming the
// file and the key, a good one reaches the muscle, a label with a space is still refused.
TEST(MuscleNameKeysTest, LabelAndSpansRefuseTheirBadValuesAndReachTheMuscle) {
  for (const auto& [key, bad] : std::vector<std::pair<std::string, std::string>>{
           {"muscles.agonist.label", "1"},
           {"muscles.agonist.label", "true"},
           {"muscles.agonist.spans", "\"shoulder\""},
           {"muscles.agonist.spans", "[\"shoulder\", 2]"},
           {"muscles.agonist.label", "\"a b\""}}) {
    const std::string set = key + "=" + bad;  // a structured binding is no lambda capture in C++17
    const InputErrorParts parts = refusal_parts([&] { load_scenario(kDropMass, {set}); }, set);
    EXPECT_EQ(parts.key, key) << bad;
    EXPECT_EQ(parts.file, kDropMass) << bad;
  }
  const Scenario sc = load_scenario(
      kDropMass, {"muscles.agonist.label=\"biceps\"", "muscles.agonist.spans=[\"shoulder\"]"});
  EXPECT_EQ(sc.muscles[0].label, "biceps");
  EXPECT_EQ(sc.muscles[0].spans, std::vector<std::string>{"shoulder"});
  EXPECT_EQ(load_scenario(kDropMass).muscles[1].label, "anta")
      << "the shorthand model.antagonist_params: its legacy label";
  MuscleSpec muscle;
  EXPECT_EQ(row_keys({muscle_name_key_table(&muscle)}),
            (std::map<std::string, int>{{"muscles.<actuator>.label", 1},
                                        {"muscles.<actuator>.params", 1},
                                        {"muscles.<actuator>.spans", 1}}));
}

}  // namespace
}  // namespace pamsim
