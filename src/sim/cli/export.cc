// export.cc: `pamsim export DB -o FILE [--timing] [--force]` (-o is also --csv): a sweep
// database as CSV, one row per trial in trial order, the columns of the trials table
// (results_db.h), streamed to a temp file and renamed into place (FILE "-" is standard output; a
// FIFO or device is written through, never replaced). Numbers are written in their shortest exact
// form, missing values as empty cells. The per-run timing metrics (wall_time_s, realtime_factor)
// are left out unless --timing, so the same sweep exports the same file whatever the machine
// or thread count.
#include <CLI/CLI.hpp>

#include <charconv>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>

#include "base/atomic_file.h"
#include "base/input_error.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/io/outputs.h"
#include "sim/sweep/results_db.h"
#include "sim/io/temp_path.h"

namespace pamsim {
namespace {

struct ExportOptions {
  std::string db;
  std::string csv;
  bool timing = false;
  bool force = false;
};

// A CSV field, quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string csv_cell(const DbValue& v) {
  switch (v.kind) {
    case DbValue::Kind::kNull:
      return "";
    case DbValue::Kind::kText:
      return csv_field(v.text);
    case DbValue::Kind::kNumber:
      break;
  }
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v.number);  // shortest round trip
  return std::string(buf, r.ptr);
}

void export_csv(const ExportOptions& opt) {
  refuse_existing_file(opt.csv, opt.force);
  const ResultsDb db = ResultsDb::open_existing(opt.db);
  const std::vector<std::string> columns = db.trial_columns();

  // rows stream into the temp file (memory flat whatever the number of trials), then rename;
  // "-" (standard output), a FIFO or a device is written through instead
  const bool stream = is_stream_output(opt.csv);
  std::unique_ptr<TempPath> tmp;
  std::ofstream file;
  if (!stream) {
    tmp = std::make_unique<TempPath>(opt.csv, TempKind::kFile);
    file.open(tmp->path(), std::ios::binary | std::ios::trunc);
  } else if (opt.csv != "-") {
    file.open(opt.csv, std::ios::binary);
  }
  std::ostream& out = opt.csv == "-" ? std::cout : file;
  if (!out) throw InputError(opt.csv + ": cannot write (missing folder or no permission)");
  std::vector<bool> keep(columns.size());
  bool first = true;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    keep[c] = opt.timing || !is_timing_metric(columns[c]);
    if (!keep[c]) continue;
    out << (first ? "" : ",") << csv_field(columns[c]);
    first = false;
  }
  out << '\n';
  std::int64_t rows = 0;
  std::string line;
  db.for_each_trial([&](const std::vector<DbValue>& cells) {
    line.clear();
    bool first_cell = true;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (!keep[c]) continue;
      if (!first_cell) line += ',';
      line += csv_cell(cells[c]);
      first_cell = false;
    }
    out << line << '\n';
    ++rows;
  });
  out.flush();
  if (file.is_open()) file.close();
  if (!out || (file.is_open() && !file)) {
    throw InputError(opt.csv + ": writing failed (disk full?)");
  }
  if (tmp) {
    if (std::rename(tmp->path().c_str(), opt.csv.c_str()) != 0) {
      throw InputError(opt.csv + ": cannot move the CSV into place (" + std::strerror(errno) + ")");
    }
    tmp->release();
  }
  std::cerr << "pamsim export: " << rows << " trials to "
            << (opt.csv == "-" ? std::string("standard output") : opt.csv) << "\n";
}

}  // namespace

void add_export_command(CLI::App& app) {
  const auto [cmd, opt] = add_command<ExportOptions>(
      app, "export", "Write a sweep database as CSV (one row per trial)", export_csv);
  cmd->add_option("db", opt->db, "Sweep database (from pamsim sweep)")->required();
  // --csv: its name before 0.3 (-o/--output names a file everywhere now)
  cmd->add_option("-o,--output,--csv", opt->csv, "Output CSV file (- for standard output)")
      ->required();
  cmd->add_flag("--force", opt->force, "Replace an existing CSV file");
  cmd->add_flag("--timing", opt->timing, "Include wall_time_s and realtime_factor");
}

}  // namespace pamsim
