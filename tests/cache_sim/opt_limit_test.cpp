// OPT buffers its whole line stream (16 bytes per access): past its stated limit it fails with an
// error that names the limit in accesses and bytes, before reading more.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cache_sim/live_bank_sink.h"
#include "cache_sim/opt_cache.h"
#include "core/error.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

TEST(OptLimit, TheDefaultLimitIs2To28AccessesOf16BytesAndItsErrorSaysSo) {
  EXPECT_NO_THROW(check_opt_capacity(kOptMaxAccesses));
  try {
    check_opt_capacity(1'000'000'000);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("opt: 1000000000 accesses, more than the 268435456 OPT holds in memory"));
    EXPECT_THAT(e.what(), HasSubstr("16 bytes each, 4GiB"));
  }
}

TEST(OptLimit, TheLiveBankStopsAtItsLimitWithTheOtherPoliciesUnaffectedBelowIt) {
  CacheBankConfig config;
  config.address.push_back({1024, 64, 0, ReplacementPolicy::Opt, 1});
  config.opt_max_accesses = 1000;
  std::vector<AddressAccess> accesses(600);
  for (std::size_t i = 0; i < accesses.size(); ++i) accesses[i].address = (i * 2654435761u) % 65536;
  LiveBankSink sink(config, {});
  sink.address_accesses(accesses);  // 600 of 1000
  try {
    sink.address_accesses(accesses);  // 1200
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("opt: 1200 accesses, more than the 1000 OPT holds in memory"));
  }
}

}  // namespace
}  // namespace rastrace
