// table_cells.h: how the validation protocols (length_estimation.h, reaching.h) write a
// number into their tables: the Markdown cells people read and the CSV cells programs read.
#pragma once

#include <string>
#include <vector>

#include "sim/validate/validation_options.h"

namespace pamsim {

struct TableEntry;  // base/config_reader.h

// Refuses (through the entry's reader, "<where>name ...") an empty name, or one holding a
// comma, quote, bar, tab or line break: a name that becomes a cell of the CSV, the Markdown
// and a chart's data (a budget's source, a band's bracket).
void check_cell_name(const TableEntry& e, const std::string& name);

// A Markdown cell's number: 3 significant digits ("%.3g"); "n/a" where it is not finite
// (a trial that diverged).
std::string markdown_number(double v);

// "max / RMSE", each as markdown_number: an error in % of length.
std::string markdown_error_pct(const ErrorPct& e);

// A Markdown table's header and its rule: "| <first> | <column> | ... |\n| --- | ... |\n".
std::string markdown_header(const std::string& first, const std::vector<std::string>& columns);

// A CSV cell's number: the shortest text that reads back the same double; empty where it is
// not finite.
std::string csv_number(double v);

// A CSV cell of text: as it is, or quoted with its quotes doubled where it holds a comma, a
// quote or a line break (RFC 4180).
std::string csv_text(const std::string& text);

}  // namespace pamsim
