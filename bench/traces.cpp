// Trace file throughput and size (docs/PERFORMANCE.md, cache simulator section):
//   - read + decode (CRC check, zstd, column decoding) of vertex and texel chunks (goal: 200 M
//     records/s)
//   - texel trace size on disk in bytes per access (goal: at most 2 on a rendered frame); here on
//     the synthetic frame-like trace of tests/support/synthetic_frame.h, labelled as such
//   - the two halves of reading a given trace, zstd and column decoding, each alone
//   - writer throughput
//   - zstd decompression alone of RASTRACE_BENCH_TRACE's payloads recompressed at other levels
//     (the writer's level is an option, not part of the format): does any level decode faster?
//   - zstd decompression alone of a group of texel columns compressed apart (an experiment for a
//     format whose consumers skip the columns they do not need): how fast would it be?
// Read benchmarks run with read-ahead off (/ahead:0, one thread) and on (/ahead:1, a second
// thread): wall-clock time, since the work is on two threads.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <meshoptimizer.h>
#include <zstd.h>

#include <benchmark/benchmark.h>

#include "scenes/mesh_io.h"
#include "tests/support/synthetic_frame.h"
#include "traces/trace_reader.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

std::string temp(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("rastrace_bench_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

const testing::SyntheticFrame& frame() {
  static const testing::SyntheticFrame f = testing::make_synthetic_frame(1024, 1024, 1024);
  return f;
}

// The texel trace of the synthetic frame, written once.
const std::string& texel_trace() {
  static const std::string path = [] {
    const std::string p = temp("texels.rtrace");
    TraceMetadata m;
    m.scene = "synthetic frame-like quad 1024x1024";
    m.textures = frame().textures;
    TraceWriter writer(p, m);
    writer.texel_accesses(frame().texels);
    writer.finish();
    return p;
  }();
  return path;
}

// The vertex trace of bunny00.off in meshoptimizer's order, repeated 20 times (20 draws).
const std::string& vertex_trace() {
  static const std::string path = [] {
    const Mesh mesh = load_mesh(RASTRACE_DATA_DIR "/meshes/bunny00.off");
    std::vector<std::uint32_t> order(mesh.indices.size());
    meshopt_optimizeVertexCache(order.data(), mesh.indices.data(), order.size(), mesh.positions.size());
    std::vector<VertexFetch> fetches;
    for (std::size_t i = 0; i < order.size(); ++i) fetches.push_back({order[i], i % 3 == 0});
    const std::string p = temp("vertices.rtrace");
    TraceWriter writer(p, {});
    for (std::uint32_t d = 0; d < 20; ++d) {
      writer.begin_draw({d, PrimitiveType::TriangleList, kNoRestart});
      writer.vertex_fetches(fetches);
      writer.end_draw();
    }
    writer.finish();
    return p;
  }();
  return path;
}

void BM_TraceReadDecode_Texels(benchmark::State& state) {
  const std::string& path = texel_trace();
  std::uint64_t records = 0;
  for (auto _ : state) {
    TexelTraceReader reader(path);
    reader.set_read_ahead(state.range(0) != 0);
    std::span<const TexelAccess> batch;
    while (reader.next(batch)) {
      records += batch.size();
      benchmark::DoNotOptimize(batch.data());
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(records));
  const TraceReader reader(path);
  state.counters["bytes_per_access"] = double(reader.file_bytes()) / double(reader.records(RecordKind::Texel));
  state.counters["accesses"] = double(reader.records(RecordKind::Texel));
}
BENCHMARK(BM_TraceReadDecode_Texels)->ArgName("ahead")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_TraceReadDecode_Vertices(benchmark::State& state) {
  const std::string& path = vertex_trace();
  std::uint64_t records = 0;
  for (auto _ : state) {
    VertexTraceReader reader(path);
    reader.set_read_ahead(state.range(0) != 0);
    VertexBatch batch;
    while (reader.next(batch)) {
      records += batch.fetches.size();
      benchmark::DoNotOptimize(batch.fetches.data());
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(records));
  const TraceReader reader(path);
  state.counters["bytes_per_fetch"] = double(reader.file_bytes()) / double(reader.records(RecordKind::Vertex));
}
BENCHMARK(BM_TraceReadDecode_Vertices)->ArgName("ahead")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// A trace file given in RASTRACE_BENCH_TRACE (e.g. one written by `rastrace render --trace`):
// every chunk read, checked and decoded.
void BM_TraceReadDecode_File(benchmark::State& state) {
  const char* path = std::getenv("RASTRACE_BENCH_TRACE");
  if (!path) {
    state.SkipWithError("set RASTRACE_BENCH_TRACE to a trace file");
    return;
  }
  std::uint64_t records = 0;
  for (auto _ : state) {
    TraceReader reader(path);
    reader.set_read_ahead(state.range(0) != 0);
    for (std::size_t i = 0; i < reader.chunks().size(); ++i) {
      const DecodedChunk& chunk = reader.read_chunk(i);
      records += chunk.vertices.size() * (chunk.kind == RecordKind::Vertex) +
                 chunk.texels.size() * (chunk.kind == RecordKind::Texel) +
                 chunk.addresses.size() * (chunk.kind == RecordKind::Address) +
                 chunk.framebuffer.size() * (chunk.kind == RecordKind::Framebuffer);
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(records));
}
BENCHMARK(BM_TraceReadDecode_File)->ArgName("ahead")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The two halves of reading RASTRACE_BENCH_TRACE, one thread, CPU time: zstd alone (arg 0) and
// column decoding alone (arg 1), on the chunk payloads held in memory. zstd alone bounds what
// one thread can reach whatever the column decoder does.
// One chunk of a trace file as stored: its index entry, its zstd payload and that payload
// decompressed (the format's raw record columns).
struct StoredChunk {
  ChunkInfo info;
  std::vector<char> stored;
  std::vector<std::uint8_t> raw;
};

// Every chunk of the trace at `path`, read and decompressed once, before any timing.
std::vector<StoredChunk> read_stored_chunks(const char* path) {
  std::vector<StoredChunk> chunks;
  const TraceReader reader(path);
  std::ifstream in(path, std::ios::binary);
  for (const ChunkInfo& c : reader.chunks()) {
    char header[kChunkHeaderBytes];  // trace_format.h: payload bytes at 12, raw bytes at 16
    in.seekg(static_cast<std::streamoff>(c.offset));
    in.read(header, kChunkHeaderBytes);
    std::uint32_t stored = 0, raw = 0;
    std::memcpy(&stored, header + 12, 4);
    std::memcpy(&raw, header + 16, 4);
    StoredChunk chunk{c, std::vector<char>(stored), std::vector<std::uint8_t>(raw)};
    in.read(chunk.stored.data(), stored);
    ZSTD_decompress(chunk.raw.data(), raw, chunk.stored.data(), stored);
    chunks.push_back(std::move(chunk));
  }
  return chunks;
}

// Decodes a stored chunk's raw payload into `out`: what the reader's column stage does.
std::string decode_payload(const StoredChunk& p, DecodedChunk& out) {
  switch (p.info.kind) {
    case RecordKind::Vertex:
      return decode_vertex_records(p.raw, p.info.records, out.draw, out.vertices);
    case RecordKind::Texel:
      return decode_texel_records(p.raw, p.info.records, out.texels);
    case RecordKind::Framebuffer:
      return decode_framebuffer_records(p.raw, p.info.records, out.framebuffer);
    default:
      return decode_address_records(p.raw, p.info.records, out.addresses);
  }
}

void BM_TraceChunkStages_File(benchmark::State& state) {
  const char* path = std::getenv("RASTRACE_BENCH_TRACE");
  if (!path) {
    state.SkipWithError("set RASTRACE_BENCH_TRACE to a trace file");
    return;
  }
  const std::vector<StoredChunk> payloads = read_stored_chunks(path);
  ZSTD_DCtx* dctx = ZSTD_createDCtx();
  std::vector<std::uint8_t> raw;
  DecodedChunk out;
  std::uint64_t records = 0;
  for (auto _ : state) {
    for (const StoredChunk& p : payloads) {
      if (state.range(0) == 0) {
        raw.resize(p.raw.size());
        benchmark::DoNotOptimize(ZSTD_decompressDCtx(dctx, raw.data(), raw.size(), p.stored.data(), p.stored.size()));
      } else {
        benchmark::DoNotOptimize(decode_payload(p, out));
      }
      records += p.info.records;
    }
  }
  ZSTD_freeDCtx(dctx);
  state.SetItemsProcessed(static_cast<std::int64_t>(records));
  state.SetLabel(state.range(0) == 0 ? "zstd only" : "column decoding only");
}
BENCHMARK(BM_TraceChunkStages_File)->ArgName("stage")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The two halves of writing RASTRACE_BENCH_TRACE's records, one thread, CPU time: column encoding
// alone (/stage:0) and zstd alone with one kept context (/stage:1 at level 1, /stage:3 at level
// 3), as a compression thread of the writer does them chunk after chunk.
void BM_TraceWriteStages_File(benchmark::State& state) {
  const char* path = std::getenv("RASTRACE_BENCH_TRACE");
  if (!path) {
    state.SkipWithError("set RASTRACE_BENCH_TRACE to a trace file");
    return;
  }
  const std::vector<StoredChunk> payloads = read_stored_chunks(path);
  std::vector<DecodedChunk> decoded(payloads.size());
  for (std::size_t i = 0; i < payloads.size(); ++i) decode_payload(payloads[i], decoded[i]);
  const int stage = static_cast<int>(state.range(0));
  ZSTD_CCtx* cctx = ZSTD_createCCtx();
  std::string raw;
  std::vector<char> compressed;
  std::uint64_t records = 0, stored = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < payloads.size(); ++i) {
      const StoredChunk& p = payloads[i];
      const DecodedChunk& d = decoded[i];
      if (stage == 0) {
        if (p.info.kind == RecordKind::Vertex) encode_vertex_records(d.draw, d.vertices, raw);
        if (p.info.kind == RecordKind::Texel) encode_texel_records(d.texels, raw);
        if (p.info.kind == RecordKind::Framebuffer) encode_framebuffer_records(d.framebuffer, raw);
        if (p.info.kind == RecordKind::Address) encode_address_records(d.addresses, raw);
        benchmark::DoNotOptimize(raw.data());
      } else {
        compressed.resize(ZSTD_compressBound(p.raw.size()));
        const std::size_t bytes =
            ZSTD_compressCCtx(cctx, compressed.data(), compressed.size(), p.raw.data(), p.raw.size(), stage);
        benchmark::DoNotOptimize(compressed.data());
        stored += bytes;
      }
      records += p.info.records;
    }
  }
  ZSTD_freeCCtx(cctx);
  state.SetItemsProcessed(static_cast<std::int64_t>(records));
  if (stage != 0) state.counters["bytes_per_record"] = double(stored) / double(std::max<std::uint64_t>(1, records));
  state.SetLabel(stage == 0 ? "column encoding only" : "zstd only, level " + std::to_string(stage));
}
BENCHMARK(BM_TraceWriteStages_File)->ArgName("stage")->Arg(0)->Arg(1)->Arg(3)->Unit(benchmark::kMillisecond);

// Bytes of raw records compressed again by an experiment, with the records they hold.
struct Recompressed {
  std::vector<char> compressed;
  std::size_t raw = 0;
  std::uint32_t records = 0;
};

// Compresses bytes [begin, end) of `chunk`'s raw payload at zstd `level`.
Recompressed recompress(const StoredChunk& chunk, std::size_t begin, std::size_t end, int level) {
  Recompressed r;
  r.raw = end - begin;
  r.records = chunk.info.records;
  r.compressed.resize(ZSTD_compressBound(r.raw));
  r.compressed.resize(ZSTD_compress(r.compressed.data(), r.compressed.size(), chunk.raw.data() + begin, r.raw, level));
  return r;
}

// Times zstd alone on `payloads` (one thread, CPU time): records per second and the compressed
// bytes per record.
void time_decompression(benchmark::State& state, const std::vector<Recompressed>& payloads) {
  std::uint64_t file_records = 0, compressed_bytes = 0;
  for (const Recompressed& p : payloads) {
    file_records += p.records;
    compressed_bytes += p.compressed.size();
  }
  ZSTD_DCtx* dctx = ZSTD_createDCtx();
  std::vector<char> raw;
  std::uint64_t records = 0;
  for (auto _ : state)
    for (const Recompressed& p : payloads) {
      raw.resize(p.raw);
      benchmark::DoNotOptimize(
          ZSTD_decompressDCtx(dctx, raw.data(), raw.size(), p.compressed.data(), p.compressed.size()));
      records += p.records;
    }
  ZSTD_freeDCtx(dctx);
  state.SetItemsProcessed(static_cast<std::int64_t>(records));
  state.counters["bytes_per_record"] = double(compressed_bytes) / double(std::max<std::uint64_t>(1, file_records));
}

// zstd alone, one thread, CPU time, on the raw payloads of RASTRACE_BENCH_TRACE compressed at the
// level given (the writer's default is 3).
void BM_TraceZstdLevel_File(benchmark::State& state) {
  const char* path = std::getenv("RASTRACE_BENCH_TRACE");
  if (!path) {
    state.SkipWithError("set RASTRACE_BENCH_TRACE to a trace file");
    return;
  }
  std::vector<Recompressed> payloads;
  std::uint64_t records = 0;
  const auto start = std::chrono::steady_clock::now();
  for (const StoredChunk& chunk : read_stored_chunks(path)) {
    payloads.push_back(recompress(chunk, 0, chunk.raw.size(), static_cast<int>(state.range(0))));
    records += chunk.info.records;
  }
  // What the level costs the writer (read_stored_chunks' own zstd decoding included, a small part).
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  state.counters["compress_M_records_per_s"] = double(records) / seconds / 1e6;
  time_decompression(state, payloads);
}
BENCHMARK(BM_TraceZstdLevel_File)->ArgName("level")->Arg(-5)->Arg(1)->Arg(3)->Arg(9)->Arg(19)->Unit(benchmark::kMillisecond);

// The byte ranges of the 7 columns of a decoded texel payload (chunk_codec.h: mode, first value,
// then the deltas; mode 0x81 adds an escape count and the escaped deltas; mode 0x82 holds run and
// escape counts, a length per run, a delta per run after the first and the escaped deltas).
std::vector<std::pair<std::size_t, std::size_t>> texel_columns(const std::vector<std::uint8_t>& raw, std::uint32_t n) {
  std::vector<std::pair<std::size_t, std::size_t>> columns;
  std::size_t at = 0;
  for (int k = 0; k < 7; ++k) {
    const std::size_t begin = at;
    const std::uint8_t mode = raw.at(at);
    at += 9;
    const std::size_t deltas = n ? n - 1 : 0;
    if (mode == 0x81) {
      std::uint32_t large = 0;
      std::memcpy(&large, raw.data() + at, 4);
      at += 4 + deltas + std::size_t{large} * 8;
    } else if (mode == 0x82) {
      std::uint32_t runs = 0, large = 0;
      std::memcpy(&runs, raw.data() + at, 4);
      std::memcpy(&large, raw.data() + at + 4, 4);
      at += 8 + std::size_t{runs} * 2 - 1 + std::size_t{large} * 8;
    } else {
      at += deltas * mode;
    }
    columns.emplace_back(begin, at);
  }
  return columns;
}

// zstd alone, one thread, CPU time, level 3, on the texel chunks of RASTRACE_BENCH_TRACE with a
// group of columns compressed on its own: /group:0 the four a cache simulation needs (texture,
// level, x, y), /group:1 the other three (pixel x, pixel y, triangle), /group:2 all seven as the
// writer compresses them. Rates are per texel record.
void BM_TraceColumnGroupZstd_File(benchmark::State& state) {
  const char* path = std::getenv("RASTRACE_BENCH_TRACE");
  if (!path) {
    state.SkipWithError("set RASTRACE_BENCH_TRACE to a trace file");
    return;
  }
  const int group = static_cast<int>(state.range(0));
  std::vector<Recompressed> payloads;
  for (const StoredChunk& chunk : read_stored_chunks(path)) {
    if (chunk.info.kind != RecordKind::Texel) continue;
    const auto columns = texel_columns(chunk.raw, chunk.info.records);
    const std::size_t begin = group == 1 ? columns[4].first : 0;
    const std::size_t end = group == 0 ? columns[3].second : columns[6].second;
    payloads.push_back(recompress(chunk, begin, end, 3));
  }
  time_decompression(state, payloads);
  state.SetLabel(group == 0 ? "texture, level, x, y" : group == 1 ? "pixel x, pixel y, triangle" : "all 7 columns");
}
BENCHMARK(BM_TraceColumnGroupZstd_File)->ArgName("group")->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_TraceWrite_Texels(benchmark::State& state) {
  const std::string path = temp("write.rtrace");
  TraceMetadata m;
  m.textures = frame().textures;
  for (auto _ : state) {
    TraceWriter writer(path, m);
    writer.texel_accesses(frame().texels);
    writer.finish();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * frame().texels.size()));
  std::filesystem::remove(path);
}
BENCHMARK(BM_TraceWrite_Texels)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rastrace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  // By name: calling texel_trace() here would write the trace just to delete it.
  std::filesystem::remove(rastrace::temp("texels.rtrace"));
  std::filesystem::remove(rastrace::temp("vertices.rtrace"));
  return 0;
}
