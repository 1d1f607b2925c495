// sqlite_file.h: opening the SQLite files pamsim keeps its results in (sweep and tuning
// databases), the same way for both: a reader can read a database on read-only media, and a
// writer finds out that it cannot write before it runs anything.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "sim/io/outputs.h"
#include "sim/io/provenance.h"   // utc_timestamp, for created_utc

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

// For a command about to create or open the database `db_path` (given with --db): refuses a
// path that names a folder (suggesting `<db_path>/<file_name>`), and makes the database's
// folder if it is missing, returning the guard that removes it again unless the caller keeps
// it once the database exists (null when nothing was to be made).
std::unique_ptr<FolderGuard> prepare_database_folder(const std::string& db_path,
                                                     const std::string& file_name);

}  // namespace pamsim
