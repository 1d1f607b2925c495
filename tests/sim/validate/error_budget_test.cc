// error_budget_test.cc: the error budget (src/sim/validate/error_budget.h): its sources read
// and refused by key, its runs (none, all, each alone, all but each) with their overrides,
// and its shares checked against sources whose errors add in quadrature by construction,
// where alone, by removal and the sum of squares must all agree exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "base/config_reader.h"
#include "base/input_error.h"
#include "sim/validate/error_budget.h"

namespace pamsim {
namespace {

using Kind = BudgetConfig::Kind;

std::vector<BudgetSource> read(const std::string& text) {
  ConfigReader in(text, "protocol.toml");
  std::vector<BudgetSource> sources = read_budget_sources(in);
  in.reject_unknown();
  return sources;
}

const char kTwoSources[] = R"(
[[budget_source]]
name = "gauge"
on = ['sensors.gauge.model="bridge"']
off = ['sensors.gauge.model="linear"']
[[budget_source]]
name = "line"
on = ["muscles.pam.line_diameter_mm=0.5", "muscles.pam.line_modulus_MPa=2500"]
)";

TEST(ErrorBudgetTest, SourcesAreReadInTheFilesOrder) {
  const std::vector<BudgetSource> s = read(kTwoSources);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].name, "gauge");
  EXPECT_EQ(s[0].off, std::vector<std::string>{"sensors.gauge.model=\"linear\""});
  EXPECT_EQ(s[1].on.size(), 2u);
  EXPECT_TRUE(s[1].off.empty()) << "off defaults to none";
  EXPECT_TRUE(read("").empty()) << "a protocol without sources has none";
}

TEST(ErrorBudgetTest, RunsAreNoneAllEachAloneAndAllButEach) {
  const std::vector<BudgetConfig> c = budget_configs(read(kTwoSources));
  ASSERT_EQ(c.size(), 6u);
  const std::string g_on = "sensors.gauge.model=\"bridge\"",
                    g_off = "sensors.gauge.model=\"linear\"";
  const std::string l1 = "muscles.pam.line_diameter_mm=0.5",
                    l2 = "muscles.pam.line_modulus_MPa=2500";
  EXPECT_EQ(c[0].name, "none");
  EXPECT_EQ(c[0].overrides, (std::vector<std::string>{g_off}));
  EXPECT_EQ(c[1].name, "all");
  EXPECT_EQ(c[1].overrides, (std::vector<std::string>{g_on, l1, l2}));
  EXPECT_EQ(c[2].name, "only gauge");
  EXPECT_EQ(c[2].overrides, (std::vector<std::string>{g_on}));
  EXPECT_EQ(c[3].name, "only line");
  EXPECT_EQ(c[3].overrides, (std::vector<std::string>{g_off, l1, l2}));
  EXPECT_EQ(c[4].name, "all but gauge");
  EXPECT_EQ(c[4].overrides, (std::vector<std::string>{g_off, l1, l2}));
  EXPECT_EQ(c[5].name, "all but line");
  EXPECT_EQ(c[5].source, 1);
  EXPECT_EQ(c[5].kind, Kind::kWithout);
  EXPECT_EQ(c[5].overrides, (std::vector<std::string>{g_on}));
}

// Sources whose errors are independent and add in quadrature: a case's RMSE is
// sqrt(base^2 + sum of the sigmas of the sources on), so each share, alone and by removal,
// is that source's sigma, and the sum of squares gives the all run's RMSE.
TEST(ErrorBudgetTest, SharesOfQuadratureAdditiveSourcesAreTheirSigmas) {
  const std::vector<BudgetSource> sources = read(kTwoSources);
  const double base[2] = {0.3, 1.2};
  const double sigma[2][2] = {{0.4, 0.05}, {0.0, 0.9}};  // [source][case]
  const ErrorBudget b = run_error_budget(sources, [&](const BudgetConfig& c) {
    std::vector<BudgetCell> cells;
    for (int k = 0; k < 2; ++k) {
      double var = base[k] * base[k];
      for (int s = 0; s < 2; ++s) {
        const bool on = c.kind == Kind::kAll || (c.kind == Kind::kOnly && c.source == s) ||
                        (c.kind == Kind::kWithout && c.source != s);
        if (on) var += sigma[s][k] * sigma[s][k];
      }
      cells.push_back({k == 0 ? "PAM-A" : "PAM-B", {2.0 * std::sqrt(var), std::sqrt(var)}});
    }
    return cells;
  });
  ASSERT_EQ(b.cases, (std::vector<std::string>{"PAM-A", "PAM-B"}));
  for (int s = 0; s < 2; ++s) {
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_NEAR(b.share_alone(s, k), sigma[s][k], 1e-12) << s << ' ' << k;
      EXPECT_NEAR(b.share_by_removal(s, k), sigma[s][k], 1e-12) << s << ' ' << k;
    }
  }
  const std::string md = budget_markdown(b);
  EXPECT_NE(md.find("| gauge | 0.4 / 0.4 | 0.05 / 0.05 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| line | 0 / 0 | 0.9 / 0.9 |"), std::string::npos) << md;
  // sqrt(0.3^2 + 0.4^2) = 0.5 and sqrt(1.2^2 + 0.05^2 + 0.9^2) = 1.5008, the all runs': ratio 1
  EXPECT_NE(md.find("| 0.5 (1) | 1.5 (1) |"), std::string::npos) << md;
}

