// `rastrace render SCENE -o image.png [--trace out.rtrace] [--vcache entries=16,policy=fifo]
//  [--tcache size=16KiB,line=64B,assoc=4,policy=lru,layout=block4] [--zcache model=attila]
//  [--ccache model=attila] [--depth-test early|late] [--hiz] [--raster tiled8] [--filter trilinear]
//  [--vipm METHOD --lod N] [--miss-map misses.png] [--json]`:
// draws a scene with the software pipeline (in a triangle ordering, or at a VIPM level of detail),
// simulating a post-transform vertex cache, a texture cache and the depth and colour caches live
// (and writing the trace when asked), and prints what the frame cost (experiments/frame_render.h).
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/render_flags.h"
#include "core/error.h"
#include "cache_sim/cache_spec.h"
#include "core/table.h"
#include "experiments/frame_render.h"

namespace rastrace {

namespace {

struct RenderCommand {
  SceneRenderFlags flags;
  std::string output;
  std::string depth;
  std::string trace;
  std::string vcache = "entries=16,policy=fifo";
  std::string tcache = "size=16KiB,line=64B,assoc=4,policy=lru,layout=block4";
  std::string zcache = "model=attila";
  std::string ccache = "model=attila";
  std::string old_layout;  // --layout, replaced by the texture cache's layout key
  std::string vipm;        // a VIPM method: draw the LoD `lod` instead of an ordering
  std::string lod;         // collapses done, with --vipm
  std::string format = "md";
  bool json = false;
  HierarchyRequest hierarchy;  // --level, --units, --tile, --inclusion
  unsigned frames = 1;
  std::string miss_map;
};

void run_render(const RenderCommand& command) {
  const TableFormat format = command.json ? TableFormat::Json : parse_table_format(command.format);
  if (!command.old_layout.empty())
    throw InputError("--layout '" + command.old_layout + "': write the layout in the texture cache spec, e.g. " +
                     "--tcache size=16KiB,line=64B,assoc=4,policy=lru,layout=" + command.old_layout);
  FrameSpec spec;
  spec.flags = command.flags;
  spec.vcache = command.vcache;
  spec.tcache = command.tcache;
  spec.zcache = command.zcache;
  spec.ccache = command.ccache;
  spec.trace = command.trace;
  spec.vipm = command.vipm;
  spec.lod = command.lod;
  spec.image = command.output;
  spec.hierarchy = command.hierarchy;
  spec.frames = command.frames;
  spec.miss_map = !command.miss_map.empty();
  const Frame frame = render_frame(spec);
  frame.result.framebuffer.write_colour(command.output);
  if (!command.depth.empty()) frame.result.framebuffer.write_depth(command.depth);
  if (frame.miss_map) {
    const ByteCacheChoice tcache = parse_byte_cache(command.tcache, "--tcache");
    std::cerr << write_texture_miss_map(
        *frame.miss_map, format_cache_spec(tcache.cache) + ",layout=" + layout_name(tcache.layout), command.miss_map);
  }
  std::vector<Table> tables = {frame.table};
  tables.insert(tables.end(), frame.hierarchy.begin(), frame.hierarchy.end());
  std::cout << render_tables(tables, format);
}

}  // namespace

void add_render_command(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("render", "Draw a scene, simulate its vertex, texture, depth and colour caches, write the image");
  auto options = std::make_shared<RenderCommand>();
  add_scene_render_flags(*command, options->flags);
  command->add_option("-o,--output", options->output, "Colour image (PNG, or any format by extension)")->required();
  command->add_option("--depth", options->depth, "Depth buffer as a float EXR");
  command->add_option("--trace", options->trace, "Write the vertex and texel trace (rastrace container)");
  command->add_option("--vcache", options->vcache, "Post-transform vertex cache (cache spec, README)")
      ->capture_default_str();
  command->add_option("--tcache", options->tcache, "Texture cache and layout (cache spec, README)")
      ->capture_default_str();
  command->add_option("--zcache", options->zcache, "Depth cache (cache spec, README; source=depth implied)")
      ->capture_default_str();
  command->add_option("--ccache", options->ccache, "Colour cache (cache spec, README; source=colour implied)")
      ->capture_default_str();
  command->add_option("--layout", options->old_layout)->group("");  // the old spelling: an error naming the new
  command
      ->add_option("--lod-formula", options->flags.lod,
                   "Texture LOD scale factor: lengths (GL eq. 8.6) or max_component (8.7)")
      ->capture_default_str();
  command->add_option("--vipm", options->vipm,
                      "Draw a VIPM level of detail: vanilla, skipstrips, skiplists, mixed, mixedstrips or sliding");
  command->add_option("--lod", options->lod, "With --vipm: the level of detail, as collapses done (0: full detail)");
  command->add_option("--level", options->hierarchy.levels,
                      "A texture cache hierarchy simulated live, one --level per level, L1 first (replay --help)");
  command->add_option("--units", options->hierarchy.units, "Hierarchy: L1 copies (texture units)")
      ->check(CLI::Range(1, 1024));
  command->add_option("--tile", options->hierarchy.tile, "Hierarchy: screen tile side in pixels dealt out to units")
      ->check(CLI::Range(1, 4096));
  command->add_option("--inclusion", options->hierarchy.inclusion, "Hierarchy: inclusive or non-inclusive")
      ->check(CLI::IsMember({"inclusive", "non-inclusive"}));
  command->add_flag("--decoded-l1", options->hierarchy.decoded_l1,
                    "Hierarchy: the L1 holds decoded texels and the levels below compressed blocks (textures the "
                    "trace or the L1's format= stores block-compressed)");
  command->add_option("--frames", options->frames,
                      "Draw frames 0..N-1 along the scene's camera_path (its static camera without one); caches keep "
                      "their contents between frames, the table sums all frames, --trace holds every frame, --level "
                      "adds a table per frame; the image is the last frame")
      ->check(CLI::Range(1u, 10000u));
  command->add_option("--miss-map", options->miss_map,
                      "Draw per pixel the misses of the texture cache (--tcache) its fragments caused (0, 1, 2, 3+; "
                      "legend and totals in FILE.txt), as replay --miss-map does from a trace");
  command->add_option("--format", options->format, "md, csv, latex or json")->capture_default_str();
  command->add_flag("--json", options->json, "Same as --format json");
  command->footer(
      "Examples:\n"
      "  rastrace render builtin:bunny -o bunny.png\n"
      "  rastrace render builtin:grid -o grid.png --raster tiled8 --tcache size=8KiB,line=32B,assoc=2,policy=fifo,"
      "layout=morton --json\n"
      "  rastrace render builtin:bunny -o bunny.png --order tipsy --vcache entries=16,policy=fifo --trace "
      "bunny.rtrace\n"
      "  rastrace render builtin:bunny -o bunny-lod.png --vipm sliding --lod 30000 --trace bunny-lod.rtrace\n"
      "  rastrace render builtin:bunny -o bunny.png --order tipsy --depth-test late --hiz --zcache "
      "model=attila,size=32KiB --ccache size=8KiB,line=64B,assoc=2,policy=fifo,layout=morton,pixel=4B --json\n"
      "  rastrace render builtin:bunny -o bunny.png --tcache size=32KiB,line=128B,assoc=2,policy=lru,layout=block4 "
      "--miss-map bunny-misses.png\n"
      "  rastrace render docs/orbit_scene.json -o orbit.png --frames 30 --trace orbit.rtrace "
      "--level size=16KiB,line=64B,assoc=4,layout=block4 --level size=1MiB,line=64B,assoc=16");
  command->callback([options] { run_render(*options); });
}

}  // namespace rastrace
