// An integer read from JSON that came from a file: nlohmann's get<unsigned>() converts a float
// such as 3e71 with a static_cast (undefined behaviour: the fuzzer found it in trace metadata)
// and wraps an integer that does not fit. json_integer() accepts only an integer within T's range.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/input_guard.h"

namespace rastrace {

// Throws InputError "<where>: <value>: expected an integer from <min> to <max>".
template <typename T>
T json_integer(const nlohmann::json& value, const std::string& where) {
  constexpr auto lo = std::numeric_limits<T>::min();
  constexpr auto hi = std::numeric_limits<T>::max();
  bool fits = false;
  if (value.is_number_unsigned())
    fits = value.get<std::uint64_t>() <= static_cast<std::uint64_t>(hi);
  else if (value.is_number_integer()) {
    const std::int64_t v = value.get<std::int64_t>();
    fits = v >= static_cast<std::int64_t>(lo) && (v < 0 || static_cast<std::uint64_t>(v) <= static_cast<std::uint64_t>(hi));
  }
  if (!fits)
    throw InputError(where + ": " + excerpt(value.dump()) + ": expected an integer from " + std::to_string(lo) +
                     " to " + std::to_string(hi));
  return value.is_number_unsigned() ? static_cast<T>(value.get<std::uint64_t>())
                                    : static_cast<T>(value.get<std::int64_t>());
}

}  // namespace rastrace
