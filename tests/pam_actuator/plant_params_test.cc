// plant_params_test.cc: the plant files (plant_params.h): the shipped one loads into the
// AVBDL law with the values it states, and every bad file is one line naming the file and
// the key: a missing file, an unknown key or law, an impossible braid angle for the
// dimensions, a negative friction, a wall that is not a number.
#include "pam_actuator/plant_params.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/units.h"

namespace pamsim {
namespace {

const std::string kShipped = std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_agonist.toml";

std::string write_temp(const std::string& text) {
  static int n = 0;
  const std::string path = ::testing::TempDir() + "plant_" + std::to_string(::getpid()) + "_" +
                           std::to_string(n++) + ".toml";
  std::ofstream(path) << text;
  return path;
}

const std::string kSlip = "model = \"maxwell_slip\"\n";
// a [bladder]'s relaxation with two terms, its weights to follow
const std::string kRelaxing =
    "C20_MPa = 0.0035\nrelaxation_times_s = [0.01, 0.1]\n"
    "relaxation_weights = ";

const char* kValid = R"(law = "avbdl"
[geometry]
length_mm = 180
diameter_mm = 10
braid_angle_deg = 25
wall_thickness_mm = 2.0
[bladder]
C10_MPa = 0.05
C01_MPa = 0.18
C20_MPa = 0.0035
[friction]
velocity_scale_mm_s = 1.0
extension = { F0_N = 0.5, A0_mm2 = 1.0, A1_mm2 = 0.0 }
contraction = { F0_N = 0.4, A0_mm2 = 0.5, A1_mm2 = 2.0 }
)";

TEST(PlantParamsTest, ShippedAgonistPlantLoads) {
  const PlantParams plant = load_plant_params(kShipped);
  EXPECT_EQ(plant.name, "agonist plant");
  EXPECT_FALSE(plant.source.empty());
  EXPECT_DOUBLE_EQ(plant.avbdl.length_m, 0.180);
  EXPECT_DOUBLE_EQ(plant.avbdl.diameter_m, 0.010);
  EXPECT_DOUBLE_EQ(plant.avbdl.wall_thickness_m, 0.002);
  EXPECT_NEAR(plant.avbdl.end_length_m, 0.16 * 0.180, 1e-15);
  EXPECT_EQ(plant.avbdl.bladder.c10_pa, kNaturalRubberTreloar.c10_pa);
  EXPECT_DOUBLE_EQ(plant.avbdl.friction.extension.pressure_area_m2, 2.36e-6);
  EXPECT_DOUBLE_EQ(plant.avbdl.friction.contraction.strain_area_m2, 4.52e-6);
  // regression pin: the free lengths its source line states at 0.2 / 0.4 / 0.6 MPa (computed
  // when the file was written); they guard the file and the law against drift, and
  // FreeLengthIsWhereTheLawStopsPulling checks what a free length is
  EXPECT_NEAR(avbdl_free_length(plant.avbdl, 0.2e6), 0.1570, 0.0005);
  EXPECT_NEAR(avbdl_free_length(plant.avbdl, 0.4e6), 0.1405, 0.0005);
  EXPECT_NEAR(avbdl_free_length(plant.avbdl, 0.6e6), 0.1344, 0.0005);
}

// Every shipped plant file loads, with the dimensions its header gives (Table I where it
// says so: PAMs A-C with Table I's tube inside the sleeve, 0 where the sleeve is the
// bladder's reference) and the friction rule of plant_agonist.toml: A0 = 0.030 pi R0^2
// lengthening, 0.024 pi R0^2 shortening, A1 = 2.4 A0 (to the file's rounding in mm^2).
TEST(PlantParamsTest, ShippedPlantsHaveTheirStatedDimensionsAndFrictionRule) {
  struct Shipped {
    const char* file;
    double length_mm, diameter_mm, tube_mm;
    bool silicone;
  };
  for (const Shipped& s : {Shipped{"plant_agonist.toml", 180, 10.0, 0.0, false},
                           Shipped{"plant_antagonist.toml", 180, 16.1, 0.0, false},
                           Shipped{"plant_pam_a.toml", 216, 19.9, 6.0, false},
                           Shipped{"plant_pam_b.toml", 211, 13.4, 4.0, false},
                           Shipped{"plant_pam_c.toml", 141, 13.4, 4.0, false},
                           Shipped{"plant_pam_d.toml", 212, 19.0, 0.0, true},
                           Shipped{"table1/plant_agonist.toml", 180, 16.0, 4.0, false},
                           Shipped{"table1/plant_antagonist.toml", 180, 16.1, 4.0, false}}) {
    SCOPED_TRACE(s.file);
    const PlantParams plant =
        load_plant_params(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/" + s.file);
    EXPECT_FALSE(plant.source.empty());
    EXPECT_NEAR(plant.avbdl.length_m, s.length_mm * 1e-3, 1e-12);
    EXPECT_NEAR(plant.avbdl.diameter_m, s.diameter_mm * 1e-3, 1e-12);
    EXPECT_NEAR(plant.avbdl.bladder_diameter_m, s.tube_mm * 1e-3, 1e-12);
    EXPECT_EQ(plant.avbdl.bladder.c10_pa,
              (s.silicone ? kSiliconeElastosilM4601 : kNaturalRubberTreloar).c10_pa);
    const double area_mm2 = units::kPi * std::pow(s.diameter_mm / 2.0, 2);
    const AvbdlFriction& f = plant.avbdl.friction;
    EXPECT_NEAR(f.extension.pressure_area_m2 * 1e6, 0.030 * area_mm2, 0.006);
    EXPECT_NEAR(f.contraction.pressure_area_m2 * 1e6, 0.024 * area_mm2, 0.006);
    EXPECT_NEAR(f.extension.strain_area_m2, 2.4 * f.extension.pressure_area_m2, 0.02e-6);
    EXPECT_NEAR(f.contraction.strain_area_m2, 2.4 * f.contraction.pressure_area_m2, 0.02e-6);
  }
  // regression pin: the antagonist's source line states free lengths 155 / 139 / 134 mm at
  // 0.2 / 0.4 / 0.6 MPa (computed when the file was written; a drift guard, as above)
  const AvbdlParams anta =
      load_plant_params(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_antagonist.toml")
          .avbdl;
  EXPECT_NEAR(avbdl_free_length(anta, 0.2e6), 0.155, 0.001);
  EXPECT_NEAR(avbdl_free_length(anta, 0.4e6), 0.139, 0.001);
  EXPECT_NEAR(avbdl_free_length(anta, 0.6e6), 0.134, 0.001);
}

// What a free length is, checked on the law itself rather than against the root finder: the
// static pull (Eq. 25) is zero there and positive once the muscle is stretched past it, it
// lies between the braid's neutral length b/sqrt(3) (where a bladder-free braid stops
// pulling, Chou-Hannaford) and the rest length, and more pressure shortens it. A tube
// bladder (PAMs A-C, Table I's build) that has not yet met the braid rests past the rest
// length, the braid stretched onto it (0.1 MPa here), short of the fibre length.
TEST(PlantParamsTest, FreeLengthIsWhereTheLawStopsPulling) {
  for (const char* file : {"plant_agonist.toml", "plant_antagonist.toml", "plant_pam_a.toml",
                           "plant_pam_b.toml", "plant_pam_c.toml", "plant_pam_d.toml",
                           "table1/plant_agonist.toml", "table1/plant_antagonist.toml"}) {
    SCOPED_TRACE(file);
    const AvbdlParams p =
        load_plant_params(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/" + file).avbdl;
    const std::string name = file;
    // PAMs A-C's tubes (1.0 mm walls) have not met the braid at 0.1 MPa
    const bool slack_at_0_1 = name.rfind("plant_pam_", 0) == 0 && name != "plant_pam_d.toml";
    const double neutral = avbdl_braid(p).fibre_length_m / std::sqrt(3.0);
    const double longest = p.bladder_diameter_m > 0.0 ? avbdl_max_length(p) : p.length_m;
    double previous = longest;
    for (double p_mpa : {0.1, 0.2, 0.4, 0.6}) {
      const double p_pa = units::mpa_to_pa(p_mpa);
      const double free = avbdl_free_length(p, p_pa);
      const double past = std::min(free + 0.001, 0.5 * (free + avbdl_max_length(p)));
      EXPECT_NEAR(avbdl_static_force(p, p_pa, free), 0.0, 1e-6) << p_mpa << " MPa";
      EXPECT_GT(avbdl_static_force(p, p_pa, past), 0.0) << p_mpa << " MPa";
      EXPECT_GT(free, neutral);
      EXPECT_LT(free, previous) << p_mpa << " MPa";
      if (slack_at_0_1 && p_mpa == 0.1) {
        EXPECT_GT(free, p.length_m);
      }
      previous = free;
    }
  }
}

TEST(PlantParamsTest, ExplicitConstantsAndFrictionAreRead) {
  const PlantParams plant = load_plant_params(write_temp(kValid));
  EXPECT_DOUBLE_EQ(plant.avbdl.bladder.c01_pa, 0.18e6);
  EXPECT_DOUBLE_EQ(plant.avbdl.friction.contraction.strain_area_m2, 2.0e-6);
  EXPECT_DOUBLE_EQ(plant.avbdl.friction.velocity_scale_m_per_s, 1e-3);
}

TEST(PlantParamsTest, MaxwellSlipFrictionIsRead) {
  std::string text = kValid;
  text.replace(text.find("velocity_scale_mm_s = 1.0"), 25,
               kSlip + "breakaway_mm = [0.05, 0.2, 1.0]\nweights = [0.25, 0.25, 0.5]");
  const AvbdlFriction f = load_plant_params(write_temp(text)).avbdl.friction;
  EXPECT_EQ(f.model, FrictionModel::kMaxwellSlip);
  ASSERT_EQ(f.slip.count, 3);
  EXPECT_DOUBLE_EQ(f.slip.breakaway_m[2], 1.0e-3);
  EXPECT_DOUBLE_EQ(f.slip.weight[0], 0.25);
  EXPECT_DOUBLE_EQ(f.contraction.strain_area_m2, 2.0e-6) << "the slip forces' law stays";
  EXPECT_EQ(load_plant_params(write_temp(kValid)).avbdl.friction.model, FrictionModel::kSmooth);
}

TEST(PlantParamsTest, FreeLengthAndLengthAtForceInvertTheStaticLaw) {
  const AvbdlParams a = load_plant_params(kShipped).avbdl;
  for (double p : {0.1e6, 0.3e6, 0.6e6}) {
    const double lf = avbdl_free_length(a, p);
    EXPECT_NEAR(avbdl_static_force(a, p, lf), 0.0, 1e-6) << p;
    for (double f : {5.0, 50.0}) {
      const double l = avbdl_length_at_force(a, p, f);
      EXPECT_GT(l, lf);
      EXPECT_NEAR(avbdl_static_force(a, p, l), f, 1e-6 * f) << p << " " << f;
    }
  }
  EXPECT_EQ(avbdl_free_length(a, 0.0), a.length_m);
  EXPECT_EQ(avbdl_length_at_force(a, 0.4e6, 1e7), -1.0);  // more than it can pull
}

TEST(PlantParamsTest, TheBladdersRelaxationIsRead) {
  std::string text = kValid;
  text.replace(text.find("C20_MPa = 0.0035"), 16, kRelaxing + "[0.07, 0.03]");
  const BladderRelaxation r = load_plant_params(write_temp(text)).avbdl.relaxation;
  ASSERT_EQ(r.count, 2);
  EXPECT_EQ(r.time_s[1], 0.1);
  EXPECT_EQ(r.weight[0], 0.07);
  EXPECT_EQ(load_plant_params(write_temp(kValid)).avbdl.relaxation.count, 0) << "none given";
}

// A bad plant file: kValid with `from` replaced by `to`; the message starts with `key`.
struct BadPlantFile {
  std::string from, to, key;
};

std::vector<BadPlantFile> bad_plant_files() {
  return {
      {"law = \"avbdl\"", "law = \"mckibben\"", "law"},
      {"braid_angle_deg = 25", "braid_angle_deg = 60", "geometry.braid_angle_deg"},
      {"braid_angle_deg = 25", "braid_angle_deg = 0", "geometry.braid_angle_deg"},
      {"diameter_mm = 10", "diameter_mm = -10", "geometry.diameter_mm"},
      {"wall_thickness_mm = 2.0", "wall_thickness_mm = -1.0", "geometry.wall_thickness_mm"},
      {"wall_thickness_mm = 2.0", "wall_thickness_mm = \"thick\"", "geometry.wall_thickness_mm"},
      {"wall_thickness_mm = 2.0", "wall_thickness_mm = nan", "geometry.wall_thickness_mm"},
      {"length_mm = 180", "length_mm = 180\nend_slope = 4", "geometry.end_slope"},
      {"length_mm = 180", "length_mm = 180\nend_length_mm = 100", "geometry.end_length_mm"},
      {"length_mm = 180", "length_mm = 180\ncolour = 1", "geometry.colour"},
      {"C20_MPa = 0.0035", "C20_MPa = -0.1", "bladder.C20_MPa"},
      {"C01_MPa = 0.18", "", "bladder.C01_MPa"},
      {"F0_N = 0.5", "F0_N = -0.5", "friction.extension.F0_N"},
      {"A1_mm2 = 2.0", "A1_mm2 = -2.0", "friction.contraction.A1_mm2"},
      {"velocity_scale_mm_s = 1.0", "velocity_scale_mm_s = 0", "friction.velocity_scale_mm_s"},
      {"velocity_scale_mm_s = 1.0", "model = \"stiction\"", "friction.model"},
      {"velocity_scale_mm_s = 1.0", "model = \"maxwell_slip\"", "friction.breakaway_mm"},
      {"velocity_scale_mm_s = 1.0", kSlip + "breakaway_mm = [0.1, 0]\nweights = [0.5, 0.5]",
       "friction.breakaway_mm: [1]"},
      {"velocity_scale_mm_s = 1.0", kSlip + "breakaway_mm = [0.1, nan]\nweights = [0.5, 0.5]",
       "friction.breakaway_mm"},
      {"velocity_scale_mm_s = 1.0", kSlip + "breakaway_mm = [0.1, 0.2]\nweights = [1.0]",
       "friction.weights"},
      {"velocity_scale_mm_s = 1.0", kSlip + "breakaway_mm = [0.1, 0.2]\nweights = [0.5, 0.4]",
       "friction.weights"},
      {"velocity_scale_mm_s = 1.0", kSlip + "breakaway_mm = [0.1]\nweights = [\"all\"]",
       "friction.weights"},
      {"velocity_scale_mm_s = 1.0", kSlip + "breakaway_mm = 0.1\nweights = [1.0]",
       "friction.breakaway_mm"},
      {"velocity_scale_mm_s = 1.0", "velocity_scale_mm_s = 1.0\nweights = [1.0]",
       "friction.weights"},
      {"C20_MPa = 0.0035", kRelaxing + "[-0.1, 0.1]", "bladder.relaxation_weights: [0]"},
      {"C20_MPa = 0.0035", kRelaxing + "[0.1]", "bladder.relaxation_weights"},
      {"C20_MPa = 0.0035", "C20_MPa = 0.0035\nrelaxation_weights = [0.1]",
       "bladder.relaxation_weights"},
      {"C20_MPa = 0.0035",
       "C20_MPa = 0.0035\nrelaxation_times_s = [1, 2, 3, 4, 5]\n"
       "relaxation_weights = [1, 1, 1, 1, 1]",
       "bladder.relaxation_times_s"},
      {"C20_MPa = 0.0035",
       "C20_MPa = 0.0035\nrelaxation_times_s = [0.01, 0]\nrelaxation_weights = [0.1, 0.1]",
       "bladder.relaxation_times_s: [1]"},
  };
}

TEST(PlantParamsTest, EveryBadFileIsOneLineNamingFileAndKey) {
  for (const BadPlantFile& c : bad_plant_files()) {
    std::string text = kValid;
    const auto at = text.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    text.replace(at, c.from.size(), c.to);
    const std::string path = write_temp(text);
    try {
      load_plant_params(path);
      ADD_FAILURE() << c.to << " accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path + ": " + c.key, 0), 0u) << c.to << " -> " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  try {
    load_plant_params("/nonexistent/plant.toml");
    ADD_FAILURE() << "a missing file was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/plant.toml"), std::string::npos);
  }
}

}  // namespace
}  // namespace pamsim
