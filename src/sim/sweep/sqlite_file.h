// sqlite_file.h: opening the SQLite files pamsim keeps its results in (sweep and tuning
// databases), the same way for both: a reader can read a database on read-only media, and a
// writer finds out that it cannot write before it runs anything.
#pragma once

#include <memory>
#include <string>

#include "sim/io/outputs.h"

struct sqlite3;

namespace pamsim {

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

// For a command about to create or open the database `db_path` (given with --db): refuses a
// path that names a folder (suggesting `<db_path>/<file_name>`), and makes the database's
// folder if it is missing, returning the guard that removes it again unless the caller keeps
// it once the database exists (null when nothing was to be made).
std::unique_ptr<FolderGuard> prepare_database_folder(const std::string& db_path,
                                                     const std::string& file_name);

}  // namespace pamsim
