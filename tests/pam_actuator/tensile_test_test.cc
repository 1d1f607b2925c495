// tensile_test_test.cc: the virtual tensile protocol (Yoshida and Hosoda, Sec. II-B) and its
// CSV.
#include "pam_actuator/tensile_test.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <vector>

#include "base/input_error.h"
#include "pam_actuator/tensile_csv.h"
#include "pam_actuator/table4_springs.h"

namespace pamsim {
namespace {

using pamsim_test::table4_agonist;

TEST(TensileTestTest, ProtocolShape) {
  const std::vector<TensileRow> rows = run_tensile_test(table4_agonist(), TensileTestOptions{});
  // 5 pressures x (9 loading + 9 unloading) set points of 0..20 mm
  ASSERT_EQ(rows.size(), 5u * 18u);
  std::set<double> pressures;
  for (const TensileRow& r : rows) pressures.insert(r.pressure_mpa);
  EXPECT_EQ(pressures, (std::set<double>{0.4, 0.5, 0.6, 0.7, 0.8}));
  for (int block = 0; block < 5; ++block) {
    for (int k = 0; k < 18; ++k) {
      const TensileRow& r = rows[block * 18 + k];
      const bool loading = k < 9;
      EXPECT_EQ(r.direction, loading ? StrokeDirection::kLoading : StrokeDirection::kUnloading);
      EXPECT_DOUBLE_EQ(r.deformation_mm, loading ? 2.5 * k : 2.5 * (17 - k));
      // Eq. (1)-(2): l = l_n + d; noise-free force is the law itself
      const double p = r.pressure_mpa * 1e6;
      EXPECT_NEAR(r.length_mm, -60.1 * r.pressure_mpa + 170.1 + r.deformation_mm, 1e-9);
      EXPECT_NEAR(r.force_n, spring_force(table4_agonist(), p, r.deformation_mm * 1e-3), 1e-12);
    }
  }
}

TEST(TensileTestTest, CustomPressuresMaxAndHysteresis) {
  TensileTestOptions o;
  o.pressures_mpa = {0.3};
  o.max_deformation_mm = 11.0;  // not a multiple of 2.5: the last step is shorter
  o.hysteresis = 0.1;
  const auto law = [](double p, double d) { return 1e-3 * p * d; };
  const auto l_n = [](double) { return 0.2; };
  const std::vector<TensileRow> rows = run_tensile_test(law, l_n, o);
  ASSERT_EQ(rows.size(), 12u);  // 0, 2.5, 5, 7.5, 10, 11 and back
  EXPECT_DOUBLE_EQ(rows[5].deformation_mm, 11.0);
  EXPECT_DOUBLE_EQ(rows[6].deformation_mm, 11.0);
  const double f = 1e-3 * 0.3e6 * 11e-3;
  EXPECT_NEAR(rows[5].force_n, 1.1 * f, 1e-12);  // loading: f (1 + h)
  EXPECT_NEAR(rows[6].force_n, 0.9 * f, 1e-12);  // unloading: f (1 - h)
  EXPECT_NEAR(rows[0].length_mm, 200.0, 1e-12);
}

TEST(TensileTestTest, NoiseIsDeterministicPerSeed) {
  TensileTestOptions o;
  o.noise_pressure_mpa = 0.002;
  o.noise_force_n = 0.2;
  o.noise_length_mm = 0.05;
  o.seed = 42;
  const auto a = run_tensile_test(table4_agonist(), o);
  const auto b = run_tensile_test(table4_agonist(), o);
  o.seed = 43;
  const auto c = run_tensile_test(table4_agonist(), o);
  int differing = 0;
  double sum_sq = 0.0;
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].force_n, b[k].force_n);
    EXPECT_EQ(a[k].pressure_mpa, b[k].pressure_mpa);
    EXPECT_EQ(a[k].length_mm, b[k].length_mm);
    differing += a[k].force_n != c[k].force_n;
    const double p = std::round(a[k].pressure_mpa * 10) / 10;
    sum_sq += std::pow(a[k].pressure_mpa - p, 2);
    // one encoder sample moves deformation and length together
    EXPECT_NEAR(a[k].length_mm - a[k].deformation_mm, -60.1 * p + 170.1, 1e-9);
  }
  EXPECT_EQ(differing, static_cast<int>(a.size()));
  // the pressure noise has roughly the requested standard deviation
  EXPECT_NEAR(std::sqrt(sum_sq / a.size()), 0.002, 0.0006);
}

