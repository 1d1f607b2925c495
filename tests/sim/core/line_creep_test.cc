// line_creep_test.cc: a creeping line (muscles.<m>.line_creep, pam_callback.h) in series with
// a linear spring law, against the closed forms of a Kelvin-Voigt element: loaded at once it
// is the elastic line (F = k s / (1 + k c)); held, it creeps to the long-term series spring
// F = k s / (1 + k c (1 + g)); slack, its state recovers as exp(-t / tau) exactly; the state
// starts at the start's tension; a creep state the model has no room for is refused.
#include <gtest/gtest.h>

#include <cmath>

#include "base/input_error.h"
#include "sim/inline_mjcf.h"
#include "sim/core/mujoco_util.h"
#include "sim/core/pam_callback.h"
#include "sim/slider_mjcf.h"

namespace pamsim {
namespace {

constexpr double kCreepLine = 0.3, kCreepEa = 300.0, kCreepStiffness = 5000.0,
                 kCreepPressure = 0.4e6;

// The slider (nuserdata 3: two pressures' room, then the creep state) with a linear spring
// law (Eq. (3), a0 only) on a line of E A 300 N creeping by g over tau
MjModelPtr creeping_slider(double g, double tau_s) {
  std::string xml = pamsim_test::kSliderXml;
  xml.replace(xml.find("nuserdata=\"2\""), 13, "nuserdata=\"3\"");
  MjModelPtr m = pamsim_test::load_inline(xml.c_str(), "slider.xml");
  SpringModel linear;
  linear.m_m_per_pa = -60e-9;
  linear.h_m = 0.170;
  linear.coef = {kCreepStiffness, 0, 0, 0, 0, 0};
  store_pam_in_model(m.get(), 0, linear, kCreepLine, 1, "slider.xml");
  store_line_in_model(m.get(), 0, LineBinding{kCreepEa, g, tau_s, 12.0, 2}, "slider.xml");
  install_pam_actuator_callback();
  return m;
}

TEST(LineCreepTest, AHeldLineCreepsFromTheElasticToTheLongTermSeriesSpring) {
  const double g = 0.5, tau = 1.0, c = kCreepLine / kCreepEa, stretch = 0.010, dt = 1e-3;
  MjModelPtr m = creeping_slider(g, tau);
  MjDataPtr d = make_data(m.get());
  SpringModel law = pam_spring_from_model(m.get(), 0);
  d->qpos[0] = kCreepLine + natural_length(law, kCreepPressure) + stretch;
  d->userdata[1] = kCreepPressure;
  d->userdata[2] = 0.0;  // a line never loaded
  mj_forward(m.get(), d.get());
  const double elastic = kCreepStiffness * stretch / (1.0 + kCreepStiffness * c);
  EXPECT_NEAR(-d->actuator_force[0], elastic, 1e-9 * elastic);
  for (int k = 0; k < 20000; ++k)
    pam_taut_length_committing_creep(m.get(), d.get(), 0, dt);  // 20 tau
  mj_forward(m.get(), d.get());
  const double long_term = kCreepStiffness * stretch / (1.0 + kCreepStiffness * c * (1.0 + g));
  EXPECT_NEAR(-d->actuator_force[0], long_term, 1e-7 * long_term);
  EXPECT_NEAR(d->userdata[2], long_term, 1e-7 * long_term);  // the state: the held tension
}

TEST(LineCreepTest, ASlackLineRecoversExponentiallyAndTheStateStartsAtTheStartsTension) {
  const double tau = 2.0, dt = 1e-3;
  MjModelPtr m = creeping_slider(0.3, tau);
  MjDataPtr d = make_data(m.get());
  pam_start_line_creep(m.get(), d.get(), 0);
  EXPECT_EQ(d->userdata[2], 12.0);  // LineBinding::start_tension_n
  d->qpos[0] = 0.0;                 // far slack: the line pulls nothing
  d->userdata[1] = kCreepPressure;
  mj_forward(m.get(), d.get());
  for (int k = 0; k < 1000; ++k) pam_taut_length_committing_creep(m.get(), d.get(), 0, dt);
  EXPECT_NEAR(d->userdata[2], 12.0 * std::exp(-1000 * dt / tau), 1e-12);
}

TEST(LineCreepTest, ACreepStateTheModelHasNoRoomForIsRefused) {
  MjModelPtr m = pamsim_test::load_inline(pamsim_test::kSliderXml, "slider.xml");  // 2 values
  store_pam_in_model(m.get(), 0, SpringModel{}, kCreepLine, 1, "slider.xml");
  EXPECT_THROW(
      store_line_in_model(m.get(), 0, LineBinding{kCreepEa, 0.2, 10.0, 0.0, 2}, "slider.xml"),
      InputError);
  EXPECT_NO_THROW(
      store_line_in_model(m.get(), 0, LineBinding{kCreepEa, 0.0, 10.0, 0.0, -1}, "slider.xml"));
}

}  // namespace
}  // namespace pamsim
