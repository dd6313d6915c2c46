#include "apps/sweep_flags.h"

#include <algorithm>

#include "cache_sim/cache_spec.h"
#include "core/error.h"

namespace rastrace {

namespace {
constexpr const char* kOldFlags[] = {"size", "line", "assoc", "policy", "layout", "texel", "align", "seed"};
}  // namespace

void add_sweep_flags(CLI::App& command, SweepFlags& flags) {
  command
      .add_option("--tcache", flags.tcache,
                  "Texture caches to sweep (cache spec, README): alternatives a/b and ranges a..b expand to every "
                  "combination")
      ->capture_default_str();
  for (const char* flag : kOldFlags) command.add_option(std::string("--") + flag, flags.old_flags[flag])->group("");
}

SweepSpec sweep_spec_from(const SweepFlags& flags) {
  std::string given, spec_text;
  for (const char* flag : kOldFlags) {
    const auto it = flags.old_flags.find(flag);
    if (it == flags.old_flags.end() || it->second.empty()) continue;
    std::string value = it->second;
    given += std::string(given.empty() ? "--" : ", --") + flag + " " + value;
    std::replace(value.begin(), value.end(), ',', '/');
    spec_text += std::string(spec_text.empty() ? "" : ",") + flag + "=" + value;
  }
  if (!given.empty()) throw InputError(given + ": write --tcache " + spec_text);
  const CacheSpec spec = parse_cache_spec(flags.tcache, "--tcache");
  if (spec.kind != CacheKind::Byte)
    throw InputError("--tcache '" + flags.tcache + "': expected a byte-cache spec (size=...), not a vertex cache");
  return sweep_spec(spec, SweepSource::Texel);
}

}  // namespace rastrace
