// `rastrace compare SCENE --driver softpipe|llvmpipe [-o diff.png] [--json]`: draws the scene with
// rastrace and with Mesa's OSMesa (the same matrices, viewport, depth test, culling, light,
// textures uploaded level by level from rastrace's mip chains, filters and wraps) and reports how
// far apart the images are: the fraction of covered pixels differing by more than 1, 2 and 8 (of
// 255) in any channel, PSNR, and coverage differences, split into centres exactly on a triangle
// edge (the drivers' fill rules legitimately differ), centres within 1/256 pixel of one (softpipe
// does not snap vertices to the 1/256 grid as rastrace and llvmpipe do) and the others.
//
// --lod-formula auto (the default) draws rastrace's image with the LOD formula the driver implements:
// softpipe takes the largest derivative component (GL eq. 8.7), llvmpipe the vector lengths
// (eq. 8.6, rastrace's default). Both are conformant; they differ by up to half a mip level.
#include <cmath>
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/render_flags.h"
#include "core/error.h"
#include "core/table.h"
#include "reference/image_compare.h"
#include "reference/osmesa_renderer.h"

namespace rastrace {

namespace {

struct CompareCommand {
  SceneRenderFlags flags;
  std::string driver = "softpipe";
  std::string diff;
  std::string save;
  std::string format = "md";
  bool json = false;
};

void run_compare(CompareCommand command) {
  const TableFormat format = command.json ? TableFormat::Json : parse_table_format(command.format);
  const ReferenceDriver driver = parse_reference_driver(command.driver);
  if (command.flags.lod == "auto")
    command.flags.lod = driver == ReferenceDriver::Softpipe ? "max_component" : "lengths";
  if (command.flags.order != "original")
    throw InputError("compare draws the scene's own triangle order: --order is not supported here");
  RenderOptions options = render_options_from(command.flags);
  const Scene scene = load_render_scene(command.flags);
  const glm::vec4 clear(glm::vec3(scene.background), 0.0f);  // alpha 0 marks uncovered pixels
  options.clear_colour = clear;
  options.debug_planes = true;
  const RenderResult ours = render_scene(scene, options, nullptr);

  ReferenceOptions reference_options;
  reference_options.driver = driver;
  reference_options.sampler = options.pipeline.raster.sampler;
  reference_options.cull = options.pipeline.cull;
  reference_options.lighting = options.pipeline.lighting;
  reference_options.clear_colour = clear;
  const ReferenceImage reference = render_reference(scene, reference_options);

  const Framebuffer& fb = ours.framebuffer;
  const ImageDifference d =
      compare_images(fb.width(), fb.height(), fb.colour(), reference.rgba.data(), fb.centre_on_edge());
  if (!command.diff.empty())
    write_difference_image(command.diff, fb.width(), fb.height(), fb.colour(), reference.rgba.data());
  if (!command.save.empty()) {
    fb.write_colour(command.save + "-rastrace.png");
    write_rgba8_image(command.save + "-" + command.driver + ".png", fb.width(), fb.height(), reference.rgba.data(), 3);
  }

  Table table;
  table.title = "rastrace against OSMesa: " + scene.name;
  table.parameters = {{"scene", command.flags.scene},
                      {"size", std::to_string(scene.width) + "x" + std::to_string(scene.height)},
                      {"filter", command.flags.filter},
                      {"wrap", command.flags.wrap},
                      {"lod", command.flags.lod},
                      {"cull", command.flags.cull},
                      {"lighting", command.flags.lighting ? "on" : "off"},
                      {"renderer", reference.renderer},
                      {"fractions_of", "covered pixels (covered in either image)"},
                      {"psnr_over", "RGB of the covered pixels; psnr_image: the whole image (OpenImageIO)"}};
  table.columns = {{"driver", "driver", 0},
                   {"pixels", "pixels", 0},
                   {"covered", "covered", 0},
                   {"coverage_differs", "coverage differs", 0},
                   {"coverage_differs_near_edge", "... near edges", 0},
                   {"coverage_differs_off_edge", "... off edges", 0},
                   {"diff_gt_1", "> 1/255", 4},
                   {"diff_gt_2", "> 2/255", 4},
                   {"diff_gt_8", "> 8/255", 4},
                   {"max_difference", "max", 0},
                   {"psnr", "PSNR dB", 2},
                   {"psnr_image", "image PSNR dB", 2}};
  auto db = [](double value) { return std::isfinite(value) ? TableCell(value) : TableCell("inf"); };
  table.add_row({command.driver, d.pixels, d.covered, d.coverage_differs, d.coverage_differs_near_edge,
                 d.coverage_differs_off_edge, d.fraction(d.diff_gt_1), d.fraction(d.diff_gt_2), d.fraction(d.diff_gt_8),
                 d.max_difference, db(d.psnr), db(d.psnr_image)});
  std::cout << render_table(table, format);
}

}  // namespace

void add_compare_command(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("compare", "Compare rastrace's image of a scene with OSMesa's (softpipe or llvmpipe)");
  auto options = std::make_shared<CompareCommand>();
  options->flags.lod = "auto";
  add_scene_render_flags(*command, options->flags);
  command->add_option("--driver", options->driver, "OSMesa driver: softpipe or llvmpipe")->capture_default_str();
  command->add_option("-o,--output", options->diff, "Difference image (|a - b| x 16, coverage differences magenta)");
  command->add_option("--save", options->save, "Also write PREFIX-rastrace.png and PREFIX-<driver>.png");
  command->add_option("--lod-formula", options->flags.lod, "auto (the driver's formula), lengths or max_component")
      ->capture_default_str();
  command->add_option("--format", options->format, "md, csv, latex or json")->capture_default_str();
  command->add_flag("--json", options->json, "Same as --format json");
  command->footer(
      "Examples:\n"
      "  rastrace compare builtin:bunny --driver softpipe -o bunny-diff.png\n"
      "  rastrace compare builtin:grid --driver llvmpipe --filter linear_mipmap_nearest --json\n"
      "  rastrace compare builtin:spider --driver softpipe --cull back --lighting --save spider");
  command->callback([options] { run_compare(*options); });
}

}  // namespace rastrace
