// mpi_sweep.h: a sweep spread over the ranks of an MPI job (`mpirun -np N pamsim sweep ...`,
// in a build with -DPAMSIM_MPI=ON). Rank 0 coordinates: it alone opens the results database,
// exactly as a sweep on one machine does (same checks, --resume, --shard), hands out the
// unfinished trials on request and commits the results as they arrive (everything that
// arrived meanwhile in one transaction). Ranks 1..N-1 run trials on their threads
// (SweepTrialRunner) and ask for more before they run dry, so a rank whose trials are slow
// simply asks less often: dynamic load balancing, with trials differing in cost.
//
// A trial's record depends only on its number, so the database, and its export, are the same
// whatever the number of ranks or threads. A rank that dies takes the job with it (Open MPI
// aborts every rank and reports which one died); the results committed so far stay, and
// `--resume` runs the rest.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include "sim/sweep/results_db.h"
#include "sim/sweep/sweep.h"
#include "sim/sweep/sweep_runner.h"

namespace pamsim {

// MPI for one command: initialised (MPI_THREAD_FUNNELED: only the main thread talks) when
// the process was started by an MPI launcher (mpirun, srun), finalised when it goes.
class MpiSession {
 public:
  // True in a build with MPI when a launcher started this process (its environment says).
  static bool launched();

  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  int ranks_on_this_node() const { return local_size_; }

  // Rank 0 tells every rank whether the sweep goes ahead (after it opened the database);
  // the others return what it said.
  bool broadcast_go(bool go) const;
  bool decided() const { return decided_; }  // broadcast_go has been called
  // Rank 0: every worker has sent its last report (set by coordinate_mpi_sweep), so rank 0
  // may end on its own, e.g. with an error, without leaving a rank waiting.
  bool workers_done() const { return workers_done_; }
  // Ends every rank of the job with `code`, from a rank that cannot go on.
  [[noreturn]] void abort(int code) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  int local_size_ = 1;
  mutable bool decided_ = false;
  mutable bool workers_done_ = false;
  friend SweepRunResult coordinate_mpi_sweep(const MpiSession&, const SweepDefinition&, ResultsDb&,
                                             const SweepRunOptions&);
};

// Rank 0: runs every trial of `sweep` (of options.shard) not yet in `db` on the other ranks
// and stores the results; options.threads is unused (workers use their own). Stops handing
// out trials when options.stop is set and returns once every worker has sent what it ran;
// when trials are left unrun for another reason (a rank that could not read the sweep, a
// worker stopped on its own), the result's incomplete_reason says why.
SweepRunResult coordinate_mpi_sweep(const MpiSession& mpi, const SweepDefinition& sweep,
                                    ResultsDb& db, const SweepRunOptions& options);

// Ranks 1..N-1: runs the trials rank 0 hands out on `threads` threads until it has none left
// (or `stop` is set, then the trials running finish and are sent). `load_error` is non-empty
// when this rank could not read the sweep: it sends that to rank 0, which reports it, and ends.
void work_mpi_sweep(const MpiSession& mpi, const SweepDefinition& sweep, int threads,
                    const std::atomic<bool>* stop, const std::string& load_error);

}  // namespace pamsim
