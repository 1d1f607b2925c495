// format.cc: see format.h.
#include "base/format.h"

#include <charconv>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace pamsim {

std::string format_value(double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.10g", v);
  return buf;
}

std::string format_shortest(double v) {
  if (std::isnan(v)) return "nan";
  char buf[40];
  return std::string(buf, std::to_chars(buf, buf + sizeof(buf), v).ptr);  // shortest exact
}

std::string format_with_error(double value, double error) {
  if (!(std::isfinite(value) && std::isfinite(error) && error > 0 && error < 1e9 &&
        error >= 1e-12)) {
    return format_value(value) + " +- " + format_value(error);
  }
  // the decimals that leave two significant digits of the error
  const int decimals = std::max(0, 1 - static_cast<int>(std::floor(std::log10(error))));
  char buf[96];
  std::snprintf(buf, sizeof(buf), "%.*f +- %.*f", decimals, value, decimals, error);
  return buf;
}

std::string format_number(double v) {
  std::string s = format_shortest(v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

namespace {

// A cut of `s` at or before `at` that splits neither a UTF-8 character nor a \xNN escape.
std::size_t safe_cut(const std::string& s, std::size_t at) {
  while (at > 0 && at < s.size() && (static_cast<unsigned char>(s[at]) & 0xC0) == 0x80) --at;
  for (std::size_t back = 1; back <= 3 && back <= at; ++back) {
    if (s[at - back] == '\\' && at - back + 1 < s.size() && s[at - back + 1] == 'x') {
      return at - back;
    }
  }
  return at;
}

// `s` with a part longer than `max` bytes cut to its two ends and the count between.
std::string shortened(const std::string& s, std::size_t max) {
  if (s.size() <= max) return s;
  const std::size_t keep = max / 2 - 16;
  const std::size_t head = safe_cut(s, keep);
  const std::size_t tail = safe_cut(s, s.size() - keep);
  return s.substr(0, head) + "...(" + std::to_string(tail - head) + " bytes)..." + s.substr(tail);
}

}  // namespace

std::string printable_message(const std::string& message) {
  // escaped first (so that a cut cannot grow again), then cut word by word, then the line
  std::string escaped;
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F) {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02X", byte);
      escaped += hex;
    } else {
      escaped += c;
    }
  }
  std::string words;
  for (std::size_t start = 0; start <= escaped.size();) {
    std::size_t end = escaped.find(' ', start);
    if (end == std::string::npos) end = escaped.size();
    words += shortened(escaped.substr(start, end - start), 512);
    if (end < escaped.size()) words += ' ';
    start = end + 1;
  }
  return shortened(words, 2000);
}

}  // namespace pamsim
