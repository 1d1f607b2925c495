// mpi_messages.cc: see mpi_messages.h.
#include "sim/sweep/mpi_messages.h"

#include <cstring>
#include <stdexcept>

#include "sim/io/provenance.h"  // fnv1a64

namespace pamsim {
namespace mpi {
namespace {

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

}  // namespace

void check(int rc, const char* call) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + call + " failed");
}

// FNV-1a of the sweep's canonical definition: every rank must run the same sweep.
std::uint64_t fingerprint(const SweepDefinition& sweep) { return fnv1a64(sweep.canonical_json()); }

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
  check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD),
        "MPI_Send");
}

std::vector<char> receive_bytes(const MPI_Status& status) {
  int n = 0;
  check(MPI_Get_count(&status, MPI_BYTE, &n), "MPI_Get_count");
  std::vector<char> bytes(static_cast<std::size_t>(n));
  check(MPI_Recv(bytes.data(), n, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE),
        "MPI_Recv");
  return bytes;
}

}  // namespace mpi
}  // namespace pamsim
