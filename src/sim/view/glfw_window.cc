// glfw_window.cc: see glfw_window.h. The event glue follows MuJoCo's `simulate` sample
// (uitools.c): positions in framebuffer pixels from the bottom-left corner, a press within
// 0.25 s of the last on the same button a double click.
#include "sim/view/glfw_window.h"

#include <GLFW/glfw3.h>

#include <string>

#include "base/input_error.h"

namespace pamsim {
namespace {

constexpr double kDoubleClickS = 0.25;

std::string& glfw_error() {
  static std::string error;
  return error;
}

void keep_glfw_error(int, const char* description) {
  glfw_error() = description ? description : "";
}

class WindowContext final : public GlContext {
 public:
  explicit WindowContext(GLFWwindow* window) : window_(window) {}
  void make_current() override { glfwMakeContextCurrent(window_); }
  std::string description() const override { return "glfw window"; }
  std::string renderer() const override {
    const auto text = [](unsigned int name) {
      const unsigned char* s = glGetString(name);
      return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return text(GL_VENDOR) + ", " + text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
  }
  void* gl_function(const char* name) const override {
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
  }

 private:
  GLFWwindow* window_;
};

GlfwWindow* owner(GLFWwindow* w) { return static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w)); }

}  // namespace

GlfwWindow::GlfwWindow(const std::string& title, int width, int height) {
  glfwSetErrorCallback(keep_glfw_error);
  if (!glfwInit()) {
    throw InputError("pamsim view needs a display (" + glfw_error() +
                     "); pamsim render SCENARIO makes the trial's video without one");
  }
  // one size, the scene's pixels as `pamsim render` frames them beside the UI: MuJoCo's
  // offscreen frame (multisampled) is blitted 1:1 into a plain window buffer
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  glfwWindowHint(GLFW_SAMPLES, 0);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = glfw_error();
    glfwTerminate();
    throw InputError("pamsim view cannot open a window (" + why +
                     "); pamsim render SCENARIO makes the trial's video without one");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(0);  // the viewer paces itself
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, on_key);
  glfwSetMouseButtonCallback(window_, on_button);
  glfwSetCursorPosCallback(window_, on_move);
  glfwSetScrollCallback(window_, on_scroll);
  glfwSetFramebufferSizeCallback(window_, on_resize);
  state_.nrect = 1;
  state_.rect[0] = {0, 0, framebuffer_width(), framebuffer_height()};
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

std::unique_ptr<GlContext> GlfwWindow::context() {
  return std::make_unique<WindowContext>(window_);
}

void GlfwWindow::set_size(int width, int height) {
  glfwSetWindowSize(window_, width, height);
  // the window system answers in its own time: wait for it, briefly
  for (int tries = 0; tries < 200; ++tries) {
    glfwPollEvents();
    if (framebuffer_width() == width && framebuffer_height() == height) break;
    glfwWaitEventsTimeout(0.005);
  }
  state_.rect[0] = {0, 0, framebuffer_width(), framebuffer_height()};
}

void GlfwWindow::poll_events() { glfwPollEvents(); }
bool GlfwWindow::should_close() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void GlfwWindow::swap_buffers() { glfwSwapBuffers(window_); }

int GlfwWindow::framebuffer_width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}

int GlfwWindow::framebuffer_height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

void GlfwWindow::update_modifiers() {
  state_.control = glfwGetKey(window_, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                   glfwGetKey(window_, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
  state_.shift = glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                 glfwGetKey(window_, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  state_.alt = glfwGetKey(window_, GLFW_KEY_LEFT_ALT) == GLFW_PRESS ||
               glfwGetKey(window_, GLFW_KEY_RIGHT_ALT) == GLFW_PRESS;
}

void GlfwWindow::emit(int type) {
  state_.type = type;
  // the rectangle under the mouse, the last one listed that holds it
  state_.mouserect = 0;
  for (int i = state_.nrect - 1; i > 0; --i) {
    const mjrRect& r = state_.rect[i];
    if (state_.x >= r.left && state_.x < r.left + r.width && state_.y >= r.bottom &&
        state_.y < r.bottom + r.height) {
      state_.mouserect = i;
      break;
    }
  }
  if (handler_) handler_(state_);
}

void GlfwWindow::on_key(GLFWwindow* w, int key, int, int act, int) {
  if (act == GLFW_RELEASE) return;
  GlfwWindow* self = owner(w);
  self->update_modifiers();
  self->state_.key = key;
  self->state_.keytime = glfwGetTime();
  self->emit(mjEVENT_KEY);
}

void GlfwWindow::on_button(GLFWwindow* w, int button, int act, int) {
  GlfwWindow* self = owner(w);
  mjuiState& s = self->state_;
  self->update_modifiers();
  s.left = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  s.right = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  s.middle = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  const int which = button == GLFW_MOUSE_BUTTON_LEFT    ? mjBUTTON_LEFT
                    : button == GLFW_MOUSE_BUTTON_RIGHT ? mjBUTTON_RIGHT
                                                        : mjBUTTON_MIDDLE;
  if (act == GLFW_PRESS) {
    const double now = glfwGetTime();
    s.doubleclick = which == s.button && now - s.buttontime < kDoubleClickS;
    s.button = which;
    s.buttontime = now;
    self->emit(mjEVENT_PRESS);
    s.dragrect = s.mouserect;
    s.dragbutton = which;
  } else {
    self->emit(mjEVENT_RELEASE);
    s.dragrect = 0;
    s.dragbutton = 0;
  }
}

void GlfwWindow::on_move(GLFWwindow* w, double x, double y) {
  GlfwWindow* self = owner(w);
  mjuiState& s = self->state_;
  // screen to framebuffer pixels, from the bottom
  int fb_w = 0, fb_h = 0, win_w = 1, win_h = 1;
  glfwGetFramebufferSize(w, &fb_w, &fb_h);
  glfwGetWindowSize(w, &win_w, &win_h);
  const double scale = win_w > 0 ? static_cast<double>(fb_w) / win_w : 1.0;
  const double fx = x * scale, fy = fb_h - y * scale;
  s.dx = fx - s.x;
  s.dy = fy - s.y;
  s.x = fx;
  s.y = fy;
  self->update_modifiers();
  self->emit(mjEVENT_MOVE);
}

void GlfwWindow::on_scroll(GLFWwindow* w, double dx, double dy) {
  GlfwWindow* self = owner(w);
  self->state_.sx = dx;
  self->state_.sy = dy;
  self->emit(mjEVENT_SCROLL);
}

void GlfwWindow::on_resize(GLFWwindow* w, int width, int height) {
  GlfwWindow* self = owner(w);
  self->state_.rect[0] = {0, 0, width, height};
  self->emit(mjEVENT_RESIZE);
}

}  // namespace pamsim
