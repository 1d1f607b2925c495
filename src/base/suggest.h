// suggest.h: "did you mean" for a mistyped name (a scenario key, a subcommand, an option):
// the candidate nearest by edit distance, if it is near enough to be the one meant.
#pragma once

#include <string>
#include <vector>

namespace pamsim {

// Levenshtein distance (insertions, deletions, substitutions).
std::size_t edit_distance(const std::string& a, const std::string& b);

// The candidate nearest `given`, or "" if none is within max(1, min(3, |given| / 3)) edits
// (a short name needs a closer match). Ties go to the first in `candidates`.
std::string nearest_name(const std::string& given, const std::vector<std::string>& candidates);

}  // namespace pamsim
