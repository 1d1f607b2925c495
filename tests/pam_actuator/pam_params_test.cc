// pam_params_test.cc: the shipped parameter files load, every bad input is rejected
// with a message naming the file and the key, and the writer round-trips.
#include "pam_actuator/pam_params.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "base/input_error.h"
#include "base/key_table.h"

namespace pamsim {
namespace {

const std::string kModels = std::string(PAMSIM_SOURCE_DIR) + "/models/pams/";

const char* kGood = R"(name = "t"
source = "test"
[spring]
law = "eq3"
units = { pressure = "MPa", length = "mm", force = "N" }
m = -60.1
h = 170.1
a0 = 0.911
a1 = 0.256
a2 = 7.00
a3 = -0.201
[strain_gauge]
q_V_per_N = 2.25e-3
[geometry]
length_mm = 180
sleeve_diameter_mm = 16.0
bladder_diameter_mm = 4.0
braid_angle_deg = 25
)";

class PamParamsTest : public ::testing::Test {
 protected:
  std::string path_ = "/tmp/pam_params_test_" + std::to_string(::getpid()) + ".toml";
  void TearDown() override { std::remove(path_.c_str()); }

  void write(const std::string& text) { std::ofstream(path_) << text; }

  // replace the first occurrence of `from` in the good file
  std::string good_with(const std::string& from, const std::string& to) {
    std::string s = kGood;
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  }

  // loading must fail with a message naming the file and containing `needle`
  void expect_error(const std::string& text, const std::string& needle) {
    write(text);
    try {
      load_pam_params(path_);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path_, 0), 0u) << msg;
      EXPECT_NE(msg.find(needle), std::string::npos) << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
  }
};

TEST_F(PamParamsTest, ShippedTable4FilesLoad) {
  const PamParams ago = load_pam_params(kModels + "table4_agonist.toml");
  EXPECT_EQ(ago.name, "agonist");
  EXPECT_NEAR(spring_force(ago.spring, 0.4e6, 10e-3), 54.67, 1e-9 * 54.67);
  EXPECT_NEAR(natural_length(ago.spring, 0.0), 0.1701, 1e-12);
  ASSERT_TRUE(ago.strain_gauge.has_value());
  EXPECT_DOUBLE_EQ(ago.strain_gauge->q_v_per_n, 2.25e-3);
  ASSERT_TRUE(ago.geometry.has_value());
  EXPECT_NEAR(ago.geometry->sleeve_diameter_m, 0.016, 1e-15);

  const PamParams anta = load_pam_params(kModels + "table4_antagonist.toml");
  // Eq. (3) at 0.4 MPa, 10 mm: (0.871*4 + 1.24*0.4 - 0.129*10 + 22.4) * 10
  const double f = (0.871 * 0.4 * 10 + 1.24 * 0.4 - 0.129 * 10 + 22.4) * 10;
  EXPECT_NEAR(spring_force(anta.spring, 0.4e6, 10e-3), f, 1e-9 * f);
  EXPECT_DOUBLE_EQ(anta.strain_gauge->q_v_per_n, 4.33e-3);
  EXPECT_NEAR(anta.geometry->sleeve_diameter_m, 0.0161, 1e-15);
}

TEST_F(PamParamsTest, OptionalSectionsMayBeAbsent) {
  std::string s = kGood;
  write(s.substr(0, s.find("[strain_gauge]")));
  const PamParams p = load_pam_params(path_);
  EXPECT_FALSE(p.strain_gauge.has_value());
  EXPECT_FALSE(p.geometry.has_value());
}

TEST_F(PamParamsTest, MissingFile) {
  try {
    load_pam_params("/nonexistent/dir/x.toml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/x.toml"), std::string::npos);
  }
}

TEST_F(PamParamsTest, SyntaxErrorNamesLine) {
  expect_error(good_with("a2 = 7.00", "a2 = = 7"), ":10:");
}

TEST_F(PamParamsTest, UnknownKeys) {
  expect_error(good_with("a3 = -0.201", "a3 = -0.201\nb4 = 1.0"),
               "spring.b4: is not a coefficient of law = \"eq3\"");
  expect_error(good_with("name = \"t\"", "name = \"t\"\ncolour = 1"), "colour: unknown key");
  expect_error(good_with("q_V_per_N", "q_V_per_N_typo = 1\nq_V_per_N"),
               "strain_gauge.q_V_per_N_typo: unknown key");
}

TEST_F(PamParamsTest, MissingCoefficientAndLaw) {
  expect_error(good_with("a1 = 0.256\n", ""), "spring.a1: is required");
  expect_error(good_with("m = -60.1\n", ""), "spring.m: is required");
  expect_error(good_with("law = \"eq3\"", "law = \"eq4\""),
               "spring.a0: is not a coefficient of law = \"eq4\"");
  expect_error(good_with("law = \"eq3\"", "law = \"eq9\""), "spring.law");
  // an eq4 file without b5
  expect_error(good_with("law = \"eq3\"", "law = \"eq4\"")
                   .replace(std::string(kGood).find("a0 = 0.911"), 44,
                            "b0 = 1\nb1 = 1\nb2 = 1\nb3 = 1\nb4 = 1\n"),
               "spring.b5: is required");
}

