// results_db.cc: see results_db.h.
#include "sim/sweep/results_db.h"

#include <algorithm>
#include <sqlite3.h>

#include <cmath>
#include <ctime>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "base/input_error.h"
#include "sim/io/build_info.h"
#include "sim/io/outputs.h"
#include "sim/io/sqlite_file.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// The first top-level field in which two canonical definitions differ.
std::string first_difference(const std::string& stored, const std::string& wanted) {
  const auto a = nlohmann::json::parse(stored, nullptr, false);
  const auto b = nlohmann::json::parse(wanted, nullptr, false);
  if (a.is_discarded() || !a.is_object()) return "definition";
  for (const auto& [key, value] : b.items()) {
    if (!a.contains(key) || a[key] != value) return key;
  }
  return "definition";
}

}  // namespace

std::vector<std::string> ResultsDb::metric_columns() const {
  const std::vector<std::string> columns = trial_columns();
  const auto message = std::find(columns.begin(), columns.end(), "message");
  if (message == columns.end()) db_.fail("is not a pamsim sweep database (no message column)");
  return std::vector<std::string>(message + 1, columns.end());
}

ResultsDb ResultsDb::create(const std::string& path, const SweepDefinition& sweep,
                            const SweepShard& shard) {
  create_sqlite_file(path, "sweep database",
                     "add --resume to finish that sweep, or choose another --db",
                     [&](const std::string& tmp) {
                       const SqliteDb db = SqliteDb::open_new(tmp, "sweep database");
                       std::string columns =
                           "trial INTEGER PRIMARY KEY, point INTEGER NOT NULL, "
                           "seed_index INTEGER NOT NULL, seed INTEGER NOT NULL";
                       for (const auto& axis : sweep.axes)
                         columns += ", " + quoted_identifier(axis.key);
                       for (const auto& r : sweep.randomize)
                         columns += ", " + quoted_identifier(r.key) + " REAL";
                       columns += ", status TEXT NOT NULL, message TEXT";
                       for (const auto& name : sweep.metric_names)
                         columns += ", " + quoted_identifier(name) + " REAL";
                       db.exec(
                           "BEGIN; CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL); "
                           "CREATE TABLE trials(" +
                           columns + ");");
                       std::vector<std::pair<std::string, std::string>> meta = {
                           {"format", "pamsim-sweep-1"},
                           {"definition", sweep.canonical_json()},
                           {"trials", std::to_string(sweep.trials())},
                           {"pamsim_version", PAMSIM_VERSION},
                           {"git_commit", build_info().git_commit},
                           {"mujoco_version", build_info().mujoco_version},
                           {"sundials_version", build_info().sundials_version},
                           {"sweep_file", sweep.file},
                           {"base_path", fs::absolute(sweep.base_path).lexically_normal().string()},
                           {"created_utc", utc_timestamp()}};
                       if (!shard.whole()) meta.emplace_back("shard", shard.text());
                       db.put_meta(meta, "cannot write the sweep's description");
                       db.exec("COMMIT; PRAGMA journal_mode=WAL;");
                     });
  return open_to_resume(path, sweep, shard);
}

void ResultsDb::record_invocation(const nlohmann::json& entry) {
  // read and written under one lock: no other writer's entry is lost
  db_.transaction([&] {
    nlohmann::json all = nlohmann::json::parse(meta("invocations"), nullptr, false);
    if (!all.is_array()) all = nlohmann::json::array();
    all.push_back(entry);
    db_.put_meta({{"invocations", all.dump()}}, "cannot write the sweep's description");
  });
}

ResultsDb ResultsDb::open_existing(const std::string& path) {
  return open_as(path, DbAccess::kRead);
}

ResultsDb ResultsDb::open_as(const std::string& path, DbAccess access) {
  ResultsDb db(SqliteDb::open(path, access, "sweep database"));
  if (db.meta("format") != "pamsim-sweep-1") {
    throw InputError(path + ": not a pamsim sweep database");
  }
  return db;
}

ResultsDb ResultsDb::open_to_resume(const std::string& path, const SweepDefinition& sweep,
                                    const SweepShard& shard) {
  ResultsDb db = open_as(path, DbAccess::kWrite);
  const std::string stored = db.meta("definition");
  const std::string wanted = sweep.canonical_json();
  if (stored != wanted) {
    throw InputError(path + ": holds a different sweep (its " + first_difference(stored, wanted) +
                     " differs from " + sweep.file +
                     "); use another --db, or the sweep file "
                     "it was made with");
  }
  const std::string stored_shard = db.meta("shard");
  if (stored_shard != (shard.whole() ? "" : shard.text())) {
    throw InputError(
        path + ": holds " +
        (stored_shard.empty() ? std::string("the whole sweep") : "shard " + stored_shard) +
        ", not " + (shard.whole() ? std::string("the whole sweep") : "shard " + shard.text()) +
        "; resume it with " +
        (stored_shard.empty() ? std::string("no --shard") : "--shard " + stored_shard));
  }
  db.db_.become_writer("another pamsim sweep is writing to it; wait for it or stop it first",
                       "sweep database");
  return db;
}

