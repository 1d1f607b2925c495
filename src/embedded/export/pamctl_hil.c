/* pamctl_hil.c: the exported controller closing the loop around pamsim's simulated arm
 * (`pamsim hil`, docs/hil.md), as a host program: the example loop's hooks served by a link.
 *   pamctl_hil --udp HOST:PORT [--encoding float64|float32|counts]
 *   pamctl_hil --serial DEVICE [--baud N] [--encoding ...]
 * It says hello (a command packet of tick PAMHIL_HELLO_TICK with its muscle count and the
 * encoding; again every 200 ms until pamsim answers), then answers every readings packet with the
 * commands of pamctl_tick for that tick, until pamsim's last readings (PAMHIL_FLAG_END: exit 0) or
 * 5 s without a packet (exit 1). Exit 2 for bad arguments or a link it cannot open. A board's
 * firmware does the same with its UART or Ethernet driver in place of these POSIX calls. */
#define _DEFAULT_SOURCE /* cfmakeraw, with -std=c99 */
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include "pamctl.h"
#include "pamctl_export.h"
#include "pamhil.h"

#define SILENCE_MS 5000
#define HELLO_MS 200

typedef struct {
  int fd;
  bool serial;
  pamhil_stream stream;
} link_t;

static int fail(const char* what, const char* detail) {
  fprintf(stderr, "pamctl_hil: %s%s%s\n", what, detail ? ": " : "", detail ? detail : "");
  return 2;
}

static int open_udp(const char* host_port, link_t* link) {
  char host[64];
  int port = 0;
  const char* colon = strrchr(host_port, ':');
  if (!colon || (size_t)(colon - host_port) >= sizeof(host)) return -1;
  memcpy(host, host_port, (size_t)(colon - host_port));
  host[colon - host_port] = '\0';
  port = atoi(colon + 1);
  struct sockaddr_in to;
  memset(&to, 0, sizeof(to));
  to.sin_family = AF_INET;
  to.sin_port = htons((uint16_t)port);
  if (port < 1 || port > 65535 || inet_pton(AF_INET, host, &to.sin_addr) != 1) return -1;
  link->fd = socket(AF_INET, SOCK_DGRAM, 0);
  if (link->fd < 0 || connect(link->fd, (struct sockaddr*)&to, sizeof(to)) != 0) return -1;
  link->serial = false;
  return 0;
}

static int open_serial(const char* device, int baud, link_t* link) {
  speed_t speed = baud == 9600     ? B9600
                  : baud == 57600  ? B57600
                  : baud == 115200 ? B115200
                  : baud == 230400 ? B230400
                  : baud == 921600 ? B921600
                                   : 0;
  link->fd = open(device, O_RDWR | O_NOCTTY);
  struct termios tty;
  if (speed == 0 || link->fd < 0 || tcgetattr(link->fd, &tty) != 0) return -1;
  cfmakeraw(&tty);
  cfsetispeed(&tty, speed);
  cfsetospeed(&tty, speed);
  tty.c_cflag |= CLOCAL | CREAD;
  if (tcsetattr(link->fd, TCSANOW, &tty) != 0) return -1;
  link->serial = true;
  pamhil_stream_init(&link->stream);
  return 0;
}

static void send_packet(link_t* link, const pamhil_packet* packet) {
  uint8_t bytes[PAMHIL_MAX_PACKET_BYTES];
  const int32_t n = pamhil_encode(packet, bytes, (int32_t)sizeof(bytes));
  for (int32_t done = 0; done < n;) {
    const ssize_t w = write(link->fd, bytes + done, (size_t)(n - done));
    if (w <= 0) return; /* the other side is gone: its silence ends the loop */
    done += (int32_t)w;
  }
}

/* The next valid readings packet; false after `timeout_ms` without one. */
static bool receive_readings(link_t* link, pamhil_packet* packet, int timeout_ms) {
  uint8_t bytes[PAMHIL_MAX_PACKET_BYTES + 1];
  struct pollfd p = {link->fd, POLLIN, 0};
  for (;;) {
    if (poll(&p, 1, timeout_ms) <= 0) return false;
    const ssize_t n = read(link->fd, bytes, sizeof(bytes));
    if (n <= 0) continue; /* (UDP: pamsim not listening yet) */
    if (!link->serial) {
      if (pamhil_decode(bytes, (int32_t)n, packet) == PAMHIL_OK &&
          packet->kind == PAMHIL_READINGS) {
        return true;
      }
      continue;
    }
    for (ssize_t k = 0; k < n; ++k) {
      if (pamhil_stream_feed(&link->stream, bytes[k], packet) && packet->kind == PAMHIL_READINGS) {
        return true; /* (a serial packet's remaining bytes wait in the next read) */
      }
    }
  }
}

