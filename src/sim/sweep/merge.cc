// merge.cc: see merge.h. The parts are read through ATTACH, so rows are copied by SQLite
// cell for cell (integers stay integers, no value passes through a double).
#include "sim/sweep/merge.h"

#include <sqlite3.h>

#include <charconv>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "base/input_error.h"
#include "sim/core/metrics.h"
#include "sim/sweep/results_db.h"
#include "sim/io/sqlite_file.h"

namespace pamsim {
namespace {

// What every part must share, read from the first.
struct PartSchema {
  std::string definition;
  std::string version;
  std::vector<std::string> columns;
  std::int64_t trials = -1;
  std::string sweep_file;
};

PartSchema schema_of(const ResultsDb& db, const std::string& part) {
  PartSchema s;
  s.definition = db.meta("definition");
  s.version = db.meta("pamsim_version");
  s.columns = db.trial_columns();
  s.sweep_file = db.meta("sweep_file");
  const std::string trials = db.meta("trials");
  if (!trials.empty()) {
    const char* end = trials.data() + trials.size();
    const auto [ptr, ec] = std::from_chars(trials.data(), end, s.trials);
    if (ec != std::errc() || ptr != end || s.trials < 0) {
      throw InputError(part + ": its trial count '" + trials + "' is not a count");
    }
  }
  return s;
}

// Refuses a part that does not belong with the first, naming what differs.
void check_part(const std::string& part, const PartSchema& got, const PartSchema& want,
                const std::string& first) {
  const auto refuse = [&](const std::string& what) {
    throw InputError(part + ": " + what + " than " + first +
                     "; merge only the parts of one "
                     "sweep run by one pamsim version");
  };
  if (got.definition != want.definition) refuse("holds another sweep definition");
  if (got.version != want.version) {
    refuse("was made by pamsim " + got.version + ", another version (" + want.version + ")");
  }
  if (got.columns != want.columns) refuse("has other columns");
  if (got.trials != want.trials) refuse("states another trial count");
}

// The merged database at `path` (a temp file), open for writing. Its errors are SQLite's
// words alone: the caller names the part being read or the database being made.
class MergedDb {
 public:
  explicit MergedDb(const std::string& path)
      : file_(SqliteDb::open_new(path, "merged sweep database", /*uri_attach=*/true)),
        db_(file_.get()) {}

  void exec(const std::string& sql) {
    if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr) != SQLITE_OK) fail();
  }
  // The statement prepared, with `text` bound to its first parameter if given.
  Statement query(const std::string& sql, const std::string* text = nullptr) {
    Statement s = prepare_statement(db_, sql);
    if (!s) fail();
    if (text) sqlite3_bind_text(s.get(), 1, text->c_str(), -1, SQLITE_TRANSIENT);
    return s;
  }
  // The first column of the first row of `sql`, as an integer (0 when there is no row).
  std::int64_t integer(const std::string& sql) {
    Statement s = query(sql);
    const int rc = sqlite3_step(s.get());
    if (rc != SQLITE_ROW && rc != SQLITE_DONE) fail();
    return rc == SQLITE_ROW ? sqlite3_column_int64(s.get(), 0) : 0;
  }
  void step_done(Statement& s) {
    if (sqlite3_step(s.get()) != SQLITE_DONE) fail();
  }
  [[noreturn]] void fail() const { throw std::runtime_error(sqlite3_errmsg(db_)); }

 private:
  SqliteDb file_;
  sqlite3* db_;
};

// The columns two runs of one trial agree on: all but the timing metrics.
std::string deterministic_columns(const std::vector<std::string>& columns) {
  std::string list;
  for (const std::string& c : columns) {
    if (is_timing_metric(c)) continue;
    list += (list.empty() ? "" : ", ") + quoted_identifier(c);
  }
  return list;
}

// Attaches `part` as "part" and checks it against what is merged so far: the trials it
// holds lie inside the sweep, and any it shares with earlier parts agree with them (timing
// aside). With `first`, makes the tables as the parts have them and copies the description.
// Adds its rows and duplicates to `result`.
void check_and_count_part(MergedDb& db, const std::string& part, bool first,
                          const PartSchema& schema, const std::string& compare,
                          MergeResult& result) {
  const std::string uri = read_only_uri(part);
  Statement attach = db.query("ATTACH DATABASE ? AS part", &uri);
  db.step_done(attach);
  attach.reset();
  if (first) {  // the tables as the parts have them, and their description
    Statement tables = db.query(
        "SELECT sql FROM part.sqlite_schema WHERE type = 'table' AND name IN "
        "('meta', 'trials') ORDER BY name");
    std::vector<std::string> create;
    while (sqlite3_step(tables.get()) == SQLITE_ROW) {
      create.push_back(reinterpret_cast<const char*>(sqlite3_column_text(tables.get(), 0)));
    }
    tables.reset();
    for (const std::string& sql : create) db.exec(sql);
    db.exec(
        "INSERT INTO main.meta SELECT * FROM part.meta WHERE key NOT IN "
        "('shard', 'created_utc', 'merged_from', 'invocations', 'git_commit')");
  }
  const std::string where = "FROM part.trials WHERE ";
  if (schema.trials >= 0) {
    const std::string outside = where + "trial < 0 OR trial >= " + std::to_string(schema.trials);
    if (db.integer("SELECT COUNT(*) " + outside) > 0) {
      throw InputError(part + ": holds trial " +
                       std::to_string(db.integer("SELECT trial " + outside + " LIMIT 1")) +
                       ", outside the sweep's " + std::to_string(schema.trials) + " trials");
    }
  }
  const std::string again = where + "trial IN (SELECT trial FROM main.trials)";
  const std::int64_t duplicates = db.integer("SELECT COUNT(*) " + again);
  if (duplicates > 0) {
    Statement differs = db.query("SELECT trial FROM (SELECT " + compare + " " + again +
                                 " EXCEPT SELECT " + compare + " FROM main.trials) LIMIT 1");
    if (sqlite3_step(differs.get()) == SQLITE_ROW) {
      throw InputError(part + ": trial " + std::to_string(sqlite3_column_int64(differs.get(), 0)) +
                       " differs from the same trial in an earlier part; parts of one sweep "
                       "run by one build agree trial for trial");
    }
  }
  result.duplicates += duplicates;
  result.per_part.push_back(db.integer("SELECT COUNT(*) FROM part.trials"));
}

