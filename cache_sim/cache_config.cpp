#include "cache_sim/cache_config.h"

#include <bit>

#include "core/enum_names.h"
#include "core/error.h"
#include "core/units.h"

namespace rastrace {

namespace {

constexpr EnumName<ReplacementPolicy> kPolicies[] = {{ReplacementPolicy::Fifo, "fifo"},
                                                     {ReplacementPolicy::Lru, "lru"},
                                                     {ReplacementPolicy::Random, "random"},
                                                     {ReplacementPolicy::Opt, "opt"}};

}  // namespace

const char* to_string(ReplacementPolicy policy) { return enum_to_string(policy, kPolicies); }

ReplacementPolicy parse_replacement_policy(const std::string& text) {
  return parse_enum(text, kPolicies, "replacement policy");
}

void validate(const CacheConfig& c) {
  const std::string name = "cache " + format_byte_size(c.size_bytes) + "/" + format_byte_size(c.line_bytes) + "/" +
                           (c.assoc == 0 ? std::string("full") : std::to_string(c.assoc) + "-way");
  if (c.size_bytes == 0) throw InputError("cache size 0: expected at least one line");
  if (c.line_bytes == 0 || !std::has_single_bit(c.line_bytes))
    throw InputError(name + ": line size " + std::to_string(c.line_bytes) + " bytes: expected a power of two");
  if (c.size_bytes % c.line_bytes != 0 || c.size_bytes < c.line_bytes)
    throw InputError(name + ": capacity is not a whole number of lines");
  if (c.lines() > (std::uint64_t{1} << 31)) throw InputError(name + ": more than 2^31 lines");
  if (c.assoc != 0 && c.lines() % c.assoc != 0)
    throw InputError(name + ": " + std::to_string(c.lines()) + " lines do not divide into " + std::to_string(c.assoc) +
                     "-way sets");
}

std::string describe(const CacheConfig& c) {
  return format_byte_size(c.size_bytes) + "/" + format_byte_size(c.line_bytes) + "/" +
         (c.assoc == 0 ? std::string("full") : std::to_string(c.assoc) + "-way") + "/" + to_string(c.policy);
}

}  // namespace rastrace
