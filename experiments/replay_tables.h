// `rastrace replay` (and the Python module's `replay`): a trace replayed once through every cache
// of the given cache specs, with the LiveBankSink that live rendering uses, as tables that state
// every parameter: post-transform vertex caches, then texture, vertex-buffer and address caches
// (a table only for the kinds the specs name).
#pragma once

#include <string>
#include <vector>

#include "core/table.h"
#include "experiments/hierarchy_tables.h"

namespace rastrace {

class Progress;

// `option` names the specs in errors ("--cache"). keep_vertex_cache: the post-transform caches
// keep their contents across draws. Byte caches with sector= become a "Sectored caches" table
// (each a one-level hierarchy, hierarchy_tables.h); `hierarchy` (replay --level ...) adds a
// "Cache hierarchy" table. The trace is read once for all of them. Throws InputError for a bad
// trace or spec.
std::vector<Table> replay_tables(const std::string& trace, const std::vector<std::string>& specs,
                                 bool keep_vertex_cache, const std::string& option = "--cache",
                                 bool progress = true, const HierarchyRequest& hierarchy = {});

}  // namespace rastrace
