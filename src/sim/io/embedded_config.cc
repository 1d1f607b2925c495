// embedded_config.cc: the embedded controller's configuration as JSON and as C, from one
// list of its fields (for_each_field).
#include "sim/io/embedded_config.h"

#include <cinttypes>
#include <cstdio>
#include <sstream>

#include "base/input_error.h"

namespace pamsim {
namespace embedded_config_fields {

// every field of a window, a reflex, a muscle and the whole configuration, by its JSON
// pointer path; `f(path, field)` for an int32_t, a bool or a pamctl_real
template <class Window, class F>
void window_fields(const std::string& at, Window& w, F&& f) {
  f(at + "/window_ticks", w.window_ticks);
  f(at + "/refractory_ticks", w.refractory_ticks);
  f(at + "/arm_after_s", w.arm_after_s);
  f(at + "/arm_tolerance_s", w.arm_tolerance_s);
}

template <class Reflex, class F>
void reflex_fields(Reflex& r, F&& f) {
  f("/reflex/enabled", r.enabled);
  f("/reflex/stretch", r.stretch);
  f("/reflex/tension", r.tension);
  f("/reflex/sensor", r.sensor);
  f("/reflex/min_tension_n", r.min_tension_n);
  f("/reflex/reciprocal_trigger_inhibition", r.reciprocal_trigger_inhibition);
  f("/reflex/excite_antagonist", r.excite_antagonist);
  f("/reflex/ia/v_thr_m_s", r.ia.v_thr_m_s);
  f("/reflex/ia/k_pa_s_per_m", r.ia.k_pa_s_per_m);
  f("/reflex/ia/mode", r.ia.mode);
  window_fields("/reflex/ia/window", r.ia.window, f);
  f("/reflex/ib/f_thr_n", r.ib.f_thr_n);
  f("/reflex/ib/df_thr_n_s", r.ib.df_thr_n_s);
  f("/reflex/ib/k_pa_per_n", r.ib.k_pa_per_n);
  f("/reflex/ib/mode", r.ib.mode);
  f("/reflex/ib/rate_alpha", r.ib.rate_alpha);
  window_fields("/reflex/ib/window", r.ib.window, f);
}

template <class Muscle, class F>
void muscle_fields(const std::string& at, Muscle& m, F&& f) {
  f(at + "/spring/law", m.spring.law);
  f(at + "/spring/m_m_per_pa", m.spring.m_m_per_pa);
  f(at + "/spring/h_m", m.spring.h_m);
  for (int k = 0; k < 6; ++k) f(at + "/spring/coef/" + std::to_string(k), m.spring.coef[k]);
  f(at + "/gauge_v_base_v", m.gauge_v_base_v);
  f(at + "/gauge_q_v_per_n", m.gauge_q_v_per_n);
  f(at + "/pressure_zero_v", m.pressure_zero_v);
  f(at + "/pressure_v_per_mpa", m.pressure_v_per_mpa);
  f(at + "/pressure_min_v", m.pressure_min_v);
  f(at + "/pressure_max_v", m.pressure_max_v);
  f(at + "/gauge_min_v", m.gauge_min_v);
  f(at + "/gauge_max_v", m.gauge_max_v);
}

// the fields of the first `muscles` muscles (the rest are unused)
template <class Config, class F>
void for_each_field(Config& c, int muscles, F&& f) {
  f("/muscle_count", c.muscle_count);
  f("/kind", c.kind);
  f("/control_period_s", c.control_period_s);
  f("/pressure_alpha", c.pressure_alpha);
  f("/velocity_alpha", c.velocity_alpha);
  f("/p_max_pa", c.p_max_pa);
  reflex_fields(c.reflex, f);
  for (int j = 0; j < muscles; ++j) {
    f("/partner/" + std::to_string(j), c.partner[j]);
    muscle_fields("/muscles/" + std::to_string(j), c.muscles[j], f);
  }
}

// "/muscles/0/spring/coef/3" as C: "muscles[0].spring.coef[3]"
std::string c_path(const std::string& pointer) {
  std::string out;
  std::istringstream parts(pointer.substr(1));
  for (std::string part; std::getline(parts, part, '/');) {
    const bool index = !part.empty() && part.find_first_not_of("0123456789") == std::string::npos;
    out += index ? "[" + part + "]" : (out.empty() ? "" : ".") + part;
  }
  return out;
}

std::string c_value(std::int32_t v) { return std::to_string(v); }
std::string c_value(bool v) { return v ? "true" : "false"; }
std::string c_value(double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%a", v);  // exact
  char decimal[40];
  std::snprintf(decimal, sizeof(decimal), "%.17g", v);
  return std::string("R(") + buf + ") /* " + decimal + " */";
}

// a JSON value as the field's type, or an InputError naming the file and the field
void read_value(const nlohmann::json& v, const std::string& where, std::int32_t* out) {
  if (!v.is_number_integer()) throw InputError(where + " must be an integer");
  *out = v.get<std::int32_t>();
}
void read_value(const nlohmann::json& v, const std::string& where, bool* out) {
  if (!v.is_boolean()) throw InputError(where + " must be true or false");
  *out = v.get<bool>();
}
void read_value(const nlohmann::json& v, const std::string& where, double* out) {
  if (!v.is_number()) throw InputError(where + " must be a number");
  *out = v.get<double>();
}

}  // namespace embedded_config_fields

using namespace embedded_config_fields;

nlohmann::json embedded_config_json(const pamctl_config& config,
                                    const std::vector<std::string>& muscles) {
  nlohmann::json j;
  j["pamctl_version"] = PAMCTL_VERSION;
  j["muscle_names"] = muscles;
  for_each_field(config, config.muscle_count, [&j](const std::string& path, const auto& field) {
    j[nlohmann::json::json_pointer(path)] = field;
  });
  return j;
}

pamctl_config embedded_config_from_json(const nlohmann::json& j, const std::string& path,
                                        std::vector<std::string>* muscles) {
  pamctl_config config{};
  const auto names = j.find("muscle_names");
  if (!j.is_object() || names == j.end() || !names->is_array()) {
    throw InputError(path + ": muscle_names must be a list of the muscles' names");
  }
  muscles->clear();
  for (const nlohmann::json& name : *names) {
    if (!name.is_string()) throw InputError(path + ": muscle_names must be a list of names");
    muscles->push_back(name.get<std::string>());
  }
  if (muscles->size() > PAMCTL_MAX_MUSCLES) {
    throw InputError(path + ": muscle_names: at most " + std::to_string(PAMCTL_MAX_MUSCLES));
  }
  const int n = static_cast<int>(muscles->size());
  for_each_field(config, n, [&](const std::string& field, auto& value) {
    const nlohmann::json::json_pointer pointer(field);
    if (!j.contains(pointer)) throw InputError(path + ": " + c_path(field) + " is missing");
    read_value(j.at(pointer), path + ": " + c_path(field), &value);
  });
  for (int k = n; k < PAMCTL_MAX_MUSCLES; ++k) config.partner[k] = -1;
  if (config.muscle_count != n) {
    throw InputError(path + ": muscle_count is " + std::to_string(config.muscle_count) +
                     ", muscle_names names " + std::to_string(n));
  }
  const std::int32_t code = pamctl_check_config(&config);
  if (code != 0) throw InputError(path + ": " + pamctl_config_error(code));
  return config;
}

std::string embedded_config_c(const pamctl_config& config, const std::vector<std::string>& muscles,
                              const std::string& comment) {
  std::ostringstream c;
  std::string head = comment + "\n * Do not edit: export again. Muscles, in order:";
  for (std::size_t j = 0; j < muscles.size(); ++j)
    head += " " + std::to_string(j) + " " + muscles[j];
  // a "*/" in a path, an override or a name would end the comment early
  for (std::size_t at = head.find("*/"); at != std::string::npos; at = head.find("*/", at)) {
    head.replace(at, 2, "* /");
  }
  c << "/* pamctl_export.c: the controller's configuration, generated by pamsim. " << head
    << ". */\n#include \"pamctl_export.h\"\n\n"
    << "#if PAMCTL_MAX_MUSCLES < " << config.muscle_count << "\n#error \"this controller has "
    << config.muscle_count << " muscles: build with PAMCTL_MAX_MUSCLES >= " << config.muscle_count
    << "\"\n#endif\n\n"
       "#ifdef PAMCTL_FLOAT\n#define R(x) x##f\n#else\n#define R(x) x\n#endif\n\n"
       "void pamctl_export_config(pamctl_config* config) {\n"
       "  /* the muscles this controller does not have: unpaired, unused */\n"
    << "  for (int j = " << config.muscle_count
    << "; j < PAMCTL_MAX_MUSCLES; ++j) "
       "config->partner[j] = -1;\n";
  for_each_field(config, config.muscle_count, [&c](const std::string& path, const auto& field) {
    c << "  config->" << c_path(path) << " = " << c_value(field) << ";\n";
  });
  c << "}\n";
  return c.str();
}

}  // namespace pamsim