TEST(ErrorBudgetTest, ASourceThatLowersTheErrorHasNoShare) {
  const ErrorBudget b = run_error_budget(read(kTwoSources), [](const BudgetConfig& c) {
    const bool gauge_on = c.kind == Kind::kAll || (c.kind == Kind::kOnly && c.source == 0) ||
                          (c.kind == Kind::kWithout && c.source == 1);
    return std::vector<BudgetCell>{{"x", {1.0, gauge_on ? 0.5 : 0.6}}};
  });
  EXPECT_EQ(b.share_alone(0, 0), 0.0);
  EXPECT_EQ(b.share_by_removal(0, 0), 0.0);
  EXPECT_EQ(b.share_alone(1, 0), 0.0) << "the line changes nothing";
}

TEST(ErrorBudgetTest, CsvHasARowPerCaseAndRunWithItsShare) {
  const ErrorBudget b = run_error_budget(read(kTwoSources), [](const BudgetConfig& c) {
    return std::vector<BudgetCell>{{"x", {2.0, c.kind == Kind::kNone ? 0.75 : 1.25}}};
  });
  const std::string csv = budget_csv(b);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "case,config,source,max_error_pct,rmse_pct,share_rmse_pct");
  EXPECT_NE(csv.find("\nx,none,,2,0.75,\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nx,only gauge,gauge,2,1.25,1\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nx,all but line,line,2,1.25,0\n"), std::string::npos) << csv;
}

TEST(ErrorBudgetTest, RunsWhoseCellsDifferAreAnError) {
  int runs = 0;
  EXPECT_THROW(run_error_budget(read(kTwoSources),
                                [&](const BudgetConfig&) {
                                  return std::vector<BudgetCell>{{runs++ ? "b" : "a", {}}};
                                }),
               std::logic_error);
}

// Every bad value of a [[budget_source]] is refused naming its key.
TEST(ErrorBudgetTest, BadSourcesNameTheirKey) {
  const std::string ok_on = "on = [\"sensors.noise_scale=1\"]\n";
  std::string many;
  for (int i = 0; i <= kMaxBudgetSources; ++i) {
    many += "[[budget_source]]\nname = \"s" + std::to_string(i) + "\"\n" + ok_on;
  }
  for (const auto& [text, says] : std::vector<std::pair<std::string, std::string>>{
           {"[[budget_source]]\n" + ok_on, "budget_source[0].name is required"},
           {"[[budget_source]]\nname = \"\"\n" + ok_on, "budget_source[0].name must not be empty"},
           {"[[budget_source]]\nname = \"a,b\"\n" + ok_on, "budget_source[0].name must hold no"},
           {"[[budget_source]]\nname = \"a\\tb\"\n" + ok_on, "budget_source[0].name must hold no"},
           {"[[budget_source]]\nname = \"a\"\n" + ok_on + "[[budget_source]]\nname = \"a\"\n" +
                ok_on,
            "budget_source[1].name repeats"},
           {"[[budget_source]]\nname = \"a\"\n", "budget_source[0].on is required"},
           {"[[budget_source]]\nname = \"a\"\non = []\n", "budget_source[0].on must hold at least"},
           {"[[budget_source]]\nname = \"a\"\non = [1]\n", "budget_source[0].on must be a list of"},
           {"[[budget_source]]\nname = \"a\"\non = \"x=1\"\n",
            "budget_source[0].on must be a list"},
           {"[[budget_source]]\nname = \"a\"\non = [\"noequals\"]\n",
            "budget_source[0].on must hold"},
           {"[[budget_source]]\nname = \"a\"\non = [\"x=1\", \"x =2\"]\n", "sets x twice"},
           {"[[budget_source]]\nname = \"a\"\n" + ok_on + "off = [\"=1\"]\n",
            "budget_source[0].off must hold"},
           {"[[budget_source]]\nname = \"a\"\n" + ok_on + "of = []\n",
            "budget_source[0].of is not a key"},
           {"budget_source = 1\n", "budget_source must be an array of tables"},
           {many, "budget_source may hold at most 16"}}) {
    SCOPED_TRACE(text);
    try {
      read(text);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("protocol.toml: "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

TEST(ErrorBudgetTest, ChecksNameTheSourceAndRefuseASetOfItsKey) {
  const std::vector<BudgetSource> sources = read(kTwoSources);
  const auto refuse_bridge = [](const std::vector<std::string>& o) {
    for (const std::string& s : o) {
      if (s == "sensors.gauge.model=\"bridge\"") throw InputError("sensors.gauge.model: no");
    }
  };
  try {
    check_budget_sources(sources, {}, "p.toml", refuse_bridge);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "p.toml: budget source \"gauge\" on: sensors.gauge.model: no");
  }
  try {
    check_budget_sources(sources, {"muscles.pam.line_modulus_MPa=9"}, "p.toml",
                         [](const std::vector<std::string>&) {});
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--set muscles.pam.line_modulus_MPa=9: p.toml: budget "
                                         "source \"line\" sets muscles.pam.line_modulus_MPa"),
              std::string::npos)
        << e.what();
  }
  std::vector<std::vector<std::string>> seen;
  check_budget_sources(sources, {"seed=3"}, "p.toml",
                       [&](const std::vector<std::string>& o) { seen.push_back(o); });
  ASSERT_EQ(seen.size(), 4u) << "each source's on and off, after the user's --set";
  EXPECT_EQ(seen[2], (std::vector<std::string>{"seed=3", "muscles.pam.line_diameter_mm=0.5",
                                               "muscles.pam.line_modulus_MPa=2500"}));
  EXPECT_EQ(seen[3], std::vector<std::string>{"seed=3"});
}

}  // namespace
}  // namespace pamsim
