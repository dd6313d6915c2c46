#include "traces/text_formats.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/input_guard.h"

namespace rastrace {

namespace {

constexpr const char* kCsvHeader =
    "event,draw,type,restart,vertex,primitive_start,texture,level,x,y,pixel_x,pixel_y,triangle,address,label,mask";
// Files exported before framebuffer events existed: no mask column.
constexpr const char* kCsvHeaderVersion1 =
    "event,draw,type,restart,vertex,primitive_start,texture,level,x,y,pixel_x,pixel_y,triangle,address,label";
constexpr const char* kFramebufferEvents[kFramebufferOps] = {"depth_read", "depth_write", "colour_write"};
constexpr const char* kMetadataPrefix = "# rastrace metadata: ";
constexpr std::size_t kBatch = 1 << 14;

class CsvExportSink final : public EventSink {
 public:
  explicit CsvExportSink(std::ostream& out) : out_(out) {}
  void begin_draw(const DrawInfo& d) override {
    out_ << "begin_draw," << d.draw << ',' << static_cast<int>(d.type) << ',';
    if (d.type == PrimitiveType::TriangleStrip && d.restart_index) out_ << *d.restart_index;
    out_ << ",,,,,,,,,,,,\n";
  }
  void end_draw() override { out_ << "end_draw,,,,,,,,,,,,,,,\n"; }
  void vertex_fetches(std::span<const VertexFetch> fetches) override {
    for (const VertexFetch& f : fetches)
      out_ << "vertex,,,," << f.vertex << ',' << (f.primitive_start ? 1 : 0) << ",,,,,,,,,,\n";
  }
  void texel_accesses(std::span<const TexelAccess> texels) override {
    for (const TexelAccess& t : texels)
      out_ << "texel,,,,,," << t.texture << ',' << static_cast<int>(t.level) << ',' << t.x << ',' << t.y << ','
           << t.pixel_x << ',' << t.pixel_y << ',' << t.triangle << ",,,\n";
  }
  void framebuffer_accesses(std::span<const FramebufferAccess> accesses) override {
    for (const FramebufferAccess& a : accesses)
      out_ << kFramebufferEvents[static_cast<std::uint8_t>(a.op)] << ",,,,,,,,,," << a.x << ',' << a.y << ','
           << a.triangle << ",,," << static_cast<int>(a.mask) << '\n';
  }
  void address_accesses(std::span<const AddressAccess> addresses) override {
    char hex[32];
    for (const AddressAccess& a : addresses) {
      const auto end = std::to_chars(hex, hex + sizeof(hex), a.address, 16).ptr;
      out_ << "address,,,,,,,,,,,,,0x" << std::string_view(hex, static_cast<std::size_t>(end - hex)) << ','
           << static_cast<int>(a.label) << ",\n";
    }
  }

 private:
  std::ostream& out_;
};

// Splits a CSV line (no quoting: every field is a number or a word).
std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

template <typename T>
T number(std::string_view text, const std::string& file, std::uint64_t line, const char* column, int base = 10) {
  if (base == 16 && text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) text.remove_prefix(2);
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size())
    throw_at_line(file, line,
                  std::string("column ") + column + ": '" + std::string(text) + "' is not " +
                      (base == 16 ? "a hexadecimal" : "an unsigned") + " number in range (0 to " +
                      std::to_string(std::uint64_t{std::numeric_limits<T>::max()}) + ")");
  return value;
}

}  // namespace

void export_csv(TraceReader& reader, std::ostream& out) {
  // The CSV has no frame boundaries: read back, it would be one long frame.
  if (reader.frames() > 1)
    throw_in_file(reader.path(), "a trace of " + std::to_string(reader.frames()) +
                                     " frames: CSV has no frame boundaries (replay and sweep read the trace itself)");
  out << kMetadataPrefix << metadata_to_json(reader.metadata()) << '\n' << kCsvHeader << '\n';
  CsvExportSink sink(out);
  replay_trace(reader, sink);
}

