// identify_outputs.cc: see identify_outputs.h.
#include "sim/optimize/identify_outputs.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/atomic_file.h"
#include "base/config_reader.h"
#include "base/file_changes.h"
#include "base/format.h"
#include "base/toml_file.h"
#include "sim/optimize/identify_residuals.h"
#include "sim/optimize/identify_uncertainty.h"
#include "sim/scenario/scenario_file.h"
#include "sim/io/staged_outputs.h"

namespace pamsim {
namespace {

std::string cell(double v) { return std::isfinite(v) ? format_shortest(v) : ""; }

// "key (0.97); key2 (-0.93)"
std::string correlated_text(const IdentifiedParameter& p) {
  std::string out;
  for (const auto& [key, r] : p.correlated) {
    out += (out.empty() ? "" : "; ") + key + " (" + format_value(std::round(r * 1000) / 1000) + ")";
  }
  return out;
}

// What a reader should make of a parameter's value (`distrust`: why the result as a whole is
// not to be trusted, distrust_reason; "": it is).
std::string verdict(const IdentifiedParameter& p, const std::string& distrust) {
  if (!p.identifiable) return "not determined by the recordings";
  std::string v = p.at_bound ? "at a bound of its range" : "identified";
  if (!p.correlated.empty()) v += ", strongly correlated";
  if (!distrust.empty()) v += "; not to be trusted: " + distrust;
  if (p.roughness > kRoughnessLimit) v += "; not to be trusted: the model's numerical error";
  return v;
}

// "[lo, hi]", or "-" where there is none
std::string interval_text(const IdentifiedParameter& p) {
  if (!std::isfinite(p.interval_lo)) return "-";
  return "[" + format_value(p.interval_lo) + ", " + format_value(p.interval_hi) + "]";
}

std::string value_or_dash(double v) { return std::isfinite(v) ? format_value(v) : "-"; }

// "95 %"
std::string level_text(const IdentifyResult& r) {
  return format_value(100.0 * r.interval_level) + " %";
}

std::string parameters_table(const IdentifyResult& r) {
  std::ostringstream md;
  const std::string distrust = distrust_reason(r);
  md << "| parameter | range | start | identified | standard error | " << level_text(r)
     << " interval | "
        "plain s.e. | verdict | correlated (> 0.9) |\n"
     << "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const IdentifiedParameter& p : r.parameters) {
    md << "| `" << p.parameter.key << "` | " << format_value(p.parameter.from) << " - "
       << format_value(p.parameter.to) << (p.parameter.log ? " (log)" : "") << " | "
       << value_or_dash(p.start) << " | " << format_value(p.value) << " | "
       << value_or_dash(p.std_error) << " | " << interval_text(p) << " | "
       << value_or_dash(p.std_error_plain) << " | " << verdict(p, distrust) << " | "
       << correlated_text(p) << " |\n";
  }
  return md.str();
}

// the warnings as a paragraph, or nothing
std::string warnings_text(const IdentifyDefinition& def, const IdentifyResult& r) {
  std::string out;
  for (const std::string& line : identify_warnings(def, r)) out += "**Warning**: " + line + ".\n";
  return out.empty() ? out : out + "\n";
}

std::string fits_table(const IdentifyResult& r) {
  std::ostringstream md;
  md << "| recording | channel | role | samples | RMSE before | RMSE after | noise floor | "
        "RMSE / noise | whiteness p | explained |\n"
     << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const ChannelFit& f : r.fits) {
    md << "| " << f.recording << " | " << f.channel << " | " << (f.held_out ? "held out" : "fitted")
       << " | " << f.samples << " | " << format_value(f.rmse_before) << " | "
       << format_value(f.rmse_after) << " | " << value_or_dash(f.noise_floor) << " | "
       << value_or_dash(f.rmse_after / f.noise_floor) << " | " << value_or_dash(f.whiteness_p)
       << " | "
       << (!f.judged     ? "unknown"
           : f.explained ? "yes"
                         : "no")
       << " |\n";
  }
  return md.str();
}

// The identified fields of one parameter file: `prefix` "muscles.agonist.plant." or
// "pneumatics.", as a table of the file's layout; empty if none is a parameter.
toml::table identified_fields(const IdentifyResult& r, const std::string& prefix) {
  toml::table fields;
  for (const IdentifiedParameter& p : r.parameters) {
    if (p.parameter.key.rfind(prefix, 0) != 0) continue;
    const std::vector<std::string> parts = split_key(p.parameter.key.substr(prefix.size()));
    toml::table* at = &fields;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      if (!at->get(parts[i])) at->insert(parts[i], toml::table{});
      at = at->get(parts[i])->as_table();
    }
    at->insert_or_assign(parts.back(), p.value);
  }
  return fields;
}

