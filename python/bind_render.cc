// bind_render.cc: a stepped trial's frames for Python (Trial.render): its state drawn
// offscreen by the same scene as `pamsim render` (sim/render/trial_scene.h), without the
// video's overlays, as a (height, width, 3) uint8 array, rows top-down.
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>

#include "bindings.h"
#include "sim/render/trial_scene.h"

namespace py = pybind11;

namespace pamsim_python {

struct FrameRenderer::Scene {
  std::unique_ptr<pamsim::TrialScene> scene;
  int width = 0, height = 0;
  std::string camera, quality, backend;
};

FrameRenderer::FrameRenderer() : scene_(std::make_unique<Scene>()) {}
FrameRenderer::~FrameRenderer() = default;

py::array_t<std::uint8_t> FrameRenderer::render(const pamsim::TrialModel& model,
                                                const pamsim::Scenario& scenario,
                                                pamsim::SteppedTrial& trial, int width, int height,
                                                const std::string& camera,
                                                const std::string& quality,
                                                const std::string& backend) {
  Scene& s = *scene_;
  if (!s.scene || s.width != width || s.height != height || s.camera != camera ||
      s.quality != quality || s.backend != backend) {
    pamsim::SceneRenderOptions o;
    o.width_px = width;
    o.height_px = height;
    o.camera = camera;
    o.quality = pamsim::parse_render_quality(quality);
    o.backend = backend.empty() ? pamsim::choose_gl_backend("")
                                : pamsim::parse_gl_backend(backend, "backend");
    s.scene.reset();  // one GL context at a time
    s.scene = std::make_unique<pamsim::TrialScene>(model, scenario, o);
    s.width = width;
    s.height = height;
    s.camera = camera;
    s.quality = quality;
    s.backend = backend;
  }
  py::array_t<std::uint8_t> frame({height, width, 3});
  {
    py::gil_scoped_release release;
    s.scene->draw(trial.snapshot());
    const unsigned char* rgb = s.scene->renderer().read_pixels();  // rows bottom-up
    std::uint8_t* out = frame.mutable_data();
    const std::size_t row = static_cast<std::size_t>(width) * 3;
    for (int y = 0; y < height; ++y) {
      std::memcpy(out + static_cast<std::size_t>(y) * row,
                  rgb + static_cast<std::size_t>(height - 1 - y) * row, row);
    }
  }
  return frame;
}

}  // namespace pamsim_python
