// viewer_window.h: the ViewerWindow behind run_viewer (viewer.h), internal to src/sim/view:
// viewer.cc holds the loop (pacing, the script, drawing), viewer_ui.cc the UI, the keys and
// the camera.
#pragma once

#include <mujoco/mujoco.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "sim/render/trial_scene.h"
#include "sim/view/glfw_window.h"
#include "sim/view/live_figures.h"
#include "sim/view/viewer.h"

namespace pamsim {

class ViewerWindow {
 public:
  ViewerWindow(LiveSession& session, const ViewOptions& options);
  ViewStats run();

  // the scene as `pamsim render` frames it, and the strip of figures below it
  static constexpr int kSceneWidthPx = 1280;
  static constexpr int kSceneHeightPx = 720;
  static constexpr int kFiguresHeightPx = 240;

 private:
  using Clock = std::chrono::steady_clock;

  // viewer.cc
  void advance(double wall_dt_s);
  bool run_script();  // false: a line waits for a frame (a screenshot, a wait)
  void run_line(const ScriptLine& line);
  void step_once();
  void draw();
  void take_screenshot(const std::string& path);
  std::string status_line() const;

  // viewer_ui.cc
  void make_ui();
  void layout();
  void on_event(mjuiState& state);
  void on_key(int key);
  void on_ui_item(const mjuiItem* item);
  void move_camera(const mjuiState& state);
  void sync_ui();  // the UI's fields from the session (after a script or a key changed it)
  void apply_pending_settings();
  void restart(std::uint64_t seed);
  void toggle_pause() { paused_ = !paused_; }
  void set_slow(int index);

  LiveSession& session_;
  ViewOptions options_;
  GlfwWindow window_;
  std::unique_ptr<TrialScene> scene_;
  LiveFigures figures_;
  mjUI ui_{};
  mjrRect scene_rect_{}, figures_rect_{};

  // the UI's fields (mjUI points at them)
  int paused_ = 0;
  int reflex_ = 1;
  int slow_index_ = 0;  // real time / 2^slow_index_
  int seed_field_ = 1;
  std::vector<mjtNum> settings_;          // per live setting, in its unit
  std::vector<mjtNum> applied_settings_;  // what the trial has
  bool free_camera_ = false;

  // the script and the pacing
  std::size_t next_line_ = 0;
  Clock::time_point wait_until_{};
  std::string screenshot_;  // taken after the next frame is drawn
  double debt_s_ = 0.0;     // simulated time owed to the wall clock
  double simulated_s_ = 0.0;
  long frames_ = 0;
};

}  // namespace pamsim
