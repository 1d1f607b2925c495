// mpi_messages.h: the two messages of an MPI sweep (mpi_sweep.cc), both byte buffers:
//   kTagReport  worker -> 0: want (trials it asks for; 0 none; -1 it is done), the sweep's
//               fingerprint, a load error (empty when fine), then finished trial records
//               (trial, seed, status, message, every metric as 8 raw bytes: bit for bit)
//   kTagWork    0 -> worker (only when want > 0): trial numbers; none means no more
// Internal to the MPI sweep (built only with -DPAMSIM_MPI=ON).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

#include "sim/sweep/results_db.h"  // TrialRecord
#include "sim/sweep/sweep.h"

namespace pamsim {
namespace mpi {

constexpr int kTagReport = 1;
constexpr int kTagWork = 2;

// Throws std::runtime_error "MPI: <call> failed" unless rc is MPI_SUCCESS.
void check(int rc, const char* call);

// FNV-1a of the sweep's canonical definition: every rank must run the same sweep.
std::uint64_t fingerprint(const SweepDefinition& sweep);

struct Report {
  std::int64_t want = 0;
  std::uint64_t fingerprint = 0;
  std::string load_error;
  std::vector<TrialRecord> records;
};

std::vector<char> encode(const Report& r, const SweepDefinition& sweep);
// Throws std::runtime_error for a message cut short, too long, or naming a bad trial.
Report decode(const std::vector<char>& bytes, const SweepDefinition& sweep);

void send_bytes(const std::vector<char>& bytes, int to, int tag);
// The message `status` announced, received.
std::vector<char> receive_bytes(const MPI_Status& status);

}  // namespace mpi
}  // namespace pamsim
