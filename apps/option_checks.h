// Range checks for numeric command-line options, applied to the text before CLI11 converts it:
// CLI11 alone reads "-5" into an unsigned as 2^64-5, "18446744073709551616" as a wrapped value and
// "nan" as a number of seconds. An out-of-range value is a usage error naming the option and the
// accepted range:  --iterations: expected a whole number from 0 to 100000000, found '1e18'
// Where a command checks a narrower range itself (exit 1, naming the option), the validator only
// guards the text: no sign, no exponent, no overflow of the option's type.
#pragma once

#include <cstdint>
#include <limits>

#include <CLI/CLI.hpp>

namespace rastrace {

// Digits only (no sign, exponent or fraction), from lo to hi.
CLI::Validator whole_number(std::uint64_t lo = 0, std::uint64_t hi = std::numeric_limits<std::uint64_t>::max());
// A finite decimal number from lo to hi (no nan, inf or overflow).
CLI::Validator finite_number(double lo, double hi);

}  // namespace rastrace
