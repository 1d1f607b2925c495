// mpi_sweep.cc: see mpi_sweep.h: the session, rank 0 handing out trials and storing what
// comes back, and the worker ranks running them (the messages: mpi_messages.h). Rank 0
// polls with MPI_Iprobe and a short sleep rather than a blocking receive, which in Open MPI
// spins a core the workers on its node need.
#include "sim/sweep/mpi_sweep.h"
#include "sim/sweep/mpi_messages.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <iostream>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace pamsim {

using namespace mpi;  // the messages

namespace {

constexpr auto kPollInterval = std::chrono::milliseconds(1);
constexpr auto kReportInterval =
    std::chrono::milliseconds(200);                           // results sent at least this often
constexpr auto kDrainLimit = std::chrono::milliseconds(100);  // rank 0 commits at least this often

}  // namespace

// ---- the session ---------------------------------------------------------------------

bool MpiSession::launched() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(var)) return true;
  }
  return false;
}

MpiSession::MpiSession() {
  int provided = 0;
  check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;  // the ranks sharing this node's memory: they share its cores
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &local_size_);
  MPI_Comm_free(&node);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

bool MpiSession::broadcast_go(bool go) const {
  decided_ = true;
  int flag = go ? 1 : 0;
  check(MPI_Bcast(&flag, 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return flag == 1;
}

void MpiSession::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);  // (MPI_Abort does not return)
}

// ---- rank 0 --------------------------------------------------------------------------

namespace {

// Rank 0's side of the job: hands trials out as workers ask, stores what they report.
class Coordinator {
 public:
  Coordinator(const MpiSession& mpi, const SweepDefinition& sweep, ResultsDb& db,
              const SweepRunOptions& options)
      : mpi_(mpi),
        sweep_(sweep),
        db_(db),
        options_(options),
        total_(sweep.trials()),
        finished_(db.finished_trials(total_)),
        expected_(fingerprint(sweep)),
        workers_left_(mpi.size() - 1) {
    for (bool f : finished_) result_.already_done += f ? 1 : 0;
  }

  SweepRunResult run() {
    const auto start = std::chrono::steady_clock::now();
    while (workers_left_ > 0) {
      drain();
      if (!batch_.empty()) {
        store_trials(sweep_, db_, batch_, options_, result_);
      } else {
        std::this_thread::sleep_for(kPollInterval);
      }
    }
    result_.interrupted = result_.already_done + result_.ran < options_.shard.trials_of(total_);
    if (result_.interrupted && !(options_.stop && options_.stop->load())) {
      result_.incomplete_reason = !refused_.empty()
                                      ? std::to_string(refused_.size()) + " of " +
                                            std::to_string(mpi_.size() - 1) +
                                            " worker ranks ran no trials (" + first_refusal_ + ")"
                                      : "a worker rank stopped before its trials were done";
    }
    result_.wall_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result_;
  }

 private:
  // what has arrived, answered at once; then one commit for all of it (at most one report
  // per worker and 100 ms between commits, so a busy job still commits steadily)
  void drain() {
    const auto drain_start = std::chrono::steady_clock::now();
    for (int drained = 0;
         drained < mpi_.size() - 1 && std::chrono::steady_clock::now() - drain_start < kDrainLimit;
         ++drained) {
      int arrived = 0;
      MPI_Status status;
      check(MPI_Iprobe(MPI_ANY_SOURCE, kTagReport, MPI_COMM_WORLD, &arrived, &status),
            "MPI_Iprobe");
      if (!arrived) break;
      answer(decode(receive_bytes(status), sweep_), status.MPI_SOURCE);
    }
  }

  void answer(Report report, int from) {
    std::int64_t want = report.want;
    if (!report.load_error.empty() || report.fingerprint != expected_) {
      if (refused_.insert(from).second) {  // said once; it gets no trials
        const std::string why =
            report.load_error.empty() ? "its sweep file differs from rank 0's" : report.load_error;
        std::cerr << "pamsim sweep: rank " << from << " runs no trials: " << why << "\n";
        if (first_refusal_.empty()) first_refusal_ = "rank " + std::to_string(from) + ": " + why;
      }
      if (want > 0) send_bytes({}, from, kTagWork);
      want = want > 0 ? 0 : want;
    }
    for (TrialRecord& r : report.records) batch_.push_back(std::move(r));
    if (want > 0) {
      const std::vector<std::int64_t> trials = hand_out(want);
      std::vector<char> bytes(trials.size() * sizeof(std::int64_t));
      if (!trials.empty()) std::memcpy(bytes.data(), trials.data(), bytes.size());
      send_bytes(bytes, from, kTagWork);
    }
    if (want == -1) --workers_left_;
  }

  // up to `want` trials of this shard not yet finished, none once a stop is asked for
  std::vector<std::int64_t> hand_out(std::int64_t want) {
    std::vector<std::int64_t> trials;
    if (options_.stop && options_.stop->load()) return trials;
    for (; next_ < total_ && static_cast<std::int64_t>(trials.size()) < want; ++next_) {
      if (options_.shard.holds(next_) && !finished_[static_cast<std::size_t>(next_)]) {
        trials.push_back(next_);
      }
    }
    return trials;
  }

