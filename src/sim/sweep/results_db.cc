// results_db.cc: see results_db.h.
#include "sim/sweep/results_db.h"

#include <algorithm>
#include <fcntl.h>
#include <sqlite3.h>
#include <sys/file.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "base/input_error.h"
#include "sim/io/build_info.h"
#include "sim/io/outputs.h"
#include "sim/sweep/sqlite_file.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

sqlite3* open_database(const std::string& path, int flags) {
  sqlite3* db = nullptr;
  const int rc = sqlite3_open_v2(path.c_str(), &db, flags, nullptr);
  if (rc != SQLITE_OK) {
    const std::string why = db ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
    sqlite3_close(db);
    throw InputError(path + ": cannot open the sweep database (" + why + ")");
  }
  sqlite3_busy_timeout(db, 10000);
  return db;
}

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
  if (message == columns.end()) fail("is not a pamsim sweep database (no message column)");
  return std::vector<std::string>(message + 1, columns.end());
}

ResultsDb::ResultsDb(sqlite3* db, std::string path) : db_(db), path_(std::move(path)) {}

ResultsDb::ResultsDb(ResultsDb&& other) noexcept
    : db_(other.db_), path_(std::move(other.path_)), writer_lock_fd_(other.writer_lock_fd_) {
  other.db_ = nullptr;
  other.writer_lock_fd_ = -1;
}

ResultsDb& ResultsDb::operator=(ResultsDb&& other) noexcept {
  if (this != &other) {
    close();
    db_ = other.db_;
    path_ = std::move(other.path_);
    writer_lock_fd_ = other.writer_lock_fd_;
    other.db_ = nullptr;
    other.writer_lock_fd_ = -1;
  }
  return *this;
}

ResultsDb::~ResultsDb() { close(); }

void ResultsDb::close() {
  sqlite3_close(db_);
  db_ = nullptr;
  // only after SQLite is done with the file: closing any descriptor of it drops the
  // process's POSIX locks, SQLite's included
  if (writer_lock_fd_ >= 0) ::close(writer_lock_fd_);
  writer_lock_fd_ = -1;
}

void ResultsDb::lock_for_writing() {
  // flock(2), independent of SQLite's fcntl locks; released by the kernel if the process dies
  writer_lock_fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (writer_lock_fd_ < 0 || ::flock(writer_lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    const bool busy = errno == EWOULDBLOCK;
    throw InputError(path_ + (busy ? ": another pamsim sweep is writing to it; wait for it or "
                                     "stop it first"
                                   : ": cannot lock the sweep database (" +
                                         std::string(std::strerror(errno)) + ")"));
  }
}

void ResultsDb::fail(const std::string& what) const {
  throw std::runtime_error(path_ + ": " + what + " (" + sqlite3_errmsg(db_) + ")");
}

void ResultsDb::exec(const std::string& sql) const {
  char* err = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string why = err ? err : "unknown error";
    sqlite3_free(err);
    throw std::runtime_error(path_ + ": " + why);
  }
}

ResultsDb ResultsDb::create(const std::string& path, const SweepDefinition& sweep,
                            const SweepShard& shard) {
  create_sqlite_file(path, "sweep database",
                     "add --resume to finish that sweep, or choose another --db",
                     [&](const std::string& tmp) {
    ResultsDb db(open_database(tmp, SQLITE_OPEN_READWRITE), tmp);
    std::string columns = "trial INTEGER PRIMARY KEY, point INTEGER NOT NULL, "
                          "seed_index INTEGER NOT NULL, seed INTEGER NOT NULL";
    for (const auto& axis : sweep.axes) columns += ", " + quoted_identifier(axis.key);
    columns += ", status TEXT NOT NULL, message TEXT";
    for (const auto& name : sweep.metric_names) columns += ", " + quoted_identifier(name) + " REAL";
    db.exec("BEGIN; CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL); "
            "CREATE TABLE trials(" + columns + ");");
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
    db.put_meta(meta);
    db.exec("COMMIT; PRAGMA journal_mode=WAL;");
  });
  return open_to_resume(path, sweep, shard);
}

void ResultsDb::record_invocation(const nlohmann::json& entry) {
  exec("BEGIN IMMEDIATE;");   // read and written under one lock: no other writer's entry is lost
  try {
    nlohmann::json all = nlohmann::json::parse(meta("invocations"), nullptr, false);
    if (!all.is_array()) all = nlohmann::json::array();
    all.push_back(entry);
    put_meta({{"invocations", all.dump()}});
  } catch (...) {
    exec("ROLLBACK;");
    throw;
  }
  exec("COMMIT;");
}

void ResultsDb::put_meta(const std::vector<std::pair<std::string, std::string>>& entries) {
  Statement put = prepare_statement(db_, "INSERT OR REPLACE INTO meta VALUES (?, ?)");
  if (!put) fail("cannot write the sweep's description");
  for (const auto& [key, value] : entries) {
    sqlite3_bind_text(put.get(), 1, key.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(put.get(), 2, value.c_str(), -1, SQLITE_TRANSIENT);
    if (sqlite3_step(put.get()) != SQLITE_DONE) fail("cannot write the sweep's description");
    sqlite3_reset(put.get());
  }
}

ResultsDb ResultsDb::open_existing(const std::string& path) {
  return open_as(path, DbAccess::kRead);
}

ResultsDb ResultsDb::open_as(const std::string& path, DbAccess access) {
  ResultsDb db(open_sqlite_file(path, access, "sweep database"), path);
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
                     " differs from " + sweep.file + "); use another --db, or the sweep file "
                     "it was made with");
  }
  const std::string stored_shard = db.meta("shard");
  if (stored_shard != (shard.whole() ? "" : shard.text())) {
    throw InputError(path + ": holds " +
                     (stored_shard.empty() ? std::string("the whole sweep")
                                           : "shard " + stored_shard) +
                     ", not " + (shard.whole() ? std::string("the whole sweep")
                                               : "shard " + shard.text()) +
                     "; resume it with " +
                     (stored_shard.empty() ? std::string("no --shard")
                                           : "--shard " + stored_shard));
  }
  db.lock_for_writing();
  db.exec("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL;");
  return db;
}

