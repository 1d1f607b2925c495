// chou_hannaford_test.cc: the virtual-work McKibben model (F = -p dV/dL) and its geometry.
#include "pam_actuator/chou_hannaford.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/input_error.h"
#include "base/units.h"

namespace pamsim {
namespace {

// Table I agonist geometry with the assumed 25 deg braid angle
BraidGeometry agonist_braid() {
  return braid_from_initial_shape(0.180, 0.016, units::deg_to_rad(25.0));
}

TEST(ChouHannafordTest, ForceIsMinusPressureTimesVolumeDerivative) {
  const BraidGeometry g = agonist_braid();
  for (double l : {0.150, 0.165, 0.180}) {
    const double h = 1e-7;
    const double dv_fd =
        (chou_hannaford_volume(g, l + h) - chou_hannaford_volume(g, l - h)) / (2 * h);
    EXPECT_NEAR(chou_hannaford_dvolume_dlength(g, l), dv_fd, 1e-9 * std::abs(dv_fd) + 1e-15);
    EXPECT_NEAR(chou_hannaford_force(g, 4e5, l), -4e5 * dv_fd, 1e-6 * std::abs(4e5 * dv_fd));
  }
}

TEST(ChouHannafordTest, VolumeAtInitialLengthIsTheCylinder) {
  // b = L0 / cos(a0), n = b sin(a0) / (pi D0) make V(L0) = pi D0^2 / 4 L0 exactly
  for (double angle_deg : {15.0, 25.0, 40.0}) {
    const double l0 = 0.180, d0 = 0.0161;
    const BraidGeometry g = braid_from_initial_shape(l0, d0, units::deg_to_rad(angle_deg));
    EXPECT_NEAR(chou_hannaford_volume(g, l0), units::kPi * d0 * d0 / 4 * l0,
                1e-12 * units::kPi * d0 * d0 / 4 * l0);
  }
}

TEST(ChouHannafordTest, DiameterIsD0AtL0AndGrowsAsTheMuscleContracts) {
  const BraidGeometry g = braid_from_initial_shape(0.180, 0.016, units::deg_to_rad(25.0));
  EXPECT_NEAR(chou_hannaford_diameter(g, 0.180), 0.016, 1e-15);
  EXPECT_GT(chou_hannaford_diameter(g, 0.150), 0.016);
  // the volume is the cylinder of that diameter: V = pi D^2 / 4 L
  for (double l : {0.140, 0.160, 0.185}) {
    const double d = chou_hannaford_diameter(g, l);
    EXPECT_NEAR(chou_hannaford_volume(g, l), units::kPi * d * d / 4 * l, 1e-15);
  }
  EXPECT_EQ(chou_hannaford_diameter(g, g.fibre_length_m * 1.01), 0.0);  // past full stretch
}

TEST(ChouHannafordTest, ForceSignAndZero) {
  const BraidGeometry g = agonist_braid();
  // pulls at the initial length (angle below 54.7 deg), zero at L = b / sqrt(3)
  EXPECT_GT(chou_hannaford_force(g, 4e5, 0.180), 0.0);
  EXPECT_NEAR(chou_hannaford_force(g, 4e5, g.fibre_length_m / std::sqrt(3.0)), 0.0, 1e-9);
  EXPECT_EQ(chou_hannaford_force(g, 0.0, 0.170), 0.0);
}

TEST(ChouHannafordTest, BadGeometryThrows) {
  EXPECT_THROW(braid_from_initial_shape(0.0, 0.016, 0.4), InputError);
  EXPECT_THROW(braid_from_initial_shape(0.18, -0.016, 0.4), InputError);
  EXPECT_THROW(braid_from_initial_shape(0.18, 0.016, 0.0), InputError);
  EXPECT_THROW(braid_from_initial_shape(0.18, 0.016, units::deg_to_rad(90.0)), InputError);
  EXPECT_THROW(braid_from_initial_shape(NAN, 0.016, 0.4), InputError);
}

}  // namespace
}  // namespace pamsim
