// render: one frame as `rastrace render` draws it (experiments/frame_render.h), with the live
// vertex and texture caches, optionally writing the trace and the image; the image also comes
// back as a numpy array.
#include <cstring>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "columns.h"
#include "experiments/frame_render.h"

namespace rastrace::python {

namespace {

py::object render(const std::string& scene, const std::string& output, const std::string& trace,
                  const std::string& vcache, const std::string& tcache, const std::string& order, unsigned order_cache,
                  const std::string& size, const std::string& filter, const std::string& wrap,
                  const std::string& raster, const std::string& cull, bool lighting, const std::string& lod_formula,
                  const std::string& vipm, const std::string& lod) {
  FrameSpec spec;
  spec.flags.scene = scene;
  spec.flags.size = size;
  spec.flags.filter = filter;
  spec.flags.wrap = wrap;
  spec.flags.lod = lod_formula;
  spec.flags.raster = raster;
  spec.flags.cull = cull;
  spec.flags.lighting = lighting;
  spec.flags.order = order;
  spec.flags.order_cache = order_cache;
  spec.vcache = vcache;
  spec.tcache = tcache;
  spec.trace = trace;
  spec.vipm = vipm;
  spec.lod = lod;
  spec.image = output;
  std::vector<std::uint8_t> pixels;
  Table table;
  py::ssize_t width = 0, height = 0;
  {
    py::gil_scoped_release release;
    Frame frame = render_frame(spec);
    const Framebuffer& fb = frame.result.framebuffer;
    if (!output.empty()) fb.write_colour(output);
    width = fb.width();
    height = fb.height();
    pixels.resize(static_cast<std::size_t>(width * height * 4));
    std::memcpy(pixels.data(), fb.colour(), pixels.size());
    table = std::move(frame.table);
  }
  py::object columns = table_columns(table);
  columns.attr("image") = to_array(std::move(pixels), {height, width, 4});
  return columns;
}

}  // namespace

void bind_render(py::module_& m) {
  m.def("render", &render, py::arg("scene"), py::arg("output") = "", py::arg("trace") = "",
        py::arg("vcache") = "entries=16,policy=fifo",
        py::arg("tcache") = "size=16KiB,line=64B,assoc=4,policy=lru,layout=block4", py::arg("order") = "original",
        py::arg("order_cache") = 16, py::arg("size") = "", py::arg("filter") = "trilinear", py::arg("wrap") = "repeat",
        py::arg("raster") = "scanline", py::arg("cull") = "none", py::arg("lighting") = false,
        py::arg("lod_formula") = "lengths", py::arg("vipm") = "", py::arg("lod") = "",
        "Draws a scene (builtin:NAME, a JSON scene or a mesh file) as `rastrace render` does, simulating\n"
        "one post-transform vertex cache and one texture cache live (cache specs). trace: also write\n"
        "every vertex fetch and texel access to this .rtrace file; output: also write the image.\n"
        "Returns rastrace.Columns with one row (triangles, vertices_shaded, acmr, fragments,\n"
        "texel_accesses, texture_misses, bytes_per_fragment, ...) and the image (height, width, 4\n"
        "uint8 RGBA) as its `image` attribute.");
}

}  // namespace rastrace::python