std::string ResultsDb::meta(const std::string& key) const {
  Statement s = prepare_statement(db_, "SELECT value FROM meta WHERE key = ?");
  if (!s) return "";   // no meta table: not a sweep database
  sqlite3_bind_text(s.get(), 1, key.c_str(), -1, SQLITE_TRANSIENT);
  if (sqlite3_step(s.get()) != SQLITE_ROW) return "";
  const auto* text = sqlite3_column_text(s.get(), 0);
  return text ? reinterpret_cast<const char*>(text) : "";
}

std::vector<bool> ResultsDb::finished_trials(std::int64_t trials) const {
  std::vector<bool> finished(static_cast<std::size_t>(trials), false);
  Statement s = prepare_statement(db_, "SELECT trial FROM trials");
  if (!s) fail("cannot read the trials");
  int rc;
  while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) {
    const std::int64_t t = sqlite3_column_int64(s.get(), 0);
    if (t < 0 || t >= trials) fail("trial " + std::to_string(t) + " is outside this sweep");
    finished[static_cast<std::size_t>(t)] = true;
  }
  if (rc != SQLITE_DONE) fail("cannot read the trials");
  return finished;
}

std::int64_t ResultsDb::trial_count() const {
  Statement s = prepare_statement(db_, "SELECT COUNT(*) FROM trials");
  if (!s || sqlite3_step(s.get()) != SQLITE_ROW) fail("cannot count the trials");
  return sqlite3_column_int64(s.get(), 0);
}

void ResultsDb::insert(const SweepDefinition& sweep, const std::vector<TrialRecord>& records) {
  if (records.empty()) return;
  const std::size_t n_columns = 4 + sweep.axes.size() + 2 + sweep.metric_names.size();
  std::string sql = "INSERT INTO trials VALUES (?";
  for (std::size_t i = 1; i < n_columns; ++i) sql += ", ?";
  sql += ")";
  Statement s = prepare_statement(db_, sql);
  if (!s) fail("cannot store trials");
  exec("BEGIN IMMEDIATE");
  try {
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
          case AxisValue::Kind::kNumber: sqlite3_bind_double(st, c++, v.number); break;
          case AxisValue::Kind::kInteger:
            sqlite3_bind_int64(st, c++, static_cast<sqlite3_int64>(v.number));
            break;
          case AxisValue::Kind::kString:
            sqlite3_bind_text(st, c++, v.text.c_str(), -1, SQLITE_TRANSIENT);
            break;
          case AxisValue::Kind::kBool: sqlite3_bind_int(st, c++, v.flag ? 1 : 0); break;
        }
      }
      sqlite3_bind_text(st, c++, r.summary.status.c_str(), -1, SQLITE_TRANSIENT);
      if (r.summary.message.empty()) sqlite3_bind_null(st, c++);
      else sqlite3_bind_text(st, c++, r.summary.message.c_str(), -1, SQLITE_TRANSIENT);
      const bool measured = r.summary.status != "failed";   // a failed trial has no metrics
      for (const std::string& name : sweep.metric_names) {
        const double value = r.summary.metric(name);
        if (measured && std::isfinite(value)) sqlite3_bind_double(st, c++, value);
        else sqlite3_bind_null(st, c++);
      }
      if (sqlite3_step(st) != SQLITE_DONE) fail("cannot store trial " + std::to_string(r.trial));
      sqlite3_reset(st);
    }
    exec("COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

std::vector<std::string> ResultsDb::trial_columns() const {
  Statement s = prepare_statement(db_, "SELECT * FROM trials LIMIT 0");
  if (!s) fail("cannot read the trials");
  std::vector<std::string> names;
  for (int c = 0; c < sqlite3_column_count(s.get()); ++c) names.push_back(sqlite3_column_name(s.get(), c));
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
      case SQLITE_NULL: v.kind = DbValue::Kind::kNull; break;
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
  Statement s = prepare_statement(db_, "SELECT * FROM trials WHERE trial = ?");
  if (!s) fail("cannot read the trials");
  sqlite3_bind_int64(s.get(), 1, trial);
  std::vector<DbValue> cells;
  const int rc = sqlite3_step(s.get());
  if (rc == SQLITE_ROW) read_cells(s.get(), &cells);
  else if (rc != SQLITE_DONE) fail("cannot read the trials");
  return cells;
}

void ResultsDb::for_each_trial(const std::function<void(const std::vector<DbValue>&)>& row) const {
  Statement s = prepare_statement(db_, "SELECT * FROM trials ORDER BY trial");
  if (!s) fail("cannot read the trials");
  std::vector<DbValue> cells;
  int rc;
  while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) {
    read_cells(s.get(), &cells);
    row(cells);
  }
  if (rc != SQLITE_DONE) fail("cannot read the trials");
}

}  // namespace pamsim
