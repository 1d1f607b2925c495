// channel_plugin_test.cc: an output channel is one row. The channel pressure_<m>_kPa is
// defined in this test alone (a row added to the channel table at start-up, no other source
// changed); the log, the observation the Python module hands out (observed_quantities) and the
// reference of trajectory.csv's columns (channel_docs, what `pamsim keys --channels` prints)
// all carry it with its unit. A row without a value or named twice is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/core/trial.h"
#include "sim/core/trial_channels.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

// the chamber's pressure in kPa, from the state every row reads
ChannelRow kilopascal_row() {
  return {"pressure_{m}_kPa",
          "kPa",
          1e3,
          1.0,
          "the chamber's gauge pressure in kPa",
          "a test's row",
          [](const TrialObservation& o, std::size_t i) { return o.pressure_pa[i]; }};
}

const bool kAdded = [] {
  add_trial_channel(kilopascal_row());
  return true;
}();

Scenario reaching() {
  return load_scenario(std::string(PAMSIM_SOURCE_DIR) + "/scenarios/reaching.toml",
                       {"sim.duration_s=0.5"});
}

TEST(ChannelPlugin, TheLogCarriesTheRowAsAColumnPerMuscleInItsUnit) {
  ASSERT_TRUE(kAdded);
  const Scenario sc = reaching();
  const TrialModel model = load_trial_model(sc);
  const TrialResult r = run_trial(model, sc, sc.seed);
  ASSERT_EQ(r.summary.status, "ok");
  const Trajectory& log = r.trajectory;
  for (const std::string m : {"ago", "anta"}) {
    ASSERT_TRUE(log.has_column("pressure_" + m + "_kPa"));
    const std::size_t kpa = log.column("pressure_" + m + "_kPa");
    const std::size_t mpa = log.column("p_" + m + "_MPa");
    for (std::size_t row = 0; row < log.rows(); row += 7) {
      // 1 MPa = 1000 kPa, both from the same pressure
      EXPECT_NEAR(log.at(row, kpa), 1e3 * log.at(row, mpa), 1e-9 * log.at(row, kpa) + 1e-12);
    }
    EXPECT_GT(log.at(log.rows() - 1, kpa), 100.0);  // the chambers are at 0.2 and 0.6 MPa
  }
  // appended: the columns before it are the log's as they were
  EXPECT_EQ(log.columns.back(), "pressure_anta_kPa");
}

TEST(ChannelPlugin, TheObservationCarriesItByItsNameWithoutTheMuscle) {
  const Scenario sc = reaching();
  const TrialModel model = load_trial_model(sc);
  SteppedTrial trial(model, sc, sc.seed);
  for (int k = 0; k < 20; ++k) trial.step();
  const TrialObservation o = trial.observe();
  const std::vector<ObservedQuantity> quantities =
      observed_quantities(trial_log_layout(model, sc), o);
  const auto it = std::find_if(quantities.begin(), quantities.end(),
                               [](const ObservedQuantity& q) { return q.name == "pressure_kPa"; });
  ASSERT_NE(it, quantities.end());
  EXPECT_EQ(it->unit, "kPa");
  EXPECT_TRUE(it->per_muscle);
  ASSERT_EQ(it->values.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(it->values[i], o.pressure_pa[i] / 1e3);
}

TEST(ChannelPlugin, TheReferenceListsItWithItsUnitAndFactor) {
  const std::vector<ChannelDoc> docs = channel_docs();
  const auto it = std::find_if(docs.begin(), docs.end(),
                               [](const ChannelDoc& d) { return d.column == "pressure_{m}_kPa"; });
  ASSERT_NE(it, docs.end());
  EXPECT_EQ(it->unit, "kPa");
  EXPECT_EQ(it->si_per_unit, 1e3);
  EXPECT_EQ(it->meaning, "the chamber's gauge pressure in kPa");
  // and a scenario's columns name it per muscle
  const Scenario sc = reaching();
  const std::vector<ChannelDoc> columns =
      channel_docs(trial_log_layout(load_trial_model(sc), sc), sc.controller_channels());
  EXPECT_EQ(columns.back().column, "pressure_anta_kPa");
  EXPECT_EQ(columns.back().unit, "kPa");
}

TEST(ChannelPlugin, ARowWithoutAValueOrUnitFactorOrNamedTwiceIsRefused) {
  ChannelRow no_value = kilopascal_row();
  no_value.name = "other_{m}_kPa";
  no_value.si = nullptr;
  EXPECT_THROW(add_trial_channel(no_value), std::invalid_argument);
  ChannelRow zero_factor = kilopascal_row();
  zero_factor.name = "other_{m}_kPa";
  zero_factor.to_si = 0.0;
  EXPECT_THROW(add_trial_channel(zero_factor), std::invalid_argument);
  EXPECT_THROW(add_trial_channel(kilopascal_row()), std::invalid_argument);
}

}  // namespace
}  // namespace pamsim