// Every part's runs (with their builds) and git commit, not only the first's.
void gather_part_meta(MergedDb& db, const std::string& part, nlohmann::json* invocations,
                      std::set<std::string>* commits) {
  const std::string key = "invocations";
  Statement runs = db.query("SELECT value FROM part.meta WHERE key = ?", &key);
  if (sqlite3_step(runs.get()) == SQLITE_ROW) {
    const nlohmann::json part_runs = nlohmann::json::parse(
        reinterpret_cast<const char*>(sqlite3_column_text(runs.get(), 0)), nullptr, false);
    for (nlohmann::json run : part_runs.is_array() ? part_runs : nlohmann::json::array()) {
      run["part"] = part;
      invocations->push_back(run);
    }
  }
  runs.reset();
  const std::string commit_key = "git_commit";
  Statement commit = db.query("SELECT value FROM part.meta WHERE key = ?", &commit_key);
  if (sqlite3_step(commit.get()) == SQLITE_ROW) {
    commits->insert(reinterpret_cast<const char*>(sqlite3_column_text(commit.get(), 0)));
  }
}

void write_merged_meta(MergedDb& db, const std::vector<std::string>& parts,
                       const nlohmann::json& invocations, const std::set<std::string>& commits) {
  nlohmann::json merged_from = nlohmann::json::array();
  for (const std::string& part : parts) merged_from.push_back(part);
  std::string commit_list;  // one, or the parts' different ones
  for (const std::string& c : commits) commit_list += (commit_list.empty() ? "" : ", ") + c;
  for (const auto& [key, value] :
       {std::pair<std::string, std::string>{"created_utc", utc_timestamp()},
        {"merged_from", merged_from.dump()},
        {"invocations", invocations.dump()},
        {"git_commit", commit_list}}) {
    Statement put = db.query("INSERT INTO main.meta VALUES (?, ?)", &key);
    sqlite3_bind_text(put.get(), 2, value.c_str(), -1, SQLITE_TRANSIENT);
    db.step_done(put);
  }
}

// the trials in no part: their count, and the first few
void note_missing_trials(MergedDb& db, const PartSchema& schema, MergeResult& result) {
  result.merged = db.integer("SELECT COUNT(*) FROM main.trials");
  if (schema.trials < 0) return;
  result.missing = schema.trials - result.merged;
  Statement ids = db.query("SELECT trial FROM main.trials ORDER BY trial");
  std::int64_t expected = 0;
  const auto note_gap_until = [&](std::int64_t end) {
    for (; expected < end && result.first_missing.size() < 10; ++expected) {
      result.first_missing.push_back(expected);
    }
    expected = end + 1;
  };
  while (result.first_missing.size() < 10 && sqlite3_step(ids.get()) == SQLITE_ROW) {
    note_gap_until(sqlite3_column_int64(ids.get(), 0));
  }
  note_gap_until(schema.trials);
}

// The merged database built in the temp file `tmp`, part by part.
void fill_merged(const std::string& tmp, const std::vector<std::string>& parts,
                 const PartSchema& schema, MergeResult& result) {
  MergedDb db(tmp);
  // built in one go: a failure discards the temp file, so no journal is needed until the end
  db.exec("PRAGMA journal_mode=OFF; PRAGMA synchronous=OFF;");
  const std::string compare = deterministic_columns(schema.columns);
  nlohmann::json invocations = nlohmann::json::array();
  std::set<std::string> commits;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    // what is read from the part and fails names the part (a file cut short, say)
    try {
      check_and_count_part(db, parts[i], i == 0, schema, compare, result);
    } catch (const InputError&) {
      throw;
    } catch (const std::runtime_error& e) {
      throw InputError(parts[i] + ": cannot read its trials (" + e.what() + ")");
    }
    db.exec("INSERT OR IGNORE INTO main.trials SELECT * FROM part.trials");
    gather_part_meta(db, parts[i], &invocations, &commits);
    db.exec("DETACH DATABASE part");
  }
  write_merged_meta(db, parts, invocations, commits);
  note_missing_trials(db, schema, result);
  db.exec("PRAGMA journal_mode=WAL;");
}

}  // namespace

MergeResult merge_sweep_databases(const std::string& out, const std::vector<std::string>& parts) {
  if (parts.empty()) throw InputError("pamsim merge: name at least one database to merge");
  // every part checked (and a WAL a killed shard left recovered) before anything is written
  PartSchema schema;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    std::error_code ec;
    if (std::filesystem::equivalent(parts[i], out, ec)) {
      throw InputError(parts[i] + ": is the output too; merge into a new file");
    }
    const PartSchema got = schema_of(ResultsDb::open_existing(parts[i]), parts[i]);
    if (i == 0)
      schema = got;
    else
      check_part(parts[i], got, schema, parts[0]);
  }

  MergeResult result;
  result.trials = schema.trials;
  result.sweep_file = schema.sweep_file;
  create_sqlite_file(out, "merged sweep database", "merge into a new file",
                     [&](const std::string& tmp) { fill_merged(tmp, parts, schema, result); });
  return result;
}

}  // namespace pamsim
