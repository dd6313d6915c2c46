#include "apps/sweep_flags.h"

#include <algorithm>

#include "core/error.h"
#include "core/units.h"

namespace rastrace {

void add_sweep_flags(CLI::App& command, SweepFlags& flags) {
  command.add_option("--size", flags.sizes, "Cache sizes: list and/or power-of-two ranges, e.g. 1KiB..64KiB")
      ->capture_default_str();
  command.add_option("--line", flags.lines, "Line sizes, e.g. 32B,64B,128B")->capture_default_str();
  command.add_option("--assoc", flags.assocs, "Associativities: numbers and/or 'full', e.g. 1,2,4,full")
      ->capture_default_str();
  command.add_option("--policy", flags.policies, "Replacement policies: fifo,lru,random,opt")->capture_default_str();
  command.add_option("--layout", flags.layouts, "Texture layouts: linear,block2,block4,block8,block16,morton")
      ->capture_default_str();
  command.add_option("--texel", flags.texel, "Texel size in bytes")->capture_default_str();
  command.add_option("--align", flags.align, "Alignment of every texture level's base")->capture_default_str();
  command.add_option("--seed", flags.seed, "Seed of the random policy")->capture_default_str();
}

SweepSpec sweep_spec_from(const SweepFlags& flags) {
  SweepSpec spec;
  spec.sizes = parse_byte_size_list(flags.sizes, "--size");
  spec.lines.clear();
  for (const std::uint64_t l : parse_byte_size_list(flags.lines, "--line")) {
    if (l > (1u << 30)) throw InputError("--line: " + std::to_string(l) + " bytes: expected at most 1GiB");
    spec.lines.push_back(static_cast<std::uint32_t>(l));
  }
  spec.assocs.clear();
  for (const std::string& a : split_list(flags.assocs, "--assoc")) {
    if (a == "full") {
      spec.assocs.push_back(0);
      continue;
    }
    for (const std::uint64_t w : parse_count_list(a, "--assoc")) {
      if (w == 0 || w > (1u << 31)) throw InputError("--assoc: " + a + ": expected a number of ways >= 1 or 'full'");
      spec.assocs.push_back(static_cast<std::uint32_t>(w));
    }
  }
  spec.policies.clear();
  for (const std::string& p : split_list(flags.policies, "--policy"))
    spec.policies.push_back(parse_replacement_policy(p));
  spec.layouts.clear();
  const std::uint64_t texel = parse_byte_size(flags.texel, "--texel");
  const std::uint64_t align = parse_byte_size(flags.align, "--align");
  for (const std::string& l : split_list(flags.layouts, "--layout")) {
    LayoutSpec layout = parse_layout(l);
    layout.texel_bytes = static_cast<std::uint32_t>(std::min<std::uint64_t>(texel, 1u << 20));
    layout.alignment = align;
    spec.layouts.push_back(layout);
  }
  spec.seed = flags.seed;
  return spec;
}

}  // namespace rastrace