TEST_F(PamParamsTest, WrongUnits) {
  expect_error(good_with("pressure = \"MPa\"", "pressure = \"bar\""),
               "spring.units.pressure: unknown value \"bar\", allowed \"MPa\"");
  expect_error(good_with("length = \"mm\"", "length = \"m\""), "spring.units.length");
  expect_error(good_with("force = \"N\"", "force = \"kN\""), "spring.units.force");
  expect_error(good_with("units = { pressure = \"MPa\", length = \"mm\", force = \"N\" }", ""),
               "spring.units");
}

TEST_F(PamParamsTest, NonFiniteAndNonNumeric) {
  expect_error(good_with("a2 = 7.00", "a2 = nan"), "spring.a2: must be finite");
  expect_error(good_with("h = 170.1", "h = inf"), "spring.h: must be finite");
  expect_error(good_with("a0 = 0.911", "a0 = \"0.911\""), "spring.a0: must be a number");
}

TEST_F(PamParamsTest, StrainGaugeSlopeMustBePositive) {
  expect_error(good_with("q_V_per_N = 2.25e-3", "q_V_per_N = 0"), "strain_gauge.q_V_per_N");
  expect_error(good_with("q_V_per_N = 2.25e-3", "q_V_per_N = -1e-3"),
               "must be in (0, inf) V/N, got -0.001");
}

TEST_F(PamParamsTest, BadGeometry) {
  expect_error(good_with("length_mm = 180", "length_mm = 0"), "geometry.length_mm");
  expect_error(good_with("sleeve_diameter_mm = 16.0", "sleeve_diameter_mm = -16"),
               "geometry.sleeve_diameter_mm");
  expect_error(good_with("bladder_diameter_mm = 4.0", "bladder_diameter_mm = 0"),
               "geometry.bladder_diameter_mm");
  expect_error(good_with("braid_angle_deg = 25", "braid_angle_deg = 90"),
               "geometry.braid_angle_deg: must be in (0, 90) deg, got 90");
  expect_error(good_with("braid_angle_deg = 25", "braid_angle_deg = 0"),
               "geometry.braid_angle_deg");
  expect_error(good_with("braid_angle_deg = 25\n", ""), "geometry.braid_angle_deg: is required");
}

TEST_F(PamParamsTest, WriterRoundTrips) {
  for (const char* file : {"table4_agonist.toml", "table4_antagonist.toml"}) {
    const PamParams a = load_pam_params(kModels + file);
    write(pam_params_to_toml(a));
    const PamParams b = load_pam_params(path_);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.source, b.source);
    EXPECT_EQ(a.spring.law, b.spring.law);
    EXPECT_DOUBLE_EQ(a.spring.m_m_per_pa, b.spring.m_m_per_pa);
    EXPECT_DOUBLE_EQ(a.spring.h_m, b.spring.h_m);
    for (int k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(a.spring.coef[k], b.spring.coef[k]);
    EXPECT_DOUBLE_EQ(a.strain_gauge->q_v_per_n, b.strain_gauge->q_v_per_n);
    EXPECT_DOUBLE_EQ(a.geometry->braid_angle_rad, b.geometry->braid_angle_rad);
    EXPECT_DOUBLE_EQ(a.geometry->length_m, b.geometry->length_m);
  }
  // an eq5 model with awkward numbers survives exactly
  PamParams p;
  p.name = "fit \"quoted\"";
  p.spring = spring_model_from_paper_units(SpringLaw::kEq5, -61.234567890123, 170.1,
                                           {1.0 / 3.0, 2e-7, -5.5, 1e10, 0.1, 0.0});
  write(pam_params_to_toml(p));
  const PamParams q = load_pam_params(path_);
  EXPECT_EQ(q.name, p.name);
  EXPECT_EQ(q.spring.law, SpringLaw::kEq5);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(q.spring.coef[k], p.spring.coef[k], 1e-15 * std::abs(p.spring.coef[k]));
  }
}

// Every number key of the file's reference (`pamsim keys --params`, the reader's rows)
// refuses a string and NaN, naming the key, whichever law's key it is.
TEST_F(PamParamsTest, EveryNumberKeyRefusesAStringAndNaN) {
  int numbers = 0;
  for (const KeyDoc& d : pam_key_docs()) {
    if (d.allowed.empty() || (d.allowed[0] != '(' && d.allowed[0] != '[')) continue;
    ++numbers;
    const std::size_t dot = d.key.find('.');
    const std::string table = d.key.substr(0, dot), name = d.key.substr(dot + 1);
    for (const char* bad : {"\"x\"", "nan"}) {
      std::string text = kGood;  // the key's line replaced, or added under its table
      const std::size_t header = text.find("[" + table + "]\n");
      ASSERT_NE(header, std::string::npos) << d.key;
      const std::size_t line = text.find("\n" + name + " = ", header);
      const std::size_t next = text.find("\n[", header + 1);
      const std::string bad_line = name + " = " + bad;
      if (line != std::string::npos && line < next) {
        text.replace(line + 1, text.find('\n', line + 1) - line - 1, bad_line);
      } else {
        text.insert(header + table.size() + 3, bad_line + "\n");
      }
      expect_error(text, d.key + ": ");
    }
  }
  EXPECT_EQ(numbers, 2 + 4 + 6 + 5 + 2 + 4) << "m, h, a0-a3, b0-b5, c0-c4, the gauge's two, "
                                               "the geometry's four";
}

}  // namespace
}  // namespace pamsim
