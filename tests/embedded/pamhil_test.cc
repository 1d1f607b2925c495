// pamhil_test.cc: the hardware-in-the-loop packet (src/embedded/pamhil.h) against independent
// truths: the CRC's published check value, the sizes its layout implies, float64 round trips
// bit for bit, float32 and counts as their rounding, every refusal, and a serial stream that
// loses, gains and corrupts bytes.
#include "embedded/pamhil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace {

pamhil_packet readings(int muscles, int encoding, std::uint32_t tick) {
  pamhil_packet p{};
  p.kind = PAMHIL_READINGS;
  p.encoding = static_cast<std::uint8_t>(encoding);
  p.muscle_count = static_cast<std::uint8_t>(muscles);
  p.flags = PAMHIL_FLAG_ENABLED;
  p.sequence = 7 + tick;
  p.tick = tick;
  p.time_s = tick / 100.0;
  for (int k = 0; k < PAMHIL_READING_VALUES * muscles; ++k) {
    p.values[k] = (k % 2 ? -1.0 : 1.0) * (0.1234567891 + 0.37 * k) * (k % 4 == 3 ? 1e5 : 1.0);
  }
  return p;
}

std::vector<std::uint8_t> encoded(const pamhil_packet& p) {
  std::vector<std::uint8_t> bytes(PAMHIL_MAX_PACKET_BYTES);
  bytes.resize(static_cast<std::size_t>(pamhil_encode(&p, bytes.data(), PAMHIL_MAX_PACKET_BYTES)));
  return bytes;
}

TEST(PamhilTest, TheCrcIsCcittFalsesCheckValue) {
  const char* check = "123456789";  // CRC-16/CCITT-FALSE of it: 0x29B1 (the catalogue's check)
  EXPECT_EQ(pamhil_crc16(reinterpret_cast<const std::uint8_t*>(check), 9), 0x29B1);
}

TEST(PamhilTest, SizesAreTheLayoutsAndOutOfRangeIsZero) {
  // 24 header bytes, the values, 2 CRC bytes
  EXPECT_EQ(pamhil_packet_bytes(PAMHIL_READINGS, PAMHIL_FLOAT64, 2), 24 + 8 * 8 + 2);
  EXPECT_EQ(pamhil_packet_bytes(PAMHIL_READINGS, PAMHIL_COUNTS, 8), 24 + 32 * 2 + 2);
  EXPECT_EQ(pamhil_packet_bytes(PAMHIL_COMMAND, PAMHIL_FLOAT32, 8), 24 + 8 * 4 + 2);
  EXPECT_EQ(pamhil_packet_bytes(PAMHIL_COMMAND, PAMHIL_FLOAT64, 0), 0);
  EXPECT_EQ(pamhil_packet_bytes(PAMHIL_COMMAND, 3, 2), 0);
  EXPECT_EQ(pamhil_packet_bytes(3, PAMHIL_FLOAT64, 2), 0);
  EXPECT_EQ(pamhil_packet_bytes(PAMHIL_COMMAND, PAMHIL_FLOAT64, PAMCTL_MAX_MUSCLES + 1), 0);
}

TEST(PamhilTest, EachEncodingRoundTripsAsItsRounding) {
  for (int encoding : {PAMHIL_FLOAT64, PAMHIL_FLOAT32, PAMHIL_COUNTS}) {
    const pamhil_packet p = readings(3, encoding, 41);
    const std::vector<std::uint8_t> bytes = encoded(p);
    ASSERT_EQ(static_cast<int>(bytes.size()), pamhil_packet_bytes(PAMHIL_READINGS, encoding, 3));
    EXPECT_EQ(bytes[0], 0xA5);
    EXPECT_EQ(bytes[1], 0x5A);
    EXPECT_EQ(bytes[12], 41);  // the tick, little-endian
    pamhil_packet q{};
    ASSERT_EQ(pamhil_decode(bytes.data(), static_cast<int>(bytes.size()), &q), PAMHIL_OK);
    EXPECT_EQ(q.tick, 41u);
    EXPECT_EQ(q.sequence, 48u);
    EXPECT_EQ(q.flags, PAMHIL_FLAG_ENABLED);
    EXPECT_EQ(std::memcmp(&q.time_s, &p.time_s, sizeof(double)), 0);  // always float64
    for (int k = 0; k < 12; ++k) {
      const double lsb = k % 4 < 2    ? PAMHIL_LSB_VOLTS
                         : k % 4 == 2 ? PAMHIL_LSB_RATE_M_S
                                      : PAMHIL_LSB_PA;
      const double counts = std::max(-32768.0, std::min(32767.0, std::round(p.values[k] / lsb)));
      const double expected = encoding == PAMHIL_FLOAT64   ? p.values[k]
                              : encoding == PAMHIL_FLOAT32 ? static_cast<float>(p.values[k])
                                                           : counts * lsb;
      EXPECT_EQ(q.values[k], expected) << "encoding " << encoding << " value " << k;
    }
  }
}

TEST(PamhilTest, EveryRefusalHasItsCode) {
  const std::vector<std::uint8_t> good = encoded(readings(2, PAMHIL_FLOAT64, 3));
  pamhil_packet q{};
  const int n = static_cast<int>(good.size());
  EXPECT_EQ(pamhil_decode(good.data(), n - 1, &q), PAMHIL_ERR_SHORT);
  std::vector<std::uint8_t> bad = good;
  bad[1] = 0x00;
  EXPECT_EQ(pamhil_decode(bad.data(), n, &q), PAMHIL_ERR_SYNC);
  bad = good;
  bad[2] = PAMHIL_VERSION + 1;
  EXPECT_EQ(pamhil_decode(bad.data(), n, &q), PAMHIL_ERR_VERSION);
  bad = good;
  bad[5] = 0;  // no muscles
  EXPECT_EQ(pamhil_decode(bad.data(), n, &q), PAMHIL_ERR_HEADER);
  bad = good;
  bad[30] ^= 0x10;  // one bit of a value
  EXPECT_EQ(pamhil_decode(bad.data(), n, &q), PAMHIL_ERR_CHECKSUM);
}

// Three packets on a line; the second loses a byte, a corrupted byte spoils the fourth, and
// garbage with a sync pattern sits between: the stream finds the first, third and fifth.
TEST(PamhilTest, AStreamSurvivesALostACorruptedAndAnAddedByte) {
  std::vector<std::uint8_t> line = {0x5A, 0xA5, 0xA5, 0x00, 0x13};  // garbage, a false start
  std::vector<std::vector<std::uint8_t>> packets;
  for (std::uint32_t tick = 0; tick < 5; ++tick)
    packets.push_back(encoded(readings(2, PAMHIL_COUNTS, tick)));
  packets[1].erase(packets[1].begin() + 20);  // a lost byte
  packets[3][40] ^= 0xFF;                     // a corrupted byte
  for (const auto& p : packets) line.insert(line.end(), p.begin(), p.end());
  pamhil_stream stream;
  pamhil_stream_init(&stream);
  std::vector<std::uint32_t> found;
  pamhil_packet q{};
  for (std::uint8_t byte : line) {
    if (pamhil_stream_feed(&stream, byte, &q)) found.push_back(q.tick);
  }
  EXPECT_EQ(found, (std::vector<std::uint32_t>{0, 2, 4}));
  EXPECT_GE(stream.bad_packets, 2u);  // the short one read into the next, the corrupted one
  EXPECT_GT(stream.skipped_bytes, 0u);
}

}  // namespace
