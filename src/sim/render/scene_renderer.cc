// scene_renderer.cc: see scene_renderer.h.
#include "sim/render/scene_renderer.h"

#include <algorithm>

#include <string>

#include "base/input_error.h"

namespace pamsim {
namespace {

constexpr int kMaxSceneGeoms = 1000;
constexpr int kLargeFontMinHeightPx = 600;  // 150 % font from here up, else 100 %

// "side, top" or "none", for the unknown-camera message
std::string camera_names(const mjModel* m) {
  std::string names;
  for (int i = 0; i < m->ncam; ++i) {
    const char* name = mj_id2name(m, mjOBJ_CAMERA, i);
    if (!names.empty()) names += ", ";
    names += name ? name : "(unnamed camera " + std::to_string(i) + ")";
  }
  return names.empty() ? "none" : names;
}

// Throws InputError naming `model_path` for a frame side outside [kMinFrameSidePx,
// kMaxFrameSidePx]; `size` is the frame's "WxH".
void check_frame_size(const SceneRenderOptions& options, const std::string& model_path,
                      const std::string& size) {
  for (int side : {options.width_px, options.height_px}) {
    if (side < kMinFrameSidePx || side > kMaxFrameSidePx) {
      throw InputError(model_path + ": frame size " + size + " outside [" +
                       std::to_string(kMinFrameSidePx) + ", " + std::to_string(kMaxFrameSidePx) +
                       "] pixels per side");
    }
  }
}

// A plain floor: planes lose their (checker) material and take one light grey.
void paint_floor_plain(mjModel* model) {
  for (int g = 0; g < model->ngeom; ++g) {
    if (model->geom_type[g] != mjGEOM_PLANE) continue;
    model->geom_matid[g] = -1;
    const float grey[4] = {0.80f, 0.80f, 0.82f, 1.0f};
    std::copy(grey, grey + 4, model->geom_rgba + 4 * g);
  }
}

}  // namespace

RenderQuality parse_render_quality(const std::string& name) {
  if (name == "fast") return RenderQuality::kFast;
  if (name == "default") return RenderQuality::kDefault;
  throw InputError("--quality must be fast or default, got '" + name + "'");
}

void check_camera(const mjModel* model, const std::string& model_path, const std::string& camera) {
  if (mj_name2id(model, mjOBJ_CAMERA, camera.c_str()) < 0) {
    throw InputError(model_path + ": no camera named '" + camera +
                     "' (the model's cameras: " + camera_names(model) + ")");
  }
}

void SceneRenderer::SceneDeleter::operator()(mjvScene* scene) const {
  mjv_freeScene(scene);
  delete scene;
}

void SceneRenderer::ContextDeleter::operator()(mjrContext* context) const {
  mjr_freeContext(context);
  delete context;
}

SceneRenderer::SceneRenderer(const mjModel* model, const std::string& model_path,
                             const SceneRenderOptions& options) {
  // check what is asked before touching GL
  const std::string size =
      std::to_string(options.width_px) + "x" + std::to_string(options.height_px);
  check_frame_size(options, model_path, size);
  check_camera(model, model_path, options.camera);
  const int camera_id = mj_name2id(model, mjOBJ_CAMERA, options.camera.c_str());

  // the copy that is drawn: offscreen buffer of the frame's size, quality as asked
  model_.reset(mj_copyModel(nullptr, model));
  if (!model_) throw std::runtime_error("mj_copyModel failed");
  model_->vis.global.offwidth = options.width_px;
  model_->vis.global.offheight = options.height_px;
  if (options.quality == RenderQuality::kFast) model_->vis.quality.offsamples = 0;
  paint_floor_plain(model_.get());
  data_ = make_data(model_.get());

  mjv_defaultOption(&option_);
  mjv_defaultCamera(&camera_);
  camera_.type = mjCAMERA_FIXED;
  camera_.fixedcamid = camera_id;
  viewport_ = {0, 0, options.width_px, options.height_px};

  // GL context, then MuJoCo's scene and render context drawing offscreen
  gl_ = options.context ? options.context()
                        : create_gl_context(options.backend, options.width_px, options.height_px,
                                            options.egl_device);
  backdrop_ = std::make_unique<Backdrop>(*gl_);
  backdrop_geom_ = options.backdrop_geom;
  scene_.reset(new mjvScene);
  mjv_defaultScene(scene_.get());
  mjv_makeScene(model_.get(), scene_.get(), kMaxSceneGeoms);
  if (options.quality == RenderQuality::kFast) {
    scene_->flags[mjRND_SHADOW] = 0;
    scene_->flags[mjRND_REFLECTION] = 0;
    scene_->flags[mjRND_SKYBOX] = 0;
  }
  context_.reset(new mjrContext);
  mjr_defaultContext(context_.get());
  const int font_scale =
      options.height_px >= kLargeFontMinHeightPx ? mjFONTSCALE_150 : mjFONTSCALE_100;
  mjr_makeContext(model_.get(), context_.get(), font_scale);
  mjr_setBuffer(mjFB_OFFSCREEN, context_.get());
  if (context_->currentBuffer != mjFB_OFFSCREEN || context_->offWidth != options.width_px ||
      context_->offHeight != options.height_px) {
    throw InputError(model_path + ": the GL implementation cannot render " + size +
                     " offscreen (got " + std::to_string(context_->offWidth) + "x" +
                     std::to_string(context_->offHeight) + ")");
  }
  rgb_.resize(3 * static_cast<std::size_t>(options.width_px) * options.height_px);
}

SceneRenderer::~SceneRenderer() {
  // MuJoCo's GL objects belong to this context: make it current before they are freed (if
  // that fails they go with the context itself)
  try {
    gl_->make_current();
  } catch (const std::exception&) {
  }
}

std::string SceneRenderer::gl_in_use() const {
  gl_->make_current();
  return gl_->description() + ": " + gl_->renderer();
}

void SceneRenderer::draw_scene(const mjData* data, const std::vector<Capsule>& capsules) {
  gl_->make_current();
  mjr_setBuffer(mjFB_OFFSCREEN, context_.get());  // (a window may have drawn in its own)
  // positions from the copied qpos: after mj_step2 the caller's own are a step old
  mj_copyData(data_.get(), model_.get(), data);
  mj_fwdPosition(model_.get(), data_.get());
  mjv_updateScene(model_.get(), data_.get(), &option_, nullptr, &camera_, mjCAT_ALL, scene_.get());
  mjvScene* scn = scene_.get();
  for (const Capsule& c : capsules) {
    if (scn->ngeom >= scn->maxgeom) break;
    mjvGeom* g = scn->geoms + scn->ngeom++;
    mjv_initGeom(g, mjGEOM_CAPSULE, nullptr, nullptr, nullptr, c.rgba);
    mjv_makeConnector(g, mjGEOM_CAPSULE, c.radius_m, c.from[0], c.from[1], c.from[2], c.to[0],
                      c.to[1], c.to[2]);
    g->category = mjCAT_DECOR;
  }
  // the plain backdrop: a quad after drawing where that pays and draws what the geom would,
  // else the geom (backdrop.h)
  const bool quad =
      !backdrop_geom_ && Backdrop::quad_pays(*scn) && backdrop_->quad_matches_geom(*scn);
  if (!quad) Backdrop::add_geom(scn);
  mjr_render(viewport_, scn, context_.get());
  if (quad) backdrop_->draw_quad(*scn, viewport_);
}

void SceneRenderer::draw_text(const char* titles, const char* values, int corner) {
  mjr_overlay(mjFONT_NORMAL, corner, viewport_, titles, values, context_.get());
}

void SceneRenderer::draw_figure(const mjrRect& viewport, mjvFigure* figure) {
  mjr_figure(viewport, figure, context_.get());
}

void SceneRenderer::draw_colour_bar(const mjrRect& bar,
                                    const std::vector<std::array<float, 3>>& colours,
                                    const char* low, const char* high) {
  const int n = static_cast<int>(colours.size());
  for (int k = 0; k < n; ++k) {
    const int left = bar.left + bar.width * k / n;
    const mjrRect cell{left, bar.bottom, bar.left + bar.width * (k + 1) / n - left, bar.height};
    const std::array<float, 3>& c = colours[static_cast<std::size_t>(k)];
    mjr_rectangle(cell, c[0], c[1], c[2], 1.0f);
  }
  // the labels in boxes of their own beside the bar, on its bottom line
  const mjrRect before{0, bar.bottom, bar.left, viewport_.height - bar.bottom};
  const mjrRect after{bar.left + bar.width, bar.bottom, viewport_.width - bar.left - bar.width,
                      viewport_.height - bar.bottom};
  mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMRIGHT, before, low, nullptr, context_.get());
  mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMLEFT, after, high, nullptr, context_.get());
}

const unsigned char* SceneRenderer::read_pixels() {
  mjr_readPixels(rgb_.data(), nullptr, viewport_, context_.get());
  return rgb_.data();
}

int SceneRenderer::line_height_px() const { return context_->charHeight; }

}  // namespace pamsim
