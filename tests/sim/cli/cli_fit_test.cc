// cli_fit_test.cc: `pamsim tensile`, `fit` and `estimate` end to end on the real binary,
// and every bad input ending in one stderr line, a non-zero exit and no output file.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace {

const std::string kModels = std::string(PAMSIM_SOURCE_DIR) + "/models/pams/";

struct Result {
  int code = 0;
  std::string out, err;
};

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

class CliFitTest : public ::testing::Test {
 protected:
  std::string dir_;

  void SetUp() override {
    char tmpl[] = "/tmp/cli_fit_test_XXXXXX";
    dir_ = ::mkdtemp(tmpl);
  }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }

  std::string path(const std::string& name) const { return dir_ + "/" + name; }

  // runs `pamsim <args>` in the temp folder, capturing stdout and stderr
  Result run(const std::string& args) const {
    const std::string cmd = "cd '" + dir_ + "' && '" + PAMSIM_BINARY + "' " + args + " >'" +
                            path("stdout") + "' 2>'" + path("stderr") + "'";
    const int status = std::system(cmd.c_str());
    Result r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_all(path("stdout"));
    r.err = read_all(path("stderr"));
    return r;
  }

  void write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
  }

  // a bad input: non-zero exit, exactly one stderr line containing every needle,
  // and `output` (if any) not created
  void expect_rejected(const std::string& args, const std::vector<std::string>& needles,
                       const std::string& output = "") const {
    const Result r = run(args);
    EXPECT_NE(r.code, 0) << args;
    ASSERT_FALSE(r.err.empty()) << args;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
    for (const std::string& n : needles) {
      EXPECT_NE(r.err.find(n), std::string::npos) << "'" << n << "' not in: " << r.err;
    }
    if (!output.empty()) {
      EXPECT_FALSE(exists(path(output))) << args;
    }
  }
};

TEST_F(CliFitTest, TensileFitEstimateRoundTrip) {
  // virtual tensile test of the Table IV agonist (noise free)
  const Result t = run("tensile --params " + kModels + "table4_agonist.toml -o t.csv");
  ASSERT_EQ(t.code, 0) << t.err;
  ASSERT_TRUE(exists(path("t.csv")));

  // fit --json: exactly one JSON object with the documented keys
  for (const std::string law : {"eq3", "eq4", "eq5"}) {
    const Result f = run("fit --model " + law + " t.csv --json");
    ASSERT_EQ(f.code, 0) << f.err;
    const nlohmann::json j = nlohmann::json::parse(f.out);
    EXPECT_EQ(j.at("model"), law);
    for (const char* key : {"m", "h", "rmse_N", "r2"}) EXPECT_TRUE(j.at(key).is_number()) << key;
    const std::string letter = law == "eq3" ? "a" : law == "eq4" ? "b" : "c";
    const int n = law == "eq3" ? 4 : law == "eq4" ? 6 : 5;
    EXPECT_EQ(j.at("coefficients").size(), static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
      EXPECT_TRUE(j.at("coefficients").at(letter + std::to_string(k)).is_number());
    }
    EXPECT_NEAR(j.at("m").get<double>(), -60.1, 1e-6);  // Eq. (2) from l - d
    EXPECT_NEAR(j.at("h").get<double>(), 170.1, 1e-6);
  }
  const nlohmann::json eq3 = nlohmann::json::parse(run("fit --model eq3 t.csv --json").out);
  EXPECT_NEAR(eq3["coefficients"]["a2"].get<double>(), 7.00, 1e-9);
  EXPECT_NEAR(eq3["r2"].get<double>(), 1.0, 1e-12);

  // fit -o writes a parameter file that estimate accepts: 54.67 N at 0.4 MPa is d = 10 mm
  ASSERT_EQ(run("fit --model eq3 t.csv -o fitted.toml").code, 0);
  const Result e = run("estimate --params fitted.toml --pressure-MPa 0.4 --force-N 54.67 --json");
  ASSERT_EQ(e.code, 0) << e.err;
  const nlohmann::json est = nlohmann::json::parse(e.out);
  EXPECT_EQ(est.at("status"), "ok");
  EXPECT_NEAR(est.at("deformation_mm").get<double>(), 10.0, 1e-9);
  // Eq. (1)-(2): l = -60.1 * 0.4 + 170.1 + 10 = 156.06 mm
  EXPECT_NEAR(est.at("length_mm").get<double>(), 156.06, 1e-9);
}

TEST_F(CliFitTest, EstimateStatusesAreData) {
  const std::string ant = "estimate --params " + kModels + "table4_antagonist.toml ";
  const Result slack = run(ant + "--pressure-MPa 0.4 --force-N -2 --json");
  ASSERT_EQ(slack.code, 0) << slack.err;
  const nlohmann::json s = nlohmann::json::parse(slack.out);
  EXPECT_EQ(s.at("status"), "slack");
  EXPECT_EQ(s.at("deformation_mm").get<double>(), 0.0);
  EXPECT_NEAR(s.at("length_mm").get<double>(), -70.3 * 0.4 + 178.5, 1e-9);

  const Result none = run(ant + "--pressure-MPa 0.1 --force-N 1e6 --json");
  ASSERT_EQ(none.code, 0) << none.err;
  EXPECT_EQ(nlohmann::json::parse(none.out).at("status"), "no_physical_root");
}

