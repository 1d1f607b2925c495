// instrument_kinds_test.cc: the instruments' registry (sensing/instrument_kinds.h): its kinds
// in reading order, each a model choice first (the ideal name, then the hardware's) whose
// setting reaches the config, a validate() that refuses a bad value of its own rows naming
// the key, and the creep series it names being the config's own.
#include "sensing/instrument_kinds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "sensing/sensors.h"

namespace pamsim {
namespace {

TEST(InstrumentKindsTest, TheKindsAreTheFourInstrumentsInReadingOrder) {
  std::vector<std::string> names;
  for (const InstrumentKind& k : instrument_kinds()) names.push_back(k.name);
  EXPECT_EQ(names, (std::vector<std::string>{"gauge", "pressure", "fiber", "encoder"}));
  ASSERT_NE(find_instrument_kind("fiber"), nullptr);
  EXPECT_EQ(find_instrument_kind("fiber")->name, "fiber");
  EXPECT_EQ(find_instrument_kind("thermometer"), nullptr);
}

TEST(InstrumentKindsTest, EachKindsModelIsItsFirstChoiceAndReachesTheConfig) {
  for (const InstrumentKind& kind : instrument_kinds()) {
    SCOPED_TRACE(kind.name);
    SensorConfig config;  // every instrument ideal by default
    std::vector<KeyTable> tables = kind.key_tables(&config);
    ASSERT_FALSE(tables.empty());
    EXPECT_EQ(tables.front().name, "sensors." + kind.name);
    const ChoiceRow& model = tables.front().choices.at(0);
    EXPECT_EQ(model.name, "model");
    ASSERT_EQ(model.allowed.size(), 2u);
    EXPECT_EQ(model.get(), model.allowed.front());
    SensorConfig ideal = config;
    model.set(model.allowed.back());  // the hardware model, set in the config
    EXPECT_EQ(model.get(), model.allowed.back());
    EXPECT_EQ(kind.key_tables(&config).front().choices.at(0).get(), model.allowed.back());
    EXPECT_NE(kind.key_tables(&ideal).front().choices.at(0).get(), model.allowed.back())
        << "the copy taken before stays ideal";
    EXPECT_NO_THROW(kind.validate(config));
  }
}

TEST(InstrumentKindsTest, EachKindsValidateRefusesABadRowValueNamingTheKey) {
  for (const InstrumentKind& kind : instrument_kinds()) {
    SCOPED_TRACE(kind.name);
    SensorConfig config;
    const std::vector<KeyTable> tables = kind.key_tables(&config);
    const KeyTable* with_numbers = nullptr;
    for (const KeyTable& t : tables) {
      if (!t.numbers.empty() && t.numbers.front().target != nullptr) {
        with_numbers = &t;
        break;
      }
    }
    ASSERT_NE(with_numbers, nullptr);
    const NumberRow& row = with_numbers->numbers.front();
    *row.target = std::nan("");  // outside every range
    try {
      kind.validate(config);
      ADD_FAILURE() << row.name << " = NaN was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(with_numbers->name + "." + row.name), std::string::npos)
          << e.what();
    }
  }
}

TEST(InstrumentKindsTest, AKindsCreepSeriesIsTheConfigsOwn) {
  SensorConfig config;
  int with_creep = 0;
  for (const InstrumentKind& kind : instrument_kinds()) {
    if (!kind.creep) {
      EXPECT_TRUE(kind.creep_table.empty()) << kind.name;
      continue;
    }
    ++with_creep;
    EXPECT_EQ(kind.creep_table.rfind("sensors." + kind.name, 0), 0u) << kind.creep_table;
    std::vector<PronyTerm>* series = kind.creep(&config);
    series->push_back({0.5, 3.0});
    EXPECT_EQ(kind.creep(&config)->back().time_s, 3.0);
  }
  EXPECT_EQ(with_creep, 2) << "the gauge's board and the fiber";
  EXPECT_EQ(config.gauge_hardware.creep.back().weight, 0.5);
  EXPECT_EQ(config.fiber_hardware.creep.back().weight, 0.5);
}

}  // namespace
}  // namespace pamsim
