#include "traces/replay_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string_view>

#include "core/error.h"
#include "core/input_guard.h"
#include "core/progress.h"
#include "traces/text_formats.h"

namespace rastrace {

TraceFileFormat detect_trace_format(const std::string& path) {
  if (!std::filesystem::exists(path)) throw_in_file(path, "no such trace file");
  require_regular_file(path);  // a FIFO or device would block or never end
  if (TraceReader::is_trace_file(path)) return TraceFileFormat::Container;
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".csv") return TraceFileFormat::Csv;
  if (extension == ".din") return TraceFileFormat::Din;
  if (extension == ".rtrace") TraceReader reader(path);  // throws the precise container error
  throw_in_file(path, "unknown trace format: expected a rastrace trace (.rtrace), a .csv export or a Dinero .din file");
}

TraceSummary summarize_trace(const std::string& path) {
  TraceSummary s;
  s.format = detect_trace_format(path);
  if (s.format == TraceFileFormat::Container) {
    TraceReader reader(path);
    s.metadata = reader.metadata();
    s.has_counts = true;
    s.vertices = reader.records(RecordKind::Vertex);
    s.texels = reader.records(RecordKind::Texel);
    s.addresses = reader.records(RecordKind::Address);
    s.framebuffer = reader.records(RecordKind::Framebuffer);
  } else if (s.format == TraceFileFormat::Csv) {
    s.metadata = read_csv_metadata(path);
  }
  return s;
}

namespace {
// Drops the kinds the caller did not ask for (text formats carry every kind).
class FilterSink final : public EventSink {
 public:
  FilterSink(EventSink& inner, ReplayKinds kinds, Progress* progress)
      : inner_(inner), kinds_(kinds), progress_(progress) {}
  void begin_frame(std::uint32_t frame) override { inner_.begin_frame(frame); }
  void begin_draw(const DrawInfo& d) override {
    if (kinds_.vertices) inner_.begin_draw(d);
  }
  void end_draw() override {
    if (kinds_.vertices) inner_.end_draw();
  }
  void vertex_fetches(std::span<const VertexFetch> f) override {
    if (kinds_.vertices) inner_.vertex_fetches(f);
    advance(f.size());
  }
  void texel_accesses(std::span<const TexelAccess> t) override {
    if (kinds_.texels) inner_.texel_accesses(t);
    advance(t.size());
  }
  void address_accesses(std::span<const AddressAccess> a) override {
    if (kinds_.addresses) inner_.address_accesses(a);
    advance(a.size());
  }
  void framebuffer_accesses(std::span<const FramebufferAccess> a) override {
    if (kinds_.framebuffer) inner_.framebuffer_accesses(a);
    advance(a.size());
  }
  bool wants_framebuffer_events() const override { return kinds_.framebuffer && inner_.wants_framebuffer_events(); }
  void finish() override { inner_.finish(); }

 private:
  void advance(std::size_t n) {
    if (progress_) progress_->advance(n);
  }
  EventSink& inner_;
  ReplayKinds kinds_;
  Progress* progress_;
};
}  // namespace

namespace {
void replay_any_format(const std::string& path, EventSink& sink, ReplayKinds kinds, Progress* progress) {
  switch (detect_trace_format(path)) {
    case TraceFileFormat::Container: {
      TraceReader reader(path);
      replay_trace(reader, sink, kinds, progress);
      break;
    }
    case TraceFileFormat::Csv: {
      FilterSink filter(sink, kinds, progress);
      import_csv(path, filter);
      break;
    }
    case TraceFileFormat::Din: {
      FilterSink filter(sink, kinds, progress);
      import_din(path, filter);
      break;
    }
  }
}
}  // namespace

void replay_file(const std::string& path, EventSink& sink, ReplayKinds kinds, Progress* progress) {
  try {
    replay_any_format(path, sink, kinds, progress);
  } catch (const InputError& e) {
    // A sink refusing a record (a texel outside the textures the metadata lists) does not know the
    // file; the readers' own errors already start with it.
    if (std::string_view(e.what()).starts_with(path)) throw;
    throw_in_file(path, e.what());
  }
}

}  // namespace rastrace
