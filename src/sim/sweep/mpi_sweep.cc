// mpi_sweep.cc: see mpi_sweep.h. Two messages, both byte buffers:
//   kTagReport  worker -> 0: want (trials it asks for; 0 none; -1 it is done), the sweep's
//               fingerprint, a load error (empty when fine), then finished trial records
//               (trial, seed, status, message, every metric as 8 raw bytes: bit for bit)
//   kTagWork    0 -> worker (only when want > 0): trial numbers; none means no more
// Rank 0 polls with MPI_Iprobe and a short sleep rather than a blocking receive, which in
// Open MPI spins a core the workers on its node need.
#include "sim/io/provenance.h"
#include "sim/sweep/mpi_sweep.h"

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
namespace {

constexpr int kTagReport = 1;
constexpr int kTagWork = 2;
constexpr auto kPollInterval = std::chrono::milliseconds(1);
constexpr auto kReportInterval = std::chrono::milliseconds(200);   // results sent at least this often
constexpr auto kDrainLimit = std::chrono::milliseconds(100);       // rank 0 commits at least this often

void check(int rc, const char* call) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + call + " failed");
}

// FNV-1a of the sweep's canonical definition: every rank must run the same sweep.
std::uint64_t fingerprint(const SweepDefinition& sweep) { return fnv1a64(sweep.canonical_json()); }

// ---- the byte format -----------------------------------------------------------------

