// Replays a Dinero din trace through one byte cache, through the installed package's front
// headers: the cache simulator and the trace readers, nothing else.
#include <iostream>

#include <rastrace/cache_sim.h>
#include <rastrace/core.h>
#include <rastrace/traces.h>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: consumer TRACE.din CACHE_SPEC\n";
    return 2;
  }
  try {
    const rastrace::ByteCacheChoice cache = rastrace::parse_byte_cache(argv[2], "cache");
    rastrace::CacheBankConfig bank;
    bank.address.push_back(cache.cache);
    rastrace::LiveBankSink sink(bank, {});
    rastrace::replay_file(argv[1], sink);
    const rastrace::CacheStats& stats = sink.address_stats().at(0);
    std::cout << "accesses " << stats.accesses << " misses " << stats.misses << " compulsory " << stats.compulsory
              << "\n";
  } catch (const rastrace::InputError& e) {
    std::cerr << "consumer: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
