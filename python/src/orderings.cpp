// reorder and vcache: the triangle orderings of reorder/ (as `rastrace reorder` and `rastrace
// vcache` run them) and post-transform vertex-cache statistics, for a mesh or for any index list.
#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "cache_sim/cache_spec.h"
#include "cache_sim/vertex_cache.h"
#include "columns.h"
#include "core/error.h"
#include "experiments/cache_report.h"
#include "experiments/vcache_table.h"
#include "meshes.h"
#include "reorder/ordering.h"

namespace rastrace::python {

namespace {

py::array_t<std::uint32_t> reorder(py::handle mesh_object, const std::string& algo, unsigned cache,
                                   const std::string& policy, std::uint64_t seed, double time_budget,
                                   const std::string& texgroup_base) {
  std::optional<Mesh> storage;
  const Mesh& mesh = mesh_argument(mesh_object, storage);
  std::vector<std::uint32_t> indices;
  {
    py::gil_scoped_release release;
    const ReorderAlgorithm& algorithm = find_reorder_algorithm(algo);
    ReorderParams params;
    params.cache_size = cache;
    params.policy = parse_vertex_cache_policy(policy);
    params.seed = seed;
    params.time_budget_seconds = time_budget;
    params.texgroup_base = texgroup_base;
    VertexCache check(params.policy, params.cache_size);  // rejects a cache of 0 before any work
    indices = indices_in_face_order(mesh, algorithm.run(mesh, params).face_order);
  }
  return to_array(std::move(indices));
}

// The vertex caches of a spec over a triangle list: the rows of `rastrace sweep --cache entries=...`.
py::object vcache_of_indices(const py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>& indices,
                             const std::string& cache) {
  const std::span<const std::uint32_t> list(indices.data(), static_cast<std::size_t>(indices.size()));
  Table table;
  {
    py::gil_scoped_release release;
    if (list.size() % 3 != 0)
      throw InputError("index list of " + std::to_string(list.size()) +
                       " indices: expected a triangle list (a multiple of 3)");
    const CacheSpec spec = parse_cache_spec(cache, "cache");
    if (spec.kind != CacheKind::Vertex)
      throw InputError("cache '" + cache + "': expected a post-transform vertex cache spec (entries=...)");
    std::vector<VertexSweepRow> rows;
    for (const VertexCacheSpec& c : vertex_caches(spec))
      rows.push_back({c, simulate_vertex_stream(list, PrimitiveType::TriangleList, c.policy, c.entries)});
    table = vertex_cache_table("Post-transform vertex caches", {}, rows);
  }
  return table_columns(table);
}

py::object vcache(py::handle mesh_object, const std::string& cache, const std::string& algo, unsigned target,
                  std::uint64_t seed, double time_budget, const std::string& accounting, bool with_time) {
  if (py::isinstance<py::array>(mesh_object) || py::isinstance<py::list>(mesh_object))
    return vcache_of_indices(py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>::ensure(mesh_object),
                             cache);
  std::optional<Mesh> storage;
  const Mesh& mesh = mesh_argument(mesh_object, storage);
  const std::string mesh_name = py::isinstance<py::str>(mesh_object) ? std::string(py::str(mesh_object)) : mesh.name;
  Table table;
  {
    py::gil_scoped_release release;
    const CacheSpec spec = parse_cache_spec(cache, "--cache");
    if (spec.kind != CacheKind::Vertex)
      throw InputError("--cache '" + cache + "': vcache simulates post-transform vertex caches: expected " +
                       "entries=...,policy=..., e.g. entries=12/16,policy=fifo/lru");
    if (accounting != "misses" && accounting != "evictions")
      throw InputError("--accounting '" + accounting + "': expected misses or evictions");
    VcacheTableSpec table_spec;
    table_spec.algorithms = algo;
    table_spec.caches = spec.entries;
    table_spec.policies = spec.vertex_policies;
    table_spec.target = target;
    table_spec.seed = seed;
    table_spec.time_budget = time_budget;
    table_spec.with_time = with_time;
    table_spec.eviction_charged = accounting == "evictions";
    table = vcache_table(mesh, mesh_name, table_spec);
  }
  return table_columns(table);
}

}  // namespace

void bind_orderings(py::module_& m) {
  m.def(
      "algorithms",
      [] {
        py::dict names;
        for (const ReorderAlgorithm& a : reorder_algorithms()) names[a.name.c_str()] = a.description;
        return names;
      },
      "Every triangle ordering: name -> one-line description (with its paper).");
  m.def("reorder", &reorder, py::arg("mesh"), py::arg("algo"), py::arg("cache") = 16, py::arg("policy") = "fifo",
        py::arg("seed") = 1, py::arg("time_budget") = 60.0, py::arg("texgroup_base") = "strip",
        "The mesh's triangle list with its faces in the algorithm's order (uint32, 3 per face, original\n"
        "winding), as `rastrace reorder` writes it. mesh: a Mesh or a mesh spec; cache and policy: the\n"
        "post-transform cache the ordering optimizes for.");
  m.def("vcache", &vcache, py::arg("mesh"), py::arg("cache") = "entries=8/12/16/20/24/32,policy=fifo",
        py::arg("algo") = "all", py::arg("target") = 0, py::arg("seed") = 1, py::arg("time_budget") = 60.0,
        py::arg("accounting") = "misses", py::arg("time") = false,
        "Post-transform vertex-cache statistics under a cache spec (entries=...,policy=...).\n"
        "mesh a Mesh or mesh spec: `rastrace vcache`'s table (one row per ordering, policy and size:\n"
        "acmr, atvr, misses, indices per triangle, Hoppe's bandwidth; run time with time=True).\n"
        "mesh a triangle-list index array: that order's rows (policy, entries, lookups, misses,\n"
        "triangles, degenerate, vertices, acmr, atvr). Returns rastrace.Columns.");
}

}  // namespace rastrace::python
