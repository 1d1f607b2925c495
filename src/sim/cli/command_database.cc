// command_database.cc: see command_database.h.
#include "sim/cli/command_database.h"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

namespace pamsim {

void add_database_options(CLI::App* cmd, DatabaseOptions* options, const std::string& db_help,
                          const std::string& resume_help, const std::string& out_help) {
  cmd->add_option("--db", options->db, db_help);
  cmd->add_option("--out", options->out, out_help);
  cmd->add_option("--threads", options->threads, "Worker threads (default: all cores)");
  cmd->add_flag("--resume", options->resume, resume_help);
}

CommandDatabase command_database(const std::string& input_file, const DatabaseOptions& options,
                                 const std::string& file_name) {
  CommandDatabase db;
  db.out = options.out.empty() ? "renders/" + std::filesystem::path(input_file).stem().string()
                               : options.out;
  db.path = options.db.empty() ? db.out + "/" + file_name : options.db;
  std::error_code ec;
  db.exists = std::filesystem::exists(db.path, ec);
  return db;
}

void warn_if_other_version(const std::string& command, const std::string& path,
                           const std::string& made_by, const std::string& items) {
  if (made_by == PAMSIM_VERSION) return;
  std::cerr << "pamsim " << command << ": warning: " << path << " was started by pamsim " << made_by
            << ", this is " << PAMSIM_VERSION << "; its " << items << " may not be comparable\n";
}

}  // namespace pamsim
