#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/error.h"
#include "experiments/reproduce/reproduce.h"
#include "scenes/scene_io.h"

namespace rastrace {

std::string cgal_mesh_path(const std::string& name) {
  const std::filesystem::path path = std::filesystem::path(data_directory()) / "meshes" / name;
  if (!std::filesystem::exists(path))
    throw InputError(path.string() + ": CGAL mesh not found: expected scripts/setup.sh to have unpacked it");
  return path.string();
}

namespace {

bool is_number(const TableCell& cell) {
  return std::holds_alternative<double>(cell.value) || std::holds_alternative<std::int64_t>(cell.value);
}
double number(const TableCell& cell) {
  return std::holds_alternative<double>(cell.value) ? std::get<double>(cell.value)
                                                    : double(std::get<std::int64_t>(cell.value));
}

// The value as a table prints it (3 decimals, ties to even like printf), so a figure that prints
// as the published one shows no difference.
double printed(double value) { return std::nearbyint(value * 1000.0) / 1000.0; }

}  // namespace

Table reproduction_table(const ReproduceOptions& options) {
  using Reproducer = std::vector<ReproducedFigure> (*)(const ReproduceOptions&);
  const std::pair<const char*, Reproducer> papers[] = {
      {"castano", [](const ReproduceOptions&) { return reproduce_castano(); }},
      {"hoppe", reproduce_hoppe},
      {"yang", [](const ReproduceOptions&) { return reproduce_yang(); }},
      {"yang-texture", [](const ReproduceOptions&) { return reproduce_yang_texture(); }},
      {"sander", [](const ReproduceOptions&) { return reproduce_sander2008(); }},
      {"forsyth", [](const ReproduceOptions&) { return reproduce_forsyth(); }},
      {"hakura", [](const ReproduceOptions&) { return reproduce_hakura(); }},
      {"hakura-compressed", [](const ReproduceOptions&) { return reproduce_hakura_compressed(); }},
  };
  std::string expected = "expected all";
  for (std::size_t i = 0; i < std::size(papers); ++i)
    expected += std::string(i + 1 == std::size(papers) ? " or " : ", ") + papers[i].first;
  std::vector<std::string> wanted;
  std::stringstream list(options.papers);
  for (std::string name; std::getline(list, name, ',');) {
    bool known = name == "all";
    for (const auto& [paper, run] : papers) known |= name == paper;
    if (!known) throw InputError("--paper '" + name + "': " + expected);
    wanted.push_back(name);
  }
  if (wanted.empty()) throw InputError("--paper '': " + expected);

  Table table;
  table.title = "Published figures (REFERENCE.md) and rastrace's";
  table.parameters = {
      {"papers", options.papers},
      {"local_iterations", static_cast<std::int64_t>(options.local_iterations)},
      {"difference",
       "ours rounded as printf rounds (3 decimals, ties to even), minus published; and in percent of published"}};
  table.columns = {{"paper", "paper", 0},
                   {"figure", "figure", 0},
                   {"paper_mesh", "paper's mesh", 0},
                   {"our_mesh", "our mesh", 0},
                   {"published", "published", 3},
                   {"ours", "ours", 3},
                   {"difference", "difference", 3},
                   {"difference_percent", "difference %", 1},
                   {"note", "note", 0}};
  for (const auto& [paper, run] : papers) {
    if (std::find(wanted.begin(), wanted.end(), "all") == wanted.end() &&
        std::find(wanted.begin(), wanted.end(), paper) == wanted.end())
      continue;
    for (const ReproducedFigure& figure : run(options)) {
      TableCell difference, percent;
      if (is_number(figure.published) && is_number(figure.ours)) {
        const double gap = printed(number(figure.ours)) - number(figure.published);
        const bool counts = std::holds_alternative<std::int64_t>(figure.published.value) &&
                            std::holds_alternative<std::int64_t>(figure.ours.value);
        difference = counts ? TableCell(static_cast<std::int64_t>(gap)) : TableCell(gap);
        percent = 100.0 * gap / number(figure.published);
      }
      table.add_row({figure.paper, figure.figure, figure.paper_mesh, figure.our_mesh.empty() ? "-" : figure.our_mesh,
                     figure.published, figure.ours, difference, percent, figure.note});
    }
  }
  return table;
}

}  // namespace rastrace