  const MpiSession& mpi_;
  const SweepDefinition& sweep_;
  ResultsDb& db_;
  const SweepRunOptions& options_;
  const std::int64_t total_;
  const std::vector<bool> finished_;
  const std::uint64_t expected_;
  int workers_left_;
  std::int64_t next_ = 0;  // the next trial to consider handing out
  std::set<int> refused_;  // ranks that run no trials (said once)
  std::string first_refusal_;
  std::vector<TrialRecord> batch_;
  SweepRunResult result_;
};

}  // namespace

SweepRunResult coordinate_mpi_sweep(const MpiSession& mpi, const SweepDefinition& sweep,
                                    ResultsDb& db, const SweepRunOptions& options) {
  SweepRunResult result = Coordinator(mpi, sweep, db, options).run();
  mpi.workers_done_ = true;
  return result;
}

// ---- ranks 1..N-1 --------------------------------------------------------------------

namespace {

// A worker rank: `threads` threads run the trials in `todo`, the main thread talks to rank 0
// (results out, trials in, asking ahead so no thread waits).
class WorkerRank {
 public:
  WorkerRank(const SweepDefinition& sweep, int threads, const std::atomic<bool>* stop,
             const std::string& load_error)
      : sweep_(sweep), threads_(threads), stop_(stop), no_more_(!load_error.empty()) {
    report_.fingerprint = fingerprint(sweep);
    report_.load_error = load_error;
  }

  void run() {
    if (report_.load_error.empty()) {
      running_threads_ = threads_;
      for (int i = 0; i < threads_; ++i) pool_.emplace_back([this] { run_trials(); });
    }
    try {
      talk_to_rank_0();
    } catch (...) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        no_more_ = true;
        todo_.clear();
        changed_.notify_all();
      }
      for (auto& t : pool_) t.join();
      throw;
    }
    for (auto& t : pool_) t.join();
  }

 private:
  void run_trials() {
    SweepTrialRunner runner(sweep_);
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      changed_.wait(lock, [&] { return !todo_.empty() || no_more_; });
      if (todo_.empty()) break;
      const std::int64_t t = todo_.front();
      todo_.pop_front();
      lock.unlock();
      TrialRecord record = runner.run(t);
      lock.lock();
      outbox_.push_back(std::move(record));
      changed_.notify_all();
    }
    --running_threads_;
    changed_.notify_all();
  }

  void talk_to_rank_0() {
    for (bool first = true;; first = false) {
      const bool done = take_report(first);
      if (report_.want == 0 && report_.records.empty()) continue;
      send_bytes(encode(report_, sweep_), 0, kTagReport);
      report_.records.clear();
      if (done) break;
      if (report_.want > 0) receive_work();
    }
  }

  // Waits for something to say, then takes the finished records and the trials to ask for
  // into report_; true once every thread has ended.
  bool take_report(bool first) {
    const std::int64_t ahead = 2 * static_cast<std::int64_t>(threads_);
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, kReportInterval, [&] {
      return first || !outbox_.empty() || running_threads_ == 0 ||
             (!no_more_ && static_cast<std::int64_t>(todo_.size()) < threads_) ||
             (stop_ && stop_->load() && !no_more_);
    });
    if (stop_ && stop_->load() && !no_more_) {  // the trials running finish; no new ones
      no_more_ = true;
      todo_.clear();
      changed_.notify_all();
    }
    report_.records.swap(outbox_);
    outbox_.clear();
    const bool done = running_threads_ == 0;
    report_.want = done ? -1
                   : no_more_
                       ? 0
                       : std::max<std::int64_t>(0, ahead - static_cast<std::int64_t>(todo_.size()));
    return done;
  }

  void receive_work() {
    MPI_Status status;
    check(MPI_Probe(0, kTagWork, MPI_COMM_WORLD, &status), "MPI_Probe");
    const std::vector<char> bytes = receive_bytes(status);
    std::vector<std::int64_t> trials(bytes.size() / sizeof(std::int64_t));
    if (!trials.empty()) std::memcpy(trials.data(), bytes.data(), bytes.size());
    std::lock_guard<std::mutex> lock(mutex_);
    if (trials.empty()) no_more_ = true;
    todo_.insert(todo_.end(), trials.begin(), trials.end());
    changed_.notify_all();
  }

  const SweepDefinition& sweep_;
  const int threads_;
  const std::atomic<bool>* stop_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::int64_t> todo_;
  std::vector<TrialRecord> outbox_;
  bool no_more_;
  int running_threads_ = 0;
  std::vector<std::thread> pool_;
  Report report_;
};

}  // namespace

void work_mpi_sweep(const MpiSession& /*mpi*/, const SweepDefinition& sweep, int threads,
                    const std::atomic<bool>* stop, const std::string& load_error) {
  WorkerRank(sweep, threads, stop, load_error).run();
}

}  // namespace pamsim
