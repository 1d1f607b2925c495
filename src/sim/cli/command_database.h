// command_database.h: what the commands that run into a database (sweep, tune) share: the
// output folder and database path from their options, the database opened or created in its
// folder (made if missing, removed again if the database cannot be made there), and the
// warning when the database was started by another pamsim version.
#pragma once

#include <memory>
#include <string>

#include "sim/io/outputs.h"      // FolderGuard
#include "sim/io/sqlite_file.h"  // prepare_database_folder

namespace CLI {
class App;
}

namespace pamsim {

// --out, --db, --resume and --threads, as a command that runs into a database has them.
struct DatabaseOptions {
  std::string out;
  std::string db;
  bool resume = false;
  int threads = 0;
};

// Registers them on `cmd`, with the command's words for its database, for what --resume
// continues and for the default output folder.
void add_database_options(CLI::App* cmd, DatabaseOptions* options, const std::string& db_help,
                          const std::string& resume_help, const std::string& out_help);

struct CommandDatabase {
  std::string out;   // --out, default renders/<input file's name without extension>
  std::string path;  // --db, default <out>/<file name>
  bool exists = false;
};

CommandDatabase command_database(const std::string& input_file, const DatabaseOptions& options,
                                 const std::string& file_name);

// `open()` (which opens or creates the database at `db.path`) with the database's folder made
// first if it is missing and removed again if `open()` throws.
template <class Open>
auto open_in_database_folder(const CommandDatabase& db, const std::string& file_name, Open open) {
  const std::unique_ptr<FolderGuard> folder = prepare_database_folder(db.path, file_name);
  auto opened = open();
  if (folder) folder->keep();
  return opened;
}

// "pamsim <command>: warning: <path> was started by pamsim <made_by>, this is <ours>; its
// <items> may not be comparable" on stderr, when `made_by` is not this version.
void warn_if_other_version(const std::string& command, const std::string& path,
                           const std::string& made_by, const std::string& items);

}  // namespace pamsim
