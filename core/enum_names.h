// The names of an enum's values, as typed on the command line and printed in tables: one table of
// {value, name} per enum gives both directions, so a name cannot be parsed one way and printed
// another. A value may have aliases ("tiled" for "tiled8"): its first entry is the name it prints
// as and the one an error lists; parse_enum accepts every entry.
//
//   constexpr EnumName<Traversal> kTraversals[] = {
//       {Traversal::Scanline, "scanline"}, {Traversal::Tiled8, "tiled8"}, {Traversal::Tiled8, "tiled"}};
//   parse_enum("tiled", kTraversals, "traversal order")    -> Traversal::Tiled8
//   enum_to_string(Traversal::Tiled8, kTraversals)         -> "tiled8"
//   parse_enum("zigzag", kTraversals, "traversal order")
//     throws InputError("unknown traversal order 'zigzag': expected scanline or tiled8")
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace rastrace {

template <typename E>
struct EnumName {
  E value;
  const char* name;
};

// Throws InputError("unknown <what> '<text>': expected a, b or c").
[[noreturn]] void throw_unknown_name(std::string_view what, std::string_view text,
                                     const std::vector<const char*>& accepted);

// The value named `text`; throws InputError naming `what` (the option or setting: "cull mode")
// and listing the accepted names (each value's first) otherwise.
template <typename E, std::size_t N>
E parse_enum(std::string_view text, const EnumName<E> (&names)[N], std::string_view what) {
  for (const EnumName<E>& entry : names)
    if (text == entry.name) return entry.value;
  std::vector<const char*> accepted;
  for (std::size_t i = 0; i < N; ++i) {
    bool alias = false;
    for (std::size_t j = 0; j < i; ++j) alias |= names[j].value == names[i].value;
    if (!alias) accepted.push_back(names[i].name);
  }
  throw_unknown_name(what, text, accepted);
}

// The name `value` prints as: its first entry ("?" if the table lacks it).
template <typename E, std::size_t N>
const char* enum_to_string(E value, const EnumName<E> (&names)[N]) {
  for (const EnumName<E>& entry : names)
    if (entry.value == value) return entry.name;
  return "?";
}

}  // namespace rastrace
