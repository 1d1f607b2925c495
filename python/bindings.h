// bindings.h: what the Python module's files share: the numpy array type its functions take
// (C order, converted to double) and the binders of its topics, each adding its classes and
// functions to the module (pamsim_module.cc calls them).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

namespace pamsim_python {

using Array = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

// SpringModel, fit, fit_csv, read_tensile_csv, tensile_test (bind_muscle.cc)
void bind_muscle(pybind11::module_& m);

}  // namespace pamsim_python