std::vector<bool> ResultsDb::finished_trials(std::int64_t trials) const {
  std::vector<bool> finished(static_cast<std::size_t>(trials), false);
  Statement s = db_.prepare("SELECT trial FROM trials", "cannot read the trials");
  int rc;
  while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) {
    const std::int64_t t = sqlite3_column_int64(s.get(), 0);
    if (t < 0 || t >= trials) db_.fail("trial " + std::to_string(t) + " is outside this sweep");
    finished[static_cast<std::size_t>(t)] = true;
  }
  if (rc != SQLITE_DONE) db_.fail("cannot read the trials");
  return finished;
}

std::int64_t ResultsDb::trial_count() const {
  Statement s = prepare_statement(db_.get(), "SELECT COUNT(*) FROM trials");
  if (!s || sqlite3_step(s.get()) != SQLITE_ROW) db_.fail("cannot count the trials");
  return sqlite3_column_int64(s.get(), 0);
}

void ResultsDb::insert(const SweepDefinition& sweep, const std::vector<TrialRecord>& records) {
  if (records.empty()) return;
  const std::size_t n_columns =
      4 + sweep.axes.size() + sweep.randomize.size() + 2 + sweep.metric_names.size();
  std::string sql = "INSERT INTO trials VALUES (?";
  for (std::size_t i = 1; i < n_columns; ++i) sql += ", ?";
  sql += ")";
  Statement s = db_.prepare(sql, "cannot store trials");
  db_.transaction([&] {
    for (const TrialRecord& r : records) {
      sqlite3_stmt* st = s.get();
      int c = 1;
      sqlite3_bind_int64(st, c++, r.trial);
      sqlite3_bind_int64(st, c++, r.point);
      sqlite3_bind_int64(st, c++, r.seed_index);
      sqlite3_bind_int64(st, c++, static_cast<sqlite3_int64>(r.summary.seed));
      for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
        const AxisValue& v = sweep.value(r.point, a);
        switch (v.kind) {
          case AxisValue::Kind::kNumber:
            sqlite3_bind_double(st, c++, v.number);
            break;
          case AxisValue::Kind::kInteger:
            sqlite3_bind_int64(st, c++, static_cast<sqlite3_int64>(v.number));
            break;
          case AxisValue::Kind::kString:
            sqlite3_bind_text(st, c++, v.text.c_str(), -1, SQLITE_TRANSIENT);
            break;
          case AxisValue::Kind::kBool:
            sqlite3_bind_int(st, c++, v.flag ? 1 : 0);
            break;
        }
      }
      for (double drawn : sweep.draws(r.trial)) sqlite3_bind_double(st, c++, drawn);
      sqlite3_bind_text(st, c++, r.summary.status.c_str(), -1, SQLITE_TRANSIENT);
      if (r.summary.message.empty())
        sqlite3_bind_null(st, c++);
      else
        sqlite3_bind_text(st, c++, r.summary.message.c_str(), -1, SQLITE_TRANSIENT);
      const bool measured = r.summary.status != "failed";  // a failed trial has no metrics
      for (const std::string& name : sweep.metric_names) {
        const double value = r.summary.metric(name);
        if (measured && std::isfinite(value))
          sqlite3_bind_double(st, c++, value);
        else
          sqlite3_bind_null(st, c++);
      }
      if (sqlite3_step(st) != SQLITE_DONE)
        db_.fail("cannot store trial " + std::to_string(r.trial));
      sqlite3_reset(st);
    }
  });
}

std::vector<std::string> ResultsDb::trial_columns() const {
  Statement s = db_.prepare("SELECT * FROM trials LIMIT 0", "cannot read the trials");
  std::vector<std::string> names;
  for (int c = 0; c < sqlite3_column_count(s.get()); ++c)
    names.push_back(sqlite3_column_name(s.get(), c));
  return names;
}

namespace {

// The current row's cells into `cells` (sized to the statement's columns).
void read_cells(sqlite3_stmt* s, std::vector<DbValue>* cells) {
  cells->resize(static_cast<std::size_t>(sqlite3_column_count(s)));
  for (std::size_t c = 0; c < cells->size(); ++c) {
    DbValue& v = (*cells)[c];
    const int i = static_cast<int>(c);
    switch (sqlite3_column_type(s, i)) {
      case SQLITE_NULL:
        v.kind = DbValue::Kind::kNull;
        break;
      case SQLITE_INTEGER:
      case SQLITE_FLOAT:
        v.kind = DbValue::Kind::kNumber;
        v.number = sqlite3_column_double(s, i);
        break;
      default:
        v.kind = DbValue::Kind::kText;
        v.text = reinterpret_cast<const char*>(sqlite3_column_text(s, i));
        break;
    }
  }
}

}  // namespace

std::vector<DbValue> ResultsDb::trial_row(std::int64_t trial) const {
  Statement s = db_.prepare("SELECT * FROM trials WHERE trial = ?", "cannot read the trials");
  sqlite3_bind_int64(s.get(), 1, trial);
  std::vector<DbValue> cells;
  const int rc = sqlite3_step(s.get());
  if (rc == SQLITE_ROW)
    read_cells(s.get(), &cells);
  else if (rc != SQLITE_DONE)
    db_.fail("cannot read the trials");
  return cells;
}

void ResultsDb::for_each_trial(const std::function<void(const std::vector<DbValue>&)>& row) const {
  Statement s = db_.prepare("SELECT * FROM trials ORDER BY trial", "cannot read the trials");
  std::vector<DbValue> cells;
  int rc;
  while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) {
    read_cells(s.get(), &cells);
    row(cells);
  }
  if (rc != SQLITE_DONE) db_.fail("cannot read the trials");
}

}  // namespace pamsim
