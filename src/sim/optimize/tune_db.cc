// tune_db.cc: see tune_db.h.
#include "sim/optimize/tune_db.h"

#include <sqlite3.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "base/input_error.h"
#include "base/no_value.h"
#include "sim/io/provenance.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

const char* const kWhat = "tuning database";

// The evaluations table's columns after its key: the unit point, the values, each
// objective with its fitness, then violation, trials, ok.
std::string evaluation_columns(const TuneDefinition& def) {
  std::string columns;
  for (std::size_t i = 0; i < def.parameters.size(); ++i)
    columns += ", u" + std::to_string(i) + " REAL";
  for (std::size_t i = 0; i < def.parameters.size(); ++i)
    columns += ", x" + std::to_string(i) + " REAL";
  for (std::size_t i = 0; i < def.objectives.size(); ++i) {
    columns += ", objective" + std::to_string(i) + " REAL, fitness" + std::to_string(i) + " REAL";
  }
  return columns + ", violation REAL, trials INTEGER, ok INTEGER";
}

void fill_new_database(const SqliteDb& db, const TuneDefinition& def) {
  db.exec(
      "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT);"
      "CREATE TABLE evaluations(evaluation INTEGER PRIMARY KEY" +
      evaluation_columns(def) +
      ");"
      "CREATE TABLE trials(evaluation INTEGER, seed INTEGER, noise_scale REAL, status TEXT,"
      " message TEXT, metrics TEXT, PRIMARY KEY(evaluation, seed, noise_scale));");
  const std::string dir = std::filesystem::path(def.base_path).parent_path().string();
  std::vector<std::pair<std::string, std::string>> meta = {
      {"kind", "pamsim tune"},
      {"tune_definition", def.canonical_json()},
      {"tune_file", def.file},
      inputs_meta(load_recorded_scenario(def.base_text, def.base_path, def.overrides, dir, "")
                      .input_paths)};
  for (auto& entry : database_provenance_meta()) meta.push_back(std::move(entry));
  db.put_meta(meta, "cannot write");
}

// Binds `v` to the next parameter, NULL where it is not finite.
void bind_real(sqlite3_stmt* s, int* col, double v) {
  if (std::isfinite(v)) {
    sqlite3_bind_double(s, (*col)++, v);
  } else {
    sqlite3_bind_null(s, (*col)++);
  }
}

}  // namespace

TuneDb TuneDb::create(const std::string& path, const TuneDefinition& def) {
  create_sqlite_file(
      path, kWhat, "give --resume to continue it, or another --db",
      [&](const std::string& tmp) { fill_new_database(SqliteDb::open_new(tmp, kWhat), def); });
  return open_to_resume(path, def);
}

TuneDb TuneDb::open_to_resume(const std::string& path, const TuneDefinition& def) {
  TuneDb db(SqliteDb::open(path, DbAccess::kWrite, kWhat));
  if (db.meta("kind") != "pamsim tune") throw InputError(path + ": not a pamsim tuning database");
  if (db.meta("tune_definition") != def.canonical_json()) {
    throw InputError(path +
                     ": holds another tuning definition (a different file, base scenario "
                     "or setting); start a new --db");
  }
  refuse_changed_inputs(path, db.meta("inputs"), "tuning");
  db.db_.become_writer("another pamsim tune is writing to it", kWhat);
  return db;
}

TuneDb TuneDb::open_existing(const std::string& path) {
  TuneDb db(SqliteDb::open(path, DbAccess::kRead, kWhat));
  if (db.meta("kind") != "pamsim tune") throw InputError(path + ": not a pamsim tuning database");
  return db;
}

bool TuneDb::is_tune_database(const std::string& path) {
  try {
    return SqliteDb::open(path, DbAccess::kRead, "database").meta("kind") == "pamsim tune";
  } catch (const std::exception&) {
    return false;  // the sweep reader says what is wrong with it
  }
}

std::vector<TuneEvaluation> TuneDb::evaluations() const {
  const TuneDefinition def = tune_definition_from_db(*this);
  const std::size_t n_x = def.parameters.size(), n_o = def.objectives.size();
  Statement s = db_.prepare("SELECT * FROM evaluations ORDER BY evaluation", "tune database");
  std::vector<TuneEvaluation> out;
  const auto real = [&](int col) {
    return sqlite3_column_type(s.get(), col) == SQLITE_NULL ? kNaN
                                                            : sqlite3_column_double(s.get(), col);
  };
  int rc;
  while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) {
    TuneEvaluation e;
    int col = 0;
    e.index = sqlite3_column_int64(s.get(), col++);
    for (std::size_t i = 0; i < n_x; ++i) e.unit.push_back(real(col++));
    for (std::size_t i = 0; i < n_x; ++i) e.values.push_back(real(col++));
    for (std::size_t i = 0; i < n_o; ++i) {
      e.objectives.push_back(real(col++));
      e.fitness.push_back(real(col++));
    }
    e.violation = real(col++);
    e.trials = sqlite3_column_int(s.get(), col++);
    e.ok = sqlite3_column_int(s.get(), col++);
    out.push_back(e);
  }
  if (rc != SQLITE_DONE) db_.fail("cannot read the evaluations");
  return out;
}

void TuneDb::insert(const TuneEvaluation& e, const std::vector<TrialRow>& trials) {
  db_.transaction([&] {
    std::string sql = "INSERT INTO evaluations VALUES (?";
    const std::size_t cells = e.unit.size() + e.values.size() + 2 * e.objectives.size() + 3;
    for (std::size_t i = 0; i < cells; ++i) sql += ", ?";
    Statement s = db_.prepare(sql + ")", "tune database");
    int col = 1;
    sqlite3_bind_int64(s.get(), col++, e.index);
    for (double v : e.unit) bind_real(s.get(), &col, v);
    for (double v : e.values) bind_real(s.get(), &col, v);
    for (std::size_t i = 0; i < e.objectives.size(); ++i) {
      bind_real(s.get(), &col, e.objectives[i]);
      bind_real(s.get(), &col, e.fitness[i]);
    }
    bind_real(s.get(), &col, e.violation);
    sqlite3_bind_int(s.get(), col++, e.trials);
    sqlite3_bind_int(s.get(), col++, e.ok);
    if (sqlite3_step(s.get()) != SQLITE_DONE) {
      db_.fail("cannot store evaluation " + std::to_string(e.index));
    }
    Statement t = db_.prepare("INSERT INTO trials VALUES (?, ?, ?, ?, ?, ?)", "tune database");
    for (const TrialRow& r : trials) {
      sqlite3_bind_int64(t.get(), 1, e.index);
      sqlite3_bind_int64(t.get(), 2, static_cast<sqlite3_int64>(r.seed));
      sqlite3_bind_double(t.get(), 3, r.noise_scale);
      sqlite3_bind_text(t.get(), 4, r.status.c_str(), -1, SQLITE_TRANSIENT);
      sqlite3_bind_text(t.get(), 5, r.message.c_str(), -1, SQLITE_TRANSIENT);
      sqlite3_bind_text(t.get(), 6, r.metrics_json.c_str(), -1, SQLITE_TRANSIENT);
      if (sqlite3_step(t.get()) != SQLITE_DONE) db_.fail("cannot store a trial");
      sqlite3_reset(t.get());
    }
  });
}

TuneDefinition tune_definition_from_db(const TuneDb& db) {
  return tune_definition_from_json(db.meta("tune_definition"), db.meta("tune_file"), db.path());
}

}  // namespace pamsim