TEST_F(CliFitTest, BadTensileData) {
  const std::string h = "pressure_MPa,deformation_mm,force_N,length_mm\n";
  std::string rows;
  for (double p : {0.4, 0.6, 0.8}) {
    for (double d : {2.5, 5.0}) {
      rows += std::to_string(p) + "," + std::to_string(d) + "," + std::to_string(10 * d * p) + "," +
              std::to_string(170 - 60 * p + d) + "\n";
    }
  }
  write("missing_column.csv", "pressure_MPa,deformation_mm,length_mm\n0.4,1,150\n");
  write("non_numeric.csv", h + rows + "0.4,abc,5,150\n");
  write("nan.csv", h + "0.4,1,nan,150\n" + rows);
  write("negative.csv", h + rows + "-0.4,1,5,150\n");
  write("few.csv", h + "0.4,1,5,150\n0.6,1,6,140\n");
  const std::string fit = "fit --model eq3 ";

  expect_rejected(fit + "absent.csv -o out.toml", {"absent.csv"}, "out.toml");
  expect_rejected(fit + "missing_column.csv -o out.toml",
                  {"missing_column.csv", "missing column force_N"}, "out.toml");
  expect_rejected(fit + "non_numeric.csv -o out.toml",
                  {"non_numeric.csv", "row 8", "deformation_mm"}, "out.toml");
  expect_rejected(fit + "nan.csv -o out.toml",
                  {"nan.csv", "row 2", "force_N", "not a decimal number"}, "out.toml");
  expect_rejected(fit + "negative.csv -o out.toml", {"negative.csv", "row 8", "negative pressure"},
                  "out.toml");
  expect_rejected(fit + "few.csv -o out.toml", {"few.csv", "too few points"}, "out.toml");
  expect_rejected("fit --model eq7 few.csv -o out.toml", {"--model", "eq7"}, "out.toml");
}

TEST_F(CliFitTest, BadParameterFiles) {
  const std::string good = read_all(kModels + "table4_agonist.toml");
  std::string missing = good;
  missing.erase(missing.find("a2 = 7.00"), std::string("a2 = 7.00").size());
  write("missing_coef.toml", missing);
  std::string unit = good;
  unit.replace(unit.find("\"MPa\""), 5, "\"kPa\"");
  write("wrong_unit.toml", unit);

  for (const std::string cmd :
       {"estimate --pressure-MPa 0.4 --force-N 50 --params ", "tensile -o out.csv --params "}) {
    expect_rejected(cmd + "missing_coef.toml", {"missing_coef.toml", "spring.a2", "missing"},
                    "out.csv");
    expect_rejected(cmd + "wrong_unit.toml", {"wrong_unit.toml", "spring.units.pressure"},
                    "out.csv");
    expect_rejected(cmd + "absent.toml", {"absent.toml"}, "out.csv");
  }
}

TEST_F(CliFitTest, BadOptions) {
  const std::string est = "estimate --params " + kModels + "table4_agonist.toml --force-N 50 ";
  expect_rejected(est + "--pressure-MPa -0.1", {"--pressure-MPa"});
  expect_rejected(est + "--pressure-MPa nan", {"--pressure-MPa"});
  const std::string ten = "tensile --params " + kModels + "table4_agonist.toml -o out.csv ";
  expect_rejected(ten + "--noise-force-N -1", {"--noise-force-N"}, "out.csv");
  expect_rejected(ten + "--noise-pressure-MPa -0.01", {"--noise-pressure-MPa"}, "out.csv");
  expect_rejected(ten + "--noise-length-mm -1", {"--noise-length-mm"}, "out.csv");
  expect_rejected(ten + "--hysteresis 0.5", {"--hysteresis"}, "out.csv");
  expect_rejected(ten + "--pressures-MPa 0.4,-0.5", {"--pressures-MPa"}, "out.csv");
  expect_rejected(ten + "--max-deformation-mm 1", {"--max-deformation-mm"}, "out.csv");
  // the seed fixes the noise
  const std::string noisy = ten + "--noise-force-N 0.5 --seed 11";
  ASSERT_EQ(run(noisy).code, 0);
  const std::string first = read_all(path("out.csv"));
  // an existing output is replaced only with --force
  const Result refused = run(noisy);
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("out.csv: exists; add --force"), std::string::npos) << refused.err;
  EXPECT_EQ(read_all(path("out.csv")), first);
  ASSERT_EQ(run(noisy + " --force").code, 0);
  EXPECT_EQ(read_all(path("out.csv")), first);
  ASSERT_EQ(run(ten + "--noise-force-N 0.5 --seed 12 --force").code, 0);
  EXPECT_NE(read_all(path("out.csv")), first);
}

}  // namespace
