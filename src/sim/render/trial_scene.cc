// trial_scene.cc: see trial_scene.h.
#include "sim/render/trial_scene.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "base/units.h"
#include "sim/core/pam_callback.h"

namespace pamsim {
namespace {

constexpr double kDefaultMuscleDiameterM = 0.016;  // a muscle without [geometry]
constexpr double kMinMuscleDiameterM = 0.004;      // still visible fully stretched

// viridis at t in [0, 1] (clamped): dark blue (low) to yellow (high), as the heat maps
std::array<float, 3> viridis(double t) {
  static const std::array<float, 3> kStops[] = {{0.267f, 0.005f, 0.329f},
                                                {0.231f, 0.322f, 0.545f},
                                                {0.129f, 0.569f, 0.553f},
                                                {0.369f, 0.788f, 0.384f},
                                                {0.992f, 0.906f, 0.145f}};
  const double x = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(x));
  const double f = x - i;
  std::array<float, 3> c;
  for (int k = 0; k < 3; ++k) {
    c[k] = static_cast<float>((1.0 - f) * kStops[i][k] + f * kStops[i + 1][k]);
  }
  return c;
}

}  // namespace

TrialScene::TrialScene(const TrialModel& model, const Scenario& scenario,
                       const SceneRenderOptions& options)
    : colour_max_pa_(scenario.pneumatics.command_max_gauge_pa),
      renderer_(model.model.get(), model.model_path, options) {
  for (const BoundMuscle& m : model.muscles) {
    DrawnMuscle drawn;
    drawn.actuator = m.actuator;
    drawn.tendon = model.model->actuator_trnid[2 * m.actuator];
    drawn.braid = m.braid;
    muscles_.push_back(drawn);
  }
}

void TrialScene::draw(const TrialSnapshot& snapshot) {
  renderer_.draw_scene(snapshot.data, muscle_capsules(snapshot));
}

void TrialScene::draw_colour_key() {
  std::vector<std::array<float, 3>> colours;
  constexpr int kCells = 48;
  for (int k = 0; k < kCells; ++k) colours.push_back(viridis((k + 0.5) / kCells));
  const int line = renderer_.line_height_px();
  const int width = 12 * line;  // the bar beside its labels, clear of the bottom-left plots
  const mjrRect bar{renderer_.width_px() - width - 6 * line, line, width, line};
  char high[32];
  std::snprintf(high, sizeof(high), "%.1f MPa", units::pa_to_mpa(colour_max_pa_));
  renderer_.draw_colour_bar(bar, colours, "0", high);
}

std::vector<SceneRenderer::Capsule> TrialScene::muscle_capsules(const TrialSnapshot& snap) const {
  std::vector<SceneRenderer::Capsule> capsules;
  const mjModel* m = snap.model;
  const mjData* d = snap.data;
  for (std::size_t i = 0; i < muscles_.size(); ++i) {
    const DrawnMuscle& muscle = muscles_[i];
    if (muscle.tendon < 0 || d->ten_wrapnum[muscle.tendon] < 2) continue;
    const mjtNum* a = d->wrap_xpos + 3 * d->ten_wrapadr[muscle.tendon];
    const mjtNum* b = a + 3;
    mjtNum dir[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const mjtNum span = mju_normalize3(dir);
    const double length = std::min<double>(pam_muscle_length(m, d, muscle.actuator), span);
    SceneRenderer::Capsule c;
    for (int k = 0; k < 3; ++k) {
      c.from[k] = a[k];
      c.to[k] = a[k] + length * dir[k];
    }
    const double diameter = muscle.braid.fibre_length_m > 0
                                ? chou_hannaford_diameter(muscle.braid, length)
                                : kDefaultMuscleDiameterM;
    c.radius_m = 0.5 * std::max(diameter, kMinMuscleDiameterM);
    const double pressure = i < snap.pressure_pa->size() ? (*snap.pressure_pa)[i] : 0.0;
    const std::array<float, 3> rgb = viridis(colour_max_pa_ > 0 ? pressure / colour_max_pa_ : 0);
    std::copy(rgb.begin(), rgb.end(), c.rgba);
    c.rgba[3] = 1.0f;
    capsules.push_back(c);
  }
  return capsules;
}

}  // namespace pamsim