TraceMetadata read_csv_metadata(const std::string& path) {
  require_regular_file(path);
  std::ifstream in(path);
  if (!in) throw_in_file(path, "cannot open for reading");
  std::string line;
  std::getline(in, line);
  if (line.rfind(kMetadataPrefix, 0) == 0)
    return metadata_from_json(line.substr(std::string(kMetadataPrefix).size()), path);
  return {};
}

void import_csv(const std::string& path, EventSink& sink) {
  require_regular_file(path);
  std::ifstream in(path);
  if (!in) throw_in_file(path, "cannot open for reading");
  std::vector<VertexFetch> vertices;
  std::vector<TexelAccess> texels;
  std::vector<AddressAccess> addresses;
  std::vector<FramebufferAccess> framebuffer;
  const auto flush = [&] {
    if (!vertices.empty()) sink.vertex_fetches(vertices);
    if (!texels.empty()) sink.texel_accesses(texels);
    if (!addresses.empty()) sink.address_accesses(addresses);
    if (!framebuffer.empty()) sink.framebuffer_accesses(framebuffer);
    vertices.clear();
    texels.clear();
    addresses.clear();
    framebuffer.clear();
  };
  std::size_t columns = 16;
  std::string text;
  std::uint64_t line = 0;
  bool header_seen = false;
  while (std::getline(in, text)) {
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (text.empty() || text[0] == '#') continue;
    if (!header_seen) {
      if (text == kCsvHeaderVersion1)
        columns = 15;
      else if (text != kCsvHeader)
        throw_at_line(path, line, std::string("expected the header line '") + kCsvHeader + "'");
      header_seen = true;
      continue;
    }
    const auto f = fields(text);
    if (f.size() != columns)
      throw_at_line(
          path, line,
          "expected " + std::to_string(columns) + " comma-separated fields, found " + std::to_string(f.size()));
    const auto* op = std::find(std::begin(kFramebufferEvents), std::end(kFramebufferEvents), f[0]);
    if (f[0] == "begin_draw") {
      flush();
      DrawInfo d;
      d.draw = number<std::uint32_t>(f[1], path, line, "draw");
      const unsigned type = number<unsigned>(f[2], path, line, "type");
      if (type > 2) throw_at_line(path, line, "column type: expected 0 (list), 1 (strip) or 2 (list with adjacency)");
      d.type = static_cast<PrimitiveType>(type);
      // Empty: no restart. Files written before that spelling store 4294967295 for every draw; a
      // list has no restart, a strip restarts at the stored index.
      if (d.type == PrimitiveType::TriangleStrip && !f[3].empty())
        d.restart_index = number<std::uint32_t>(f[3], path, line, "restart");
      else if (!f[3].empty())
        number<std::uint32_t>(f[3], path, line, "restart");
      sink.begin_draw(d);
    } else if (f[0] == "end_draw") {
      flush();
      sink.end_draw();
    } else if (op != std::end(kFramebufferEvents) && columns == 16) {
      if (!vertices.empty() || !texels.empty() || !addresses.empty()) flush();
      FramebufferAccess a;
      a.op = static_cast<FramebufferOp>(op - std::begin(kFramebufferEvents));
      a.x = number<std::uint16_t>(f[10], path, line, "pixel_x");
      a.y = number<std::uint16_t>(f[11], path, line, "pixel_y");
      a.triangle = number<std::uint32_t>(f[12], path, line, "triangle");
      const unsigned mask = number<unsigned>(f[15], path, line, "mask");
      if (mask > 15) throw_at_line(path, line, "column mask: expected 0..15 (the pixels of a 2x2 quad)");
      a.mask = static_cast<std::uint8_t>(mask);
      framebuffer.push_back(a);
    } else if (f[0] == "vertex") {
      if (!texels.empty() || !addresses.empty() || !framebuffer.empty()) flush();
      const unsigned start = number<unsigned>(f[5], path, line, "primitive_start");
      if (start > 1) throw_at_line(path, line, "column primitive_start: expected 0 or 1");
      vertices.push_back({number<std::uint32_t>(f[4], path, line, "vertex"), start == 1});
    } else if (f[0] == "texel") {
      if (!vertices.empty() || !addresses.empty() || !framebuffer.empty()) flush();
      TexelAccess t;
      t.texture = number<std::uint16_t>(f[6], path, line, "texture");
      t.level = number<std::uint8_t>(f[7], path, line, "level");
      t.x = number<std::uint16_t>(f[8], path, line, "x");
      t.y = number<std::uint16_t>(f[9], path, line, "y");
      t.pixel_x = number<std::uint16_t>(f[10], path, line, "pixel_x");
      t.pixel_y = number<std::uint16_t>(f[11], path, line, "pixel_y");
      t.triangle = number<std::uint32_t>(f[12], path, line, "triangle");
      texels.push_back(t);
    } else if (f[0] == "address") {
      if (!vertices.empty() || !texels.empty() || !framebuffer.empty()) flush();
      addresses.push_back(
          {number<std::uint64_t>(f[13], path, line, "address", 16), number<std::uint8_t>(f[14], path, line, "label")});
    } else {
      throw_at_line(
          path, line,
          "unknown event '" + std::string(f[0]) +
              "': expected begin_draw, end_draw, vertex, texel, address, depth_read, depth_write or colour_write");
    }
    if (vertices.size() + texels.size() + addresses.size() + framebuffer.size() >= kBatch) flush();
  }
  if (!header_seen) throw_in_file(path, std::string("no CSV header line: expected '") + kCsvHeader + "'");
  flush();
  sink.finish();
}