// `file` with `fields` written over it, as TOML under `header` (the file's own comments are
// in the file itself: TOML text cannot keep them through a rewrite).
void write_identified_file(const std::string& out, const std::string& file,
                           const toml::table& fields, const std::string& header) {
  toml::table root = parse_toml_file(file);
  write_changes(root, fields, "");
  write_file_atomically(out, header + "# (identified from " + file +
                                 "; its comments say where "
                                 "its other values come from)\n" +
                                 toml_text(root));
}

// plant_<muscle>.toml and pneumatics.toml with the identified fields.
void write_identified_files(const IdentifyDefinition& def, const IdentifyResult& r,
                            const StagedOutputs& out, const std::string& header) {
  const Scenario sc = load_scenario_text(def.base_text, def.base_path, def.overrides);
  for (const MuscleSpec& m : sc.muscles) {
    const toml::table fields = identified_fields(r, "muscles." + m.actuator + ".plant.");
    if (!fields.empty() && !m.plant_file.empty()) {
      write_identified_file(out.path("plant_" + m.actuator + ".toml"), m.plant_file, fields,
                            header);
    }
  }
  const toml::table fields = identified_fields(r, "pneumatics.");
  if (!fields.empty())
    write_identified_file(out.path("pneumatics.toml"), sc.pneumatics_file, fields, header);
}

}  // namespace

std::vector<std::string> identify_warnings(const IdentifyDefinition& def, const IdentifyResult& r) {
  std::vector<std::string> out = start_warnings(def, r);
  for (const std::string& line : unexplained_channels(r)) {
    out.push_back(line +
                  (r.parameters.empty() ? "" : "; the standard errors are not to be trusted"));
  }
  for (const ChannelFit& f : r.fits) {
    if (f.held_out || f.judged) continue;
    out.push_back("recording " + f.recording + " (" + f.channel + ") has too few samples to " +
                  "estimate its noise: whether the model explains it is unknown (give noise = { " +
                  f.channel + " = ... })");
  }
  if (r.polish_failed) {
    out.push_back("the polish failed; the global search's best point stands (" + r.polish_summary +
                  ")");
  } else if (!r.polish_converged && def.polish_iterations > 0) {
    out.push_back("the polish stopped after " + std::to_string(r.polish_iterations) +
                  " iterations without converging (polish_iterations = " +
                  std::to_string(def.polish_iterations) + "): the point may not be the minimum");
  }
  for (const IdentifiedParameter& p : r.parameters) {
    if (!(p.roughness > kRoughnessLimit) || !p.identifiable) continue;
    out.push_back(p.parameter.key +
                  ": the model's prediction is rough along it (second "
                  "differences " +
                  format_value(std::round(p.roughness * 100) / 100) +
                  " x the first at the difference step): numerical error, such as the chamber "
                  "solver's (pneumatics.solver.relative_tolerance), an instrument's quantiser "
                  "(sensors.*_adc_bits) or a contact starting on a step "
                  "(sim.contact_soft_onset_mm), makes its standard error too small; tighten the "
                  "tolerance, make the instruments ideal or soften the contacts' start in "
                  "`overrides`");
  }
  for (const IdentifiedParameter& p : r.parameters) {
    if (!p.at_bound || !p.identifiable) continue;  // (undetermined: said so, wherever it sits)
    out.push_back(p.parameter.key + " = " + format_value(p.value) + " sits at a bound of its " +
                  "range [" + format_value(p.parameter.from) + ", " + format_value(p.parameter.to) +
                  "]: widen it, or the value is not identified");
  }
  return out;
}

std::string identify_parameters_csv(const IdentifyResult& r) {
  std::string out =
      "key,from,to,scale,start,identified,std_error,at_bound,identifiable,"
      "correlated_with,std_error_plain,interval_lo,interval_hi,verdict,"
      "difference_roughness\n";
  const std::string distrust = distrust_reason(r);
  for (const IdentifiedParameter& p : r.parameters) {
    out += p.parameter.key + "," + cell(p.parameter.from) + "," + cell(p.parameter.to) + "," +
           (p.parameter.log ? "log" : "linear") + "," + cell(p.start) + "," + cell(p.value) + "," +
           cell(p.std_error) + "," + (p.at_bound ? "1" : "0") + "," + (p.identifiable ? "1" : "0") +
           "," + correlated_text(p) + "," + cell(p.std_error_plain) + "," + cell(p.interval_lo) +
           "," + cell(p.interval_hi) + ",\"" + verdict(p, distrust) + "\"," + cell(p.roughness) +
           "\n";
  }
  return out;
}

