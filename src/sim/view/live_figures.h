// live_figures.h: the viewer's live plots, MuJoCo figures (mjvFigure, drawn by mjr_figure)
// fed at every control period: the joint (angle in degrees, or a slide's position in mm),
// each muscle's valve command and chamber pressure [MPa], each muscle's estimated stretch
// velocity [mm/s] with the reflex's threshold as a line, and each muscle's reflex windows
// (1 while open). The last mjMAXLINEPNT control periods are shown; a restart clears them.
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <string>
#include <vector>

#include "sim/core/trial_channels.h"

namespace pamsim {

class LiveFigures {
 public:
  // `labels`: the muscles' (model order); `hinge`: the joint is a hinge.
  LiveFigures(const std::vector<std::string>& labels, bool hinge);

  void clear();
  // One control period's values; `threshold_mm_s` NaN where the controller has none.
  void add(const TrialObservation& o, double threshold_mm_s);
  // The four figures side by side in `strip` (pixels from the window's bottom left).
  void draw(const mjrRect& strip, const mjrContext* context);

 private:
  static constexpr int kFigures = 4;
  void push(int figure, int line, float x, float y);
  std::array<mjvFigure, kFigures> figures_;
  std::size_t muscles_;
  bool hinge_;
};

}  // namespace pamsim