// The lab's test on a physical plant: the set points start at the plant's free length,
// the forces are its static law, and its friction opens a loop (loading above unloading
// by the two strokes' friction) that is closed without it.
TEST(TensileTestTest, OnAPlantStartsAtItsFreeLengthAndShowsItsFriction) {
  AvbdlParams plant =
      avbdl_params_from_geometry(0.18, 0.010, 25.0 * M_PI / 180.0, 0.002, kNaturalRubberTreloar);
  TensileTestOptions o;
  o.pressures_mpa = {0.4, 0.6};
  const std::vector<TensileRow> frictionless = run_tensile_test(plant, o);
  ASSERT_EQ(frictionless.size(), 2u * 2u * 9u);
  for (const TensileRow& r : frictionless) {
    const double p = r.pressure_mpa * 1e6;
    const double l_n = avbdl_free_length(plant, p);
    EXPECT_NEAR(r.length_mm, 1e3 * l_n + r.deformation_mm, 1e-9);
    EXPECT_NEAR(r.force_n, avbdl_static_force(plant, p, l_n + r.deformation_mm * 1e-3), 1e-9);
  }
  plant.friction.extension = {0.5, 2e-6, 0.0};
  plant.friction.contraction = {0.5, 2e-6, 0.0};
  const std::vector<TensileRow> rubbing = run_tensile_test(plant, o);
  for (std::size_t k = 0; k < 9; ++k) {
    const TensileRow& up = rubbing[k];
    const TensileRow& down = rubbing[17 - k];  // the same set point on the way back
    ASSERT_EQ(up.deformation_mm, down.deformation_mm);
    EXPECT_NEAR(up.force_n - down.force_n, 2.0 * (0.5 + 0.4e6 * 2e-6), 1e-9) << k;
  }
}

// With Maxwell-slip friction the loop turns over at a reversal instead of jumping: at the
// turning point the unloading sample reads what the loading one did (the elements have not
// moved yet), one 2.5 mm step later (more than twice every breakaway travel) the whole
// shortening friction acts; the first loading sample starts from unloaded elements.
TEST(TensileTestTest, OnAMaxwellSlipPlantTheLoopTurnsOverAtTheReversal) {
  AvbdlParams plant =
      avbdl_params_from_geometry(0.18, 0.010, 25.0 * M_PI / 180.0, 0.002, kNaturalRubberTreloar);
  plant.friction.extension = {0.5, 2e-6, 0.0};
  plant.friction.contraction = {0.3, 1e-6, 0.0};
  plant.friction.model = FrictionModel::kMaxwellSlip;
  plant.friction.slip.count = 2;
  plant.friction.slip.weight = {0.5, 0.5};
  plant.friction.slip.breakaway_m = {0.2e-3, 1.0e-3};
  TensileTestOptions o;
  o.pressures_mpa = {0.4, 0.6};
  const std::vector<TensileRow> rows = run_tensile_test(plant, o);
  ASSERT_EQ(rows.size(), 2u * 2u * 9u);
  for (std::size_t start : {0u, 18u}) {
    const double p = rows[start].pressure_mpa * 1e6;
    const double l_n = avbdl_free_length(plant, p);
    const auto static_at = [&](const TensileRow& r) {
      return avbdl_static_force(plant, p, l_n + r.deformation_mm * 1e-3);
    };
    const double up = 0.5 + p * 2e-6, down = 0.3 + p * 1e-6;
    EXPECT_NEAR(rows[start].force_n, static_at(rows[start]), 1e-9) << "unloaded at the start";
    EXPECT_NEAR(rows[start + 8].force_n, static_at(rows[start + 8]) + up, 1e-9);
    EXPECT_EQ(rows[start + 9].force_n, rows[start + 8].force_n) << "the turning point";
    EXPECT_NEAR(rows[start + 10].force_n, static_at(rows[start + 10]) - down, 1e-9);
  }
}

TEST(TensileTestTest, BadOptions) {
  const auto bad = [](auto edit) {
    TensileTestOptions o;
    edit(o);
    EXPECT_THROW(validate_tensile_options(o), InputError);
  };
  bad([](TensileTestOptions& o) { o.pressures_mpa.clear(); });
  bad([](TensileTestOptions& o) { o.pressures_mpa = {0.4, -0.1}; });
  bad([](TensileTestOptions& o) { o.pressures_mpa = {NAN}; });
  bad([](TensileTestOptions& o) { o.step_mm = 0.0; });
  bad([](TensileTestOptions& o) { o.max_deformation_mm = 1.0; });
  bad([](TensileTestOptions& o) { o.hysteresis = 0.5; });
  bad([](TensileTestOptions& o) { o.hysteresis = -0.01; });
  bad([](TensileTestOptions& o) { o.noise_force_n = -1.0; });
  bad([](TensileTestOptions& o) { o.noise_length_mm = INFINITY; });
  bad([](TensileTestOptions& o) { o.noise_pressure_mpa = NAN; });
  EXPECT_NO_THROW(validate_tensile_options(TensileTestOptions{}));
}

