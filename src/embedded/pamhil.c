/* pamhil.c: the hardware-in-the-loop packet (pamhil.h): little-endian fields written byte by
 * byte (any board's byte order), floats by their bits, counts rounded and saturated. */
#include "pamhil.h"

#include <string.h>

static int32_t value_count(int32_t kind, int32_t muscles) {
  return kind == PAMHIL_READINGS ? PAMHIL_READING_VALUES * muscles : muscles;
}

static int32_t value_bytes(int32_t encoding) {
  return encoding == PAMHIL_FLOAT64 ? 8 : encoding == PAMHIL_FLOAT32 ? 4 : 2;
}

/* the counts encoding's LSB of value k of a packet of `kind` */
static double lsb(int32_t kind, int32_t k) {
  if (kind == PAMHIL_COMMAND) return PAMHIL_LSB_PA;
  switch (k % PAMHIL_READING_VALUES) {
    case 0:
    case 1:
      return PAMHIL_LSB_VOLTS;
    case 2:
      return PAMHIL_LSB_RATE_M_S;
    default:
      return PAMHIL_LSB_PA;
  }
}

int32_t pamhil_packet_bytes(int32_t kind, int32_t encoding, int32_t muscle_count) {
  if ((kind != PAMHIL_READINGS && kind != PAMHIL_COMMAND) || encoding < PAMHIL_FLOAT64 ||
      encoding > PAMHIL_COUNTS || muscle_count < 1 || muscle_count > PAMCTL_MAX_MUSCLES) {
    return 0;
  }
  return PAMHIL_HEADER_BYTES + value_count(kind, muscle_count) * value_bytes(encoding) +
         PAMHIL_CRC_BYTES;
}

uint16_t pamhil_crc16(const uint8_t* data, int32_t size) {
  uint16_t crc = 0xFFFFu;
  for (int32_t i = 0; i < size; ++i) {
    crc ^= (uint16_t)((uint16_t)data[i] << 8);
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x8000u) ? (uint16_t)((crc << 1) ^ 0x1021u) : (uint16_t)(crc << 1);
    }
  }
  return crc;
}

static void put_u(uint8_t* out, uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out[i] = (uint8_t)(v >> (8 * i));
}

static uint64_t get_u(const uint8_t* in, int bytes) {
  uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= (uint64_t)in[i] << (8 * i);
  return v;
}

static void put_value(uint8_t* out, int32_t encoding, double v, double step) {
  if (encoding == PAMHIL_FLOAT64) {
    uint64_t bits;
    memcpy(&bits, &v, 8);
    put_u(out, bits, 8);
  } else if (encoding == PAMHIL_FLOAT32) {
    const float f = (float)v;
    uint32_t bits;
    memcpy(&bits, &f, 4);
    put_u(out, bits, 4);
  } else {
    double c = v / step;
    c = c != c ? 0.0 : c > 32767.0 ? 32767.0 : c < -32768.0 ? -32768.0 : c;
    const int32_t count = (int32_t)(c < 0 ? c - 0.5 : c + 0.5);
    put_u(out, (uint16_t)(int16_t)count, 2);
  }
}

static double get_value(const uint8_t* in, int32_t encoding, double step) {
  if (encoding == PAMHIL_FLOAT64) {
    const uint64_t bits = get_u(in, 8);
    double v;
    memcpy(&v, &bits, 8);
    return v;
  }
  if (encoding == PAMHIL_FLOAT32) {
    const uint32_t bits = (uint32_t)get_u(in, 4);
    float f;
    memcpy(&f, &bits, 4);
    return (double)f;
  }
  return (double)(int16_t)(uint16_t)get_u(in, 2) * step;
}

