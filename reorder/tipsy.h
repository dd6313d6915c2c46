// Tipsy's vertex pass with the places its path breaks, for the overdraw pass (tipsy_overdraw.cpp):
// Sander, Nehab and Barczak, "Fast triangle reordering for vertex locality and reduced overdraw",
// SIGGRAPH 2007, section 4: "each dead-end results in a path discontinuity", which flushes the
// cache; these are the hard cluster boundaries.
#pragma once

#include <cstdint>
#include <vector>

#include "reorder/ordering.h"

namespace rastrace {

// reorder_tipsy's ordering (identical); when path_starts is given, appends to it the position in
// face_order of the first face of every path: 0, then every face emitted after a dead end (the
// fan vertex came from the dead-end stack or the input order, not from the last fan's vertices).
// A position equal to the face count (a dead end after the last fan) may close the list.
Ordering tipsify(const Mesh& mesh, const ReorderParams& params, std::vector<std::uint32_t>* path_starts);

}  // namespace rastrace
