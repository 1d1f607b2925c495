// pamsim_module.cc: the compiled half of the Python package `pamsim` (pybind11), a thin
// layer over the C++ libraries: spring laws Eq. (2)-(5) and their inversion (vectorised
// over numpy arrays), fitting (seeds/000 Sec. II-B), the virtual tensile test, whole trials
// (`run`), trials stepped by a Python controller (`Trial`), and sweep and tuning databases.
// Units at this boundary are the papers' (MPa, mm, N) and are named in every argument and
// key; the C++ inside is SI. InputError becomes pamsim.InputError, a ValueError with the same
// one-line message. The GIL is released while trials run. python/pamsim/__init__.py adds
// the pure-Python conveniences (pandas frames).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "pam_actuator/identification.h"
#include "base/input_error.h"
#include "pam_actuator/pam_params.h"
#include "pam_actuator/plant_params.h"
#include "pam_actuator/spring_model.h"
#include "pam_actuator/tensile_csv.h"
#include "pam_actuator/tensile_test.h"
#include "base/units.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/io/outputs.h"
#include "sim/scenario/scenario_file.h"
#include "sim/sweep/results_db.h"
#include "sim/optimize/tune_outputs.h"

namespace py = pybind11;
using namespace pamsim;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

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
    throw InputError("pressure_MPa, deformation_mm, force_N (and length_mm) must have the same "
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

// ---- trials ------------------------------------------------------------------------------

// "key=value" overrides from a list of such strings or a dict of Python values.
std::vector<std::string> overrides_of(const py::object& given) {
  std::vector<std::string> out;
  if (given.is_none()) return out;
  if (py::isinstance<py::dict>(given)) {
    for (const auto& [key, value] : given.cast<py::dict>()) {
      std::string text;
      if (py::isinstance<py::bool_>(value)) {
        text = value.cast<bool>() ? "true" : "false";
      } else if (py::isinstance<py::str>(value)) {
        text = py::repr(value).cast<std::string>();   // a TOML string ('...' is literal)
      } else if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) {
        text = py::repr(value).cast<std::string>();   // shortest round trip
      } else {
        throw InputError("overrides: " + key.cast<std::string>() +
                         ": give a number, a string or a bool");
      }
      out.push_back(key.cast<std::string>() + "=" + text);
    }
    return out;
  }
  return given.cast<std::vector<std::string>>();
}

// summary.json's object as `pamsim run` writes it (status, seed, the metrics by name, null
// where undefined, "scenario"), and "metrics": every metric again, NaN where undefined, the
// timing ones included (the shape of `summary` before 0.4, kept for its callers)
py::dict summary_to_dict(const TrialSummary& s, const std::string& summary_json) {
  py::dict out = py::module_::import("json").attr("loads")(summary_json);
  py::dict metrics;
  for (const Metric& m : s.metrics) metrics[py::str(m.name)] = m.value;
  out["metrics"] = metrics;
  return out;
}

// A finished trial as Python sees it: the log's columns, its values (rows x columns) and the
// summary; the CSV is the one `pamsim run` writes.
struct PyResult {
  TrialResult result;
  Scenario scenario;
  std::vector<std::string> columns() const { return result.trajectory.columns; }
  py::array_t<double> values() const {
    const Trajectory& t = result.trajectory;
    py::array_t<double> a({static_cast<py::ssize_t>(t.rows()),
                           static_cast<py::ssize_t>(t.columns.size())});
    if (!t.values.empty()) {
      std::memcpy(a.mutable_data(), t.values.data(), t.values.size() * sizeof(double));
    }
    return a;
  }
  py::dict summary() const { return summary_to_dict(result.summary, summary_json()); }
  std::string csv() const { return trajectory_to_csv(result.trajectory); }
  std::string summary_json() const { return summary_to_json(result.summary, scenario, false).dump(2) + "\n"; }
};

struct LoadedScenario {
  Scenario scenario;
  std::unique_ptr<TrialModel> model;
  LoadedScenario(const std::string& path, const py::object& overrides)
      : scenario(load_scenario(path, overrides_of(overrides))),
        model(std::make_unique<TrialModel>(load_trial_model(scenario))) {}
};

