// identify_offsets.h: the global search without the channels' offsets. A sensor's zero error
// (`channel.<column>.offset`, identify_file.h) enters every residual of its channel
// additively, so at any point of the other parameters the offset that minimises the cost is
// one weighted mean of those residuals: the cost separates (variable projection, Golub and
// Pereyra, SIAM J. Numer. Anal. 10(2), 1973). CMA-ES then searches only the parameters that
// need trials, each point's offsets moved to their best values within their ranges; the
// offsets, whose wrong values dominate a cost measured in noise floors (an angle offset 2 deg
// off is 600 floors of a 0.003 deg logger), no longer take its budget, nor can they hold its
// best point in a valley of a compensating wall and gauge offset. The polish then fits all
// parameters together as before. Offsets on a log scale are left to the search.
#pragma once

#include <cstddef>
#include <vector>

#include "sim/optimize/identify_file.h"
#include "sim/optimize/identify_residuals.h"

namespace pamsim {

class OffsetProjection {
 public:
  // The offsets def.offset_projected names (none without the file's profile_offsets).
  OffsetProjection(const IdentifyDefinition& def, const IdentifyResiduals& residuals);

  // The parameters the global search moves (their indices, in order): every one but the
  // projected offsets.
  const std::vector<std::size_t>& searched() const { return searched_; }
  bool projects() const { return !projected_.empty(); }

  // The whole unit point of the search's point `searched_unit` (searched().size() values), the
  // projected offsets at their ranges' middle.
  std::vector<double> embed(const std::vector<double>& searched_unit) const;

  // `unit` with each projected offset at its least-squares value given the rest (clamped to
  // its range), `residuals` being the residual vector at `unit` (identify_residuals.h).
  std::vector<double> project(const std::vector<double>& unit,
                              const std::vector<double>& residuals) const;

 private:
  struct Projected {
    std::size_t parameter;
    std::vector<double> slope;  // d residual / d offset, per residual (0 off its channel)
    double slope_squares = 0.0;
  };
  const IdentifyDefinition& def_;
  std::vector<std::size_t> searched_;
  std::vector<Projected> projected_;
};

}  // namespace pamsim
