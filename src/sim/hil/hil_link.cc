// hil_link.cc: see hil_link.h. Both links wait with poll(2) against a deadline on the steady
// clock; a datagram is one packet, a serial line's bytes go through pamhil_stream.
#include "sim/hil/hil_link.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <random>

#include "base/input_error.h"

namespace pamsim {
namespace {

using Clock = std::chrono::steady_clock;

// the milliseconds left until `deadline`, at least 0
int ms_until(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  return left.count() < 0 ? 0 : static_cast<int>(left.count());
}

Clock::time_point deadline_after(double timeout_s) {
  return Clock::now() +
         std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
}

// true when `fd` has bytes before `deadline`
bool wait_readable(int fd, Clock::time_point deadline) {
  pollfd p{fd, POLLIN, 0};
  for (;;) {
    const int r = poll(&p, 1, ms_until(deadline));
    if (r > 0) return true;
    if (r == 0 || errno != EINTR) return false;
  }
}

void count_refusal(int result, LinkCounts* counts) {
  if (result == PAMHIL_ERR_CHECKSUM) ++counts->bad_checksum;
  if (result == PAMHIL_ERR_VERSION) ++counts->other_version;
  if (result == PAMHIL_ERR_HEADER || result == PAMHIL_ERR_SHORT) ++counts->bad_header;
}

class UdpLink final : public HilLink {
 public:
  UdpLink(int fd, std::string where) : fd_(fd), where_(std::move(where)) {}
  ~UdpLink() override { close(fd_); }

  void send(const pamhil_packet& packet) override {
    std::uint8_t bytes[PAMHIL_MAX_PACKET_BYTES];
    const int n = pamhil_encode(&packet, bytes, sizeof(bytes));
    if (has_peer_) (void)::send(fd_, bytes, static_cast<std::size_t>(n), MSG_NOSIGNAL);
  }

  bool receive(double timeout_s, pamhil_packet* packet) override {
    const Clock::time_point deadline = deadline_after(timeout_s);
    while (wait_readable(fd_, deadline)) {
      std::uint8_t bytes[PAMHIL_MAX_PACKET_BYTES + 1];
      sockaddr_in from{};
      socklen_t from_size = sizeof(from);
      const ssize_t n =
          recvfrom(fd_, bytes, sizeof(bytes), 0, reinterpret_cast<sockaddr*>(&from), &from_size);
      if (n <= 0) continue;  // a connected socket's refused send shows here: passed over
      const int result = pamhil_decode(bytes, static_cast<std::int32_t>(n), packet);
      if (result != PAMHIL_OK) {
        count_refusal(result, &counts_);
        continue;
      }
      if (!has_peer_) {  // the first packet says where the board is
        has_peer_ = connect(fd_, reinterpret_cast<sockaddr*>(&from), from_size) == 0;
      }
      return true;
    }
    return false;
  }

  void corrupt_received_bytes(double, std::uint64_t) override {
    throw InputError(where_ + ": corrupted bytes are a serial line's fault (--serial)");
  }
  std::string describe() const override { return "udp " + where_; }

 private:
  int fd_;
  std::string where_;
  bool has_peer_ = false;
};

class SerialLink final : public HilLink {
 public:
  SerialLink(int fd, std::string device) : fd_(fd), device_(std::move(device)) {
    pamhil_stream_init(&stream_);
  }
  ~SerialLink() override { close(fd_); }

  void send(const pamhil_packet& packet) override {
    std::uint8_t bytes[PAMHIL_MAX_PACKET_BYTES];
    const int n = pamhil_encode(&packet, bytes, sizeof(bytes));
    for (int done = 0; done < n;) {
      const ssize_t w = write(fd_, bytes + done, static_cast<std::size_t>(n - done));
      if (w > 0) {
        done += static_cast<int>(w);
      } else if (w < 0 && errno != EAGAIN && errno != EINTR) {
        return;  // the line is gone: the receive side will tell
      } else {
        pollfd p{fd_, POLLOUT, 0};
        poll(&p, 1, 10);
      }
    }
  }

