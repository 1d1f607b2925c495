// identify_global.h: the global phase of `pamsim identify` (identify.h): CMA-ES over the unit
// box in `runs` independent runs, each with its own seed and a population doubled from the
// last's (the restarts of IPOP-CMA-ES), and the points the polish starts from.
#pragma once

#include <vector>

#include "sim/optimize/identify.h"
#include "sim/optimize/identify_residuals.h"

namespace pamsim {

// A point the polish starts from: a run's best point (run >= 0), or a further point of the
// pooled runs at least kStartSpacing from every start before (run -1).
struct GlobalStart {
  std::vector<double> unit;
  int run = -1;
};

// Each run's best point in run order, then further distinct points up to def.starts in all;
// the middle of the box alone without generations, the middle projected when every parameter
// is an offset. Sets *interrupted when options.stop stopped it.
// The generations each run ran go to *generations.
std::vector<GlobalStart> global_search(const IdentifyDefinition& def, IdentifyResiduals& residuals,
                                       const IdentifyRunOptions& options, bool* interrupted,
                                       std::vector<unsigned>* generations);

}  // namespace pamsim
