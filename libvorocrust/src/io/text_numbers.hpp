// Internal: numbers as text for the export formats, the same in every locale (std::to_chars): a
// host application that sets a decimal-comma locale must not change a file.
#pragma once

#include <string>

namespace vorocrust::io {

// The shortest decimal form that reads back as exactly x.
void append_number(std::string& out, double x);
void append_number(std::string& out, long long n);

// x in a Fortran E field exactly `width` characters wide, right-justified, with as many
// significant digits as fit ("1.2346E+01", "-1.235E+01" in ten). Throws Error(Output) for a
// value no such field holds (not finite, or an exponent too wide).
std::string fortran_e(double x, int width);

}  // namespace vorocrust::io
