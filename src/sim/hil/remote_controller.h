// remote_controller.h: a controller board on a link (hil_link.h) as the trial's command
// source (core/trial.h: CommandSource): at every control tick the muscles' raw readings go out
// as a pamhil packet, and the board's command for that tick comes back. In lockstep the plant
// waits for it (hil.command_timeout_ms); in real time the tick is paced to the wall clock and
// a command must come before the next tick. A command late or lost: the last one is held for
// hil.hold_ticks ticks, then hil.safe_command (vent: 0 Pa); a packet of another tick, a
// sequence gap, a bad checksum, another version: counted and passed over; no packet at all for
// hil.link_lost_s: the trial ends there. Faults can be injected as hardware has them (a share
// of the commands dropped, a burst, corrupted serial bytes), from a seed.
#pragma once

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "sim/core/scenario.h"
#include "sim/core/trial.h"
#include "sim/hil/hil_link.h"

namespace pamsim {

enum class HilMode { kLockstep, kRealTime };

struct HilFaults {
  double drop_fraction = 0.0;  // of the board's commands, each dropped with this probability
  long burst_at_tick = -1;     // the commands of ticks [at, at + length) dropped
  long burst_length = 0;
  std::uint64_t seed = 1;
};

// One control tick as the link saw it (link.csv).
struct HilTick {
  long tick = 0;
  double time_s = 0.0;
  double sent_s = 0.0;     // wall clock since the trial's start
  double arrived_s = NAN;  // the command's arrival; NaN: none
  bool on_time = false;
  char applied = 'b';      // b the board's command, h the last one held, v vented
  double jitter_ms = 0.0;  // real time: the send's delay after the tick's due time
};

class RemoteController final : public CommandSource {
 public:
  RemoteController(HilLink& link, const HilSpec& spec, HilMode mode, double control_hz,
                   int muscle_count, const HilFaults& faults);

  // Waits up to `timeout_s` for the board's hello. Throws InputError when none comes, or it
  // speaks another pamhil version or runs another number of muscles.
  void connect(double timeout_s);
  bool command(const ControlTick& tick, std::vector<double>* p_cmd_pa, std::string* why) override;
  // Tells the board the trial is over (its last readings carry PAMHIL_FLAG_END).
  void finish(double time_s);

  int encoding() const { return encoding_; }
  const std::vector<HilTick>& ticks() const { return ticks_; }
  // latency (p50, p99, max), jitter, missed, held and vented ticks, refusals: summary.json's "hil"
  nlohmann::json summary() const;

 private:
  using Clock = std::chrono::steady_clock;
  bool await_command(long index, Clock::time_point deadline, pamhil_packet* packet);
  bool dropped(long index);
  pamhil_packet readings_packet(const ControlTick& tick);  // the tick's readings, numbered
  double wall_s() const;

  HilLink& link_;
  HilSpec spec_;
  HilMode mode_;
  double period_s_;
  int muscles_;
  HilFaults faults_;
  std::mt19937_64 random_;
  int encoding_ = PAMHIL_FLOAT64;
  std::uint32_t sent_sequence_ = 0, expected_sequence_ = 0;
  Clock::time_point start_, last_packet_;
  std::vector<double> last_command_;
  bool have_command_ = false;
  long missed_in_a_row_ = 0;
  long missed_ = 0, held_ = 0, vented_ = 0, injected_drops_ = 0, stale_ = 0, gaps_ = 0;
  std::vector<HilTick> ticks_;
};

}  // namespace pamsim
