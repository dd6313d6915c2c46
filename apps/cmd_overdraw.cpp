// `rastrace overdraw MESH --algo A,B,... [--cache 16] [--lambda 1.05] [--view X,Y,Z] [--sphere N]
//  [--resolution 256] [--rules exact|meshopt-fixed|meshopt-0.18] [--no-peer] --format md|csv|latex|json
//  [--no-time]`: view-independent overdraw and ACMR under each ordering, meshoptimizer 0.18 beside
// (experiments/overdraw_table.h).
#include <iostream>
#include <memory>
#include <sstream>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "core/error.h"
#include "experiments/overdraw_table.h"
#include "scenes/mesh_spec.h"

namespace rastrace {

namespace {

struct OverdrawCommandOptions {
  std::string mesh;
  std::string algorithms = "original,tipsy,tipsy-overdraw";
  unsigned cache = 16;
  double lambda = 1.05;
  std::string view = "0,0,-1";
  unsigned sphere = 0;
  int resolution = 256;
  std::string rules = "exact";
  bool no_peer = false;
  std::uint64_t seed = 1;
  std::string format = "md";
  bool no_time = false;
};

glm::vec3 parse_view(const std::string& text) {
  std::istringstream in(text);
  glm::vec3 v;
  char comma1 = 0, comma2 = 0;
  if (!(in >> v.x >> comma1 >> v.y >> comma2 >> v.z) || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof())
    throw InputError("--view '" + text + "': expected three numbers X,Y,Z (the direction the camera looks)");
  return v;
}

OverdrawRules parse_rules(const std::string& text) {
  if (text == "exact") return OverdrawRules::exact();
  if (text == "meshopt-fixed") return OverdrawRules::meshopt_fixed();
  if (text == "meshopt-0.18") return OverdrawRules::meshopt_018();
  throw InputError("--rules '" + text + "': expected exact, meshopt-fixed or meshopt-0.18");
}

void run_overdraw(const OverdrawCommandOptions& options) {
  const TableFormat format = parse_table_format(options.format);
  OverdrawTableSpec spec;
  spec.algorithms = options.algorithms;
  spec.cache = options.cache;
  spec.lambda = options.lambda;
  spec.view_direction = parse_view(options.view);
  spec.sphere_views = options.sphere;
  spec.resolution = options.resolution;
  spec.rules = parse_rules(options.rules);
  if (spec.rules != OverdrawRules::exact() && spec.resolution != 256)
    throw InputError("--rules " + options.rules + ": meshoptimizer's rules draw 256 x 256 views (--resolution 256)");
  spec.peers = !options.no_peer;
  spec.seed = options.seed;
  spec.with_time = !options.no_time;
  const Mesh mesh = load_mesh_spec(options.mesh);
  std::cout << render_table(overdraw_table(mesh, options.mesh, spec), format);
}

}  // namespace

void add_overdraw_command(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("overdraw", "View-independent overdraw and ACMR under each ordering, meshoptimizer beside");
  auto options = std::make_shared<OverdrawCommandOptions>();
  command->add_option("mesh", options->mesh, "Mesh file, builtin:<scene> or grid:WxH")->required();
  command->add_option("--algo", options->algorithms, "all, or a comma-separated list of orderings")
      ->capture_default_str();
  command->add_option("--cache", options->cache, "FIFO entries the orderings optimize for and ACMR is measured on")->check(whole_number(1, 65536))
      ->capture_default_str();
  command
      ->add_option("--lambda", options->lambda,
                   "tipsy-overdraw: cut clusters below lambda x Tipsy's ACMR (also meshopt's threshold)")->check(finite_number(0, 1000))
      ->capture_default_str();
  command->add_option("--view", options->view, "front-to-back, back-to-front: direction the camera looks, X,Y,Z")
      ->capture_default_str();
  command->add_option("--sphere", options->sphere, "Also measure from N directions on the sphere (Tootle-style)")->check(whole_number(0, 10000))
      ->capture_default_str();
  command->add_option("--resolution", options->resolution, "Pixels per side of each view")->check(whole_number(1, 16384))->capture_default_str();
  command
      ->add_option("--rules", options->rules,
                   "Depth rules: exact, meshopt-fixed (upstream 2025) or meshopt-0.18 (Debian, its gradient defect)")
      ->capture_default_str();
  command->add_flag("--no-peer", options->no_peer, "Leave out the meshopt-overdraw and meshopt-full rows");
  command->add_option("--seed", options->seed, "Seed of the randomized orderings")->check(whole_number(0, 9223372036854775807))->capture_default_str();
  command->add_option("--format", options->format, "md, csv, latex or json")->capture_default_str();
  command->add_flag("--no-time", options->no_time, "Leave out the run-time column so outputs compare byte for byte");
  command->footer(
      "Examples:\n"
      "  rastrace overdraw data/meshes/bunny00.off --algo tipsy,tipsy-overdraw --format json\n"
      "  rastrace overdraw builtin:spider --algo tipsy-overdraw,front-to-back,back-to-front --view 0,0,-1\n"
      "  rastrace overdraw data/meshes/bunny00.off --algo tipsy --rules meshopt-0.18 --no-time");
  command->callback([options] { run_overdraw(*options); });
}

}  // namespace rastrace