  bool receive(double timeout_s, pamhil_packet* packet) override {
    const Clock::time_point deadline = deadline_after(timeout_s);
    for (;;) {
      while (next_ < size_) {
        std::uint8_t byte = buffer_[next_++];
        if (corrupt_ > 0 && coin_(random_) < corrupt_)
          byte ^= static_cast<std::uint8_t>(1 + random_() % 255);
        const std::uint32_t bad_before = stream_.bad_packets;
        const bool done = pamhil_stream_feed(&stream_, byte, packet);
        if (stream_.bad_packets != bad_before) count_refusal(stream_.last_error, &counts_);
        counts_.skipped_bytes = stream_.skipped_bytes;
        if (done) return true;
      }
      if (!wait_readable(fd_, deadline)) return false;
      const ssize_t n = read(fd_, buffer_, sizeof(buffer_));
      if (n <= 0 && ms_until(deadline) == 0) return false;
      next_ = 0;
      size_ = n > 0 ? static_cast<int>(n) : 0;
    }
  }

  void corrupt_received_bytes(double fraction, std::uint64_t seed) override {
    corrupt_ = fraction;
    random_.seed(seed);
  }
  std::string describe() const override { return "serial " + device_; }

 private:
  int fd_;
  std::string device_;
  pamhil_stream stream_;
  std::uint8_t buffer_[256];
  int next_ = 0, size_ = 0;
  double corrupt_ = 0.0;
  std::mt19937_64 random_;
  std::uniform_real_distribution<double> coin_{0.0, 1.0};
};

speed_t baud_constant(int baud, const std::string& where) {
  static const std::map<int, speed_t> kRates = {
      {9600, B9600},     {19200, B19200},   {38400, B38400},   {57600, B57600},
      {115200, B115200}, {230400, B230400}, {460800, B460800}, {921600, B921600}};
  const auto it = kRates.find(baud);
  if (it == kRates.end()) {
    throw InputError(where + ": --baud " + std::to_string(baud) +
                     " is no standard rate (9600, 19200, 38400, 57600, 115200, 230400, 460800, "
                     "921600)");
  }
  return it->second;
}

}  // namespace

std::unique_ptr<HilLink> open_udp_link(const std::string& host_port) {
  const std::string where = "--udp " + host_port;
  const std::size_t colon = host_port.rfind(':');
  sockaddr_in address{};
  address.sin_family = AF_INET;
  int port = -1;
  try {
    port = colon == std::string::npos ? -1 : std::stoi(host_port.substr(colon + 1));
  } catch (const std::exception&) {
  }
  if (colon == std::string::npos || port < 1 || port > 65535 ||
      inet_pton(AF_INET, host_port.substr(0, colon).c_str(), &address.sin_addr) != 1) {
    throw InputError(where +
                     ": expected HOST:PORT, a numeric IPv4 address and a port in [1, 65535]");
  }
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) throw InputError(where + ": cannot make a socket (" + std::strerror(errno) + ")");
  if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0) {
    const std::string why = std::strerror(errno);
    close(fd);
    throw InputError(where + ": cannot listen there (" + why + ")");
  }
  return std::make_unique<UdpLink>(fd, host_port);
}

std::unique_ptr<HilLink> open_serial_link(const std::string& device, int baud) {
  const std::string where = "--serial " + device;
  const speed_t speed = baud_constant(baud, where);
  const int fd = open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError(where + ": cannot open it (" + std::strerror(errno) + ")");
  termios tty{};
  if (!isatty(fd) || tcgetattr(fd, &tty) != 0) {
    close(fd);
    throw InputError(where + ": not a serial line (a tty)");
  }
  cfmakeraw(&tty);
  cfsetispeed(&tty, speed);
  cfsetospeed(&tty, speed);
  tty.c_cflag |= CLOCAL | CREAD;
  if (tcsetattr(fd, TCSANOW, &tty) != 0) {
    const std::string why = std::strerror(errno);
    close(fd);
    throw InputError(where + ": cannot set it raw at " + std::to_string(baud) + " baud (" + why +
                     ")");
  }
  tcflush(fd, TCIOFLUSH);
  return std::make_unique<SerialLink>(fd, device);
}

}  // namespace pamsim