std::uint64_t import_din(const std::string& path, EventSink& sink) {
  require_regular_file(path);
  std::ifstream in(path);
  if (!in) throw_in_file(path, "cannot open for reading");
  std::vector<AddressAccess> batch;
  batch.reserve(kBatch);
  std::uint64_t total = 0;
  std::string text;
  std::uint64_t line = 0;
  while (std::getline(in, text)) {
    ++line;
    std::string_view rest(text);
    const auto skip_space = [&] {
      while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t' || rest.front() == '\r'))
        rest.remove_prefix(1);
    };
    const auto word = [&] {
      skip_space();
      std::size_t n = 0;
      while (n < rest.size() && rest[n] != ' ' && rest[n] != '\t' && rest[n] != '\r') ++n;
      const std::string_view w = rest.substr(0, n);
      rest.remove_prefix(n);
      return w;
    };
    const std::string_view label_text = word();
    if (label_text.empty()) continue;  // blank line
    const std::string_view address_text = word();
    if (address_text.empty()) throw_at_line(path, line, "expected 'label hexaddress' (din format)");
    const unsigned label = number<unsigned>(label_text, path, line, "label");
    if (label == 3) continue;
    if (label == 4) throw_at_line(path, line, "label 4 (cache flush) is not supported: expected labels 0, 1, 2 or 3");
    if (label > 4)
      throw_at_line(path, line,
                    "label " + std::to_string(label) + ": expected 0 (read), 1 (write), 2 (fetch) or 3 (escape)");
    const std::uint64_t address = number<std::uint64_t>(address_text, path, line, "address", 16);
    // Extended din (Dinero IV's default): a third field, the access size in hexadecimal. The
    // access is one reference at its first byte, as our export writes them (never across a line).
    if (const std::string_view size_text = word(); !size_text.empty()) {
      if (number<std::uint64_t>(size_text, path, line, "size", 16) == 0)
        throw_at_line(path, line, "size 0: expected the access size in bytes (hexadecimal, at least 1)");
      if (!word().empty()) throw_at_line(path, line, "expected 'label hexaddress [hexsize]' (extended din)");
    }
    batch.push_back({address, static_cast<std::uint8_t>(label)});
    if (batch.size() == kBatch) {
      sink.address_accesses(batch);
      total += batch.size();
      batch.clear();
    }
  }
  if (!batch.empty()) sink.address_accesses(batch);
  total += batch.size();
  sink.finish();
  return total;
}

}  // namespace rastrace