int32_t pamhil_encode(const pamhil_packet* p, uint8_t* out, int32_t capacity) {
  const int32_t bytes = pamhil_packet_bytes(p->kind, p->encoding, p->muscle_count);
  if (bytes == 0 || bytes > capacity) return 0;
  out[0] = PAMHIL_SYNC0;
  out[1] = PAMHIL_SYNC1;
  out[2] = PAMHIL_VERSION;
  out[3] = p->kind;
  out[4] = p->encoding;
  out[5] = p->muscle_count;
  out[6] = p->flags;
  out[7] = 0;
  put_u(out + 8, p->sequence, 4);
  put_u(out + 12, p->tick, 4);
  put_value(out + 16, PAMHIL_FLOAT64, p->time_s, 1.0);
  const int32_t n = value_count(p->kind, p->muscle_count), w = value_bytes(p->encoding);
  for (int32_t k = 0; k < n; ++k) {
    put_value(out + PAMHIL_HEADER_BYTES + k * w, p->encoding, p->values[k], lsb(p->kind, k));
  }
  const int32_t crc_at = bytes - PAMHIL_CRC_BYTES;
  put_u(out + crc_at, pamhil_crc16(out + 2, crc_at - 2), 2);
  return bytes;
}

int32_t pamhil_decode(const uint8_t* in, int32_t size, pamhil_packet* p) {
  if (size < PAMHIL_HEADER_BYTES) return PAMHIL_ERR_SHORT;
  if (in[0] != PAMHIL_SYNC0 || in[1] != PAMHIL_SYNC1) return PAMHIL_ERR_SYNC;
  if (in[2] != PAMHIL_VERSION) return PAMHIL_ERR_VERSION;
  const int32_t bytes = pamhil_packet_bytes(in[3], in[4], in[5]);
  if (bytes == 0 || in[7] != 0) return PAMHIL_ERR_HEADER;
  if (size < bytes) return PAMHIL_ERR_SHORT;
  const int32_t crc_at = bytes - PAMHIL_CRC_BYTES;
  if ((uint16_t)get_u(in + crc_at, 2) != pamhil_crc16(in + 2, crc_at - 2)) {
    return PAMHIL_ERR_CHECKSUM;
  }
  p->version = in[2];
  p->kind = in[3];
  p->encoding = in[4];
  p->muscle_count = in[5];
  p->flags = in[6];
  p->sequence = (uint32_t)get_u(in + 8, 4);
  p->tick = (uint32_t)get_u(in + 12, 4);
  p->time_s = get_value(in + 16, PAMHIL_FLOAT64, 1.0);
  const int32_t n = value_count(p->kind, p->muscle_count), w = value_bytes(p->encoding);
  for (int32_t k = 0; k < n; ++k) {
    p->values[k] = get_value(in + PAMHIL_HEADER_BYTES + k * w, p->encoding, lsb(p->kind, k));
  }
  return PAMHIL_OK;
}

void pamhil_stream_init(pamhil_stream* s) { memset(s, 0, sizeof(*s)); }

/* drops the first `count` bytes of the buffer */
static void shift(pamhil_stream* s, int32_t count) {
  memmove(s->buffer, s->buffer + count, (size_t)(s->used - count));
  s->used -= count;
}

bool pamhil_stream_feed(pamhil_stream* s, uint8_t byte, pamhil_packet* packet) {
  s->buffer[s->used++] = byte;
  /* bounded: each pass either waits for more bytes, returns, or drops at least one byte */
  while (s->used > 0) {
    if (s->buffer[0] != PAMHIL_SYNC0 || (s->used > 1 && s->buffer[1] != PAMHIL_SYNC1)) {
      shift(s, 1);
      ++s->skipped_bytes;
      continue;
    }
    const int32_t result = pamhil_decode(s->buffer, s->used, packet);
    if (result == PAMHIL_ERR_SHORT) return false; /* wait for the rest */
    if (result == PAMHIL_OK) {
      shift(s, pamhil_packet_bytes(packet->kind, packet->encoding, packet->muscle_count));
      return true;
    }
    /* a sync pattern inside a bad packet: look again one byte on */
    ++s->bad_packets;
    s->last_error = result;
    shift(s, 1);
  }
  return false;
}