static int32_t parse_encoding(const char* name) {
  if (strcmp(name, "float64") == 0) return PAMHIL_FLOAT64;
  if (strcmp(name, "float32") == 0) return PAMHIL_FLOAT32;
  if (strcmp(name, "counts") == 0) return PAMHIL_COUNTS;
  return -1;
}

static pamctl_config config;
static pamctl_state state;
static pamctl_input input;
static pamctl_output output;
static pamhil_packet in_packet, out_packet;

/* one tick: the readings in, pamctl_tick, the commands out */
static void answer(link_t* link, int32_t encoding) {
  const int32_t n = config.muscle_count;
  input.time_s = (pamctl_real)in_packet.time_s;
  input.enabled = (in_packet.flags & PAMHIL_FLAG_ENABLED) != 0;
  for (int32_t j = 0; j < n; ++j) {
    const double* v = in_packet.values + PAMHIL_READING_VALUES * j;
    input.pressure_v[j] = (pamctl_real)v[0];
    input.gauge_v[j] = (pamctl_real)v[1];
    input.fiber_rate_m_s[j] = (pamctl_real)v[2];
    input.p_tp_pa[j] = (pamctl_real)v[3];
  }
  pamctl_tick(&config, &state, &input, &output);
  out_packet.kind = PAMHIL_COMMAND;
  out_packet.encoding = (uint8_t)encoding;
  out_packet.muscle_count = (uint8_t)n;
  out_packet.tick = in_packet.tick;
  out_packet.time_s = in_packet.time_s;
  for (int32_t j = 0; j < n; ++j) out_packet.values[j] = (double)output.p_cmd_pa[j];
  send_packet(link, &out_packet);
  ++out_packet.sequence;
}

int main(int argc, char** argv) {
  const char* udp = NULL;
  const char* serial = NULL;
  int baud = 115200;
  int32_t encoding = PAMHIL_FLOAT64;
  for (int k = 1; k < argc; ++k) {
    const bool more = k + 1 < argc;
    if (strcmp(argv[k], "--udp") == 0 && more)
      udp = argv[++k];
    else if (strcmp(argv[k], "--serial") == 0 && more)
      serial = argv[++k];
    else if (strcmp(argv[k], "--baud") == 0 && more)
      baud = atoi(argv[++k]);
    else if (strcmp(argv[k], "--encoding") == 0 && more)
      encoding = parse_encoding(argv[++k]);
    else
      return fail("unknown argument", argv[k]);
  }
  if ((udp == NULL) == (serial == NULL))
    return fail("give --udp HOST:PORT or --serial DEVICE", NULL);
  if (encoding < 0) return fail("--encoding must be float64, float32 or counts", NULL);
  link_t link;
  memset(&link, 0, sizeof(link));
  if ((udp ? open_udp(udp, &link) : open_serial(serial, baud, &link)) != 0) {
    return fail("cannot open the link", udp ? udp : serial);
  }
  pamctl_export_config(&config);
  if (pamctl_init(&config, &state) != 0) return fail("the exported configuration is refused", NULL);
  /* hello (the muscles and the encoding), again every HELLO_MS until pamsim answers */
  out_packet.kind = PAMHIL_COMMAND;
  out_packet.encoding = (uint8_t)encoding;
  out_packet.muscle_count = (uint8_t)config.muscle_count;
  out_packet.tick = PAMHIL_HELLO_TICK;
  bool started = false;
  for (int tries = 0; tries < SILENCE_MS / HELLO_MS && !started; ++tries) {
    send_packet(&link, &out_packet);
    started = receive_readings(&link, &in_packet, HELLO_MS);
  }
  ++out_packet.sequence;
  while (started) {
    if (in_packet.flags & PAMHIL_FLAG_END) return 0;
    answer(&link, encoding);
    started = receive_readings(&link, &in_packet, SILENCE_MS);
  }
  fprintf(stderr, "pamctl_hil: no readings for %d ms; stopping\n", SILENCE_MS);
  return 1;
}
