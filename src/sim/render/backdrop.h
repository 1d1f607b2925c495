// backdrop.h: the video's plain backdrop (MuJoCo 2.2 has no background colour; without a
// skybox it is black), a white wall square to the camera's view about kBackdropDistanceM
// in front of it, hiding what lies beyond. Two forms that draw the same frames, but for the
// geom's own shadow (a strip a few pixels high where a floor meets it; the quad casts none):
//   quad  one flat, unlit quad drawn after mjr_render, depth-tested against the scene: one
//         cheap pass over the pixels it covers
//   geom  a box added to the scene before mjr_render: shaded like every geom, in the lit
//         pass and again in each shadow-casting light's pass (with shadows on llvmpipe,
//         about a fifth of the drop-mass video's time at 720p)
// The quad is used where it pays (shadows on: without them the geom costs one flat pass
// too, and the quad's extra GL state costs llvmpipe shader compiles) and draws what the
// geom would; the geom elsewhere: no shadows, a transparent geom blended over it, a mirror
// reflecting it, fog, or a GL context that lacks an entry point the quad needs.
#pragma once

#include <mujoco/mujoco.h>

#include <memory>

#include "sim/render/gl_context.h"

namespace pamsim {

inline constexpr double kBackdropDistanceM = 2.5;  // from the camera, along its view

class Backdrop {
 public:
  // Looks up the quad's GL entry points in `gl` (kept: it must outlive this object).
  explicit Backdrop(const GlContext& gl);
  ~Backdrop();
  Backdrop(const Backdrop&) = delete;
  Backdrop& operator=(const Backdrop&) = delete;

  // Whether the quad saves time in `scene`: shadows are on and a light casts them.
  static bool quad_pays(const mjvScene& scene);

  // Whether draw_quad, after mjr_render of `scene` (its geoms final, camera set by
  // mjv_updateScene), draws the frame that add_geom before mjr_render would (but for the
  // geom's shadow): no geom is
  // transparent (alpha < 0.995, or a plane seen from behind) or reflective, no fog, and
  // the context has every entry point the quad needs.
  bool quad_matches_geom(const mjvScene& scene) const;

  // Appends the backdrop as a box geom to `scene` (if there is room).
  static void add_geom(mjvScene* scene);

  // Draws the backdrop as a quad in `viewport` of the current framebuffer (the one
  // mjr_render drew `scene` into there), over what is farther than the backdrop or empty;
  // restores the GL state it changes. Needs quad_matches_geom(scene) to hold.
  void draw_quad(const mjvScene& scene, const mjrRect& viewport) const;

 private:
  struct Gl;
  std::unique_ptr<Gl> gl_;
};

}  // namespace pamsim
