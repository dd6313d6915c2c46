#include "core/enum_names.h"

#include <string>

#include "core/error.h"

namespace rastrace {

void throw_unknown_name(std::string_view what, std::string_view text, const std::vector<const char*>& accepted) {
  std::string expected;
  for (std::size_t i = 0; i < accepted.size(); ++i) {
    if (i > 0) expected += i + 1 == accepted.size() ? " or " : ", ";
    expected += accepted[i];
  }
  throw InputError("unknown " + std::string(what) + " '" + std::string(text) + "': expected " + expected);
}

}  // namespace rastrace
