// scene_renderer.h: draws a MuJoCo model's state offscreen, from one of the model's cameras,
// with MuJoCo's own renderer (mjv_updateScene, mjr_render), adds text and figures on top
// (mjr_overlay, mjr_figure) and reads the frame back (mjr_readPixels). It renders a copy of
// the model (its visual settings changed to suit the frame) and a copy of each state it is
// given, so drawing never touches the simulation.
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sim/render/backdrop.h"
#include "sim/render/gl_context.h"
#include "sim/core/mujoco_util.h"

namespace pamsim {

// Frame sides are limited so a typo cannot ask for gigabytes; 8192 covers 8K video.
inline constexpr int kMinFrameSidePx = 16;
inline constexpr int kMaxFrameSidePx = 8192;

enum class RenderQuality {
  kFast,     // no shadows, reflections or skybox, no multisampling
  kDefault,  // the model's own <visual> settings
};

// "fast" | "default". Throws InputError "--quality must be fast or default, got '<name>'".
RenderQuality parse_render_quality(const std::string& name);

struct SceneRenderOptions {
  int width_px = 1280;
  int height_px = 720;
  RenderQuality quality = RenderQuality::kDefault;
  std::string camera = "side";  // a camera named in the model
  GlBackend backend = GlBackend::kOsmesa;
  EglDeviceChoice egl_device;  // egl only
  // the backdrop always as a scene geom (backdrop.h), never as the quad that draws it
  // faster where it can: for comparisons
  bool backdrop_geom = false;
  // the GL context to draw in, current on return (a window's: `pamsim view`); none: a new
  // one of `backend`. The frame is still drawn offscreen; the window shows it by
  // mjr_blitBuffer.
  std::function<std::unique_ptr<GlContext>()> context{};
};

// Throws InputError naming `model_path` if `model` has no camera `camera` (the message lists
// the model's cameras). For commands that check before they create any output.
void check_camera(const mjModel* model, const std::string& model_path, const std::string& camera);

class SceneRenderer {
 public:
  // Prepares the GL context and MuJoCo's scene and render context for `model` (copied; the
  // original is only read). Throws InputError naming `model_path` for an unknown camera (the
  // message lists the model's cameras), for a size outside [kMinFrameSidePx,
  // kMaxFrameSidePx] or beyond what the GL implementation supports, and when the GL context
  // cannot be created.
  SceneRenderer(const mjModel* model, const std::string& model_path,
                const SceneRenderOptions& options);
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  int width_px() const { return viewport_.width; }
  int height_px() const { return viewport_.height; }
  // the overlay font's line height [px]
  int line_height_px() const;
  // The GL context in use: "<description>: <vendor>, <renderer>, OpenGL <version>".
  std::string gl_in_use() const;

  // A capsule drawn into the scene beside the model's own geoms (e.g. a muscle), world
  // coordinates [m].
  struct Capsule {
    double from[3], to[3];
    double radius_m;
    float rgba[4];
  };
  // Draws the state `data` (of the model given at construction) over the whole frame, with
  // `capsules` added to the scene, in front of a plain backdrop.
  void draw_scene(const mjData* data, const std::vector<Capsule>& capsules = {});

  // Two columns of text in a corner (mjGRID_TOPLEFT, mjGRID_TOPRIGHT, ...), lines separated
  // by '\n'.
  void draw_text(const char* titles, const char* values, int corner = mjGRID_TOPLEFT);

  // A figure (e.g. a live plot) in `viewport`, pixels from the bottom-left corner.
  void draw_figure(const mjrRect& viewport, mjvFigure* figure);

  // A colour key in `bar` (pixels from the bottom-left corner): `colours` drawn left to right
  // in equal cells, `low` written left of it and `high` right of it.
  void draw_colour_bar(const mjrRect& bar, const std::vector<std::array<float, 3>>& colours,
                       const char* low, const char* high);

  // MuJoCo's objects, for a window that draws its own UI beside the frame (`pamsim view`):
  // the render context, the scene last drawn, the camera (fixed on the named one until the
  // caller moves it) and the model drawn.
  mjrContext* render_context() { return context_.get(); }
  mjvScene* scene() { return scene_.get(); }
  mjvCamera* camera() { return &camera_; }
  const mjModel* model() const { return model_.get(); }

  // The frame drawn so far: width * height RGB triplets, rows bottom-up (OpenGL's order).
  // Valid until the next call; the buffer is reused from frame to frame.
  const unsigned char* read_pixels();

 private:
  struct SceneDeleter {
    void operator()(mjvScene* scene) const;
  };
  struct ContextDeleter {
    void operator()(mjrContext* context) const;
  };

  MjModelPtr model_;  // the copy that is drawn
  MjDataPtr data_;    // the state being drawn, copied from the caller's
  mjvOption option_;
  mjvCamera camera_;
  mjrRect viewport_;
  std::unique_ptr<GlContext> gl_;
  std::unique_ptr<Backdrop> backdrop_;
  bool backdrop_geom_ = false;  // SceneRenderOptions::backdrop_geom
  std::unique_ptr<mjvScene, SceneDeleter> scene_;
  std::unique_ptr<mjrContext, ContextDeleter> context_;  // freed while gl_ is current
  std::vector<unsigned char> rgb_;
};

}  // namespace pamsim
