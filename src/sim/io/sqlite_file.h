// sqlite_file.h: the one room for the SQLite files pamsim keeps its results in (sweep, tuning
// and merged databases): creating one whole or not at all, opening it the same way for all
// (a reader can read a database on read-only media, a writer finds out that it cannot write
// before it runs anything), its writer's lock, its meta table and its transactions.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sim/io/outputs.h"
#include "sim/io/provenance.h"  // utc_timestamp, for created_utc

struct sqlite3;
struct sqlite3_stmt;

namespace pamsim {

// A prepared statement, finalized when it goes.
struct StatementDeleter {
  void operator()(sqlite3_stmt* s) const;
};
using Statement = std::unique_ptr<sqlite3_stmt, StatementDeleter>;

// `sql` prepared on `db`, or null if it does not prepare (sqlite3_errmsg says why).
Statement prepare_statement(sqlite3* db, const std::string& sql);

// `name` as an SQL identifier, quoted (axis keys hold dots).
std::string quoted_identifier(const std::string& name);

enum class DbAccess {
  kRead,   // export, report: nothing is written
  kWrite,  // --resume: trials will be stored
};

// Opens the existing database `path` (`what` names it in messages: "sweep database").
//   kRead:  read-write where the file and its folder are writable, so that a WAL left by a
//           killed writer is recovered into the database; read-only otherwise (a read-only
//           file, folder or mount), where the file is read as it stands.
//   kWrite: refused with "is read-only" when the file, its folder or the mount cannot be
//           written (a resume would otherwise run trials and fail at the first commit).
// Either way the file must read as an SQLite database. Throws InputError "<path>: <problem>";
// the caller owns the handle (sqlite3_close).
sqlite3* open_sqlite_file(const std::string& path, DbAccess access, const std::string& what);

// Creates the database `path` whole or not at all: refuses an existing `path` (InputError
// "<path>: already exists; <exists_hint>") or a journal left beside it by an earlier database,
// makes an empty file beside it exclusively (SQLite takes it for a new database), calls `fill`
// with that file's name to build the database (closing it before returning), then links it
// into place (link(2) refuses a file made meanwhile) and syncs the folder so the new name
// survives a power cut. Any failure removes the temp file. An error `fill` throws about the
// temp file is rethrown as std::runtime_error naming `path`; an InputError about anything
// else (an input `fill` read) passes unchanged.
void create_sqlite_file(const std::string& path, const std::string& what,
                        const std::string& exists_hint,
                        const std::function<void(const std::string& tmp)>& fill);

// An SQLite URI that reads the existing database `path` without writing it: immutable where
// its folder or the file cannot be written (read-only media, no -shm can be made), read-only
// otherwise. For ATTACH on a connection opened with SQLITE_OPEN_URI.
std::string read_only_uri(const std::string& path);

// One open pamsim database: the SQLite handle, its path (for messages) and, once taken, the
// writer's lock; closes both when it goes. Errors of SQLite itself are std::runtime_error
// "<path>: <what> (<SQLite's reason>)"; a refusal the user can act on is InputError.
class SqliteDb {
 public:
  SqliteDb() = default;
  // The existing database `path` (open_sqlite_file's rules; `what` names it in messages).
  static SqliteDb open(const std::string& path, DbAccess access, const std::string& what);
  // The empty file `tmp` that create_sqlite_file made, read-write, to be filled; with
  // `uri_attach`, ATTACH takes URIs (a read-only part: read_only_uri). Throws InputError
  // "<tmp>: cannot open the <what> (<why>)".
  static SqliteDb open_new(const std::string& tmp, const std::string& what,
                           bool uri_attach = false);

  SqliteDb(SqliteDb&& other) noexcept;
  SqliteDb& operator=(SqliteDb&& other) noexcept;
  SqliteDb(const SqliteDb&) = delete;
  SqliteDb& operator=(const SqliteDb&) = delete;
  ~SqliteDb();

  sqlite3* get() const { return db_; }
  const std::string& path() const { return path_; }

  // Runs `sql` (several statements allowed); throws std::runtime_error "<path>: <why>".
  void exec(const std::string& sql) const;
  // `sql` prepared; throws std::runtime_error "<path>: <what> (<why>)" if it does not prepare.
  Statement prepare(const std::string& sql, const std::string& what) const;
  [[noreturn]] void fail(const std::string& what) const;

  // The meta table's value for `key`, "" if absent (or if there is no meta table: not a
  // pamsim database).
  std::string meta(const std::string& key) const;
  // Writes (or replaces) meta entries; `what` names them in an error.
  void put_meta(const std::vector<std::pair<std::string, std::string>>& entries,
                const std::string& what) const;

  // Makes this handle the database's only writer: an exclusive flock(2) on the file, held
  // until the handle goes (released by the kernel if the process dies), then WAL journal with
  // full sync. Throws InputError "<path>: <busy>" when another process holds it, or
  // "<path>: cannot lock the <what> (<why>)".
  void become_writer(const std::string& busy, const std::string& what);

  // Runs `body` in one write transaction (BEGIN IMMEDIATE ... COMMIT), rolled back if it throws.
  void transaction(const std::function<void()>& body) const;

 private:
  SqliteDb(sqlite3* db, std::string path) : db_(db), path_(std::move(path)) {}
  void close();

  sqlite3* db_ = nullptr;
  std::string path_;
  int writer_lock_fd_ = -1;
};

// For a command about to create or open the database `db_path` (given with --db): refuses a
// path that names a folder (suggesting `<db_path>/<file_name>`), and makes the database's
// folder if it is missing, returning the guard that removes it again unless the caller keeps
// it once the database exists (null when nothing was to be made).
std::unique_ptr<FolderGuard> prepare_database_folder(const std::string& db_path,
                                                     const std::string& file_name);

}  // namespace pamsim