std::string identify_fits_csv(const IdentifyResult& r) {
  std::string out =
      "recording,channel,held_out,samples,rmse_before,rmse_after,noise_floor,"
      "whiteness_p,explained\n";
  for (const ChannelFit& f : r.fits) {
    out += f.recording + "," + f.channel + "," + (f.held_out ? "1" : "0") + "," +
           std::to_string(f.samples) + "," + cell(f.rmse_before) + "," + cell(f.rmse_after) + "," +
           cell(f.noise_floor) + "," + cell(f.whiteness_p) + "," +
           (!f.judged     ? ""
            : f.explained ? "1"
                          : "0") +
           "\n";
  }
  return out;
}

// No parameter: the model as the file gives it, against the recordings.
std::string check_markdown(const IdentifyDefinition& def, const IdentifyResult& r) {
  std::ostringstream md;
  md << "# The model held against the recordings: " << def.file << "\n\n"
     << "Base scenario `" << def.base_path << "`; " << def.recordings.size() << " recordings, "
     << r.residuals << " residuals. No parameter is fitted: the scenario as the file gives it "
     << "ran each recording's conditions once, at a cost of " << format_value(r.cost_final)
     << " (the sum of squared residuals in noise floors) in " << format_value(r.check_s)
     << " s. A channel is explained when its RMS error is within explained_noise_factor = "
     << format_value(def.explained_noise_factor) << " noise floors.\n\n"
     << warnings_text(def, r)
     << "## Recordings: the model's RMSE, in each channel's unit (before = after)\n\n"
     << fits_table(r);
  return md.str();
}

std::string identify_markdown(const IdentifyDefinition& def, const IdentifyResult& r) {
  if (def.parameters.empty()) return check_markdown(def, r);
  std::ostringstream md;
  md << "# Identification: " << def.file << "\n\n"
     << "Base scenario `" << def.base_path << "`; " << def.recordings.size() << " recordings, "
     << r.residuals << " residuals fitted. CMA-ES (" << global_search_text(def, r)
     << ") reached a cost of " << format_value(r.cost_global) << " in " << format_value(r.global_s)
     << " s; the Levenberg-Marquardt polish " << format_value(r.cost_final) << " in "
     << format_value(r.polish_s) << " s (" << r.polish_summary << "). " << r.simulated
     << " points simulated, " << r.cached << " answered from the database.\n\n"
     << warnings_text(def, r) << "## Parameters\n\n"
     << parameters_table(r) << "\n"
     << "Standard errors and " << level_text(r)
     << " intervals: the sandwich (HAC) covariance, which holds for "
        "residuals correlated in time, as a recording's are (Newey-West with Andrews' "
        "bandwidth for each recording's channel, here up to "
     << r.hac_lags
     << " lags; the "
        "lag-1 autocorrelation pooled over them "
     << format_value(std::round(r.residual_lag1 * 1000) / 1000)
     << "; prewhitened); "
        "\"plain s.e.\": s^2 (J^T J)^-1, which assumes independent residuals. \"not "
        "determined\": the recordings do not move with it (its Jacobian column vanishes) or "
        "J^T J is singular. The costs are sums of squared residuals (Ceres's own report "
        "halves them).\n\n"
     << "## Recordings: RMSE before (the base scenario) and after, in each channel's unit\n\n"
     << fits_table(r);
  return md.str();
}

void write_identify_outputs(const IdentifyDefinition& def, const IdentifyResult& r,
                            const StagedOutputs& out, bool plots) {
  std::vector<double> values;
  for (const IdentifiedParameter& p : r.parameters) values.push_back(p.value);
  std::string header = "# pamsim identify: " + def.file + ", from the recordings";
  for (const IdentifyRecording& rec : def.recordings) {
    if (!rec.held_out) header += " " + rec.data.path;
  }
  for (const IdentifyTensile& t : def.tensile) header += " " + t.file;
  header += "\n";
  write_file_atomically(out.path("identified.toml"),
                        resolved_scenario_toml(def.base_text, def.base_path,
                                               def.overrides_at(values), out.dir(), header));
  write_file_atomically(out.path("identify.csv"), identify_parameters_csv(r));
  write_file_atomically(out.path("identify_fits.csv"), identify_fits_csv(r));
  write_file_atomically(out.path("identify.md"), identify_markdown(def, r));
  write_identified_files(def, r, out, header);
  if (!plots) return;
  for (const IdentifyRecording& rec : def.recordings) {
    std::vector<const ChannelFit*> fits;
    for (const ChannelFit& f : r.fits) {
      if (f.recording == rec.name) fits.push_back(&f);
    }
    write_recording_plot(out.path("recording_" + rec.name + ".png"), rec, fits,
                         !def.parameters.empty());
  }
}

}  // namespace pamsim
