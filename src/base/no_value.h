// no_value.h: the value pamsim writes where a quantity was not measured (a metric whose
// event never happened, a column a log does not hold): a quiet NaN, one name for the project.
#pragma once

#include <limits>

namespace pamsim {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace pamsim
