// pamsim_module.cc: the compiled half of the Python package `pamsim` (pybind11), a thin
// layer over the C++ libraries. This file: the module itself, whole trials (`run`), trials
// stepped by a Python controller (`Trial`), sweep and tuning databases, and the loops the
// overhead benchmark compares with; the spring laws, fits and tensile test are bound in
// bind_muscle.cc. Units at this boundary are the papers' (MPa, mm, N) and are named in every
// argument and key; the C++ inside is SI. InputError becomes pamsim.InputError, a ValueError
// with the same one-line message. The GIL is released while trials run.
// python/pamsim/__init__.py adds the pure-Python conveniences (pandas frames).
#include "bindings.h"

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

using pamsim_python::Array;
using pamsim_python::FrameRenderer;

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
        text = py::repr(value).cast<std::string>();  // a TOML string ('...' is literal)
      } else if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) {
        text = py::repr(value).cast<std::string>();  // shortest round trip
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
    py::array_t<double> a(
        {static_cast<py::ssize_t>(t.rows()), static_cast<py::ssize_t>(t.columns.size())});
    if (!t.values.empty()) {
      std::memcpy(a.mutable_data(), t.values.data(), t.values.size() * sizeof(double));
    }
    return a;
  }
  py::dict summary() const { return summary_to_dict(result.summary, summary_json()); }
  std::string csv() const { return trajectory_to_csv(result.trajectory); }
  std::string summary_json() const {
    return summary_to_json(result.summary, scenario, false).dump(2) + "\n";
  }
};

struct LoadedScenario {
  Scenario scenario;
  std::unique_ptr<TrialModel> model;
  LoadedScenario(const std::string& path, const py::object& overrides)
      : scenario(load_scenario(path, overrides_of(overrides))),
        model(std::make_unique<TrialModel>(load_trial_model(scenario))) {}
};

// a tuning database's evaluations as a list of dicts
py::list read_tune(const std::string& path) {
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
}

// trial_channel_table() as a list of dicts
py::list channel_rows() {
  py::list out;
  for (const ChannelRow& r : trial_channel_table()) {
    py::dict d;
    d["name"] = r.name;
    d["unit"] = r.unit;
    d["to_si"] = r.to_si;
    d["divisor"] = r.divisor;
    d["meaning"] = r.meaning;
    d["source"] = r.source;
    d["per_muscle"] = r.per_muscle() || r.controller_channels;
    d["measured"] = r.measured;
    d["quantity"] = r.quantity();
    out.append(d);
  }
  return out;
}

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
  PyTrial(const std::string& path, const py::object& overrides, std::optional<std::uint64_t> seed)
      : loaded_(path, overrides),
        seed_(seed.value_or(loaded_.scenario.seed)),
        trial_(std::make_unique<SteppedTrial>(*loaded_.model, loaded_.scenario, seed_)),
        commands_pa_(loaded_.model->muscles.size()),
        layout_(trial_log_layout(*loaded_.model, loaded_.scenario)) {
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

  // the valve's command range's top [MPa] (the scenario's valve.command_max_MPa, else its
  // pneumatics file's): the largest command a muscle's valve acts on
  double command_max_mpa() const {
    return units::pa_to_mpa(loaded_.scenario.pneumatics.command_max_gauge_pa);
  }

  // The state now as the log's columns name it (trial_channels.h), each quantity by its name
  // without the muscle ("p_meas_MPa": one value per muscle; "angle_deg": one value), in the
  // log's units and bits; "measured" holds what a controller on the robot sees.
  py::dict observe() const {
    const TrialObservation o = trial_->observe();
    py::dict out, measured;
    out["steps"] = o.steps;
    out["muscles"] = labels_;
    for (const ObservedQuantity& q : observed_quantities(layout_, o)) {
      out[q.name.c_str()] = q.per_muscle ? py::object(as_array(q.values)) : py::float_(q.values[0]);
      if (q.measured) measured[q.name.c_str()] = q.values;
    }
    // the names this module gave these before the channel table
    out["pressure_MPa"] = out["p_MPa"];
    out["command_MPa"] = out["p_cmd_MPa"];
    if (out.contains("omega_deg_s")) out["angular_velocity_deg_s"] = out["omega_deg_s"];
    out["reflex_active"] = windows_open(o, "reflex_");
    out["measured"] = measured;
    return out;
  }

  PyResult finish() {
    PyResult r;
    r.result = trial_->finish();
    r.scenario = loaded_.scenario;
    trial_->reset(seed_);  // ready to run again
    return r;
  }

  const std::vector<std::string>& muscles() const { return labels_; }

  py::array_t<std::uint8_t> render(int width, int height, const std::string& camera,
                                   const std::string& quality, const std::string& backend) {
    return frames_.render(*loaded_.model, loaded_.scenario, *trial_, width, height, camera, quality,
                          backend);
  }

 private:
  // whether each muscle's window in the controller's channel `name` is open (all closed
  // when its kind has no such channel): a reflex's "reflex_", its stretch (Ia) windows
  static std::vector<bool> windows_open(const TrialObservation& o, const std::string& name) {
    std::vector<bool> open(o.pressure_pa.size(), false);
    for (std::size_t k = 0; k < o.channel_names.size(); ++k) {
      if (o.channel_names[k] != name) continue;
      for (std::size_t i = 0; i < open.size(); ++i) open[i] = o.channels[k][i] != 0.0;
    }
    return open;
  }

  static Array as_array(const std::vector<double>& v) {
    Array a(static_cast<py::ssize_t>(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) a.mutable_at(static_cast<py::ssize_t>(i)) = v[i];
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
  LogLayout layout_;
  std::vector<std::string> labels_;
  FrameRenderer frames_;
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
        if (v.kind == DbValue::Kind::kText)
          values.append(v.text);
        else
          values.append(py::none());
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
  volatile double sink = sum;  // the loop's result is used, so it is not optimised away
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

// clang-format off
PYBIND11_MODULE(_pamsim, m) {
  m.doc() = "pamsim: PAM-driven arms with a stretch reflex (the compiled half)";
  m.attr("__version__") = PAMSIM_VERSION;
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  pamsim_python::bind_muscle(m);


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
      .def_property_readonly("command_max_MPa", &PyTrial::command_max_mpa,
                             "The valve's largest command [MPa] (valve.command_max_MPa)")
      .def("finish", &PyTrial::finish, "The trial's Result (ended early if not done); then reset")
      .def("render", &PyTrial::render, py::arg("width") = 640, py::arg("height") = 480,
           py::arg("camera") = "side", py::arg("quality") = "fast", py::arg("backend") = "",
           "The state now as an RGB frame, a (height, width, 3) uint8 array (pamsim render's "
           "scene without its overlays)");

  m.def("channels", &channel_rows,
        "trajectory.csv's channels as rows: name ('{m}': a muscle's label), unit, to_si, "
        "divisor (a column's value is SI * divisor / to_si), meaning, source, per_muscle, "
        "measured (what a controller on the robot sees), quantity (the observation's name)");
  m.def("read_sweep", &read_sweep, py::arg("path"),
        "A sweep database's trials: {column: values} (numbers as float arrays)");
  m.def("read_tune", &read_tune, py::arg("path"), "A tuning database's evaluations, in order");

  m.def("_cxx_force_loop_s", &cxx_force_loop_s);
  m.def("_cxx_step_s", &cxx_step_s, py::arg("scenario"), py::arg("overrides"), py::arg("periods"));
}
// clang-format on
