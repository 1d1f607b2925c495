// viewer.h: `pamsim view`'s window, MuJoCo's `simulate` for a pamsim trial: the scenario's
// trial (a LiveSession: its sensors, estimator, controller and pneumatics exactly as
// `pamsim run` has them) paced to the wall clock, drawn as `pamsim render` draws it (the
// muscles coloured by pressure), beside MuJoCo's UI (mjUI: play, pause, step, slow motion,
// restart, drop, the reflex switch, a slider per controller setting) above live figures
// (live_figures.h). Keys:
//   space  pause / play          right arrow  one control period (paused)
//   D      drop the mass now     R            reflex on / off
//   - / =  slower / faster       backspace    restart (the same seed; the UI's seed field
//   Esc    the model's camera back              sets another)
// The mouse moves the camera as in `simulate` (left drag rotates, right drag moves, the
// wheel zooms; the first drag frees the camera from the model's). Every change applies from
// the next control tick. A script (view_script.h) presses the keys and moves the sliders.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "sim/render/scene_renderer.h"
#include "sim/view/live_session.h"
#include "sim/view/view_script.h"

namespace pamsim {

struct ViewOptions {
  std::vector<ScriptLine> script;
  RenderQuality quality = RenderQuality::kDefault;  // the scene's, as `pamsim render --quality`
  std::function<bool()> stop_requested;             // polled every frame (SIGTERM)
};

struct ViewStats {
  long frames = 0;
  double wall_s = 0.0;
  double frames_per_s = 0.0;
  double simulated_s = 0.0;  // simulated time shown, over restarts
  std::string gl;            // the GL context that drew it
};

// Opens the window and runs until it is closed (its button, a script's `close`, or
// stop_requested). Throws InputError without a display (glfw_window.h).
ViewStats run_viewer(LiveSession& session, const ViewOptions& options);

}  // namespace pamsim
