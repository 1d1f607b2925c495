// bindings.h: what the Python module's files share: the numpy array type its functions take
// (C order, converted to double) and the binders of its topics, each adding its classes and
// functions to the module (pamsim_module.cc calls them).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <memory>
#include <string>

namespace pamsim {
struct Scenario;
struct TrialModel;
class SteppedTrial;
}  // namespace pamsim

namespace pamsim_python {

using Array = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

// SpringModel, fit, fit_csv, read_tensile_csv, tensile_test (bind_muscle.cc)
void bind_muscle(pybind11::module_& m);

// A stepped trial's frames (bind_render.cc): its scene, made at the first render and again
// when the size, camera, quality or backend change.
class FrameRenderer {
 public:
  FrameRenderer();
  ~FrameRenderer();
  // The trial's state now as a (height, width, 3) uint8 array, rows top-down; quality "fast"
  // or "default"; backend "osmesa", "egl" or "" (PAMSIM_GL_BACKEND, MUJOCO_GL, else
  // osmesa). Throws pamsim::InputError for a bad size, camera, quality or backend.
  pybind11::array_t<std::uint8_t> render(const pamsim::TrialModel& model,
                                         const pamsim::Scenario& scenario,
                                         pamsim::SteppedTrial& trial, int width, int height,
                                         const std::string& camera, const std::string& quality,
                                         const std::string& backend);

 private:
  struct Scene;
  std::unique_ptr<Scene> scene_;
};

}  // namespace pamsim_python