class TensileCsvTest : public ::testing::Test {
 protected:
  std::string path_ = "/tmp/tensile_csv_test_" + std::to_string(::getpid()) + ".csv";
  void TearDown() override { std::remove(path_.c_str()); }
  void write(const std::string& text) { std::ofstream(path_) << text; }

  void expect_error(const std::string& text, const std::string& needle) {
    write(text);
    try {
      read_tensile_csv(path_);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path_, 0), 0u) << msg;
      EXPECT_NE(msg.find(needle), std::string::npos) << msg;
    }
  }
};

TEST_F(TensileCsvTest, RoundTripIsExact) {
  TensileTestOptions o;
  o.noise_force_n = 0.3;
  o.noise_pressure_mpa = 0.001;
  o.noise_length_mm = 0.01;
  const auto rows = run_tensile_test(table4_agonist(), o);
  write(tensile_rows_to_csv(rows));
  const auto back = read_tensile_csv(path_);
  ASSERT_EQ(back.size(), rows.size());
  for (size_t k = 0; k < rows.size(); ++k) {
    EXPECT_EQ(back[k].pressure_mpa, rows[k].pressure_mpa);
    EXPECT_EQ(back[k].deformation_mm, rows[k].deformation_mm);
    EXPECT_EQ(back[k].force_n, rows[k].force_n);
    EXPECT_EQ(back[k].length_mm, rows[k].length_mm);
    EXPECT_EQ(back[k].direction, rows[k].direction);
  }
}

TEST_F(TensileCsvTest, ColumnsInAnyOrderExtrasIgnored) {
  write("note,force_N,length_mm,pressure_MPa,deformation_mm\nx,12.5,150,0.4,2.5\n\n");
  const auto rows = read_tensile_csv(path_);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].force_n, 12.5);
  EXPECT_EQ(rows[0].length_mm, 150.0);
  EXPECT_EQ(rows[0].pressure_mpa, 0.4);
  EXPECT_EQ(rows[0].deformation_mm, 2.5);
}

// A UTF-8 byte-order mark (spreadsheet exports) before the header is accepted.
TEST_F(TensileCsvTest, AByteOrderMarkIsAccepted) {
  write("\xEF\xBB\xBFpressure_MPa,deformation_mm,force_N,length_mm\n0.4,1,5,150\n");
  const std::vector<TensileRow> rows = read_tensile_csv(path_);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_DOUBLE_EQ(rows[0].pressure_mpa, 0.4);
  EXPECT_DOUBLE_EQ(rows[0].force_n, 5.0);
}

TEST_F(TensileCsvTest, BadInputs) {
  const std::string h = "pressure_MPa,deformation_mm,force_N,length_mm\n";
  expect_error("pressure_MPa,deformation_mm,length_mm\n0.4,1,150\n", "missing column force_N");
  expect_error(h + "0.4,1,5,150\n0.4,abc,5,150\n", "row 3, column deformation_mm");
  expect_error(h + "0.4,1,5x,150\n", "\"5x\" is not a decimal number");
  expect_error(h + "0.4,1,nan,150\n", "row 2, column force_N: \"nan\" is not a decimal number");
  expect_error(h + "0.4,1,5,inf\n", "column length_mm");
  expect_error(h + "0.4,1,5,1e999\n", "row 2, column length_mm: \"1e999\" is not finite");
  // hexadecimal floats are refused
  expect_error(h + "0.4,1,0x1p3,150\n", "row 2, column force_N: \"0x1p3\" is not a decimal");
  // a column named twice is refused, not silently the last one
  expect_error("pressure_MPa,deformation_mm,force_N,length_mm,force_N\n0.4,1,5,150,6\n",
               "column force_N appears twice (columns 3 and 5)");
  expect_error(h + "-0.1,1,5,150\n", "row 2, column pressure_MPa: negative pressure");
  expect_error(h + "0.4,1,,150\n", "row 2, column force_N: empty cell");
  expect_error(h + "0.4,1,5\n", "row 2: 3 cells");
  expect_error(h, "no data rows");
  expect_error("", "no header");
  expect_error("pressure_MPa,deformation_mm,force_N,length_mm,direction\n0.4,1,5,150,up\n",
               "column direction");
  try {
    read_tensile_csv("/nonexistent/t.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/t.csv"), std::string::npos);
  }
}

}  // namespace
}  // namespace pamsim
