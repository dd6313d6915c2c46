#include "apps/sweep_flags.h"

#include <algorithm>

#include "cache_sim/cache_spec.h"
#include "core/error.h"

namespace rastrace {

void RetiredCacheFlags::add(CLI::App& command, std::initializer_list<const char*> names) {
  for (const char* name : names) {
    flags_.emplace_back(name, "");
    command.add_option(std::string("--") + name, flags_.back().second)->group("");
  }
}

void RetiredCacheFlags::reject(const std::string& option) const {
  std::string given, spec;
  for (auto [name, value] : flags_) {
    if (value.empty()) continue;
    given += (given.empty() ? "--" : ", --") + name + " " + value;
    std::replace(value.begin(), value.end(), ',', '/');
    spec += (spec.empty() ? "" : ",") + name + "=" + value;
  }
  if (!given.empty()) throw InputError(given + ": write " + option + " " + spec);
}

void add_sweep_flags(CLI::App& command, SweepFlags& flags) {
  command
      .add_option("--tcache", flags.tcache,
                  "Texture caches to sweep (cache spec, README): alternatives a/b and ranges a..b expand to every "
                  "combination")
      ->capture_default_str();
  flags.retired.add(command, {"size", "line", "assoc", "policy", "layout", "texel", "align", "seed"});
}

SweepSpec sweep_spec_from(const SweepFlags& flags) {
  flags.retired.reject("--tcache");
  const CacheSpec spec = parse_cache_spec(flags.tcache, "--tcache");
  if (spec.kind != CacheKind::Byte)
    throw InputError("--tcache '" + flags.tcache + "': expected a byte-cache spec (size=...), not a vertex cache");
  return sweep_spec(spec, SweepSource::Texel);
}

}  // namespace rastrace
