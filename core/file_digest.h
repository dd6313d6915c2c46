// A content digest of a whole file, for results that must say which input they came from (a
// sharded sweep's parts are merged only when they were computed from the same trace).
#pragma once

#include <string>

namespace rastrace {

// "fnv1a64:" and 16 hex digits: FNV-1a over every byte (not cryptographic: it tells files apart,
// it does not defend against forgery). Throws InputError naming the file if it cannot be read.
std::string file_digest(const std::string& path);

}  // namespace rastrace
