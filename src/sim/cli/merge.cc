// merge.cc: `pamsim merge OUT.db PART.db...`: one sweep database from the databases of its
// shards (`pamsim sweep --shard I/N`), see sim/sweep/merge.h. Prints OUT.db on stdout and
// on stderr what came from where, the duplicates kept once and the trials still missing
// (exit 0: the merged database is complete or can be finished with --resume).
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/sweep/merge.h"

namespace pamsim {
namespace {

struct MergeOptions {
  std::string out;
  std::vector<std::string> parts;
};

void merge(const MergeOptions& opt) {
  const MergeResult r = merge_sweep_databases(opt.out, opt.parts);
  for (std::size_t i = 0; i < opt.parts.size(); ++i) {
    std::cerr << "pamsim merge: " << opt.parts[i] << ": " << r.per_part[i] << " trials\n";
  }
  std::cerr << "pamsim merge: " << r.merged << " trials into " << opt.out;
  if (r.trials >= 0) std::cerr << " (of " << r.trials << ")";
  std::cerr << "\n";
  if (r.duplicates > 0) {
    std::cerr << "pamsim merge: " << r.duplicates
              << " trials were in more than one part (identical, kept once)\n";
  }
  if (r.missing > 0) {
    std::cerr << "pamsim merge: " << r.missing << " trials are missing (in no part), first:";
    for (std::int64_t t : r.first_missing) std::cerr << " " << t;
    std::cerr << "; run them with: pamsim sweep "
              << (r.sweep_file.empty() ? "SWEEP.toml" : r.sweep_file) << " --db " << opt.out
              << " --resume\n";
  }
  std::cout << opt.out << "\n";
}

}  // namespace

void add_merge_command(CLI::App& app) {
  const auto [cmd, opt] = add_command<MergeOptions>(
      app, "merge", "Merge the databases of a sweep's shards (sweep --shard I/N) into one", merge);
  cmd->add_option("out", opt->out, "The merged database (a new file)")->required();
  cmd->add_option("parts", opt->parts, "The shards' databases")->required();
}

}  // namespace pamsim
