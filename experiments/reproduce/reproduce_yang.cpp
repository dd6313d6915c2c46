// Yang, Mitra, Huang, Table 1: vertices sent by generalized triangle strips (Evans et al.), swaps
// included. CGAL's triceratops is the paper's model (2,832 vertices, 5,660 triangles); the other
// models are not available here.
#include "experiments/reproduce/reproduce.h"
#include "reorder/ordering.h"
#include "reorder/strip.h"
#include "scenes/mesh_io.h"

namespace rastrace {

std::vector<ReproducedFigure> reproduce_yang() {
  const std::string paper = "Yang et al.";
  struct Row {
    const char* name;
    const char* paper_mesh;
    const char* our_mesh;
    std::int64_t cost;
  };
  const Row rows[] = {
      {"Plane", "Plane (1,508 v, 2,992 t)", "", 3509},
      {"Skyscraper", "Skyscraper (2,022 v, 3,692 t)", "", 4616},
      {"Foot", "Foot (2,154 v, 4,202 t)", "", 5102},
      {"Triceratops", "Triceratops (2,832 v, 5,660 t)", "triceratops.off", 6911},
      {"Porsche", "Porsche (5,247 v, 10,425 t)", "", 12367},
  };
  std::vector<ReproducedFigure> figures;
  for (const Row& row : rows) {
    const std::string figure = std::string(row.name) + ": strip vertices sent";
    if (!*row.our_mesh) {
      figures.push_back({paper, figure, row.paper_mesh, "", row.cost, {}, "no such mesh"});
      continue;
    }
    const Mesh mesh = load_mesh(cgal_mesh_path(row.our_mesh));
    const Ordering ordering = find_reorder_algorithm("strip").run(mesh, ReorderParams{});
    const StripStats stats = strip_stats(ordering.indices, ordering.type, ordering.restart_index);
    figures.push_back({paper, figure, row.paper_mesh, row.our_mesh, row.cost,
                       static_cast<std::int64_t>(stats.vertices_sent), "the same model; ours: rastrace's strip"});
  }
  return figures;
}

}  // namespace rastrace
