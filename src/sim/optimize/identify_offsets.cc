// identify_offsets.cc: see identify_offsets.h.
#include "sim/optimize/identify_offsets.h"

#include <algorithm>

namespace pamsim {

OffsetProjection::OffsetProjection(const IdentifyDefinition& def,
                                   const IdentifyResiduals& residuals)
    : def_(def) {
  for (std::size_t k = 0; k < def.parameters.size(); ++k) {
    if (!def.offset_projected(k)) {
      searched_.push_back(k);
      continue;
    }
    Projected p{k, residuals.offset_slope(def.channel_parameters[k].column), 0.0};
    for (double s : p.slope) p.slope_squares += s * s;
    if (p.slope_squares > 0.0) {
      projected_.push_back(std::move(p));
    } else {
      searched_.push_back(k);  // fitted on no sample: nothing to project from
    }
  }
}

std::vector<double> OffsetProjection::embed(const std::vector<double>& searched_unit) const {
  std::vector<double> unit(def_.parameters.size(), 0.5);
  for (std::size_t i = 0; i < searched_.size(); ++i) unit[searched_[i]] = searched_unit[i];
  return unit;
}

std::vector<double> OffsetProjection::project(const std::vector<double>& unit,
                                              const std::vector<double>& residuals) const {
  std::vector<double> out = unit;
  if (residuals.empty()) return out;  // the point's trials failed: nothing to move by
  for (const Projected& p : projected_) {
    // the least-squares step of a parameter the residuals are linear in
    double dot = 0.0;
    for (std::size_t i = 0; i < residuals.size(); ++i) dot += p.slope[i] * residuals[i];
    const SearchParameter& sp = def_.parameters[p.parameter];
    const double value = value_at(sp, std::clamp(unit[p.parameter], 0.0, 1.0));
    const double best = std::clamp(value - dot / p.slope_squares, sp.from, sp.to);
    out[p.parameter] = (best - sp.from) / (sp.to - sp.from);
  }
  return out;
}

}  // namespace pamsim
