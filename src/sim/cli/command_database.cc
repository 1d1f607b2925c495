// command_database.cc: see command_database.h.
#include "sim/cli/command_database.h"

#include <filesystem>
#include <iostream>

namespace pamsim {

CommandDatabase command_database(const std::string& input_file, const std::string& out_option,
                                 const std::string& db_option, const std::string& file_name) {
  CommandDatabase db;
  db.out = out_option.empty() ? "renders/" + std::filesystem::path(input_file).stem().string()
                              : out_option;
  db.path = db_option.empty() ? db.out + "/" + file_name : db_option;
  std::error_code ec;
  db.exists = std::filesystem::exists(db.path, ec);
  return db;
}

void warn_if_other_version(const std::string& command, const std::string& path,
                           const std::string& made_by, const std::string& items) {
  if (made_by == PAMSIM_VERSION) return;
  std::cerr << "pamsim " << command << ": warning: " << path << " was started by pamsim "
            << made_by << ", this is " << PAMSIM_VERSION << "; its " << items
            << " may not be comparable\n";
}

}  // namespace pamsim
