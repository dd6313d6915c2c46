// `rastrace reproduce`: every published figure in REFERENCE.md beside the one rastrace measures
// now, with the difference. Each paper has its own file (reproduce_<paper>.cpp) holding the
// published numbers and the code that measures ours. Where our mesh is not the paper's (CGAL's
// fandisk has 6,475 vertices where Hoppe's has 7,233; bunny00 is not Stanford's 69,473-face
// bunny), the row says so; where we have no such mesh (buddha, dragon), the row is kept with
// no measurement, rather than hidden.
#pragma once

#include <string>
#include <vector>

#include "core/table.h"

namespace rastrace {

struct ReproducedFigure {
  std::string paper;       // "Castano 2009"
  std::string figure;      // what is measured: "Optimal, FIFO 12: ACMR"
  std::string paper_mesh;  // the paper's mesh, with its size
  std::string our_mesh;    // ours, or "" when we have none
  TableCell published;
  TableCell ours;  // std::monostate when we have no such mesh
  std::string note;
};

struct ReproduceOptions {
  std::string papers = "all";  // all, or a comma-separated list of castano, hoppe, yang, sander, forsyth, hakura,
                               // hakura-compressed
  // Hoppe's local optimization: perturbation searches (the paper ran to convergence).
  std::uint64_t local_iterations = 8000;
};

std::vector<ReproducedFigure> reproduce_castano();
std::vector<ReproducedFigure> reproduce_hoppe(const ReproduceOptions& options);
std::vector<ReproducedFigure> reproduce_yang();
// Renders the bunny and the spider: a few seconds.
std::vector<ReproducedFigure> reproduce_yang_texture();
std::vector<ReproducedFigure> reproduce_sander2008();
std::vector<ReproducedFigure> reproduce_forsyth();
// Renders the bunny, the spider and the grid twice each (scanline, tiled8): under a minute.
std::vector<ReproducedFigure> reproduce_hakura();
// Hakura and Gupta's working-set knee per storage format (RGBA8, BC1, BC7) and anisotropy (1, 4,
// 16) on the same three scenes at 512x384: nine renders.
std::vector<ReproducedFigure> reproduce_hakura_compressed();

// One table: paper, figure, meshes, published, ours, difference (ours - published) and its
// percentage, note. Throws InputError for an unknown paper name.
Table reproduction_table(const ReproduceOptions& options);

// CGAL's mesh `name` from the data folder (scripts/setup.sh unpacks them).
std::string cgal_mesh_path(const std::string& name);

}  // namespace rastrace
