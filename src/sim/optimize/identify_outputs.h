// identify_outputs.h: what `pamsim identify` writes into its output folder (the identified
// scenario and plant files, the parameter and fit tables, the figures; each listed at
// write_identify_outputs), and the warnings a user must not miss.
#pragma once

#include <string>
#include <vector>

#include "sim/io/html_page.h"
#include "sim/optimize/identify.h"

namespace pamsim {

class StagedOutputs;

inline const std::vector<std::string> kIdentifyOutputs = {
    "identified.toml", "identify.csv",    "identify_fits.csv", "identify.md",
    "recording_*.png", "recording_*.svg", "recording_*.pdf",   "plant_*.toml",
    "pneumatics.toml", "plan.csv",        "plan.md",           kReportPageFile};

// A polish start that ends more than kLocalMinimumMargin (identify.h) above the result's cost
// ended in a local minimum (or stopped short of one); one that ends within it but elsewhere
// (not at the same end, same_end in identify.h) is an equal minimum: the recordings do not
// single out one. One line each (none for one start), and one when fewer starts ran than
// `starts` asks, with the reason.
std::vector<std::string> start_warnings(const IdentifyDefinition& def, const IdentifyResult& r);

// The global search as it ran: "6 generations of 8"; with runs or a stall stop, each run's
// ("2 runs: 9 generations of 8, 12 of 16, stalled after 3 without progress").
std::string global_search_text(const IdentifyDefinition& def, const IdentifyResult& r);

// Whether the runs' polished ends agree (SearchSettled, identify.h): kNotChecked with fewer
// than two runs.
SearchSettled judge_settled(const IdentifyDefinition& def, const IdentifyResult& r);

// What a user must not miss, one line each: a fitted channel the model does not explain, a
// polish that did not converge or failed, a parameter at a bound of its range.
std::vector<std::string> identify_warnings(const IdentifyDefinition& def,
                                           const IdentifyResult& result);

std::string identify_parameters_csv(const IdentifyResult& result);
std::string identify_fits_csv(const IdentifyResult& result);
std::string identify_markdown(const IdentifyDefinition& def, const IdentifyResult& result);

// The outputs:
//   identified.toml    the base scenario with the identified values (plus the file's
//                      overrides), ready for `pamsim run`; its header names the recordings
//   identify.csv       per parameter: key, bounds, start (the model's value), identified
//                      value, standard error (HAC, identify_uncertainty.h), whether
//                      it hit a bound, whether the recordings determine it, the parameters
//                      it correlates with above 0.9, the plain s^2 (J^T J)^-1 error and the
//                      95 % interval
//   identify_fits.csv  per recording and channel: fitted or held out, samples, RMSE before
//                      (the base scenario as it stands) and after, in the channel's unit, the
//                      channel's noise floor, the residuals' Ljung-Box p-value, explained (1 or 0;
//                      empty: too few samples to estimate the floor, so unknown)
//   identify.md        both tables, the search's cost and time, and a warning for each
//                      fitted channel the model does not explain
//   recording_<name>.png  each recording's channels: recorded, before and after (plots on;
//                      with no parameter, recorded and the model)
//   plant_<muscle>.toml   for each muscle with a plant field among the parameters: its plant
//                      file with the identified fields, a comment naming the recordings
//   pneumatics.toml    the same for the pneumatics file's fields (pneumatics.<table>.<field>)
//   plan.csv, plan.md  with --plan: the [[candidate]] experiments ranked (identify_plan.h)
// All of them into the staging folder of `out` (published by the caller); the figures only
// with `plots`.
void write_identify_outputs(const IdentifyDefinition& def, const IdentifyResult& result,
                            const StagedOutputs& out, bool plots);

// Each parameter's value in the model as it stands (the base scenario with the file's
// overrides; a sensor's neutral value), NaN where pamsim cannot say (identify_start.cc).
std::vector<double> start_values(const IdentifyDefinition& def);

// recording_<name>.png: `fits` are the recording's channels' (identify_plot.cc); without
// `fitted` (no parameter) the model's one line, no before.
void write_recording_plot(const std::string& png_path, const IdentifyRecording& recording,
                          const std::vector<const ChannelFit*>& fits, bool fitted = true);

}  // namespace pamsim