class Writer {
 public:
  template <typename T>
  void put(const T& v) {
    const auto* p = reinterpret_cast<const char*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  void put(const std::string& s) {
    put(static_cast<std::uint64_t>(s.size()));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  std::vector<char> bytes_;
};

class Reader {
 public:
  explicit Reader(const std::vector<char>& bytes) : bytes_(bytes) {}
  template <typename T>
  T get() {
    T v;
    need(sizeof(T));
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  std::string get_string() {
    const auto n = static_cast<std::size_t>(get<std::uint64_t>());
    need(n);
    std::string s(bytes_.data() + at_, n);
    at_ += n;
    return s;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  void need(std::size_t n) const {
    if (n > bytes_.size() - at_) throw std::runtime_error("MPI: a message was cut short");
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

struct Report {
  std::int64_t want = 0;
  std::uint64_t fingerprint = 0;
  std::string load_error;
  std::vector<TrialRecord> records;
};

std::vector<char> encode(const Report& r, const SweepDefinition& sweep) {
  Writer w;
  w.put(r.want);
  w.put(r.fingerprint);
  w.put(r.load_error);
  w.put(static_cast<std::uint64_t>(r.records.size()));
  for (const TrialRecord& t : r.records) {
    w.put(t.trial);
    w.put(t.summary.seed);
    w.put(t.summary.status);
    w.put(t.summary.message);
    for (const std::string& name : sweep.metric_names) w.put(t.summary.metric(name));
  }
  return w.bytes();
}

Report decode(const std::vector<char>& bytes, const SweepDefinition& sweep) {
  Reader in(bytes);
  Report r;
  r.want = in.get<std::int64_t>();
  r.fingerprint = in.get<std::uint64_t>();
  r.load_error = in.get_string();
  const auto n = in.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < n; ++i) {
    TrialRecord t;
    t.trial = in.get<std::int64_t>();
    if (t.trial < 0 || t.trial >= sweep.trials()) throw std::runtime_error("MPI: a bad trial");
    t.point = t.trial / sweep.seeds;
    t.seed_index = t.trial % sweep.seeds;
    t.summary.seed = in.get<std::uint64_t>();
    t.summary.status = in.get_string();
    t.summary.message = in.get_string();
    for (const std::string& name : sweep.metric_names) {
      t.summary.metrics.push_back({name, in.get<double>(), false});
    }
    r.records.push_back(std::move(t));
  }
  if (!in.done()) throw std::runtime_error("MPI: a message is longer than its content");
  return r;
}

void send_bytes(const std::vector<char>& bytes, int to, int tag) {
  check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag,
                 MPI_COMM_WORLD), "MPI_Send");
}

std::vector<char> receive_bytes(const MPI_Status& status) {
  int n = 0;
  check(MPI_Get_count(&status, MPI_BYTE, &n), "MPI_Get_count");
  std::vector<char> bytes(static_cast<std::size_t>(n));
  check(MPI_Recv(bytes.data(), n, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE), "MPI_Recv");
  return bytes;
}

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
  MPI_Comm node;   // the ranks sharing this node's memory: they share its cores
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
  std::exit(code);   // (MPI_Abort does not return)
}

// ---- rank 0 --------------------------------------------------------------------------

SweepRunResult coordinate_mpi_sweep(const MpiSession& mpi, const SweepDefinition& sweep,
                                    ResultsDb& db, const SweepRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::int64_t total = sweep.trials();
  const std::vector<bool> finished = db.finished_trials(total);
  SweepRunResult result;
  for (bool f : finished) result.already_done += f ? 1 : 0;
  const std::uint64_t expected = fingerprint(sweep);

  std::int64_t next = 0;   // the next trial to consider handing out
  auto hand_out = [&](std::int64_t want) {
    std::vector<std::int64_t> trials;
    if (options.stop && options.stop->load()) return trials;
    for (; next < total && static_cast<std::int64_t>(trials.size()) < want; ++next) {
      if (options.shard.holds(next) && !finished[static_cast<std::size_t>(next)]) {
        trials.push_back(next);
      }
    }
    return trials;
  };

  int workers_left = mpi.size() - 1;
  std::set<int> refused;   // ranks that run no trials (said once)
  std::string first_refusal;
  std::vector<TrialRecord> batch;
  while (workers_left > 0) {
    // what has arrived, answered at once; then one commit for all of it (at most one report
    // per worker and 100 ms between commits, so a busy job still commits steadily)
    const auto drain_start = std::chrono::steady_clock::now();
    for (int drained = 0; drained < mpi.size() - 1 &&
                          std::chrono::steady_clock::now() - drain_start < kDrainLimit;
         ++drained) {
      int arrived = 0;
      MPI_Status status;
      check(MPI_Iprobe(MPI_ANY_SOURCE, kTagReport, MPI_COMM_WORLD, &arrived, &status),
            "MPI_Iprobe");
      if (!arrived) break;
      Report report = decode(receive_bytes(status), sweep);
      const int from = status.MPI_SOURCE;
      std::int64_t want = report.want;
      if (!report.load_error.empty() || report.fingerprint != expected) {
        if (refused.insert(from).second) {   // said once; it gets no trials
          const std::string why = report.load_error.empty()
                                      ? "its sweep file differs from rank 0's"
                                      : report.load_error;
          std::cerr << "pamsim sweep: rank " << from << " runs no trials: " << why << "\n";
          if (first_refusal.empty()) first_refusal = "rank " + std::to_string(from) + ": " + why;
        }
        if (want > 0) send_bytes({}, from, kTagWork);
        want = want > 0 ? 0 : want;
      }
      for (TrialRecord& r : report.records) batch.push_back(std::move(r));
      if (want > 0) {
        const std::vector<std::int64_t> trials = hand_out(want);
        std::vector<char> bytes(trials.size() * sizeof(std::int64_t));
        if (!trials.empty()) std::memcpy(bytes.data(), trials.data(), bytes.size());
        send_bytes(bytes, from, kTagWork);
      }
      if (want == -1) --workers_left;
    }
    if (!batch.empty()) {
      store_trials(sweep, db, batch, options, result);
    } else {
      std::this_thread::sleep_for(kPollInterval);
    }
  }
  mpi.workers_done_ = true;
  result.interrupted = result.already_done + result.ran < options.shard.trials_of(total);
  if (result.interrupted && !(options.stop && options.stop->load())) {
    result.incomplete_reason =
        !refused.empty() ? std::to_string(refused.size()) + " of " +
                               std::to_string(mpi.size() - 1) + " worker ranks ran no trials (" +
                               first_refusal + ")"
                         : "a worker rank stopped before its trials were done";
  }
  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// ---- ranks 1..N-1 --------------------------------------------------------------------

void work_mpi_sweep(const MpiSession& /*mpi*/, const SweepDefinition& sweep, int threads,
                    const std::atomic<bool>* stop, const std::string& load_error) {
  std::mutex mutex;
  std::condition_variable changed;
  std::deque<std::int64_t> todo;
  std::vector<TrialRecord> outbox;
  bool no_more = !load_error.empty();
  int running_threads = 0;

  auto worker = [&] {
    SweepTrialRunner runner(sweep);
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      changed.wait(lock, [&] { return !todo.empty() || no_more; });
      if (todo.empty()) break;
      const std::int64_t t = todo.front();
      todo.pop_front();
      lock.unlock();
      TrialRecord record = runner.run(t);
      lock.lock();
      outbox.push_back(std::move(record));
      changed.notify_all();
    }
    --running_threads;
    changed.notify_all();
  };
  std::vector<std::thread> pool;
  if (load_error.empty()) {
    running_threads = threads;
    for (int i = 0; i < threads; ++i) pool.emplace_back(worker);
  }

  // the main thread talks to rank 0: results out, trials in, asking ahead so no thread waits
  const std::int64_t ahead = 2 * static_cast<std::int64_t>(threads);
  Report report;
  report.fingerprint = fingerprint(sweep);
  report.load_error = load_error;
  try {
    for (bool first = true;; first = false) {
      bool done = false;
      {
        std::unique_lock<std::mutex> lock(mutex);
        changed.wait_for(lock, kReportInterval, [&] {
          return first || !outbox.empty() || running_threads == 0 ||
                 (!no_more && static_cast<std::int64_t>(todo.size()) < threads) ||
                 (stop && stop->load() && !no_more);
        });
        if (stop && stop->load() && !no_more) {   // the trials running finish; no new ones
          no_more = true;
          todo.clear();
          changed.notify_all();
        }
        report.records.swap(outbox);
        outbox.clear();
        done = running_threads == 0;
        report.want = done ? -1 : no_more ? 0 : std::max<std::int64_t>(0, ahead - static_cast<std::int64_t>(todo.size()));
      }
      if (report.want == 0 && report.records.empty()) continue;
      send_bytes(encode(report, sweep), 0, kTagReport);
      report.records.clear();
      if (done) break;
      if (report.want > 0) {
        MPI_Status status;
        check(MPI_Probe(0, kTagWork, MPI_COMM_WORLD, &status), "MPI_Probe");
        const std::vector<char> bytes = receive_bytes(status);
        std::vector<std::int64_t> trials(bytes.size() / sizeof(std::int64_t));
        if (!trials.empty()) std::memcpy(trials.data(), bytes.data(), bytes.size());
        std::lock_guard<std::mutex> lock(mutex);
        if (trials.empty()) no_more = true;
        todo.insert(todo.end(), trials.begin(), trials.end());
        changed.notify_all();
      }
    }
  } catch (...) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      no_more = true;
      todo.clear();
      changed.notify_all();
    }
    for (auto& t : pool) t.join();
    throw;
  }
  for (auto& t : pool) t.join();
}

}  // namespace pamsim
