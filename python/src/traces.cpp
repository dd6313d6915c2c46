// open_trace: a rastrace trace file read chunk by chunk (traces/trace_reader.h, the reader
// `replay` and `sweep` use), each chunk's records as a numpy structured array:
//   vertex   vertex u4, primitive_start ?       (the chunk names its draw and primitive type)
//   texel    texture u2, level u1, x u2, y u2, pixel_x u2, pixel_y u2, triangle u4
//   address  address u8, label u1
#include <cstring>
#include <memory>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "columns.h"
#include "core/error.h"
#include "traces/chunk_codec.h"
#include "traces/trace_reader.h"

namespace rastrace::python {

namespace {

const char* primitive_name(PrimitiveType type) {
  switch (type) {
    case PrimitiveType::TriangleStrip:
      return "triangle_strip";
    case PrimitiveType::TriangleListAdjacency:
      return "triangle_list_adjacency";
    default:
      return "triangle_list";
  }
}

RecordKind parse_kind(const std::string& text) {
  if (text == "vertex") return RecordKind::Vertex;
  if (text == "texel") return RecordKind::Texel;
  if (text == "address") return RecordKind::Address;
  if (text == "framebuffer") return RecordKind::Framebuffer;
  throw InputError("record kind '" + text + "': expected vertex, texel, address or framebuffer");
}

// FramebufferAccess with its operation as a plain byte (numpy has no enum fields): op 0 depth
// read, 1 depth write, 2 colour write.
struct FramebufferRecord {
  std::uint16_t x, y;
  std::uint8_t op, mask;
  std::uint32_t triangle;
};

py::array framebuffer_array(const std::vector<FramebufferAccess>& records) {
  py::array_t<FramebufferRecord> array(static_cast<py::ssize_t>(records.size()));
  FramebufferRecord* out = array.mutable_data();
  for (const FramebufferAccess& r : records) *out++ = {r.x, r.y, static_cast<std::uint8_t>(r.op), r.mask, r.triangle};
  return array;
}

template <typename Record>
py::array records_array(const std::vector<Record>& records) {
  py::array_t<Record> array(static_cast<py::ssize_t>(records.size()));
  if (!records.empty()) std::memcpy(array.mutable_data(), records.data(), records.size() * sizeof(Record));
  return array;
}

struct Chunk {
  std::string kind;
  std::uint64_t first_record = 0;
  // Vertex chunks: the draw, its primitive type and restart index (-1: none), and whether the
  // chunk starts and ends the draw.
  std::int64_t draw = -1;
  std::string primitive;
  std::int64_t restart_index = -1;
  bool starts_draw = false, ends_draw = false;
  py::array records;
};

class TraceFile {
 public:
  explicit TraceFile(const std::string& path) {
    py::gil_scoped_release release;
    reader_ = std::make_unique<TraceReader>(path);
  }
  const TraceReader& reader() const { return *reader_; }
  std::size_t chunk_count() const { return reader_->chunks().size(); }

  // Chunk i, decoded and checked (InputError naming the file, chunk and offset when corrupt).
  Chunk chunk(std::size_t i) {
    if (i >= reader_->chunks().size())
      throw py::index_error("chunk " + std::to_string(i) + " of " + std::to_string(reader_->chunks().size()));
    const DecodedChunk* decoded = nullptr;
    {
      py::gil_scoped_release release;
      decoded = &reader_->read_chunk(i);
    }
    Chunk chunk;
    chunk.kind = to_string(decoded->kind);
    chunk.first_record = decoded->first_record;
    switch (decoded->kind) {
      case RecordKind::Vertex:
        chunk.draw = decoded->draw.draw;
        chunk.primitive = primitive_name(decoded->draw.type);
        if (decoded->draw.restart_index) chunk.restart_index = *decoded->draw.restart_index;
        chunk.starts_draw = decoded->flags & kChunkStartsDraw;
        chunk.ends_draw = decoded->flags & kChunkEndsDraw;
        chunk.records = records_array(decoded->vertices);
        break;
      case RecordKind::Texel:
        chunk.records = records_array(decoded->texels);
        break;
      case RecordKind::Address:
        chunk.records = records_array(decoded->addresses);
        break;
      case RecordKind::Framebuffer:
        chunk.records = framebuffer_array(decoded->framebuffer);
        break;
    }
    return chunk;
  }

  // Every record of one kind, in file order, as one array.
  py::array read(const std::string& kind_text) {
    const RecordKind kind = parse_kind(kind_text);
    std::vector<VertexFetch> vertices;
    std::vector<TexelAccess> texels;
    std::vector<AddressAccess> addresses;
    std::vector<FramebufferAccess> framebuffer;
    {
      py::gil_scoped_release release;
      ReplayKinds kinds{kind == RecordKind::Vertex, kind == RecordKind::Texel, kind == RecordKind::Address,
                        kind == RecordKind::Framebuffer};
      reader_->set_read_ahead_kinds(kinds);
      for (std::size_t i = 0; i < reader_->chunks().size(); ++i) {
        if (reader_->chunks()[i].kind != kind) continue;
        const DecodedChunk& c = reader_->read_chunk(i);
        vertices.insert(vertices.end(), c.vertices.begin(), c.vertices.end());
        texels.insert(texels.end(), c.texels.begin(), c.texels.end());
        addresses.insert(addresses.end(), c.addresses.begin(), c.addresses.end());
        framebuffer.insert(framebuffer.end(), c.framebuffer.begin(), c.framebuffer.end());
      }
    }
    if (kind == RecordKind::Vertex) return records_array(vertices);
    if (kind == RecordKind::Texel) return records_array(texels);
    if (kind == RecordKind::Framebuffer) return framebuffer_array(framebuffer);
    return records_array(addresses);
  }

