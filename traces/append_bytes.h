// Appends a value's bytes to a byte string, as the trace format stores integers: little endian,
// the machine's own order (the trace code builds only on little-endian machines).
#pragma once

#include <cstring>
#include <string>

namespace rastrace {

template <typename T>
void append_bytes(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace rastrace
