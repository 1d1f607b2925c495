// hil_link.h: the byte link between `pamsim hil` and a controller board, carrying the
// packets of src/embedded/pamhil.h: a UDP socket (pamsim listens on HOST:PORT; the board's
// first packet, its hello, says where to send) or a serial line (a tty, raw, 8N1 at a given
// baud; the packets found in the byte stream by their sync bytes and CRC). POSIX sockets and
// termios; every wait bounded by its timeout.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "embedded/pamhil.h"

namespace pamsim {

// What a link refused on the way in.
struct LinkCounts {
  long bad_checksum = 0;
  long other_version = 0;
  long bad_header = 0;
  long skipped_bytes = 0;  // serial: bytes passed over between packets
};

class HilLink {
 public:
  virtual ~HilLink() = default;
  virtual void send(const pamhil_packet& packet) = 0;
  // Waits up to `timeout_s` for the next valid packet; false when none came. Refused ones are
  // counted in counts() and passed over.
  virtual bool receive(double timeout_s, pamhil_packet* packet) = 0;
  // Corrupts each received byte with probability `fraction` (a fault as a line has it; from
  // `seed`, so a run is repeatable). Serial only; UDP refuses it (one datagram, one packet).
  virtual void corrupt_received_bytes(double fraction, std::uint64_t seed) = 0;
  virtual std::string describe() const = 0;
  const LinkCounts& counts() const { return counts_; }

 protected:
  LinkCounts counts_;
};

// Listens on HOST:PORT (a numeric IPv4 address). Throws InputError "--udp HOST:PORT: ..." for
// a malformed address or one that cannot be bound (in use).
std::unique_ptr<HilLink> open_udp_link(const std::string& host_port);
// Opens the tty `device` raw at `baud` (one of the standard rates). Throws InputError
// "--serial DEVICE: ..." when it is missing or not a tty, and for a rate termios lacks.
std::unique_ptr<HilLink> open_serial_link(const std::string& device, int baud);

}  // namespace pamsim
