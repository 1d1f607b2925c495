// backdrop.cc: see backdrop.h.
#include "sim/render/backdrop.h"

#include <GL/gl.h>

namespace pamsim {
namespace {

// the box's half thickness; the wall it shows is its far face, kBackdropDistanceM + this
// from the camera: its frame (right, up, forward) is mirrored, so MuJoCo culls its near face
constexpr double kHalfThicknessM = 0.01;
constexpr double kHalfSideM = 20.0;  // the box's width and height, halved

// the legacy GL calls the quad makes (the types from GL/gl.h's declarations; the functions
// themselves come from the context: the linked ones may belong to another library)
// clang-format off
#define PAMSIM_BACKDROP_GL(X)                                                              \
  X(PushAttrib) X(PopAttrib) X(MatrixMode) X(PushMatrix) X(PopMatrix) X(LoadIdentity)       \
  X(Disable) X(Enable) X(DepthFunc) X(DepthMask) X(PolygonMode) X(Viewport) X(Color4f)      \
  X(Begin) X(Vertex3f) X(End)
// clang-format on

// whether `head` is behind plane geom `g` (MuJoCo 2.2's test: mjr_render then draws the
// plane transparent)
bool head_behind(const mjtNum head[3], const mjvGeom& g) {
  return (head[0] - g.pos[0]) * g.mat[2] + (head[1] - g.pos[1]) * g.mat[5] +
             (head[2] - g.pos[2]) * g.mat[8] <
         0.0;
}

}  // namespace

struct Backdrop::Gl {
#define PAMSIM_GL_POINTER(name) decltype(&::gl##name) name = nullptr;
  PAMSIM_BACKDROP_GL(PAMSIM_GL_POINTER)
#undef PAMSIM_GL_POINTER
  bool complete = true;  // every entry point found
};

Backdrop::Backdrop(const GlContext& gl) : gl_(std::make_unique<Gl>()) {
#define PAMSIM_GL_LOAD(name)                                                     \
  gl_->name = reinterpret_cast<decltype(gl_->name)>(gl.gl_function("gl" #name)); \
  gl_->complete = gl_->complete && gl_->name != nullptr;
  PAMSIM_BACKDROP_GL(PAMSIM_GL_LOAD)
#undef PAMSIM_GL_LOAD
}

Backdrop::~Backdrop() = default;

bool Backdrop::quad_pays(const mjvScene& scene) {
  if (!scene.flags[mjRND_SHADOW]) return false;
  for (int i = 0; i < scene.nlight; ++i) {
    if (scene.lights[i].castshadow) return true;
  }
  return false;
}

bool Backdrop::quad_matches_geom(const mjvScene& scene) const {
  if (!gl_->complete || scene.flags[mjRND_FOG]) return false;
  mjtNum head[3], forward[3];
  mjv_cameraInModel(head, forward, nullptr, &scene);
  for (int i = 0; i < scene.ngeom; ++i) {
    const mjvGeom& g = scene.geoms[i];
    // mjr_render blends a transparent geom over what is behind it, and mirrors the scene,
    // backdrop included, in a reflective plane or box: both before a quad could be drawn
    if (g.rgba[3] < 0.995f) return false;
    if (g.type == mjGEOM_PLANE && head_behind(head, g)) return false;
    if ((g.type == mjGEOM_PLANE || g.type == mjGEOM_BOX) && g.reflectance > 0) return false;
  }
  return true;
}

void Backdrop::add_geom(mjvScene* scene) {
  if (scene->ngeom >= scene->maxgeom) return;
  // a wide light-grey box facing the camera, emitting: its emission and the lights add up
  // past 1 in every channel, so it comes out white (which the quad is)
  const mjvGLCamera& eye = scene->camera[0];
  mjtNum right[3], up[3], forward[3], pos[3];
  for (int i = 0; i < 3; ++i) {
    forward[i] = eye.forward[i];
    up[i] = eye.up[i];
    pos[i] = eye.pos[i] + kBackdropDistanceM * eye.forward[i];
  }
  mju_cross(right, forward, up);
  const mjtNum mat[9] = {right[0],   up[0],    forward[0], right[1],  up[1],
                         forward[1], right[2], up[2],      forward[2]};
  const mjtNum size[3] = {kHalfSideM, kHalfSideM, kHalfThicknessM};
  const float rgba[4] = {0.93f, 0.93f, 0.95f, 1.0f};
  mjvGeom* g = scene->geoms + scene->ngeom++;
  mjv_initGeom(g, mjGEOM_BOX, size, pos, mat, rgba);
  g->category = mjCAT_DECOR;
  g->emission = 1.0f;
  g->specular = 0.0f;
  g->reflectance = 0.0f;
}

void Backdrop::draw_quad(const mjvScene& scene, const mjrRect& viewport) const {
  const Gl& gl = *gl_;
  // the wall the box shows in normalised device depth: a plane square to the view axis is at
  // one depth in a perspective projection (MuJoCo's, from the averaged camera's frustum)
  const mjvGLCamera cam = mjv_averageCamera(scene.camera, scene.camera + 1);
  const double n = cam.frustum_near;
  const double f = cam.frustum_far;
  const double d = kBackdropDistanceM + kHalfThicknessM;
  const float z = static_cast<float>((f + n) / (f - n) - 2.0 * f * n / ((f - n) * d));

  // flat white, depth-tested, nothing else; the state as mjr_render left it afterwards
  // (the colour white must not reach the material: glColor sets it where GL_COLOR_MATERIAL
  // is on)
  gl.PushAttrib(GL_ENABLE_BIT | GL_DEPTH_BUFFER_BIT | GL_CURRENT_BIT | GL_LIGHTING_BIT |
                GL_POLYGON_BIT | GL_VIEWPORT_BIT);
  for (GLenum cap : {GL_LIGHTING, GL_COLOR_MATERIAL, GL_TEXTURE_2D, GL_BLEND, GL_FOG, GL_CULL_FACE,
                     GL_ALPHA_TEST, GL_STENCIL_TEST, GL_SCISSOR_TEST, GL_CLIP_PLANE0}) {
    gl.Disable(cap);
  }
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.DepthMask(GL_FALSE);
  gl.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  gl.Viewport(viewport.left, viewport.bottom, viewport.width, viewport.height);
  gl.MatrixMode(GL_PROJECTION);
  gl.PushMatrix();
  gl.LoadIdentity();
  gl.MatrixMode(GL_MODELVIEW);
  gl.PushMatrix();
  gl.LoadIdentity();

  // the whole viewport at that depth
  gl.Color4f(1.0f, 1.0f, 1.0f, 1.0f);
  gl.Begin(GL_QUADS);
  gl.Vertex3f(-1.0f, -1.0f, z);
  gl.Vertex3f(1.0f, -1.0f, z);
  gl.Vertex3f(1.0f, 1.0f, z);
  gl.Vertex3f(-1.0f, 1.0f, z);
  gl.End();

  gl.PopMatrix();
  gl.MatrixMode(GL_PROJECTION);
  gl.PopMatrix();
  gl.MatrixMode(GL_MODELVIEW);
  gl.PopAttrib();
}

}  // namespace pamsim
