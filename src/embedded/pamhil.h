/* pamhil.h: the hardware-in-the-loop packet between pamsim's simulated arm and a controller
 * board (docs/hil.md): at every control tick pamsim sends the muscles' raw readings (the
 * embedded controller's inputs, pamctl_input) and the board answers with the valve commands.
 * One layout for both directions, little-endian, framed for a serial line that may lose or
 * corrupt bytes (two sync bytes, the length implied by the header, a CRC-16 over the rest):
 *
 *   offset  type    field
 *   0       u8[2]   sync 0xA5 0x5A
 *   2       u8      version (PAMHIL_VERSION)
 *   3       u8      kind: 1 readings (pamsim -> board), 2 command (board -> pamsim)
 *   4       u8      encoding of the values: 0 float64, 1 float32, 2 counts (int16, scales below)
 *   5       u8      muscle count n (1 .. PAMCTL_MAX_MUSCLES)
 *   6       u8      flags: bit 0 the reflexes enabled, bit 1 the trial is over (readings)
 *   7       u8      0
 *   8       u32     sequence number (each side counts its own packets from 0)
 *   12      u32     tick (the control tick the readings are of, the command answers)
 *   16      f64     the tick's time [s] (pamctl_input.time_s, as the simulator has it)
 *   24      values  readings: per muscle pressure [V], gauge [V], fiber rate [m/s], goal
 *                   pressure p_tp [Pa]; command: per muscle valve command [Pa gauge]
 *   24+V    u16     CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF) of bytes 2 .. 24+V-1
 * A board opens the link with a hello: a command packet of tick PAMHIL_HELLO_TICK (its muscle
 * count and the encoding both sides then use); pamsim's last readings carry PAMHIL_FLAG_END.
 *
 * Same rules as pamctl.h: no heap, no I/O, no globals; <string.h> for memcpy alone. */
#ifndef PAMHIL_H
#define PAMHIL_H

#include <stdbool.h>
#include <stdint.h>

#include "pamctl.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PAMHIL_VERSION 1
#define PAMHIL_SYNC0 0xA5u
#define PAMHIL_SYNC1 0x5Au
#define PAMHIL_HEADER_BYTES 24
#define PAMHIL_CRC_BYTES 2
#define PAMHIL_READING_VALUES 4 /* per muscle */
#define PAMHIL_MAX_VALUES (PAMHIL_READING_VALUES * PAMCTL_MAX_MUSCLES)
#define PAMHIL_MAX_PACKET_BYTES (PAMHIL_HEADER_BYTES + 8 * PAMHIL_MAX_VALUES + PAMHIL_CRC_BYTES)
#define PAMHIL_FLAG_ENABLED 0x1u /* readings: the reflexes enabled */
#define PAMHIL_FLAG_END 0x2u     /* readings: the trial is over, the board may stop */
#define PAMHIL_HELLO_TICK 0xFFFFFFFFu

typedef enum { PAMHIL_READINGS = 1, PAMHIL_COMMAND = 2 } pamhil_kind;
typedef enum { PAMHIL_FLOAT64 = 0, PAMHIL_FLOAT32 = 1, PAMHIL_COUNTS = 2 } pamhil_encoding;

/* The counts encoding's scales (the value is count x LSB, saturated at the int16 range):
 * volts 0.25 mV (+-8.19 V), fiber rate 50 um/s (+-1.64 m/s), pressures 40 Pa (+-1.31 MPa). */
#define PAMHIL_LSB_VOLTS 0.00025
#define PAMHIL_LSB_RATE_M_S 0.00005
#define PAMHIL_LSB_PA 40.0

/* decode's results */
#define PAMHIL_OK 0
#define PAMHIL_ERR_SHORT -1    /* fewer bytes than the header says */
#define PAMHIL_ERR_SYNC -2     /* not a packet's start */
#define PAMHIL_ERR_VERSION -3  /* another version's packet */
#define PAMHIL_ERR_HEADER -4   /* a kind, encoding or muscle count out of range */
#define PAMHIL_ERR_CHECKSUM -5 /* the CRC does not match */

typedef struct {
  uint8_t version;
  uint8_t kind;
  uint8_t encoding;
  uint8_t muscle_count;
  uint8_t flags;
  uint32_t sequence;
  uint32_t tick;
  double time_s;
  /* readings: [4 j + 0] pressure V, [4 j + 1] gauge V, [4 j + 2] fiber m/s, [4 j + 3] p_tp
   * Pa; command: [j] p_cmd Pa */
  double values[PAMHIL_MAX_VALUES];
} pamhil_packet;

/* The bytes of a packet of this kind, encoding and muscle count; 0 when out of range. */
int32_t pamhil_packet_bytes(int32_t kind, int32_t encoding, int32_t muscle_count);
uint16_t pamhil_crc16(const uint8_t* data, int32_t size);
/* Writes `packet` (its version is written as PAMHIL_VERSION) into `out`; returns the bytes
 * written, or 0 when the header is out of range or `capacity` is too small. */
int32_t pamhil_encode(const pamhil_packet* packet, uint8_t* out, int32_t capacity);
/* Reads the packet at the start of `in` (`size` bytes); returns PAMHIL_OK or an error. */
int32_t pamhil_decode(const uint8_t* in, int32_t size, pamhil_packet* packet);

/* A serial line's bytes, one at a time, into packets: a lost, added or corrupted byte costs
 * the packets it touches, never the stream (it searches the next sync and checks the CRC). */
typedef struct {
  uint8_t buffer[PAMHIL_MAX_PACKET_BYTES];
  int32_t used;
  uint32_t skipped_bytes; /* bytes passed over looking for a packet's start */
  uint32_t bad_packets;   /* packets refused: CRC, version, header */
  int32_t last_error;     /* the last refusal's PAMHIL_ERR_* */
} pamhil_stream;

void pamhil_stream_init(pamhil_stream* stream);
/* Adds one byte; returns true when it completes a valid packet (written to *packet). */
bool pamhil_stream_feed(pamhil_stream* stream, uint8_t byte, pamhil_packet* packet);

#ifdef __cplusplus
}
#endif

#endif /* PAMHIL_H */
