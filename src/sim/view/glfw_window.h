// glfw_window.h: the window of `pamsim view`: a GLFW window (Debian's libglfw3, on the X
// display: a desktop or Xvfb) whose OpenGL context MuJoCo draws in, and its mouse and
// keyboard turned into MuJoCo's UI state (mjuiState, as MuJoCo's `simulate` sample fills
// it), handed to the viewer event by event. Without a display it refuses in one line that
// points to `pamsim render`.
#pragma once

#include <mujoco/mujoco.h>

#include <functional>
#include <memory>
#include <string>

#include "sim/render/gl_context.h"

struct GLFWwindow;

namespace pamsim {

class GlfwWindow {
 public:
  // Opens the window (width x height screen pixels) with its context current. Throws
  // InputError "pamsim view needs a display ...; pamsim render SCENARIO makes the video
  // without one" when GLFW finds none.
  GlfwWindow(const std::string& title, int width, int height);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  // A GlContext that makes this window's context current (the window keeps it; it must
  // outlive the context): what SceneRenderOptions::context hands the renderer.
  std::unique_ptr<GlContext> context();

  // Called for every mouse and keyboard event and resize, with the state after it
  // (mjuiState::type says which); the rectangles (state().rect) are the caller's to set.
  void on_event(std::function<void(mjuiState&)> handler) { handler_ = std::move(handler); }
  mjuiState& state() { return state_; }
  // Resizes the window (screen pixels), waiting up to a second for the window system.
  void set_size(int width, int height);
  void poll_events();
  bool should_close() const;
  void close();
  void swap_buffers();
  int framebuffer_width() const;
  int framebuffer_height() const;

 private:
  static void on_key(GLFWwindow* w, int key, int scancode, int act, int mods);
  static void on_button(GLFWwindow* w, int button, int act, int mods);
  static void on_move(GLFWwindow* w, double x, double y);
  static void on_scroll(GLFWwindow* w, double dx, double dy);
  static void on_resize(GLFWwindow* w, int width, int height);
  void update_modifiers();
  void emit(int type);

  GLFWwindow* window_ = nullptr;
  mjuiState state_{};
  std::function<void(mjuiState&)> handler_;
};

}  // namespace pamsim
