#include "apps/option_checks.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

#include "core/input_guard.h"

namespace rastrace {

namespace {
std::string shown(const std::string& text) { return "'" + excerpt(text) + "'"; }
}  // namespace

CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi) {
  const std::string expected = "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        std::uint64_t value = 0;
        bool ok = !text.empty();
        for (const char c : text) {
          if (c < '0' || c > '9' || value > (std::numeric_limits<std::uint64_t>::max() - 9) / 10) {
            ok = false;
            break;
          }
          value = value * 10 + static_cast<std::uint64_t>(c - '0');
        }
        if (!ok || value < lo || value > hi) return "expected " + expected + ", found " + shown(text);
        return {};
      },
      "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

CLI::Validator finite_number(double lo, double hi) {
  const std::string expected = "a finite number from " + CLI::detail::to_string(lo) + " to " +
                               CLI::detail::to_string(hi);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const double value = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
        if (text.empty() || !end || *end != '\0' || errno == ERANGE || !std::isfinite(value) || value < lo ||
            value > hi)
          return "expected " + expected + ", found " + shown(text);
        return {};
      },
      "NUMBER in [" + CLI::detail::to_string(lo) + ", " + CLI::detail::to_string(hi) + "]");
}

}  // namespace rastrace