PyResult run_scenario(const std::string& path, const py::object& overrides,
                      std::optional<std::uint64_t> seed) {
  LoadedScenario loaded(path, overrides);
  PyResult r;
  {
    py::gil_scoped_release release;
    r.result = run_trial(*loaded.model, loaded.scenario, seed.value_or(loaded.scenario.seed));
  }
  r.scenario = std::move(loaded.scenario);
  return r;
}

// A trial stepped from Python: one control period per step, with the scenario's controller
// or with pressure commands [MPa] from the caller.
class PyTrial {
 public:
  PyTrial(const std::string& path, const py::object& overrides,
          std::optional<std::uint64_t> seed)
      : loaded_(path, overrides),
        seed_(seed.value_or(loaded_.scenario.seed)),
        trial_(std::make_unique<SteppedTrial>(*loaded_.model, loaded_.scenario, seed_)),
        commands_pa_(loaded_.model->muscles.size()) {
    for (const BoundMuscle& b : loaded_.model->muscles) labels_.push_back(b.label);
  }

  void reset(std::optional<std::uint64_t> seed) {
    if (seed) seed_ = *seed;
    trial_->reset(seed_);
  }

  bool step(const std::optional<Array>& commands_mpa) {
    if (!commands_mpa) {
      py::gil_scoped_release release;
      return trial_->step(nullptr);
    }
    if (static_cast<std::size_t>(commands_mpa->size()) != commands_pa_.size()) {
      throw InputError("pressure_commands_MPa: " + std::to_string(commands_mpa->size()) +
                       " values for " + std::to_string(commands_pa_.size()) + " muscles (" +
                       join_labels() + ")");
    }
    for (std::size_t i = 0; i < commands_pa_.size(); ++i) {
      const double c = commands_mpa->data()[i];
      if (!std::isfinite(c)) throw InputError("pressure_commands_MPa: values must be finite");
      commands_pa_[i] = units::mpa_to_pa(c);
    }
    py::gil_scoped_release release;
    return trial_->step(&commands_pa_);
  }

  bool done() const { return trial_->done(); }

  py::dict observe() const {
    const TrialObservation o = trial_->observe();
    const bool hinge = loaded_.model->joint.hinge;
    py::dict out;
    out["time_s"] = o.time_s;
    out["steps"] = o.steps;
    out[hinge ? "angle_deg" : "position_mm"] =
        hinge ? units::rad_to_deg(o.joint_position) : units::m_to_mm(o.joint_position);
    out[hinge ? "angular_velocity_deg_s" : "velocity_mm_s"] =
        hinge ? units::rad_to_deg(o.joint_velocity) : units::m_to_mm(o.joint_velocity);
    out["muscles"] = labels_;
    out["pressure_MPa"] = scaled(o.pressure_pa, 1e-6);
    out["command_MPa"] = scaled(o.command_pa, 1e-6);
    out["force_N"] = scaled(o.force_n, 1.0);
    out["length_mm"] = scaled(o.length_m, 1e3);
    out["length_est_mm"] = scaled(o.length_est_m, 1e3);
    std::vector<bool> active(o.reflex_active.begin(), o.reflex_active.end());
    out["reflex_active"] = active;
    return out;
  }

  PyResult finish() {
    PyResult r;
    r.result = trial_->finish();
    r.scenario = loaded_.scenario;
    trial_->reset(seed_);   // ready to run again
    return r;
  }

  const std::vector<std::string>& muscles() const { return labels_; }

 private:
  static Array scaled(const std::vector<double>& v, double factor) {
    Array a(static_cast<py::ssize_t>(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) a.mutable_at(static_cast<py::ssize_t>(i)) = v[i] * factor;
    return a;
  }
  std::string join_labels() const {
    std::string s;
    for (const std::string& l : labels_) s += (s.empty() ? "" : ", ") + l;
    return s;
  }

  LoadedScenario loaded_;
  std::uint64_t seed_;
  std::unique_ptr<SteppedTrial> trial_;
  std::vector<double> commands_pa_;
  std::vector<std::string> labels_;
};

// ---- databases ---------------------------------------------------------------------------

// A sweep database's trials as {column: list}, numbers as floats, NULL as NaN (numbers) or
// None (text).
py::dict read_sweep(const std::string& path) {
  const ResultsDb db = ResultsDb::open_existing(path);
  const std::vector<std::string> columns = db.trial_columns();
  std::vector<std::vector<DbValue>> cells(columns.size());
  db.for_each_trial([&](const std::vector<DbValue>& row) {
    for (std::size_t c = 0; c < columns.size(); ++c) cells[c].push_back(row[c]);
  });
  py::dict out;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    bool text = false;
    for (const DbValue& v : cells[c]) text |= v.kind == DbValue::Kind::kText;
    if (text) {
      py::list values;
      for (const DbValue& v : cells[c]) {
        if (v.kind == DbValue::Kind::kText) values.append(v.text);
        else values.append(py::none());
      }
      out[py::str(columns[c])] = values;
    } else {
      Array values(static_cast<py::ssize_t>(cells[c].size()));
      for (std::size_t r = 0; r < cells[c].size(); ++r) {
        values.mutable_at(static_cast<py::ssize_t>(r)) =
            cells[c][r].kind == DbValue::Kind::kNumber ? cells[c][r].number : std::nan("");
      }
      out[py::str(columns[c])] = values;
    }
  }
  return out;
}