 private:
  std::unique_ptr<TraceReader> reader_;
};

class ChunkIterator {
 public:
  ChunkIterator(TraceFile& file, std::optional<RecordKind> kind) : file_(file), kind_(kind) {}
  Chunk next() {
    const auto& chunks = file_.reader().chunks();
    while (next_ < chunks.size() && kind_ && chunks[next_].kind != *kind_) ++next_;
    if (next_ >= chunks.size()) throw py::stop_iteration();
    return file_.chunk(next_++);
  }

 private:
  TraceFile& file_;
  std::optional<RecordKind> kind_;
  std::size_t next_ = 0;
};

}  // namespace

void bind_traces(py::module_& m) {
  PYBIND11_NUMPY_DTYPE(VertexFetch, vertex, primitive_start);
  PYBIND11_NUMPY_DTYPE(TexelAccess, texture, level, x, y, pixel_x, pixel_y, triangle);
  PYBIND11_NUMPY_DTYPE(AddressAccess, address, label);
  PYBIND11_NUMPY_DTYPE(FramebufferRecord, x, y, op, mask, triangle);

  py::class_<Chunk>(m, "TraceChunk", "One chunk of a trace: its kind and its records as a numpy structured array.")
      .def_readonly("kind", &Chunk::kind, "vertex, texel, address or framebuffer")
      .def_readonly("first_record", &Chunk::first_record, "index of its first record among the records of its kind")
      .def_readonly("draw", &Chunk::draw, "vertex chunks: the draw number (-1 otherwise)")
      .def_readonly("primitive", &Chunk::primitive, "vertex chunks: triangle_list, triangle_strip, ...")
      .def_readonly("restart_index", &Chunk::restart_index, "vertex chunks of strips: the restart index, or -1")
      .def_readonly("starts_draw", &Chunk::starts_draw)
      .def_readonly("ends_draw", &Chunk::ends_draw)
      .def_readonly("records", &Chunk::records, "numpy structured array (see open_trace)")
      .def("__len__", [](const Chunk& c) { return c.records.size(); })
      .def("__repr__", [](const Chunk& c) {
        return "<rastrace.TraceChunk " + c.kind + " records " + std::to_string(c.first_record) + ".." +
               std::to_string(c.first_record + static_cast<std::uint64_t>(c.records.size())) + ">";
      });

  py::class_<ChunkIterator>(m, "_ChunkIterator")
      .def("__iter__", [](ChunkIterator& it) -> ChunkIterator& { return it; })
      .def("__next__", &ChunkIterator::next);

  py::class_<TraceFile>(m, "TraceFile", "A rastrace trace file (.rtrace), read chunk by chunk in bounded memory.")
      .def_property_readonly("path", [](const TraceFile& f) { return f.reader().path(); })
      .def_property_readonly(
          "metadata",
          [](const TraceFile& f) {
            return py::module_::import("json").attr("loads")(metadata_to_json(f.reader().metadata()));
          },
          "The trace's metadata (scene, ordering, resolution, filter, texture level sizes, ...) as a dict")
      .def_property_readonly("file_bytes", [](const TraceFile& f) { return f.reader().file_bytes(); })
      .def(
          "records", [](const TraceFile& f, const std::string& kind) { return f.reader().records(parse_kind(kind)); },
          py::arg("kind"), "Number of records of a kind: vertex, texel, address or framebuffer")
      .def("__len__", &TraceFile::chunk_count, "Number of chunks")
      .def("chunk", &TraceFile::chunk, py::arg("index"), "Chunk `index` (any order)")
      .def(
          "chunks",
          [](TraceFile& f, const std::optional<std::string>& kind) {
            return ChunkIterator(f, kind ? std::optional<RecordKind>(parse_kind(*kind)) : std::nullopt);
          },
          py::arg("kind") = py::none(), py::keep_alive<0, 1>(),
          "Iterates the chunks in file order (only those of `kind` when given)")
      .def(
          "__iter__", [](TraceFile& f) { return ChunkIterator(f, std::nullopt); }, py::keep_alive<0, 1>())
      .def("read", &TraceFile::read, py::arg("kind"), "Every record of a kind, in file order, as one array")
      .def("__repr__", [](const TraceFile& f) {
        return "<rastrace.TraceFile " + f.reader().path() + ": " + std::to_string(f.reader().chunks().size()) +
               " chunks>";
      });

  m.def(
      "open_trace", [](const std::string& path) { return TraceFile(path); }, py::arg("path"),
      "Opens a rastrace trace (written by render(trace=...) or `rastrace render --trace`). Iterate it\n"
      "for its chunks (TraceChunk: kind, records as a numpy structured array: vertex (vertex,\n"
      "primitive_start), texel (texture, level, x, y, pixel_x, pixel_y: 16 bits but level 8; triangle),\n"
      "address (address, label), framebuffer (x, y of the quad, op 0 depth read / 1 depth write /\n"
      "2 colour write, mask, triangle)), or read(kind) for all records of a kind. Errors (truncated\n"
      "file, bad checksum) name the file, the chunk and its offset.");
}

}  // namespace rastrace::python
