// reflex_keys.cc: the rows of reflex.* and reflex.ib.* (see reflex_keys.h).
#include "reflex/reflex_keys.h"

#include <limits>

#include "base/format.h"
#include "base/units.h"

namespace pamsim {
namespace {

// reflex.mode / reflex.ib.mode
ChoiceRow mode_row(ReflexMode* mode, const std::string& key, const std::string& doc) {
  return {"mode",
          {"follow", "latch"},
          doc,
          [mode, key](const std::string& name) { *mode = parse_reflex_mode(name, key); },
          [mode] { return std::string(to_string(*mode)); }};
}

// the window every reflex shares (ReflexWindow, stretch_reflex.h): the duration is also
// checked against the control period by validate()
std::vector<NumberRow> window_rows(double* duration_s, double* refractory_s, double* arm_after_s,
                                   const std::string& what) {
  return {{"duration_s", "s", 1.0, kPositiveRange, what + " window (at least one control period)",
           duration_s},
          {"refractory_s", "s", 1.0, kNonNegativeRange,
           "no retrigger this long after a window ends (0: off)", refractory_s},
          {"arm_after_s", "s", 1.0, kNonNegativeRange, "no trigger before this time (0: off)",
           arm_after_s}};
}

}  // namespace

KeyTable stretch_reflex_key_table(ReflexConfig* reflex, double* velocity_lowpass_hz, bool stretch) {
  ReflexConfig& r = *reflex;
  KeyTable t{"reflex", {}, {}, {}};
  t.trial_only = true;  // the controller's, not the simulated model's
  t.bools.push_back(
      {"enabled", "the reflex may trigger (false: the passive arm, same sensing)", &r.enabled});
  if (!stretch) return t;
  t.bools.push_back({"reciprocal_trigger_inhibition",
                     "a triggered muscle inhibits its antagonist's trigger",
                     &r.reciprocal_trigger_inhibition});
  t.choices = {{"sensor",
                {"model", "fiber"},
                "the stretch velocity from the spring model (Eq. (9)-(11)) or a fiber sensor; sets "
                "Table II's v_thr and k for it",
                [&r](const std::string& name) {
                  const ReflexConfig table = table_ii_reflex_config(parse_reflex_sensor(name));
                  r.sensor = table.sensor;
                  r.v_thr_m_s = table.v_thr_m_s;
                  r.k_pa_s_per_m = table.k_pa_s_per_m;
                },
                [&r] { return std::string(to_string(r.sensor)); }},
               mode_row(&r.mode, "reflex.mode",
                        "the command follows the velocity, or holds its trigger value")};
  const ReflexConfig model = table_ii_reflex_config(ReflexSensor::kModel);
  const ReflexConfig fiber = table_ii_reflex_config(ReflexSensor::kFiber);
  NumberRow v_thr{
      "v_thr_mm_s", "mm/s", units::kMPerMm, kPositiveRange, "the trigger threshold V_thr, Eq. (12)",
      &r.v_thr_m_s};
  NumberRow k{"k_MPa_s_per_mm",
              "MPa s/mm",
              units::kPaPerMPa / units::kMPerMm,
              kNonNegativeRange,
              "the reflex gain k, Eq. (13)-(14)",
              &r.k_pa_s_per_m};
  v_thr.fallback_doc = "(Table II: " + format_number(from_si(v_thr, model.v_thr_m_s)) + " model, " +
                       format_number(from_si(v_thr, fiber.v_thr_m_s)) + " fiber)";
  k.fallback_doc = "(Table II: 1/800 model, 1/300 fiber)";
  t.numbers = {v_thr, k};
  for (NumberRow& row : window_rows(&r.duration_s, &r.refractory_s, &r.arm_after_s, "the reflex")) {
    t.numbers.push_back(row);
  }
  t.numbers.push_back({"lowpass_hz", "Hz", 1.0, kNonNegativeRange,
                       "low-pass on the estimated velocity (0: off; at most sim.control_hz / 2)",
                       velocity_lowpass_hz});
  t.numbers.push_back({"min_tension_N", "N", 1.0, kNonNegativeRange,
                       "trigger only while the gauge reads at least this tension",
                       &r.min_tension_n});
  return t;
}

KeyTable tension_reflex_key_table(TensionReflexParams* ib) {
  TensionReflexParams& p = *ib;
  KeyTable t{"reflex.ib", {}, {}, {}};
  t.trial_only = true;
  t.bools.push_back({"excite_antagonist", "the output also raises the pair partner's command",
                     &p.excite_antagonist});
  t.choices.push_back(mode_row(&p.mode, "reflex.ib.mode",
                               "the output follows the tension, or holds its trigger value"));
  NumberRow f_thr{"f_thr_N",
                  "N",
                  1.0,
                  kPositiveRange,
                  "the tension (Ib) reflex's threshold on the gauge's tension",
                  &p.f_thr_N};
  NumberRow k{"k_MPa_per_N",
              "MPa/N",
              units::kPaPerMPa,
              kNonNegativeRange,
              "its gain: dp = k f, off its own muscle's command",
              &p.k_pa_per_n};
  f_thr.required = k.required = true;
  t.numbers = {f_thr,
               k,
               {"df_thr_N_s", "N/s", 1.0, kNonNegativeRange,
                "it also triggers when the tension's rate exceeds this (0: off)", &p.df_thr_N_s}};
  for (NumberRow& row : window_rows(&p.duration_s, &p.refractory_s, &p.arm_after_s, "its")) {
    t.numbers.push_back(row);
  }
  t.numbers.push_back({"rate_lowpass_hz", "Hz", 1.0, kNonNegativeRange,
                       "low-pass on the tension's rate (0: off; at most sim.control_hz / 2)",
                       &p.rate_lowpass_hz});
  return t;
}

}  // namespace pamsim
