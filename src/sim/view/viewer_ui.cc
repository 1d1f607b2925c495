// viewer_ui.cc: the viewer's UI (viewer.h) on MuJoCo's mjUI, as MuJoCo's `simulate` builds
// its own: a "Trial" section (play/pause, step, restart with the seed field, drop now, the
// reflex switch, slow motion) and a "Controller" section with a slider per setting the
// controller's kind lets change during a trial; the keys; the mouse on the camera.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "base/input_error.h"
#include "sim/view/viewer_window.h"

namespace pamsim {
namespace {

constexpr int kUiRect = 1, kSceneRect = 2;
constexpr int kSlowest = 4;  // 1/16 of real time

const char* const kPlay = "Play/pause";
const char* const kStep = "Step";
const char* const kRestart = "Restart";
const char* const kDrop = "Drop now";

mjuiDef item(int type, const std::string& name, void* data, const std::string& other) {
  mjuiDef d{};
  d.type = type;
  std::snprintf(d.name, sizeof(d.name), "%s", name.c_str());
  d.state = 1;
  d.pdata = data;
  std::snprintf(d.other, sizeof(d.other), "%s", other.c_str());
  return d;
}

}  // namespace

void ViewerWindow::make_ui() {
  ui_.spacing = mjui_themeSpacing(0);
  ui_.color = mjui_themeColor(0);
  ui_.rectid = kUiRect;
  ui_.auxid = 0;
  mjuiDef drop = item(mjITEM_BUTTON, kDrop, nullptr, "");
  drop.state = session_.has_mass_to_drop() ? 1 : 0;  // (greyed out: the leg drops no mass)
  std::vector<mjuiDef> defs = {item(mjITEM_SECTION, "Trial", nullptr, ""),
                               item(mjITEM_BUTTON, kPlay, nullptr, ""),
                               item(mjITEM_BUTTON, kStep, nullptr, ""),
                               item(mjITEM_BUTTON, kRestart, nullptr, ""),
                               item(mjITEM_EDITINT, "Seed", &seed_field_, "1 0 1000000000"),
                               drop,
                               item(mjITEM_CHECKINT, "Reflex", &reflex_, ""),
                               item(mjITEM_RADIO, "Speed", &slow_index_, "1\n1/2\n1/4\n1/8\n1/16")};
  if (!settings_.empty()) defs.push_back(item(mjITEM_SECTION, "Controller", nullptr, ""));
  for (std::size_t k = 0; k < settings_.size(); ++k) {
    const LiveSettingValue& s = session_.settings()[k];
    const std::string name = s.key.substr(s.key.find('.') + 1);  // "v_thr_mm_s"
    defs.push_back(item(mjITEM_SLIDERNUM, name, &settings_[k],
                        std::to_string(s.slider_min) + " " + std::to_string(s.slider_max)));
  }
  defs.push_back(item(mjITEM_END, "", nullptr, ""));
  mjui_add(&ui_, defs.data());
  mjrContext* con = scene_->renderer().render_context();
  mjui_resize(&ui_, con);
  mjr_addAux(ui_.auxid, ui_.width, ui_.maxheight, ui_.spacing.samples, con);
  window_.set_size(kSceneWidthPx + ui_.width, kSceneHeightPx + kFiguresHeightPx);
  layout();
  mjui_update(-1, -1, &ui_, &window_.state(), con);
}

void ViewerWindow::layout() {
  mjuiState& s = window_.state();
  const int w = window_.framebuffer_width(), h = window_.framebuffer_height();
  const int figures = std::max(0, h - kSceneHeightPx);
  s.nrect = 3;
  s.rect[0] = {0, 0, w, h};
  s.rect[kUiRect] = {0, 0, ui_.width, h};
  scene_rect_ = {ui_.width, figures, std::max(1, w - ui_.width), std::max(1, h - figures)};
  figures_rect_ = {ui_.width, 0, std::max(1, w - ui_.width), figures};
  s.rect[kSceneRect] = scene_rect_;
}

void ViewerWindow::on_event(mjuiState& state) {
  layout();
  mjrContext* con = scene_->renderer().render_context();
  if (state.type == mjEVENT_RESIZE) {
    mjui_resize(&ui_, con);
    mjui_update(-1, -1, &ui_, &state, con);
    return;
  }
  if (const mjuiItem* it = mjui_event(&ui_, &state, con)) {
    on_ui_item(it);
    return;
  }
  if (state.type == mjEVENT_KEY && ui_.editsect == 0) {
    on_key(state.key);
  } else {
    move_camera(state);
  }
}

void ViewerWindow::on_key(int key) {
  switch (key) {
    case ' ':
      toggle_pause();
      break;
    case mjKEY_RIGHT:
      if (paused_) step_once();
      break;
    case 'D':
      session_.drop_now();
      break;
    case 'R':
      session_.set_reflex(!session_.reflex_on());
      break;
    case '-':
      set_slow(slow_index_ + 1);
      break;
    case '=':
      set_slow(slow_index_ - 1);
      break;
    case mjKEY_BACKSPACE:
      restart(static_cast<std::uint64_t>(seed_field_));
      break;
    case mjKEY_ESCAPE:
      free_camera_ = false;
      scene_->renderer().camera()->type = mjCAMERA_FIXED;
      break;
    default:
      return;
  }
  sync_ui();
}

void ViewerWindow::on_ui_item(const mjuiItem* it) {
  const std::string name = it->name;
  if (name == kPlay) toggle_pause();
  if (name == kStep) step_once();
  if (name == kRestart) restart(static_cast<std::uint64_t>(seed_field_));
  if (name == kDrop) session_.drop_now();
  if (it->pdata == &reflex_) session_.set_reflex(reflex_ != 0);
  sync_ui();  // (a slider's value is applied from the next control tick)
}

// The mouse on the scene moves the camera as in `simulate`; the first move frees it from
// the model's camera where that camera looked.
void ViewerWindow::move_camera(const mjuiState& state) {
  const bool drag = state.type == mjEVENT_MOVE && state.dragrect == kSceneRect &&
                    (state.left || state.right || state.middle);
  const bool zoom = state.type == mjEVENT_SCROLL && state.mouserect == kSceneRect;
  if (!drag && !zoom) return;
  SceneRenderer& r = scene_->renderer();
  mjvCamera* cam = r.camera();
  if (!free_camera_) {
    const mjvGLCamera& eye = r.scene()->camera[0];
    const double distance = 2.0 * r.model()->stat.extent;
    cam->type = mjCAMERA_FREE;
    cam->distance = distance;
    for (int k = 0; k < 3; ++k) cam->lookat[k] = eye.pos[k] + distance * eye.forward[k];
    cam->azimuth = std::atan2(eye.forward[1], eye.forward[0]) * 180.0 / M_PI;
    cam->elevation = std::asin(eye.forward[2]) * 180.0 / M_PI;
    free_camera_ = true;
  }
  const double h = scene_rect_.height;
  if (zoom) {
    mjv_moveCamera(r.model(), mjMOUSE_ZOOM, 0, -0.05 * state.sy, r.scene(), cam);
    return;
  }
  const int action = state.right  ? (state.shift ? mjMOUSE_MOVE_H : mjMOUSE_MOVE_V)
                     : state.left ? (state.shift ? mjMOUSE_ROTATE_H : mjMOUSE_ROTATE_V)
                                  : mjMOUSE_ZOOM;
  mjv_moveCamera(r.model(), action, state.dx / h, -state.dy / h, r.scene(), cam);
}

void ViewerWindow::sync_ui() {
  reflex_ = session_.reflex_on() ? 1 : 0;
  mjui_update(-1, -1, &ui_, &window_.state(), scene_->renderer().render_context());
}

void ViewerWindow::apply_pending_settings() {
  for (std::size_t k = 0; k < settings_.size(); ++k) {
    if (settings_[k] == applied_settings_[k]) continue;
    const std::string key = session_.settings()[k].key;
    try {
      session_.set_setting(key, settings_[k], "the slider " + key);
      applied_settings_[k] = settings_[k];
    } catch (const InputError& e) {
      std::cerr << "pamsim: warning: " << e.what() << " (the slider goes back)\n";
      settings_[k] = applied_settings_[k];
    }
  }
}

void ViewerWindow::restart(std::uint64_t seed) {
  apply_pending_settings();
  session_.restart(seed);
  seed_field_ = static_cast<int>(seed);
  figures_.clear();
  figures_.add(session_.trial().observe(), NAN);
  debt_s_ = 0.0;
}

void ViewerWindow::set_slow(int index) { slow_index_ = std::max(0, std::min(kSlowest, index)); }

}  // namespace pamsim
