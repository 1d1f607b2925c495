// remote_controller.cc: see remote_controller.h. A tick: pace (real time), send the readings,
// wait for that tick's command until its deadline, then the board's command, the last one
// held, or the safe one.
#include "sim/hil/remote_controller.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "base/input_error.h"

namespace pamsim {
namespace {

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double rank = std::ceil(q * static_cast<double>(v.size()));
  return v[std::min(v.size() - 1, static_cast<std::size_t>(std::max(1.0, rank)) - 1)];
}

nlohmann::json ms_stats(const std::vector<double>& ms) {
  if (ms.empty()) return nullptr;
  return {{"p50", percentile(ms, 0.5)},
          {"p99", percentile(ms, 0.99)},
          {"max", *std::max_element(ms.begin(), ms.end())}};
}

}  // namespace

RemoteController::RemoteController(HilLink& link, const HilSpec& spec, HilMode mode,
                                   double control_hz, int muscle_count, const HilFaults& faults)
    : link_(link),
      spec_(spec),
      mode_(mode),
      period_s_(1.0 / control_hz),
      muscles_(muscle_count),
      faults_(faults),
      random_(faults.seed),
      last_command_(static_cast<std::size_t>(muscle_count), 0.0) {}

double RemoteController::wall_s() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void RemoteController::connect(double timeout_s) {
  const Clock::time_point deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                        std::chrono::duration<double>(timeout_s));
  pamhil_packet hello{};
  for (;;) {
    const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
    const bool got = left > 0 && link_.receive(left, &hello);
    if (link_.counts().other_version > 0) {
      throw InputError(link_.describe() +
                       ": the controller speaks another pamhil version (this "
                       "pamsim speaks " +
                       std::to_string(PAMHIL_VERSION) + ")");
    }
    if (!got) {
      throw InputError(link_.describe() + ": no controller said hello within " +
                       std::to_string(timeout_s) + " s (start it, pointed at this link)");
    }
    if (hello.kind == PAMHIL_COMMAND && hello.tick == PAMHIL_HELLO_TICK) break;
  }
  if (hello.muscle_count != muscles_) {
    throw InputError(link_.describe() + ": the controller runs " +
                     std::to_string(hello.muscle_count) + " muscles, the scenario " +
                     std::to_string(muscles_));
  }
  encoding_ = hello.encoding;
  expected_sequence_ = hello.sequence + 1;
  start_ = last_packet_ = Clock::now();
}

bool RemoteController::dropped(long index) {
  const bool burst = faults_.burst_at_tick >= 0 && index >= faults_.burst_at_tick &&
                     index < faults_.burst_at_tick + faults_.burst_length;
  // one draw per command received, so the draws do not depend on the timing
  const bool random_drop = faults_.drop_fraction > 0 && std::uniform_real_distribution<double>(
                                                            0, 1)(random_) < faults_.drop_fraction;
  return burst || random_drop;
}

bool RemoteController::await_command(long index, Clock::time_point deadline,
                                     pamhil_packet* packet) {
  for (;;) {
    const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
    if (left <= 0 || !link_.receive(left, packet)) return false;
    last_packet_ = Clock::now();
    if (packet->kind != PAMHIL_COMMAND || packet->muscle_count != muscles_ ||
        packet->tick == PAMHIL_HELLO_TICK) {
      continue;  // (a hello said again before the first readings reached the board)
    }
    if (packet->sequence != expected_sequence_) gaps_ += 1;
    expected_sequence_ = packet->sequence + 1;
    if (packet->tick != static_cast<std::uint32_t>(index)) {
      ++stale_;  // an earlier tick's, come late
      continue;
    }
    if (dropped(index)) {
      ++injected_drops_;
      return false;  // the board answers once: nothing more comes for this tick
    }
    return true;
  }
}

pamhil_packet RemoteController::readings_packet(const ControlTick& tick) {
  pamhil_packet out{};
  out.kind = PAMHIL_READINGS;
  out.encoding = static_cast<std::uint8_t>(encoding_);
  out.muscle_count = static_cast<std::uint8_t>(muscles_);
  out.flags = tick.enabled ? PAMHIL_FLAG_ENABLED : 0;
  out.sequence = sent_sequence_++;
  out.tick = static_cast<std::uint32_t>(tick.index);
  out.time_s = tick.time_s;
  for (int j = 0; j < muscles_; ++j) {
    const MuscleReading& r = (*tick.readings)[static_cast<std::size_t>(j)];
    double* v = out.values + PAMHIL_READING_VALUES * j;
    v[0] = r.pressure_sensor_v;
    v[1] = r.gauge_v;
    v[2] = r.fiber_rate_m_s;
    v[3] = (*tick.p_tp_pa)[static_cast<std::size_t>(j)];
  }
  return out;
}

