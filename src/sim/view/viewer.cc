// viewer.cc: the viewer's loop (viewer.h): each frame its events, the script's lines that are
// due, the trial advanced by the wall time passed (divided by the slow motion) one control
// period at a time, a script line run before the period it is due at, and the frame drawn:
// the scene offscreen as `pamsim render` draws it, blitted into the window beside the UI and
// above the figures.
#include "sim/view/viewer.h"

#include <cmath>
#include <cstdio>
#include <thread>

#include "sim/render/png_sequence_writer.h"
#include "sim/view/viewer_window.h"

namespace pamsim {
namespace {

constexpr double kMaxDebtS = 0.1;  // a slow frame does not make the trial race to catch up

std::vector<std::string> muscle_labels(const TrialModel& model) {
  std::vector<std::string> labels;
  for (const BoundMuscle& m : model.muscles) labels.push_back(m.label);
  return labels;
}

std::string fixed(double v, int decimals) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.*f", decimals, v);
  return text;
}

}  // namespace

ViewerWindow::ViewerWindow(LiveSession& session, const ViewOptions& options)
    : session_(session),
      options_(options),
      window_("pamsim view: " + session.scenario().path, kSceneWidthPx + mjui_themeSpacing(0).total,
              kSceneHeightPx + kFiguresHeightPx),
      figures_(muscle_labels(session.model()), session.model().joint.hinge) {
  SceneRenderOptions scene;
  scene.width_px = kSceneWidthPx;
  scene.height_px = kSceneHeightPx;
  scene.quality = options.quality;
  scene.context = [this] { return window_.context(); };
  scene_ = std::make_unique<TrialScene>(session.model(), session.scenario(), scene);
  seed_field_ = static_cast<int>(session.seed());
  for (const LiveSettingValue& s : session.settings()) settings_.push_back(s.value);
  applied_settings_ = settings_;
  make_ui();
  window_.on_event([this](mjuiState& state) { on_event(state); });
  figures_.add(session_.trial().observe(), NAN);
}

void ViewerWindow::step_once() {
  if (session_.done()) return;
  apply_pending_settings();
  session_.step();
  simulated_s_ += session_.control_period_s();
  double threshold = NAN;
  for (const LiveSettingValue& s : session_.settings()) {
    if (s.key == "reflex.v_thr_mm_s") threshold = s.value;
  }
  figures_.add(session_.trial().observe(), session_.reflex_on() ? threshold : NAN);
}

void ViewerWindow::advance(double wall_dt_s) {
  if (!paused_ && !session_.done())
    debt_s_ = std::min(debt_s_ + wall_dt_s / (1 << slow_index_), kMaxDebtS);
  const double period = session_.control_period_s();
  while (run_script()) {
    if (paused_ || session_.done() || debt_s_ < period || window_.should_close()) break;
    step_once();
    debt_s_ -= period;
  }
  if (paused_ || session_.done()) debt_s_ = 0.0;
}

bool ViewerWindow::run_script() {
  const std::vector<ScriptLine>& lines = options_.script;
  while (next_line_ < lines.size()) {
    if (Clock::now() < wait_until_ || !screenshot_.empty()) return false;
    const ScriptLine& line = lines[next_line_];
    // due once the trial's clock reaches it (a done trial runs the rest)
    if (!session_.done() && session_.time_s() < line.at_s - 1e-9) return true;
    ++next_line_;
    run_line(line);
    if (line.command == ScriptCommand::kScreenshot || line.command == ScriptCommand::kWait) {
      return false;
    }
  }
  return true;
}

void ViewerWindow::run_line(const ScriptLine& line) {
  switch (line.command) {
    case ScriptCommand::kPause:
      paused_ = 1;
      break;
    case ScriptCommand::kPlay:
      paused_ = 0;
      break;
    case ScriptCommand::kStep:
      for (long k = 0; k < (line.has_number ? static_cast<long>(line.number) : 1); ++k) step_once();
      break;
    case ScriptCommand::kSlow:
      set_slow(static_cast<int>(std::lround(std::log2(line.number))));
      break;
    case ScriptCommand::kRestart:
      restart(line.has_number ? static_cast<std::uint64_t>(line.number) : session_.seed());
      break;
    case ScriptCommand::kDrop:
      session_.drop_now();
      break;
    case ScriptCommand::kReflex:
      session_.set_reflex(line.on);
      break;
    case ScriptCommand::kSet:
      for (std::size_t k = 0; k < settings_.size(); ++k) {
        if (session_.settings()[k].key == line.text) settings_[k] = line.number;
      }
      break;
    case ScriptCommand::kScreenshot:
      screenshot_ = line.text;
      break;
    case ScriptCommand::kWait:
      wait_until_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double>(line.number));
      break;
    case ScriptCommand::kClose:
      window_.close();
      break;
  }
  sync_ui();
}

std::string ViewerWindow::status_line() const {
  std::string s = "t = " + fixed(session_.time_s(), 2) + " s";
  if (session_.done()) s += "  (ended)";
  if (paused_) s += "  paused";
  if (slow_index_ > 0) s += "  slow 1/" + std::to_string(1 << slow_index_);
  s += session_.reflex_on() ? "  reflex on" : "  reflex off";
  s += "  seed " + std::to_string(session_.seed());
  return s;
}

void ViewerWindow::draw() {
  layout();
  TrialSnapshot snap = session_.trial().snapshot();
  scene_->draw(snap);
  scene_->draw_colour_key();
  SceneRenderer& r = scene_->renderer();
  r.draw_text(status_line().c_str(), nullptr, mjGRID_TOPLEFT);
  mjrContext* con = r.render_context();
  mjr_blitBuffer({0, 0, kSceneWidthPx, kSceneHeightPx}, scene_rect_, 1, 0, con);
  mjr_setBuffer(mjFB_WINDOW, con);
  mjr_rectangle(figures_rect_, 0.1f, 0.1f, 0.12f, 1.0f);
  figures_.draw(figures_rect_, con);
  mjui_render(&ui_, &window_.state(), con);
}

void ViewerWindow::take_screenshot(const std::string& path) {
  const int w = window_.framebuffer_width(), h = window_.framebuffer_height();
  std::vector<unsigned char> rgb(3 * static_cast<std::size_t>(w) * h);
  mjr_readPixels(rgb.data(), nullptr, {0, 0, w, h}, scene_->renderer().render_context());
  write_png_file(path, rgb.data(), w, h);
}

ViewStats ViewerWindow::run() {
  const Clock::time_point start = Clock::now();
  Clock::time_point last = start;
  while (!window_.should_close()) {
    if (options_.stop_requested && options_.stop_requested()) break;
    window_.poll_events();
    const Clock::time_point now = Clock::now();
    advance(std::chrono::duration<double>(now - last).count());
    last = now;
    draw();
    if (!screenshot_.empty()) {
      take_screenshot(screenshot_);
      screenshot_.clear();
    }
    window_.swap_buffers();
    ++frames_;
  }
  ViewStats stats;
  stats.frames = frames_;
  stats.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  stats.frames_per_s = stats.wall_s > 0 ? frames_ / stats.wall_s : 0.0;
  stats.simulated_s = simulated_s_;
  stats.gl = scene_->renderer().gl_in_use();
  return stats;
}

ViewStats run_viewer(LiveSession& session, const ViewOptions& options) {
  ViewerWindow viewer(session, options);
  return viewer.run();
}

}  // namespace pamsim
