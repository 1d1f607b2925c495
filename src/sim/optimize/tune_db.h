// tune_db.h: a tuning run's database (SQLite, through the room of sim/io/sqlite_file.h):
//   meta(key, value)   kind "pamsim tune", tune_definition (canonical JSON), tune_file,
//                      inputs (the base scenario's files, fingerprinted: a resume after one
//                      changed is refused, provenance.h),
//                      pamsim_version, git_commit, mujoco_version, sundials_version,
//                      command_line, created_utc
//   evaluations(evaluation, u0.., x0.., objective0, fitness0, .., violation, trials, ok)
//   trials(evaluation, seed, noise_scale, status, message, metrics JSON)
// Written by one process at a time (its writer's lock), in WAL mode with full sync, one
// transaction per evaluation.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/io/sqlite_file.h"
#include "sim/optimize/tuning_file.h"

namespace pamsim {

using TuneEvaluation = Evaluation;

class TuneDb {
 public:
  // Creates `path` (refused if it exists), or opens it to resume (refused if it holds
  // another definition or is being written).
  static TuneDb create(const std::string& path, const TuneDefinition& def);
  static TuneDb open_to_resume(const std::string& path, const TuneDefinition& def);
  static TuneDb open_existing(const std::string& path);  // read-only
  // True if `path` is a pamsim tuning database (for `pamsim report`).
  static bool is_tune_database(const std::string& path);

  const std::string& path() const { return db_.path(); }
  std::string meta(const std::string& key) const { return db_.meta(key); }
  std::vector<TuneEvaluation> evaluations() const;
  struct TrialRow {
    std::uint64_t seed = 0;
    double noise_scale = 1.0;
    std::string status, message, metrics_json;
  };
  void insert(const TuneEvaluation& evaluation, const std::vector<TrialRow>& trials);

 private:
  explicit TuneDb(SqliteDb db) : db_(std::move(db)) {}

  SqliteDb db_;
};

// The definition stored in a tuning database (for `pamsim report`), with its file as given.
TuneDefinition tune_definition_from_db(const TuneDb& db);

}  // namespace pamsim
