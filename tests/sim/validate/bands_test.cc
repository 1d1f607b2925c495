// bands_test.cc: the validation bands (src/sim/validate/bands.h): the brackets read and
// refused by key, the draws fixed by bracket_seed and the rig alone and inside their
// brackets, the statistics against order statistics worked by hand, a band over a run whose
// cell is its draw (uniform: median near the middle, the 5-95 % range near 5 % and 95 % of
// the bracket), the paper judged inside or outside, a rig the protocol refuses counted and
// kept out of the statistics, an assumption drawn only when asked, and the sensitivity's runs
// and swings.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "sim/validate/bands.h"

namespace pamsim {
namespace {

std::vector<Bracket> read_bracket_text(const std::string& text, std::uint64_t* seed) {
  ConfigReader in(text, "protocol.toml");
  std::vector<Bracket> brackets = read_brackets(in, seed);
  in.reject_unknown();
  return brackets;
}

const char kTwoBrackets[] =
    "bracket_seed = 3\n"
    "[[bracket]]\nname = \"creep\"\nkey = \"a.b\"\nfrom = 0.0\nto = 0.6\nsource = \"s1\"\n"
    "[[bracket]]\nname = \"line\"\nkey = \"c.d\"\nfrom = -2\nto = 2\nsource = \"s2\"\n";

TEST(BandsTest, BracketsAreReadInTheFilesOrder) {
  std::uint64_t seed = 0;
  const std::vector<Bracket> b = read_bracket_text(kTwoBrackets, &seed);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(seed, 3u);
  EXPECT_EQ(b[0].key, "a.b");
  EXPECT_EQ(b[1].from, -2.0);
  EXPECT_EQ(b[1].source, "s2");
  EXPECT_TRUE(read_bracket_text("", &seed).empty());
  EXPECT_EQ(seed, 1u);
}

TEST(BandsTest, BadBracketsNameTheirKey) {
  const std::string head = "[[bracket]]\nname = \"a\"\nkey = \"x.y\"\n";
  const std::string src = "source = \"a datasheet\"\n";
  for (const auto& [text, says] : std::vector<std::pair<std::string, std::string>>{
           {head + "from = 2\nto = 1\n" + src, "bracket[0].from must be below to, got 2 and 1"},
           {head + "from = 1\nto = 1\n" + src, "bracket[0].from must be below to"},
           {head + "to = 1\n" + src, "bracket[0].from is required"},
           {head + "from = 0\nto = 1\n", "bracket[0].source is required"},
           {head + "from = 0\nto = 1\nsource = \"\"\n", "bracket[0].source must cite"},
           {"[[bracket]]\nname = \"a\"\nkey = \"x=1\"\nfrom = 0\nto = 1\n" + src,
            "bracket[0].key must be a scenario key"},
           {head + "from = 0\nto = 1\n" + src + head + "from = 0\nto = 1\n" + src,
            "bracket[1].name repeats"},
           {head + "from = 0\nto = 1\nsourc = \"x\"\n", "bracket[0].sourc is not a key"},
           {"bracket_seed = -1\n", "bracket_seed must be >= 0"}}) {
    SCOPED_TRACE(text);
    std::uint64_t seed = 0;
    try {
      read_bracket_text(text, &seed);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("protocol.toml: "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

TEST(BandsTest, ARigsDrawsDependOnTheSeedAndTheRigAloneAndStayInTheirBrackets) {
  std::uint64_t seed = 0;
  const std::vector<Bracket> b = read_bracket_text(kTwoBrackets, &seed);
  const std::vector<double> rig5 = bracket_draws(b, seed, 5);
  EXPECT_EQ(bracket_draws(b, seed, 5), rig5);
  EXPECT_NE(bracket_draws(b, seed, 6), rig5);
  EXPECT_NE(bracket_draws(b, seed + 1, 5), rig5);
  for (int rig = 0; rig < 200; ++rig) {
    const std::vector<double> v = bracket_draws(b, seed, rig);
    EXPECT_TRUE(v[0] >= 0.0 && v[0] <= 0.6) << v[0];
    EXPECT_TRUE(v[1] >= -2.0 && v[1] <= 2.0) << v[1];
  }
  EXPECT_EQ(bracket_overrides(b, {0.25, -1.0}), (std::vector<std::string>{"a.b=0.25", "c.d=-1.0"}));
}

TEST(BandsTest, StatisticsAreTheOrderStatisticsInterpolated) {
  std::vector<double> v;
  for (int i = 21; i >= 1; --i) v.push_back(i);  // 1 .. 21, shuffled order irrelevant
  v.push_back(NAN);                              // a diverged rig: not counted
  const BandStats s = band_stats(v);
  EXPECT_EQ(s.n, 21);
  EXPECT_DOUBLE_EQ(s.median, 11.0);
  EXPECT_DOUBLE_EQ(s.p5, 2.0);    // 1 + 0.05 * 20
  EXPECT_DOUBLE_EQ(s.p95, 20.0);  // 1 + 0.95 * 20
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 21.0);
  EXPECT_EQ(band_stats({NAN}).n, 0);
  const BandStats two = band_stats({1.0, 3.0});
  EXPECT_DOUBLE_EQ(two.p5, 1.1);
  EXPECT_DOUBLE_EQ(two.median, 2.0);
}

// One run: the cell "x" errs by the value drawn for a.b (RMSE) and twice it (max)
std::vector<BandCell> echo_run(const std::vector<std::string>& overrides,
                               std::optional<ErrorPct> paper) {
  double drawn = NAN;
  for (const std::string& o : overrides) {
    if (o.rfind("a.b=", 0) == 0) drawn = std::stod(o.substr(4));
  }
  return {{"x", {2 * drawn, drawn}, paper}};
}

TEST(BandsTest, ABandOfAUniformDrawIsItsQuantilesAndJudgesThePaper) {
  std::uint64_t seed = 0;
  const std::vector<Bracket> b = read_bracket_text(kTwoBrackets, &seed);
  const Bands bands = run_bands(b, seed, 400, [](int, const std::vector<std::string>& o) {
    return echo_run(o, ErrorPct{1.0, 0.5});
  });
  ASSERT_EQ(bands.runs.errors.size(), 400u);
  std::vector<double> rmse;
  for (const auto& rig : bands.runs.errors) rmse.push_back(rig[0].rmse_pct);
  const BandStats s = band_stats(rmse);
  // U(0, 0.6): median 0.3, 5 % 0.03, 95 % 0.57; 400 draws put each within about 0.03
  EXPECT_NEAR(s.median, 0.3, 0.04);
  EXPECT_NEAR(s.p5, 0.03, 0.02);
  EXPECT_NEAR(s.p95, 0.57, 0.02);
  const std::string csv = bands_csv(bands);
  // the paper's RMSE 0.5 lies inside [0.03, 0.57]; its max 1.0 inside [0.06, 1.14]
  EXPECT_NE(csv.find("x,rmse,400,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",0.5,inside\n"), std::string::npos) << csv;
  const Bands outside = run_bands(b, seed, 50, [](int, const std::vector<std::string>& o) {
    return echo_run(o, ErrorPct{5.0, 0.7});
  });
  EXPECT_NE(bands_csv(outside).find(",0.7,outside\n"), std::string::npos);
  EXPECT_NE(bands_markdown(outside).find("inside the range: 0 of 1 cells"), std::string::npos);
  EXPECT_NE(draws_csv(outside).find("rig,a.b,c.d,x rmse_pct,refused\n0,"), std::string::npos);
}

// A bracket without a published source: drawn only when asked, listed apart when held, and
// the headline count says when it was drawn.
TEST(BandsTest, AnAssumptionIsDrawnOnlyWhenAskedAndNeverInTheHeadline) {
  std::uint64_t seed = 0;
  const std::vector<Bracket> b =
      read_bracket_text(std::string(kTwoBrackets) +
                            "[[bracket]]\nname = \"guess\"\nkey = \"e.f\"\nfrom = 1\nto = 2\n"
                            "source = \"nothing published\"\nassumption = true\n",
                        &seed);
  ASSERT_EQ(b.size(), 3u);
  EXPECT_FALSE(b[0].assumption);
  EXPECT_TRUE(b[2].assumption);
  ASSERT_EQ(drawn_brackets(b, false).size(), 2u);
  EXPECT_EQ(drawn_brackets(b, true).size(), 3u);
  auto run = [](int, const std::vector<std::string>& o) { return echo_run(o, ErrorPct{1, 0.3}); };
  Bands sourced = run_bands(drawn_brackets(b, false), seed, 20, run);
  sourced.held = {b[2]};
  const std::string md = bands_markdown(sourced);
  EXPECT_NE(md.find("inside the range: 1 of 1 cells.\n"), std::string::npos) << md;
  EXPECT_NE(md.find("Assumptions, not drawn"), std::string::npos) << md;
  EXPECT_NE(md.find("| guess | e.f | 1 | 2 | ASSUMPTION: nothing published |"), std::string::npos);
  EXPECT_EQ(draws_csv(sourced).find("e.f"), std::string::npos);
  const Bands all = run_bands(drawn_brackets(b, true), seed, 20, run);
  EXPECT_NE(bands_markdown(all).find("1 of 1 cells, assumptions drawn too: not the headline"),
            std::string::npos);
  EXPECT_NE(draws_csv(all).find("e.f"), std::string::npos);
  try {
    read_bracket_text(
        "[[bracket]]\nname = \"a\"\nkey = \"x.y\"\nfrom = 0\nto = 1\n"
        "source = \"s\"\nassumption = \"yes\"\n",
        &seed);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bracket[0].assumption must be"), std::string::npos)
        << e.what();
  }
}

TEST(BandsTest, ARigTheProtocolRefusesIsCountedNotFatal) {
  std::uint64_t seed = 0;
  const std::vector<Bracket> b = read_bracket_text(kTwoBrackets, &seed);
  // the rigs whose a.b is drawn above 0.3 cannot be tested, as a too thick wall cannot
  const auto run = [](int, const std::vector<std::string>& o) {
    const std::vector<BandCell> cells = echo_run(o, std::nullopt);
    if (cells[0].error.rmse_pct > 0.3) throw InputError("tensile test: cannot stretch, so far");
    return cells;
  };
  const Bands bands = run_bands(b, seed, 100, run);
  const int refused = bands.runs.refused_count();
  EXPECT_GT(refused, 30);
  EXPECT_LT(refused, 70);
  for (std::size_t r = 0; r < 100; ++r) {
    EXPECT_EQ(bands.runs.refused[r].empty(), std::isfinite(bands.runs.errors[r][0].rmse_pct));
  }
  std::vector<double> rmse;
  for (const auto& rig : bands.runs.errors) rmse.push_back(rig[0].rmse_pct);
  EXPECT_EQ(band_stats(rmse).n, 100 - refused);  // the refused rigs are in no statistic
  EXPECT_LE(band_stats(rmse).max, 0.3);
  EXPECT_NE(bands_markdown(bands).find("could not run " + std::to_string(refused) + " of 100 rigs"),
            std::string::npos);
  // quoted in the CSV, its comma kept
  EXPECT_NE(draws_csv(bands).find(",\"tensile test: cannot stretch, so far\"\n"),
            std::string::npos);
  // every run refused: the first refusal is the error
  EXPECT_THROW(run_bands(b, seed, 3,
                         [](int, const std::vector<std::string>&) -> std::vector<BandCell> {
                           throw InputError("no rig at all");
                         }),
               InputError);
}

TEST(BandsTest, RunsWhoseCellsDifferAreAnError) {
  std::uint64_t seed = 0;
  const std::vector<Bracket> b = read_bracket_text(kTwoBrackets, &seed);
  EXPECT_THROW(run_bands(b, seed, 2,
                         [](int rig, const std::vector<std::string>&) {
                           return std::vector<BandCell>{{rig == 0 ? "x" : "y", {1, 1}, {}}};
                         }),
               std::logic_error);
}

TEST(BandsTest, SensitivitySetsEachBracketAloneAtItsEnds) {
  std::uint64_t seed = 0;
  const std::vector<Bracket> b = read_bracket_text(kTwoBrackets, &seed);
  std::vector<std::vector<std::string>> seen;
  const Sensitivity s = run_sensitivity(b, [&](const std::vector<std::string>& o) {
    seen.push_back(o);
    return echo_run(o, std::nullopt);
  });
  ASSERT_EQ(seen.size(), 5u);
  using Set = std::vector<std::string>;
  EXPECT_EQ(seen[0], (Set{"a.b=0.3", "c.d=0.0"}));  // every bracket at its middle
  EXPECT_EQ(seen[1], (Set{"a.b=0.0", "c.d=0.0"}));
  EXPECT_EQ(seen[2], (Set{"a.b=0.6", "c.d=0.0"}));
  EXPECT_EQ(seen[4], (Set{"a.b=0.3", "c.d=2.0"}));
  EXPECT_DOUBLE_EQ(s.swing(0, 0), 0.6);  // the cell is a.b's value
  EXPECT_DOUBLE_EQ(s.swing(1, 0), 0.0);  // c.d moves nothing
  EXPECT_NE(sensitivity_markdown(s).find("| creep |"), std::string::npos);
}

// The swing is the cell's range over the bracket's two ends and middle: a cell whose middle
// is its extreme swings by that range, not by |to - from| (0 for an even function); an end
// whose rig the protocol refuses (a line that would break) is left out, and under two runs
// give no swing
TEST(BandsTest, ASwingIsTheRangeOverTheEndsAndMiddleThatRan) {
  std::uint64_t seed = 0;
  const std::vector<Bracket> b = read_bracket_text(kTwoBrackets, &seed);
  const auto value_of = [](const std::vector<std::string>& o, const std::string& key) {
    for (const std::string& s : o) {
      if (s.rfind(key + "=", 0) == 0) return std::stod(s.substr(key.size() + 1));
    }
    return std::nan("");
  };
  // the cell is (c.d)^2 (c.d in [-2, 2], middle 0), and a.b's rig is refused above 0.5
  const Sensitivity s = run_sensitivity(b, [&](const std::vector<std::string>& o) {
    if (value_of(o, "a.b") > 0.5) throw InputError("a.b: its line breaks");
    const double cd = value_of(o, "c.d");
    return std::vector<BandCell>{{"x", {cd * cd, cd * cd + value_of(o, "a.b")}, std::nullopt}};
  });
  EXPECT_DOUBLE_EQ(s.swing(1, 0), 4.0) << "0 at the middle to 4 at either end";
  EXPECT_DOUBLE_EQ(s.swing(0, 0), 0.3) << "from 0 to the middle 0.3; the end at 0.6 refused";
  EXPECT_EQ(s.runs.refused_count(), 1);
  const Sensitivity none = run_sensitivity(b, [&](const std::vector<std::string>& o) {
    if (value_of(o, "a.b") != 0.0) throw InputError("refused");
    return std::vector<BandCell>{{"x", {1, 1}, std::nullopt}};
  });
  EXPECT_TRUE(std::isnan(none.swing(0, 0))) << "only a.b's `from` ran";
}

}  // namespace
}  // namespace pamsim
