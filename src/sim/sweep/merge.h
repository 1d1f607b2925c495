// merge.h: `pamsim merge`: combines the databases of one sweep run in parts (the shards of
// `pamsim sweep --shard I/N`, or any partial databases of the same sweep) into one sweep
// database, which export, report and `pamsim sweep --resume` take like any other.
//
// The parts must hold the same sweep definition, have been made by the same pamsim version
// and have the same columns; a trial found in two parts is kept once if the two rows agree
// (timing metrics aside) and refused if they differ (the parts were not made by the same
// build, or not from the same sweep). Trials in no part are reported, not invented: resume
// the merged database to run them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pamsim {

struct MergeResult {
  std::string sweep_file;                   // the sweep file the parts were made from
  std::int64_t trials = -1;                 // the sweep's count (-1: the parts do not say)
  std::int64_t merged = 0;                  // distinct trials in the merged database
  std::int64_t duplicates = 0;              // rows found again in a later part, kept once
  std::int64_t missing = 0;                 // trials in no part (trials - merged)
  std::vector<std::int64_t> first_missing;  // the first of them (at most 10)
  std::vector<std::int64_t> per_part;       // rows read from each part
};

// Writes `out` (whole or not at all; refused if it exists) from `parts`. Throws InputError
// "<part>: <problem>" for a part that is missing, not a sweep database, of another sweep,
// version or schema, or holding a trial outside the sweep or one that differs from another
// part's; std::runtime_error when `out` cannot be written.
MergeResult merge_sweep_databases(const std::string& out, const std::vector<std::string>& parts);

}  // namespace pamsim