// ---- overhead measurement ------------------------------------------------------------------

// The plain C++ loops the Python calls are compared with (bench/python_overhead.py):
// seconds for Eq. (3)-(5) over the arrays, and per control period of a stepped trial.
double cxx_force_loop_s(const SpringModel& model, const Array& p_mpa, const Array& d_mm) {
  if (d_mm.size() != p_mpa.size()) throw InputError("the arrays must have the same length");
  const auto start = std::chrono::steady_clock::now();
  double sum = 0;
  for (py::ssize_t i = 0; i < p_mpa.size(); ++i) {
    sum += spring_force(model, units::mpa_to_pa(p_mpa.data()[i]), units::mm_to_m(d_mm.data()[i]));
  }
  volatile double sink = sum;   // the loop's result is used, so it is not optimised away
  (void)sink;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double cxx_step_s(const std::string& path, const py::object& overrides, int periods) {
  LoadedScenario loaded(path, overrides);
  SteppedTrial trial(*loaded.model, loaded.scenario, loaded.scenario.seed);
  py::gil_scoped_release release;
  const auto start = std::chrono::steady_clock::now();
  int done = 0;
  for (; done < periods && trial.step(); ++done) {
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
         std::max(done, 1);
}

}  // namespace

PYBIND11_MODULE(_pamsim, m) {
  m.doc() = "pamsim: PAM-driven arms with a stretch reflex (the compiled half)";
  m.attr("__version__") = PAMSIM_VERSION;
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

  py::class_<SpringModel>(m, "SpringModel",
                          "A fitted spring law, Eq. (2) with Eq. (3), (4) or (5) (paper units)")
      .def(py::init(&make_spring), py::arg("law"), py::arg("m_mm_per_MPa"), py::arg("h_mm"),
           py::arg("coefficients"))
      .def_static("from_file", [](const std::string& path) { return load_pam_params(path).spring; },
                  py::arg("path"), "The [spring] of a PAM parameter file (models/pams/*.toml)")
      .def_property_readonly("law", [](const SpringModel& s) { return std::string(to_string(s.law)); })
      .def_property_readonly("m_mm_per_MPa", [](const SpringModel& s) { return paper_units(s).m_mm_per_mpa; })
      .def_property_readonly("h_mm", [](const SpringModel& s) { return paper_units(s).h_mm; })
      .def_property_readonly("coefficients", [](const SpringModel& s) { return paper_units(s).coefficients; })
      .def("force_N",
           py::vectorize([](SpringModel& s, double p_mpa, double d_mm) {
             return spring_force(s, units::mpa_to_pa(p_mpa), units::mm_to_m(d_mm));
           }),
           py::arg("pressure_MPa"), py::arg("deformation_mm"),
           "Eq. (3)-(5): force [N]; d <= 0 is a slack line (0 N)")
      .def("natural_length_mm",
           py::vectorize([](SpringModel& s, double p_mpa) {
             return units::m_to_mm(natural_length(s, units::mpa_to_pa(p_mpa)));
           }),
           py::arg("pressure_MPa"), "Eq. (2): natural length [mm]")
      .def("deformation_mm",
           py::vectorize([](SpringModel& s, double p_mpa, double f_n) {
             return units::m_to_mm(invert_spring_model(s, units::mpa_to_pa(p_mpa), f_n).d_m);
           }),
           py::arg("pressure_MPa"), py::arg("force_N"),
           "The law inverted for d [mm] (Eq. (10)); 0 where the line is slack or no root")
      .def("inversion_status",
           py::vectorize([](SpringModel& s, double p_mpa, double f_n) {
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
        for (std::size_t k = 0; k < p.coefficients.size(); ++k) o << (k ? ", " : "") << p.coefficients[k];
        o << "])";
        return o.str();
      });

  m.def("fit",
        [](const std::string& law, const Array& p, const Array& d, const Array& f,
           const std::optional<Array>& l) {
          return fit_to_dict(fit_spring_model(parse_spring_law(law, "law"),
                                              rows_from_arrays(p, d, f, l), "fit"));
        },
        py::arg("law"), py::arg("pressure_MPa"), py::arg("deformation_mm"), py::arg("force_N"),
        py::arg("length_mm") = py::none(),
        "Least-squares fit of Eq. (2) and the law (seeds/000 Sec. II-B): {model, rmse_N, r2, points}");
  m.def("fit_csv",
        [](const std::string& law, const std::string& path) {
          return fit_to_dict(fit_spring_model(parse_spring_law(law, "law"), read_tensile_csv(path), path));
        },
        py::arg("law"), py::arg("path"), "The same fit from a tensile CSV (pamsim tensile's format)");
  m.def("read_tensile_csv", [](const std::string& path) { return rows_to_dict(read_tensile_csv(path)); },
        py::arg("path"));
  m.def("tensile_test",
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
        py::arg("law_or_plant"), py::arg("pressures_MPa") = std::vector<double>{0.4, 0.5, 0.6, 0.7, 0.8},
        py::arg("step_mm") = 2.5, py::arg("max_deformation_mm") = 20.0,
        py::arg("noise_pressure_MPa") = 0.0, py::arg("noise_force_N") = 0.0,
        py::arg("noise_length_mm") = 0.0, py::arg("seed") = 1,
        "The virtual static tensile test on a SpringModel or a plant file (models/pams/plant_*.toml)");

  py::class_<PyResult>(m, "Result", "A finished trial")
      .def_property_readonly("columns", &PyResult::columns)
      .def_property_readonly("values", &PyResult::values, "rows x columns, one row per control tick")
      .def_property_readonly("summary", &PyResult::summary)
      .def("to_csv", &PyResult::csv, "trajectory.csv as `pamsim run` writes it")
      .def("summary_json", &PyResult::summary_json, "summary.json as `pamsim run` writes it");
  m.def("run", &run_scenario, py::arg("scenario"), py::arg("overrides") = py::none(),
        py::arg("seed") = py::none(),
        "Runs a scenario file's trial (overrides: ['key=value', ...] or {key: value}); "
        "the GIL is released while it runs");

  py::class_<PyTrial>(m, "Trial", "A trial stepped one control period at a time")
      .def(py::init<const std::string&, const py::object&, std::optional<std::uint64_t>>(),
           py::arg("scenario"), py::arg("overrides") = py::none(), py::arg("seed") = py::none())
      .def("reset", &PyTrial::reset, py::arg("seed") = py::none())
      .def("step", &PyTrial::step, py::arg("pressure_commands_MPa") = py::none(),
           "One control period; commands (one per muscle) replace the scenario's controller. "
           "False once the trial has ended")
      .def("observe", &PyTrial::observe)
      .def_property_readonly("done", &PyTrial::done)
      .def_property_readonly("muscles", &PyTrial::muscles)
      .def("finish", &PyTrial::finish, "The trial's Result (ended early if not done); then reset");

  m.def("read_sweep", &read_sweep, py::arg("path"),
        "A sweep database's trials: {column: values} (numbers as float arrays)");
  m.def("read_tune",
        [](const std::string& path) {
          const TuneDb db = TuneDb::open_existing(path);
          py::list out;
          for (const TuneEvaluation& e : db.evaluations()) {
            py::dict d;
            d["evaluation"] = e.index;
            d["values"] = e.values;
            d["fitness"] = e.fitness;
            d["trials"] = e.trials;
            d["ok"] = e.ok;
            d["objectives"] = e.objectives;
            d["violation"] = e.violation;
            out.append(d);
          }
          return out;
        },
        py::arg("path"), "A tuning database's evaluations, in order");

  m.def("_cxx_force_loop_s", &cxx_force_loop_s);
  m.def("_cxx_step_s", &cxx_step_s, py::arg("scenario"), py::arg("overrides"), py::arg("periods"));
}
