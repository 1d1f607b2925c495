// format.cc: see format.h.
#include "pam_actuator/format.h"

#include <cstdio>
#include <cstdlib>

namespace pamsim {

std::string format_value(double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.10g", v);
  return buf;
}

std::string format_shortest(double v) {
  char buf[40];
  for (int digits : {15, 16, 17}) {
    std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string format_number(double v) {
  std::string s = format_shortest(v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

namespace {

// A cut of `s` at or before `at` that does not split a UTF-8 character.
std::size_t utf8_boundary(const std::string& s, std::size_t at) {
  while (at > 0 && at < s.size() && (static_cast<unsigned char>(s[at]) & 0xC0) == 0x80) --at;
  return at;
}

// `s` with a part longer than `max` bytes cut to its two ends and the count between.
std::string shortened(const std::string& s, std::size_t max) {
  if (s.size() <= max) return s;
  const std::size_t keep = max / 2 - 16;
  const std::size_t head = utf8_boundary(s, keep);
  const std::size_t tail = utf8_boundary(s, s.size() - keep);
  return s.substr(0, head) + "...(" + std::to_string(tail - head) + " bytes)..." + s.substr(tail);
}

}  // namespace

std::string printable_message(const std::string& message) {
  std::string words;
  std::size_t start = 0;
  while (start <= message.size()) {
    std::size_t end = message.find(' ', start);
    if (end == std::string::npos) end = message.size();
    words += shortened(message.substr(start, end - start), 160);
    if (end < message.size()) words += ' ';
    start = end + 1;
  }
  std::string out;
  for (const char c : shortened(words, 2000)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F) {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02X", byte);
      out += hex;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace pamsim
