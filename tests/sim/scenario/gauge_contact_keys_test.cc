// gauge_contact_keys_test.cc: a muscle's own gauge contact (muscles.<m>.gauge.contact.*, the
// shared sensors.gauge.contact its defaults): its keys reach the muscle, a line laid to leave
// one board leaves that gauge alone silent, and bad values are refused by the muscle's key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sim/scenario_errors.h"
#include "sim/validate/reaching.h"

namespace pamsim {
namespace {

using pamsim_test::kReaching;
using pamsim_test::kScenarios;

// the knife-edge contact of docs/validation.md's mechanisms, under `table` (a muscle's or
// the shared one)
std::vector<std::string> knife_edge(const std::string& table) {
  std::vector<std::string> set;
  for (const char* kv : {"misalignment_mm=5", "fitting_distance_mm=10", "shaft_distance_mm=100",
                         "wrap_deg=5", "friction_coefficient=0.2"}) {
    set.push_back(table + "." + kv);
  }
  set.push_back("sensors.gauge.board.length_mm=0");
  set.push_back("model.antagonist_deformation_mm=5");  // the lines tied as the docs' run
  return set;
}

TEST(GaugeContactKeysTest, AMusclesOwnContactReachesItAndTheSharedOneIsItsDefault) {
  const Scenario sc = load_scenario(kReaching, {"muscles.agonist.gauge.contact.wrap_deg=5",
                                                "sensors.gauge.contact.friction_coefficient=0.3"});
  ASSERT_TRUE(sc.muscles[0].gauge_contact.has_value());
  EXPECT_EQ(sc.muscles[0].gauge_contact->wrap_deg, 5.0);
  EXPECT_EQ(sc.muscles[0].gauge_contact->friction_coefficient, 0.3) << "the shared one's";
  EXPECT_FALSE(sc.muscles[1].gauge_contact.has_value());
}

// The slack episodes' starts of one reaching trial, per muscle (agonist, antagonist)
std::vector<double> loss_times(const std::vector<std::string>& overrides) {
  ValidationOptions options;
  options.threads = 1;
  options.overrides = overrides;
  const ReachingValidationResult r = run_reaching_validation(
      load_reaching_validation(kScenarios + "validate_reaching.toml", {"trials=1"}), options);
  return {r.slack_start_s[0].front(), r.slack_start_s[1].front()};
}

TEST(GaugeContactKeysTest, ALineLaidToLeaveOneBoardSilencesThatGaugeAlone) {
  const std::vector<double> shared = loss_times(knife_edge("sensors.gauge.contact"));
  EXPECT_TRUE(std::isfinite(shared[0]) && std::isfinite(shared[1])) << "both lines leave";
  const std::vector<double> own = loss_times(knife_edge("muscles.agonist.gauge.contact"));
  EXPECT_NEAR(own[0], shared[0], 0.05) << "the agonist's, as with the shared contact";
  EXPECT_TRUE(std::isnan(own[1])) << "the antagonist's line stays on its board";
}

TEST(GaugeContactKeysTest, BadValuesAreRefusedByTheMusclesKey) {
  using pamsim_test::error_of;
  const std::string key = "muscles.agonist.gauge.contact.";
  for (const auto& [set, named] : std::vector<std::pair<std::string, std::string>>{
           {key + "wrap_deg=200", key + "wrap_deg"},
           {key + "friction_coefficient=-1", key + "friction_coefficient"},
           {key + "model=\"glued\"", key + "model"},
           {key + "reseat_mm=50", key + "reseat_mm"}}) {  // off the board: the gauge's check
    const std::string message = error_of("reaching.toml", {set});
    EXPECT_NE(message.find(named), std::string::npos) << set << ": " << message;
  }
  const std::string ideal = error_of("drop_mass_ideal.toml", {key + "wrap_deg=5"});
  EXPECT_NE(ideal.find("is used only by sensors.gauge.model = \"bridge\""), std::string::npos)
      << ideal;
}

}  // namespace
}  // namespace pamsim
