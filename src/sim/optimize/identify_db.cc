// identify_db.cc: see identify_db.h.
#include "sim/optimize/identify_db.h"

#include <sqlite3.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "base/input_error.h"
#include "sim/io/provenance.h"

namespace pamsim {
namespace {

const char* const kDbWhat = "identification database";
const char* const kDbKind = "pamsim identify";

// A point's key: the hex of its doubles' bits, so equal points are equal keys, exactly.
std::string point_key(const std::vector<double>& unit) {
  static const char* kHex = "0123456789abcdef";
  std::string key;
  for (double u : unit) {
    unsigned char bytes[sizeof(double)];
    std::memcpy(bytes, &u, sizeof(double));
    for (unsigned char b : bytes) {
      key += kHex[b >> 4];
      key += kHex[b & 15];
    }
  }
  return key;
}

}  // namespace

IdentifyDb::IdentifyDb(SqliteDb db) : db_(std::move(db)) {
  Statement s = db_.prepare("SELECT point, residuals FROM evaluations", "cannot read evaluations");
  while (sqlite3_step(s.get()) == SQLITE_ROW) {
    const auto* key = reinterpret_cast<const char*>(sqlite3_column_text(s.get(), 0));
    const int bytes = sqlite3_column_bytes(s.get(), 1);
    std::vector<double> r(static_cast<std::size_t>(bytes) / sizeof(double));
    if (bytes > 0)
      std::memcpy(r.data(), sqlite3_column_blob(s.get(), 1), r.size() * sizeof(double));
    stored_[key] = std::move(r);
  }
}

IdentifyDb IdentifyDb::create(const std::string& path, const IdentifyDefinition& def) {
  create_sqlite_file(
      path, kDbWhat, "give --resume to continue it, or another --db", [&](const std::string& tmp) {
        const SqliteDb db = SqliteDb::open_new(tmp, kDbWhat);
        db.exec(
            "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT);"
            "CREATE TABLE evaluations(point TEXT PRIMARY KEY, phase TEXT NOT NULL, cost REAL,"
            " residuals BLOB);");
        std::vector<std::pair<std::string, std::string>> meta = {
            {"kind", kDbKind},
            {"identify_definition", def.canonical_json()},
            {"identify_file", def.file},
            inputs_meta(identify_input_paths(def))};
        for (auto& entry : database_provenance_meta()) meta.push_back(std::move(entry));
        db.put_meta(meta, "cannot write");
      });
  return open_to_resume(path, def);
}

IdentifyDb IdentifyDb::open_to_resume(const std::string& path, const IdentifyDefinition& def) {
  SqliteDb db = SqliteDb::open(path, DbAccess::kWrite, kDbWhat);
  if (db.meta("kind") != kDbKind) throw InputError(path + ": not a pamsim identification database");
  if (db.meta("identify_definition") != def.canonical_json()) {
    throw InputError(path +
                     ": holds another identification (a different file, base scenario, "
                     "recording or setting); start a new --db");
  }
  refuse_changed_inputs(path, db.meta("inputs"), "identification");
  db.become_writer("another pamsim identify is writing to it", kDbWhat);
  return IdentifyDb(std::move(db));
}

std::optional<std::vector<double>> IdentifyDb::find(const std::vector<double>& unit) const {
  const auto it = stored_.find(point_key(unit));
  if (it == stored_.end()) return std::nullopt;
  return it->second;
}

void IdentifyDb::insert(const std::vector<double>& unit, const std::string& phase, double cost,
                        const std::vector<double>& residuals) {
  const std::string key = point_key(unit);
  if (stored_.count(key)) return;
  Statement s = db_.prepare("INSERT INTO evaluations VALUES (?, ?, ?, ?)", "cannot store");
  db_.transaction([&] {
    sqlite3_bind_text(s.get(), 1, key.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s.get(), 2, phase.c_str(), -1, SQLITE_TRANSIENT);
    if (std::isfinite(cost))
      sqlite3_bind_double(s.get(), 3, cost);
    else
      sqlite3_bind_null(s.get(), 3);
    sqlite3_bind_blob(s.get(), 4, residuals.data(),
                      static_cast<int>(residuals.size() * sizeof(double)), SQLITE_TRANSIENT);
    if (sqlite3_step(s.get()) != SQLITE_DONE) db_.fail("cannot store an evaluation");
  });
  stored_[key] = residuals;
}

}  // namespace pamsim
