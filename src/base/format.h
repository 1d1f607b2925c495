// format.h: numbers (and messages) as pamsim writes them: in messages (ten significant digits, no
// trailing noise: "0.7", "1e-09", "nan"), and in files, where the text must read back to
// the same double (CSV cells; TOML values, kept recognisable as floats).
#pragma once

#include <string>

namespace pamsim {

// "%.10g": for error messages and reports.
std::string format_value(double v);
// The shortest decimal text that reads back to exactly v (std::to_chars: "0.14", not
// "0.14000000000000001"; "inf", "-inf", "nan").
std::string format_shortest(double v);
// format_shortest with ".0" appended to an integer-looking result, so TOML reads a float.
std::string format_number(double v);
// A value and its uncertainty as a reader writes them: the uncertainty to two significant
// digits and the value to the same decimal place ("2.7006 +- 0.0053", "123 +- 13"); each
// as format_value when the uncertainty is not finite and positive, or too small or large
// for fixed decimals.
std::string format_with_error(double value, double error);

// A message as one line a terminal shows as it is: a value echoed from the input may be
// megabytes long (a word over 512 bytes, longer than any sensible path, is cut to its two
// ends and the count between, the whole line to 2000 bytes) or hold control bytes (NUL,
// newline, escape sequences), written as \xNN before any cut. Idempotent, so a message
// wrapped again keeps its form. InputError applies it.
std::string printable_message(const std::string& message);

}  // namespace pamsim