bool RemoteController::command(const ControlTick& tick, std::vector<double>* p_cmd_pa,
                               std::string* why) {
  HilTick record;
  record.tick = tick.index;
  record.time_s = tick.time_s;
  const Clock::time_point due = start_ + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(tick.index * period_s_));
  if (mode_ == HilMode::kRealTime) {
    std::this_thread::sleep_until(due);
    record.jitter_ms = std::chrono::duration<double, std::milli>(Clock::now() - due).count();
  }
  const pamhil_packet out = readings_packet(tick);
  record.sent_s = wall_s();
  link_.send(out);
  const Clock::time_point deadline =
      mode_ == HilMode::kRealTime
          ? due + std::chrono::duration_cast<Clock::duration>(
                      std::chrono::duration<double>(period_s_))
          : Clock::now() + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(spec_.command_timeout_s));
  pamhil_packet in{};
  if (await_command(tick.index, deadline, &in)) {
    record.arrived_s = wall_s();
    record.on_time = true;
    std::copy(in.values, in.values + muscles_, last_command_.begin());
    have_command_ = true;
    missed_in_a_row_ = 0;
  } else {
    ++missed_;
    ++missed_in_a_row_;
    const bool hold =
        have_command_ && (missed_in_a_row_ <= spec_.hold_ticks || spec_.safe == SafeCommand::kHold);
    record.applied = hold ? 'h' : 'v';
    ++(hold ? held_ : vented_);
    if (!hold) std::fill(last_command_.begin(), last_command_.end(), 0.0);
  }
  ticks_.push_back(record);
  *p_cmd_pa = last_command_;
  const double silent_s = std::chrono::duration<double>(Clock::now() - last_packet_).count();
  if (silent_s >= spec_.link_lost_s) {
    *why = "no packet from the controller for " + std::to_string(silent_s) + " s (" +
           link_.describe() + "; hil.link_lost_s = " + std::to_string(spec_.link_lost_s) + ")";
    return false;
  }
  return true;
}

void RemoteController::finish(double time_s) {
  pamhil_packet out{};
  out.kind = PAMHIL_READINGS;
  out.encoding = static_cast<std::uint8_t>(encoding_);
  out.muscle_count = static_cast<std::uint8_t>(muscles_);
  out.flags = PAMHIL_FLAG_END;
  out.sequence = sent_sequence_++;
  out.tick = static_cast<std::uint32_t>(ticks_.size());
  out.time_s = time_s;
  link_.send(out);
}

nlohmann::json RemoteController::summary() const {
  std::vector<double> latency, jitter;
  for (const HilTick& t : ticks_) {
    if (!std::isnan(t.arrived_s)) latency.push_back(1000.0 * (t.arrived_s - t.sent_s));
    if (mode_ == HilMode::kRealTime) jitter.push_back(t.jitter_ms);
  }
  const LinkCounts& c = link_.counts();
  return {{"mode", mode_ == HilMode::kRealTime ? "realtime" : "lockstep"},
          {"link", link_.describe()},
          {"encoding", encoding_ == PAMHIL_FLOAT64   ? "float64"
                       : encoding_ == PAMHIL_FLOAT32 ? "float32"
                                                     : "counts"},
          {"ticks", ticks_.size()},
          {"latency_ms", ms_stats(latency)},
          {"jitter_ms", ms_stats(jitter)},
          {"missed_ticks", missed_},
          {"held_ticks", held_},
          {"vented_ticks", vented_},
          {"dropped_by_fault", injected_drops_},
          {"late_packets", stale_},
          {"sequence_gaps", gaps_},
          {"bad_checksum", c.bad_checksum},
          {"other_version", c.other_version},
          {"bad_header", c.bad_header},
          {"skipped_bytes", c.skipped_bytes}};
}

}  // namespace pamsim
