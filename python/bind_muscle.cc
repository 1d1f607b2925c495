// bind_muscle.cc: the muscle half of the Python module: spring laws Eq. (2)-(5) and their
// inversion Eq. (10), vectorised over numpy arrays (SpringModel), their least-squares fit
// (Yoshida and Hosoda, Sec. II-B: fit, fit_csv) and the virtual tensile test (tensile_test,
// read_tensile_csv). Paper units (MPa, mm, N) at this boundary, SI inside.
#include "bindings.h"

#include <cstring>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/units.h"
#include "pam_actuator/identification.h"
#include "pam_actuator/pam_params.h"
#include "pam_actuator/plant_params.h"
#include "pam_actuator/spring_model.h"
#include "pam_actuator/tensile_csv.h"
#include "pam_actuator/tensile_test.h"

namespace pamsim_python {

namespace py = pybind11;
using namespace pamsim;

namespace {

// ---- spring laws -----------------------------------------------------------------------

SpringModel make_spring(const std::string& law, double m_mm_per_mpa, double h_mm,
                        const std::vector<double>& coefficients) {
  const SpringLaw l = parse_spring_law(law, "law");
  if (static_cast<int>(coefficients.size()) != coefficient_count(l)) {
    throw InputError("coefficients: " + law + " takes " + std::to_string(coefficient_count(l)) +
                     " coefficients, got " + std::to_string(coefficients.size()));
  }
  std::array<double, 6> coef{};
  for (std::size_t k = 0; k < coefficients.size(); ++k) {
    if (!std::isfinite(coefficients[k])) {
      throw InputError("coefficients: " + coefficient_name(l, static_cast<int>(k)) +
                       " must be finite");
    }
    coef[k] = coefficients[k];
  }
  if (!std::isfinite(m_mm_per_mpa) || !std::isfinite(h_mm)) {
    throw InputError("m_mm_per_MPa and h_mm must be finite");
  }
  return spring_model_from_paper_units(l, m_mm_per_mpa, h_mm, coef);
}

struct PaperUnits {
  double m_mm_per_mpa = 0, h_mm = 0;
  std::vector<double> coefficients;
};

PaperUnits paper_units(const SpringModel& s) {
  PaperUnits p;
  std::array<double, 6> coef{};
  spring_model_to_paper_units(s, &p.m_mm_per_mpa, &p.h_mm, &coef);
  p.coefficients.assign(coef.begin(), coef.begin() + coefficient_count(s.law));
  return p;
}

// ---- tensile data as columns -------------------------------------------------------------

py::dict rows_to_dict(const std::vector<TensileRow>& rows) {
  const auto n = static_cast<py::ssize_t>(rows.size());
  Array p(n), d(n), f(n), l(n);
  py::list direction;
  for (py::ssize_t i = 0; i < n; ++i) {
    const TensileRow& r = rows[static_cast<std::size_t>(i)];
    p.mutable_at(i) = r.pressure_mpa;
    d.mutable_at(i) = r.deformation_mm;
    f.mutable_at(i) = r.force_n;
    l.mutable_at(i) = r.length_mm;
    direction.append(to_string(r.direction));
  }
  py::dict out;
  out["pressure_MPa"] = p;
  out["deformation_mm"] = d;
  out["force_N"] = f;
  out["length_mm"] = l;
  out["direction"] = direction;
  return out;
}

std::vector<TensileRow> rows_from_arrays(const Array& p, const Array& d, const Array& f,
                                         const std::optional<Array>& l) {
  const py::ssize_t n = p.size();
  if (d.size() != n || f.size() != n || (l && l->size() != n)) {
    throw InputError(
        "pressure_MPa, deformation_mm, force_N (and length_mm) must have the same "
        "length");
  }
  std::vector<TensileRow> rows(static_cast<std::size_t>(n));
  for (py::ssize_t i = 0; i < n; ++i) {
    TensileRow& r = rows[static_cast<std::size_t>(i)];
    r.pressure_mpa = p.data()[i];
    r.deformation_mm = d.data()[i];
    r.force_n = f.data()[i];
    r.length_mm = l ? l->data()[i] : std::nan("");
    if (!std::isfinite(r.pressure_mpa) || !std::isfinite(r.deformation_mm) ||
        !std::isfinite(r.force_n)) {
      throw InputError("row " + std::to_string(i) + ": values must be finite");
    }
  }
  return rows;
}

py::dict fit_to_dict(const SpringFit& fit) {
  py::dict out;
  out["model"] = fit.model;
  out["rmse_N"] = fit.rmse_n;
  out["r2"] = fit.r2;
  out["points"] = fit.points;
  return out;
}

// the SpringModel class: a law's coefficients in paper units, the law and its inversion
// vectorised over numpy arrays
void bind_spring_model(py::module_& m) {
  py::class_<SpringModel>(m, "SpringModel",
                          "A fitted spring law, Eq. (2) with Eq. (3), (4) or (5) (paper units)")
      .def(py::init(&make_spring), py::arg("law"), py::arg("m_mm_per_MPa"), py::arg("h_mm"),
           py::arg("coefficients"))
      .def_static(
          "from_file", [](const std::string& path) { return load_pam_params(path).spring; },
          py::arg("path"), "The [spring] of a PAM parameter file (models/pams/*.toml)")
      .def_property_readonly("law",
                             [](const SpringModel& s) { return std::string(to_string(s.law)); })
      .def_property_readonly("m_mm_per_MPa",
                             [](const SpringModel& s) { return paper_units(s).m_mm_per_mpa; })
      .def_property_readonly("h_mm", [](const SpringModel& s) { return paper_units(s).h_mm; })
      .def_property_readonly("coefficients",
                             [](const SpringModel& s) { return paper_units(s).coefficients; })
      .def("force_N", py::vectorize([](SpringModel& s, double p_mpa, double d_mm) {
             return spring_force(s, units::mpa_to_pa(p_mpa), units::mm_to_m(d_mm));
           }),
           py::arg("pressure_MPa"), py::arg("deformation_mm"),
           "Eq. (3)-(5): force [N]; d <= 0 is a slack line (0 N)")
      .def("natural_length_mm", py::vectorize([](SpringModel& s, double p_mpa) {
             return units::m_to_mm(natural_length(s, units::mpa_to_pa(p_mpa)));
           }),
           py::arg("pressure_MPa"), "Eq. (2): natural length [mm]")
      .def("deformation_mm", py::vectorize([](SpringModel& s, double p_mpa, double f_n) {
             return units::m_to_mm(invert_spring_model(s, units::mpa_to_pa(p_mpa), f_n).d_m);
           }),
           py::arg("pressure_MPa"), py::arg("force_N"),
           "The law inverted for d [mm] (Eq. (10)); 0 where the line is slack or no root")
      .def("inversion_status", py::vectorize([](SpringModel& s, double p_mpa, double f_n) {
             return static_cast<int>(invert_spring_model(s, units::mpa_to_pa(p_mpa), f_n).status);
           }),
           py::arg("pressure_MPa"), py::arg("force_N"),
           "0 ok, 1 slack (f <= 0), 2 no physical root")
      .def("__repr__", [](const SpringModel& s) {
        const PaperUnits p = paper_units(s);
        std::ostringstream o;
        o.precision(17);
        o << "SpringModel(law='" << to_string(s.law) << "', m_mm_per_MPa=" << p.m_mm_per_mpa
          << ", h_mm=" << p.h_mm << ", coefficients=[";
        for (std::size_t k = 0; k < p.coefficients.size(); ++k) {
          o << (k ? ", " : "") << p.coefficients[k];
        }
        o << "])";
        return o.str();
      });
}

}  // namespace

void bind_muscle(py::module_& m) {
  bind_spring_model(m);
  m.def(
      "fit",
      [](const std::string& law, const Array& p, const Array& d, const Array& f,
         const std::optional<Array>& l) {
        return fit_to_dict(
            fit_spring_model(parse_spring_law(law, "law"), rows_from_arrays(p, d, f, l), "fit"));
      },
      py::arg("law"), py::arg("pressure_MPa"), py::arg("deformation_mm"), py::arg("force_N"),
      py::arg("length_mm") = py::none(),
      "Least-squares fit of Eq. (2) and the law (Yoshida and Hosoda, Sec. II-B): {model, rmse_N, "
      "r2, points}");
  m.def(
      "fit_csv",
      [](const std::string& law, const std::string& path) {
        return fit_to_dict(
            fit_spring_model(parse_spring_law(law, "law"), read_tensile_csv(path), path));
      },
      py::arg("law"), py::arg("path"), "The same fit from a tensile CSV (pamsim tensile's format)");
  m.def(
      "read_tensile_csv",
      [](const std::string& path) { return rows_to_dict(read_tensile_csv(path)); },
      py::arg("path"));
  m.def(
      "tensile_test",
      [](const py::object& law_or_plant, const std::vector<double>& pressures_mpa, double step_mm,
         double max_deformation_mm, double noise_pressure_mpa, double noise_force_n,
         double noise_length_mm, std::uint64_t seed) {
        TensileTestOptions o;
        o.pressures_mpa = pressures_mpa;
        o.step_mm = step_mm;
        o.max_deformation_mm = max_deformation_mm;
        o.noise_pressure_mpa = noise_pressure_mpa;
        o.noise_force_n = noise_force_n;
        o.noise_length_mm = noise_length_mm;
        o.seed = seed;
        validate_tensile_options(o);
        if (py::isinstance<SpringModel>(law_or_plant)) {
          return rows_to_dict(run_tensile_test(law_or_plant.cast<SpringModel>(), o));
        }
        if (!py::isinstance<py::str>(law_or_plant)) {
          throw InputError("law_or_plant: give a SpringModel or a plant file's path");
        }
        return rows_to_dict(
            run_tensile_test(load_plant_params(law_or_plant.cast<std::string>()).avbdl, o));
      },
      py::arg("law_or_plant"),
      py::arg("pressures_MPa") = std::vector<double>{0.4, 0.5, 0.6, 0.7, 0.8},
      py::arg("step_mm") = 2.5, py::arg("max_deformation_mm") = 20.0,
      py::arg("noise_pressure_MPa") = 0.0, py::arg("noise_force_N") = 0.0,
      py::arg("noise_length_mm") = 0.0, py::arg("seed") = 1,
      "The virtual static tensile test on a SpringModel or a plant file "
      "(models/pams/plant_*.toml)");
}

}  // namespace pamsim_python
