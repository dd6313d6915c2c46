// The texture-cache sweep option shared by `rastrace texsweep` and `rastrace report`: one
// byte-cache spec of the cache-spec grammar (cache_sim/cache_spec.h) with alternatives, e.g.
// --tcache size=1KiB..64KiB,assoc=full,policy=fifo/lru/opt,layout=linear/morton.
#pragma once

#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "cache_sim/sweep.h"

namespace rastrace {

struct SweepFlags {
  std::string tcache;
  // The per-axis flags the spec replaced (--size, --line, ...): given, they are an error that
  // shows the spec to write.
  std::map<std::string, std::string> old_flags;
};

void add_sweep_flags(CLI::App& command, SweepFlags& flags);
// The texel-trace sweep the spec stands for. Throws InputError for a malformed spec, a vertex
// cache spec, or one of the retired flags.
SweepSpec sweep_spec_from(const SweepFlags& flags);

}  // namespace rastrace
