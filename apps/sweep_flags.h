// The byte-cache sweep flags shared by `rastrace sweep` and `rastrace texsweep`: --size, --line,
// --assoc, --policy, --layout, --texel, --align, --seed, parsed into a SweepSpec.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "cache_sim/sweep.h"

namespace rastrace {

struct SweepFlags {
  std::string sizes = "1KiB..64KiB";
  std::string lines = "64B";
  std::string assocs = "4";
  std::string policies = "lru";
  std::string layouts = "linear";
  std::string texel = "4B";
  std::string align = "4KiB";
  std::uint64_t seed = 1;
};

void add_sweep_flags(CLI::App& command, SweepFlags& flags);
// Throws InputError naming the flag for a malformed value. The source stays Texel.
SweepSpec sweep_spec_from(const SweepFlags& flags);

}  // namespace rastrace
