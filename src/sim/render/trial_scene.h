// trial_scene.h: a trial's state drawn as a frame: the model from one of its cameras, each
// PAM a capsule from its tendon's first point (the PAM's fixed end) along the tendon for the
// muscle's length, as thick as its braid at that length (Chou & Hannaford's D(L)) and
// coloured by its chamber pressure (viridis over the valve's range). What a video's frames
// (trial_video.h, which adds its overlays) and the Python module's Trial.render draw.
#pragma once

#include <vector>

#include "pam_actuator/chou_hannaford.h"
#include "sim/core/scenario.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/render/scene_renderer.h"

namespace pamsim {

class TrialScene {
 public:
  // Throws as SceneRenderer (an unknown camera, a bad size, no GL context).
  TrialScene(const TrialModel& model, const Scenario& scenario, const SceneRenderOptions& options);

  // Draws the snapshot's state over the whole frame (the renderer keeps it for overlays).
  void draw(const TrialSnapshot& snapshot);
  SceneRenderer& renderer() { return renderer_; }
  double colour_max_pa() const { return colour_max_pa_; }  // the colour scale's top [Pa]
  // The muscles' colour scale as a bar with its ends' pressures, in the bottom-right corner.
  void draw_colour_key();

 private:
  struct DrawnMuscle {
    int actuator = -1;
    int tendon = -1;
    BraidGeometry braid;  // fibre length 0: no [geometry], a fixed thickness
  };
  std::vector<SceneRenderer::Capsule> muscle_capsules(const TrialSnapshot& snapshot) const;

  std::vector<DrawnMuscle> muscles_;
  double colour_max_pa_ = 0.0;
  SceneRenderer renderer_;
};

}  // namespace pamsim
