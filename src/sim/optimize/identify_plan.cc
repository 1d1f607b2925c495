// identify_plan.cc: see identify_plan.h.
#include "sim/optimize/identify_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>

#include "base/format.h"
#include "base/no_value.h"
#include "sim/core/runner.h"
#include "sim/optimize/identify_residuals.h"

namespace pamsim {
namespace {

// A recording's or candidate's sensitivities, one row per sample of a channel with a floor,
// each divided by the floor (`noise`, per chosen channel; NaN or <= 0: the channel left out);
// empty with *failure set if a trial failed.
Eigen::MatrixXd sensitivity(const IdentifyDefinition& def, const IdentifyRecording& r,
                            const std::vector<double>& unit, const std::vector<double>& noise,
                            int threads, std::string* failure) {
  const std::size_t n = unit.size();
  std::vector<std::vector<double>> points = {unit};
  std::vector<std::pair<std::size_t, std::size_t>> trial_of(n, {0, 0});  // plus, minus
  for (std::size_t j = 0; j < n; ++j) {
    if (def.channel_parameters[j].kind != ChannelParameter::Kind::kNone) continue;
    const DifferenceSides s = difference_sides(unit, j, kDifferenceStep);
    trial_of[j] = {points.size(), points.size() + 1};
    points.push_back(s.plus);
    points.push_back(s.minus);
  }
  std::vector<SimulatedRecording> trials(points.size());
  parallel_for(static_cast<int>(points.size()), threads, [&](int k) {
    const auto i = static_cast<std::size_t>(k);
    trials[i] = simulate_recording(def, r, def.overrides_at(r, parameter_values(def, points[i])));
  });
  for (const SimulatedRecording& t : trials) {
    if (!t.failure.empty()) {
      *failure = t.failure;
      return {};
    }
  }
  const auto centre = sample_channels(def, r, trials[0], parameter_values(def, unit));
  Eigen::Index rows = 0;
  for (std::size_t c = 0; c < centre.size(); ++c) {
    if (!(noise[c] > 0.0)) continue;
    for (double v : centre[c]) rows += std::isnan(v) ? 0 : 1;
  }
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(rows, static_cast<Eigen::Index>(n));
  for (std::size_t j = 0; j < n; ++j) {
    const DifferenceSides side = difference_sides(unit, j, kDifferenceStep);
    const auto plus =
        sample_channels(def, r, trials[trial_of[j].first], parameter_values(def, side.plus));
    const auto minus =
        sample_channels(def, r, trials[trial_of[j].second], parameter_values(def, side.minus));
    Eigen::Index row = 0;
    for (std::size_t c = 0; c < centre.size(); ++c) {
      if (!(noise[c] > 0.0)) continue;
      for (std::size_t k = 0; k < centre[c].size(); ++k) {
        if (std::isnan(centre[c][k])) continue;
        s(row++, static_cast<Eigen::Index>(j)) = (plus[c][k] - minus[c][k]) / side.width / noise[c];
      }
    }
  }
  return s;
}

// A tensile test's force sensitivities over `floor` [N]; a parameter whose test failed on a
// side keeps a zero column, with *failure set.
Eigen::MatrixXd tensile_sensitivity(const IdentifyDefinition& def, const IdentifyTensile& t,
                                    const std::vector<double>& unit, double floor,
                                    std::string* failure) {
  const std::size_t n = unit.size();
  Eigen::MatrixXd s =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(t.rows.size()), static_cast<Eigen::Index>(n));
  for (std::size_t j = 0; j < n && floor > 0.0; ++j) {
    if (def.channel_parameters[j].kind != ChannelParameter::Kind::kNone) continue;
    const DifferenceSides side = difference_sides(unit, j, kDifferenceStep);
    const auto forces_at = [&](const std::vector<double>& u) {
      return tensile_forces(def, t, def.overrides_at(parameter_values(def, u)), failure);
    };
    const auto plus = forces_at(side.plus);
    const auto minus = forces_at(side.minus);
    if (plus.empty() || minus.empty()) continue;
    for (std::size_t k = 0; k < plus.size(); ++k) {
      s(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) =
          (plus[k] - minus[k]) / side.width / floor;
    }
  }
  return s;
}

// The floor identify found for `channel` of `recording` (any fitted recording's for "")
double floor_of(const IdentifyResult& result, const std::string& recording,
                const std::string& channel) {
  for (const ChannelFit& f : result.fits) {
    if (f.channel != channel || f.held_out || !std::isfinite(f.noise_floor)) continue;
    if (recording.empty() || f.recording == recording) return f.noise_floor;
  }
  return kNaN;
}

// The information of the fitted recordings and tensile tests, with the prior I. A recording
// or test whose trial failed is left out, and named in *failures: the information it lacks
// makes every candidate's gain look larger.
Eigen::MatrixXd information_now(const IdentifyDefinition& def, const IdentifyResult& result,
                                int threads, std::vector<std::string>* left_out) {
  const auto n = static_cast<Eigen::Index>(result.unit.size());
  Eigen::MatrixXd f = Eigen::MatrixXd::Identity(n, n);
  for (const IdentifyRecording& r : def.recordings) {
    if (r.held_out) continue;
    std::vector<double> noise;
    for (std::size_t c : r.channels) noise.push_back(floor_of(result, r.name, r.data.channels[c]));
    std::string failure;
    const Eigen::MatrixXd s = sensitivity(def, r, result.unit, noise, threads, &failure);
    if (!failure.empty()) left_out->push_back(r.name + ": " + failure);
    if (s.size() > 0) f += s.transpose() * s;
  }
  for (const IdentifyTensile& t : def.tensile) {
    double floor = kNaN;
    for (const ChannelFit& fit : result.fits) {
      if (fit.recording == "tensile_" + t.muscle) floor = fit.rmse_after;
    }
    std::string failure;
    const Eigen::MatrixXd s = tensile_sensitivity(def, t, result.unit, floor, &failure);
    if (!failure.empty()) left_out->push_back("tensile_" + t.muscle + ": " + failure);
    f += s.transpose() * s;
  }
  return f;
}

// dx/du of each parameter at the result
std::vector<double> slopes(const IdentifyDefinition& def, const IdentifyResult& result) {
  std::vector<double> out;
  for (std::size_t j = 0; j < result.unit.size(); ++j) {
    out.push_back(std::abs(slope_at(def.parameters[j], result.unit[j])));
  }
  return out;
}

// The candidate (index into plan.ranked) that leaves parameter j the smallest standard
// deviation; plan.ranked.size() if there is none.
std::size_t best_for(const IdentifyPlan& plan, std::size_t j) {
  std::size_t best = plan.ranked.size();
  for (std::size_t c = 0; c < plan.ranked.size(); ++c) {
    if (best == plan.ranked.size() || plan.ranked[c].sd_after[j] < plan.ranked[best].sd_after[j]) {
      best = c;
    }
  }
  return best;
}

// three significant digits, for reading
std::string rounded(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

}  // namespace

InformationGain information_gain(const Eigen::MatrixXd& now, const Eigen::MatrixXd& added) {
  const Eigen::MatrixXd after = now + added;
  const Eigen::LLT<Eigen::MatrixXd> l_now(now), l_after(after);
  InformationGain g;
  g.d_gain = 0.0;
  for (Eigen::Index i = 0; i < now.rows(); ++i) {
    g.d_gain += std::log(l_after.matrixL()(i, i)) - std::log(l_now.matrixL()(i, i));
  }
  g.sd = l_after.solve(Eigen::MatrixXd::Identity(now.rows(), now.cols())).diagonal().cwiseSqrt();
  return g;
}

IdentifyPlan plan_candidates(const IdentifyDefinition& def, const IdentifyResult& result,
                             int threads) {
  IdentifyPlan plan;
  for (const SearchParameter& p : def.parameters) plan.keys.push_back(p.key);
  const Eigen::MatrixXd now = information_now(def, result, threads, &plan.left_out);
  const std::vector<double> slope = slopes(def, result);
  const Eigen::VectorXd sd_now =
      information_gain(now, Eigen::MatrixXd::Zero(now.rows(), now.cols())).sd;
  for (std::size_t j = 0; j < slope.size(); ++j) {
    plan.sd_now.push_back(sd_now(static_cast<Eigen::Index>(j)) * slope[j]);
  }
  for (const IdentifyRecording& c : def.candidates) {
    std::vector<double> noise;
    for (std::size_t k = 0; k < c.channels.size(); ++k) {
      noise.push_back(std::isnan(c.noise[k]) ? floor_of(result, "", c.data.channels[k])
                                             : c.noise[k]);
    }
    std::string failure;
    const Eigen::MatrixXd s = sensitivity(def, c, result.unit, noise, threads, &failure);
    if (!failure.empty()) {
      plan.failures.push_back(c.name + ": " + failure);
      continue;
    }
    const InformationGain g = information_gain(now, s.transpose() * s);
    PlannedCandidate pc{c.name, g.d_gain, {}};
    for (std::size_t j = 0; j < slope.size(); ++j) {
      pc.sd_after.push_back(g.sd(static_cast<Eigen::Index>(j)) * slope[j]);
    }
    plan.ranked.push_back(std::move(pc));
  }
  std::stable_sort(
      plan.ranked.begin(), plan.ranked.end(),
      [](const PlannedCandidate& a, const PlannedCandidate& b) { return a.d_gain > b.d_gain; });
  return plan;
}

std::string plan_csv(const IdentifyPlan& plan) {
  std::string out = "candidate,rank,information_gain,parameter,sd_now,sd_after\n";
  for (std::size_t c = 0; c < plan.ranked.size(); ++c) {
    const PlannedCandidate& pc = plan.ranked[c];
    for (std::size_t j = 0; j < plan.keys.size(); ++j) {
      out += pc.name + "," + std::to_string(c + 1) + "," + format_value(pc.d_gain) + "," +
             plan.keys[j] + "," + format_value(plan.sd_now[j]) + "," +
             format_value(pc.sd_after[j]) + "\n";
    }
  }
  return out;
}

std::vector<std::string> plan_lines(const IdentifyPlan& plan) {
  std::vector<std::string> lines;
  for (std::size_t c = 0; c < plan.ranked.size(); ++c) {
    lines.push_back(std::to_string(c + 1) + ". " + plan.ranked[c].name + ": information gain " +
                    rounded(plan.ranked[c].d_gain) + " (D-optimal)");
  }
  for (std::size_t j = 0; j < plan.keys.size(); ++j) {
    const std::size_t b = best_for(plan, j);
    if (b == plan.ranked.size()) continue;
    lines.push_back(plan.keys[j] + ": standard deviation " + rounded(plan.sd_now[j]) + " now, " +
                    rounded(plan.ranked[b].sd_after[j]) + " with " + plan.ranked[b].name);
  }
  for (const std::string& f : plan.failures) lines.push_back("not ranked: " + f);
  for (const std::string& f : plan.left_out) {
    lines.push_back("left out of the current information (every gain overstated): " + f);
  }
  return lines;
}

std::string plan_markdown(const IdentifyPlan& plan) {
  std::ostringstream md;
  md << "# Experiment plan: the candidates at the identified point\n\n"
     << "Ranked by the D-optimal criterion: 0.5 ln det(F_now + F_c) - 0.5 ln det(F_now), F the "
        "Fisher information of white noise at each channel's floor, F_now the fitted "
        "recordings' and tensile tests' with a prior of one range per parameter.\n\n"
     << "| rank | candidate | information gain |\n| --- | --- | --- |\n";
  for (std::size_t c = 0; c < plan.ranked.size(); ++c) {
    md << "| " << c + 1 << " | " << plan.ranked[c].name << " | " << rounded(plan.ranked[c].d_gain)
       << " |\n";
  }
  md << "\n| parameter | standard deviation now | best candidate | standard deviation with it |\n"
     << "| --- | --- | --- | --- |\n";
  for (std::size_t j = 0; j < plan.keys.size(); ++j) {
    const std::size_t b = best_for(plan, j);
    const std::string best = b < plan.ranked.size()
                                 ? plan.ranked[b].name + " | " + rounded(plan.ranked[b].sd_after[j])
                                 : std::string("- | -");
    md << "| `" << plan.keys[j] << "` | " << rounded(plan.sd_now[j]) << " | " << best << " |\n";
  }
  for (const std::string& f : plan.failures) md << "\nNot ranked: " << f << "\n";
  for (const std::string& f : plan.left_out) {
    md << "\nLeft out of the current information (every gain overstated): " << f << "\n";
  }
  return md.str();
}

}  // namespace pamsim
