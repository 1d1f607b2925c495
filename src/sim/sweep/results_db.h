// results_db.h: a sweep's results in SQLite, one file per sweep (its tables: meta and
// trials, listed at ResultsDb). A new database is built under a temp name and renamed into
// place, so a half-made file never exists. Results are committed in transactions (WAL
// journal, synchronous=FULL): a process killed at any moment, or a power loss, loses at most
// the trials not yet committed, and the trial primary key makes a repeated trial an error
// rather than a duplicate row.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "sim/io/sqlite_file.h"
#include "sim/sweep/sweep.h"
#include "sim/core/trial.h"

namespace pamsim {

// One finished trial, as stored.
struct TrialRecord {
  std::int64_t trial = 0;
  std::int64_t point = 0;
  std::int64_t seed_index = 0;
  TrialSummary summary;  // summary.seed is the trial's seed
};

// A cell read back: NULL, a number or text.
struct DbValue {
  enum class Kind { kNull, kNumber, kText } kind = Kind::kNull;
  double number = 0;
  std::string text;
};

// The tables:
//   meta(key, value)   format, the sweep definition (canonical JSON, sweep.h), trials (the
//                      sweep's count), pamsim_version, git_commit, mujoco_version,
//                      sundials_version, sweep_file, base_path, created_utc; shard ("I/N") in
//                      a shard's database; merged_from in a merged one; invocations (a JSON
//                      array: each `pamsim sweep` that ran trials into it, with its command
//                      line, threads, start, wall time and trials run: provenance.h)
//   trials(trial INTEGER PRIMARY KEY, point, seed_index, seed, <one column per axis key>,
//          <one per [[randomize]] key: the value drawn for the trial>,
//          status, message, <every metric of summary.json>; NULL where undefined, and all
//          NULL for a trial that failed to run)
class ResultsDb {
 public:
  // Creates `path` for `sweep` (or one shard of it); throws InputError if it exists or
  // cannot be written.
  static ResultsDb create(const std::string& path, const SweepDefinition& sweep,
                          const SweepShard& shard = {});
  // Opens `path` to finish `sweep` (or its `shard`), as its only writer; throws InputError if
  // it is missing, not a pamsim sweep database, holds a different sweep definition (naming
  // what differs) or another shard, or another process is writing to it.
  static ResultsDb open_to_resume(const std::string& path, const SweepDefinition& sweep,
                                  const SweepShard& shard = {});
  // Opens an existing sweep database to read it (export, report), also on read-only media
  // (open_sqlite_file); nothing is written. Throws InputError if `path` is missing, cannot
  // be read or is not a sweep database.
  static ResultsDb open_existing(const std::string& path);

  const std::string& path() const { return db_.path(); }
  std::string meta(const std::string& key) const { return db_.meta(key); }  // "" if absent

  // finished[t] is true for every trial already stored; `trials` is the sweep's count.
  std::vector<bool> finished_trials(std::int64_t trials) const;
  std::int64_t trial_count() const;
  // Stores `records` in one transaction; `sweep` gives the axis values of their points.
  void insert(const SweepDefinition& sweep, const std::vector<TrialRecord>& records);

  // Appends `entry` to the meta invocations array (one transaction).
  void record_invocation(const nlohmann::json& entry);

  // The trials table's columns, in order.
  std::vector<std::string> trial_columns() const;
  // The metric columns (after status and message), in order.
  std::vector<std::string> metric_columns() const;
  // The cells of trial `trial` (columns of trial_columns()), or none if it is not stored.
  std::vector<DbValue> trial_row(std::int64_t trial) const;
  // Calls `row` for every trial in trial order with its cells (columns of trial_columns()).
  void for_each_trial(const std::function<void(const std::vector<DbValue>&)>& row) const;

 private:
  explicit ResultsDb(SqliteDb db) : db_(std::move(db)) {}
  static ResultsDb open_as(const std::string& path, DbAccess access);

  SqliteDb db_;  // the handle, and while this handle writes, the writer's lock
};

}  // namespace pamsim
