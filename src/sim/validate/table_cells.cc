// table_cells.cc: see table_cells.h.
#include "sim/validate/table_cells.h"

#include <cmath>
#include <cstdio>

#include "base/config_reader.h"
#include "base/format.h"

namespace pamsim {

std::string markdown_number(double v) {
  if (!std::isfinite(v)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3g", v);
  return std::string(buf);
}

std::string markdown_error_pct(const ErrorPct& e) {
  return markdown_number(e.max_pct) + " / " + markdown_number(e.rmse_pct);
}

std::string markdown_header(const std::string& first, const std::vector<std::string>& columns) {
  std::string out = "| " + first + " |";
  for (const std::string& c : columns) out += " " + c + " |";
  out += "\n| --- |";
  for (std::size_t i = 0; i < columns.size(); ++i) out += " --- |";
  return out + "\n";
}

std::string csv_number(double v) { return std::isfinite(v) ? format_shortest(v) : std::string(); }

void check_cell_name(const TableEntry& e, const std::string& name) {
  e.in.check(!name.empty(), e.where + "name", "must not be empty");
  e.in.check(name.find_first_of(",\"|\t\n\r") == std::string::npos, e.where + "name",
             "must hold no comma, quote, bar, tab or newline, got \"" + name + "\"");
}

std::string csv_text(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char ch : text) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

}  // namespace pamsim
