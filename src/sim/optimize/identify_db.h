// identify_db.h: an identification run's database (SQLite, through sim/io/sqlite_file.h):
//   meta(key, value)   kind "pamsim identify", identify_definition (canonical JSON),
//                      identify_file, pamsim_version, git_commit, mujoco_version,
//                      sundials_version, command_line, created_utc
//   evaluations(point TEXT PRIMARY KEY, phase, cost, residuals)
// Every residual vector the search computes is committed as it is computed, keyed by the
// exact bits of its point in the unit box; both phases (CMA-ES, then Ceres's Levenberg-
// Marquardt) are deterministic, so a run killed at any moment is resumed by running it again
// with the stored points answered from here: nothing is simulated twice and the result is the
// uninterrupted run's. The files the scenarios read are fingerprinted in meta "inputs" when
// the database is made: a resume after one of them changed (a plant file edited) is refused,
// since its stored points would belong to another model. One writer at a time (its lock),
// WAL with full sync.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sim/io/sqlite_file.h"
#include "sim/optimize/identify_file.h"

namespace pamsim {

class IdentifyDb {
 public:
  // Creates `path` (refused if it exists), or opens it to resume (refused if it holds another
  // definition or is being written).
  static IdentifyDb create(const std::string& path, const IdentifyDefinition& def);
  static IdentifyDb open_to_resume(const std::string& path, const IdentifyDefinition& def);

  const std::string& path() const { return db_.path(); }
  // The residuals stored for `unit`, if any. An empty vector: its simulations failed.
  std::optional<std::vector<double>> find(const std::vector<double>& unit) const;
  void insert(const std::vector<double>& unit, const std::string& phase, double cost,
              const std::vector<double>& residuals);
  std::size_t size() const { return stored_.size(); }

 private:
  explicit IdentifyDb(SqliteDb db);

  SqliteDb db_;
  std::map<std::string, std::vector<double>> stored_;  // by point key
};

}  // namespace pamsim
