// outputs_test.cc: the statistics of an aggregate summary (sample_stats): mean, sample SD and
// the 95 % confidence interval of the mean against values worked by hand.
#include "sim/io/outputs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pamsim {
namespace {

TEST(OutputsTest, SampleStatsGiveTheStudentTIntervalOfTheMean) {
  const SampleStats s = sample_stats({1.0, 2.0, 3.0});
  EXPECT_EQ(s.count, 3);
  EXPECT_DOUBLE_EQ(s.mean, 2.0);
  EXPECT_DOUBLE_EQ(s.sd, 1.0);
  // t(0.975, 2 degrees of freedom) = 4.30265272974946 (tables); half-width t sd / sqrt(3)
  const double half = 4.30265272974946 / std::sqrt(3.0);
  EXPECT_NEAR(s.ci95_low, 2.0 - half, 1e-12);
  EXPECT_NEAR(s.ci95_high, 2.0 + half, 1e-12);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 3.0);

  // large n: the interval approaches mean +- 1.96 sd / sqrt(n)
  std::vector<double> many;
  for (int i = 0; i < 10000; ++i) many.push_back(i % 2 ? 1.0 : -1.0);
  const SampleStats m = sample_stats(many);
  EXPECT_NEAR(m.ci95_high - m.mean, 1.96 * m.sd / 100.0, 1e-4);

  // one value: a mean, no spread; none: nothing
  const SampleStats one = sample_stats({5.0});
  EXPECT_EQ(one.mean, 5.0);
  EXPECT_TRUE(std::isnan(one.sd));
  EXPECT_TRUE(std::isnan(one.ci95_low));
  const SampleStats none = sample_stats({});
  EXPECT_EQ(none.count, 0);
  EXPECT_TRUE(std::isnan(none.mean));
}

}  // namespace
}  // namespace pamsim
