// The texture-cache sweep option shared by `rastrace texsweep` and `rastrace report`: one
// byte-cache spec of the cache-spec grammar (cache_sim/cache_spec.h) with alternatives, e.g.
// --tcache size=1KiB..64KiB,assoc=full,policy=fifo/lru/opt,layout=linear/morton.
#pragma once

#include <deque>
#include <initializer_list>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

#include "cache_sim/sweep.h"

namespace rastrace {

// The per-axis flags a cache spec replaced (--size, --line, --entries, ...): still accepted by the
// parser, hidden from --help, and an error that shows the spec to write when given.
class RetiredCacheFlags {
 public:
  void add(CLI::App& command, std::initializer_list<const char*> names);
  // Throws InputError("--size 1KiB,4KiB, --policy lru: write OPTION size=1KiB/4KiB,policy=lru")
  // if any was given.
  void reject(const std::string& option) const;

 private:
  std::deque<std::pair<std::string, std::string>> flags_;  // name, value given ("" if none); stable addresses
};

struct SweepFlags {
  std::string tcache;
  RetiredCacheFlags retired;
};

void add_sweep_flags(CLI::App& command, SweepFlags& flags);
// The texel-trace sweep the spec stands for. Throws InputError for a malformed spec, a vertex
// cache spec, or one of the retired flags.
SweepSpec sweep_spec_from(const SweepFlags& flags);

}  // namespace rastrace
