// Forsyth, "Comparison of VIPM methods": static meshes reordered for a cache of about 16 entries
// reach about 0.65 vertices per drawn triangle. Ours: his linear-speed optimizer (reorder/forsyth)
// on the CGAL meshes, FIFO 16. And the figures of Sander, Nehab, Barczak 2007 (Tipsy) as cited,
// on a dragon we do not have.
#include "cache_sim/vertex_cache.h"
#include "experiments/reproduce/reproduce.h"
#include "reorder/ordering.h"
#include "scenes/mesh_io.h"

namespace rastrace {

std::vector<ReproducedFigure> reproduce_forsyth() {
  std::vector<ReproducedFigure> figures;
  for (const char* name : {"fandisk.off", "triceratops.off", "bunny00.off"}) {
    const Mesh mesh = load_mesh(cgal_mesh_path(name));
    ReorderParams params;
    params.cache_size = 16;
    const Ordering ordering = find_reorder_algorithm("forsyth").run(mesh, params);
    const VertexStreamStats stats =
        simulate_vertex_stream(ordering.indices, ordering.type, VertexCachePolicy::Fifo, 16, ordering.restart_index);
    figures.push_back({"Forsyth (VIPM)", "static mesh, cache ~16: vertices per triangle", "his meshes (unnamed)", name,
                       0.65, stats.acmr(), "the paper says 'about'"});
  }
  const std::string tipsy = "Sander et al. 2007";
  for (const auto& [method, acmr] : {std::pair{"K-Cache-Reorder", 0.63}, {"Hoppe", 0.65}, {"Tipsy", 0.69}})
    figures.push_back(
        {tipsy, std::string("dragon: ") + method + " ACMR", "dragon (40k t)", "", acmr, {}, "no such mesh"});
  return figures;
}

}  // namespace rastrace
