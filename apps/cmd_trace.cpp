// `rastrace trace info|convert`: look inside a trace file, and convert between the rastrace
// container, its CSV export and Dinero din input (din -> container or CSV).
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "cache_sim/trace_export.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/table.h"
#include "core/units.h"
#include "traces/replay_file.h"
#include "traces/text_formats.h"
#include "traces/trace_writer.h"

namespace rastrace {

void add_trace_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("trace", "Inspect and convert trace files (rastrace, CSV, din)");
  command->require_subcommand(1);

  CLI::App* info = command->add_subcommand("info", "Print a trace's metadata, record counts and size");
  auto info_path = std::make_shared<std::string>();
  auto info_format = std::make_shared<std::string>("md");
  info->add_option("trace", *info_path, "Trace file (.rtrace)")->required();
  info->add_option("--format", *info_format, "Table format: md, csv, latex or json");
  info->footer("Example:\n  rastrace trace info frame.rtrace");
  info->callback([=] {
    TraceReader reader(*info_path);
    // Every chunk is read and checked: the table below comes from the index alone, and a damaged
    // file must not pass as sound.
    verify_trace(reader);
    const TraceMetadata& m = reader.metadata();
    Table t;
    t.title = "Trace " + std::filesystem::path(*info_path).filename().string();
    t.parameters = {{"scene", m.scene},
                    {"ordering", m.ordering},
                    {"resolution", std::to_string(m.width) + "x" + std::to_string(m.height)},
                    {"filter", m.filter},
                    {"tool_version", m.tool_version},
                    {"trace_version", static_cast<std::int64_t>(reader.version())},
                    {"frames", static_cast<std::int64_t>(reader.frames())},
                    {"textures", static_cast<std::int64_t>(m.textures.size())}};
    t.columns = {{"kind", "records of kind", 0},
                 {"records", "records", 0},
                 {"chunks", "chunks", 0},
                 {"bytes", "bytes on disk", 0},
                 {"bytes_per_record", "bytes/record", 3}};
    // A chunk's bytes: up to the next chunk, the last one up to the index.
    std::uint64_t index_offset = reader.file_bytes();
    {
      std::ifstream in(*info_path, std::ios::binary);
      in.seekg(static_cast<std::streamoff>(reader.file_bytes() - kFooterBytes));
      in.read(reinterpret_cast<char*>(&index_offset), 8);
    }
    for (const RecordKind kind :
         {RecordKind::Vertex, RecordKind::Texel, RecordKind::Address, RecordKind::Framebuffer}) {
      std::int64_t chunks = 0;
      std::uint64_t bytes = 0;
      for (std::size_t i = 0; i < reader.chunks().size(); ++i) {
        const ChunkInfo& c = reader.chunks()[i];
        if (c.kind != kind) continue;
        ++chunks;
        bytes += (i + 1 < reader.chunks().size() ? reader.chunks()[i + 1].offset : index_offset) - c.offset;
      }
      const std::uint64_t records = reader.records(kind);
      t.add_row({to_string(kind), records, chunks, bytes, records ? double(bytes) / double(records) : 0.0});
    }
    const std::uint64_t records =
        reader.records(RecordKind::Vertex) + reader.records(RecordKind::Texel) + reader.records(RecordKind::Address) +
        reader.records(RecordKind::Framebuffer);
    t.parameters.emplace_back("file_bytes", reader.file_bytes());
    t.parameters.emplace_back("verified", "all " + std::to_string(reader.chunks().size()) + " chunks");
    t.parameters.emplace_back("bytes_per_record", records ? double(reader.file_bytes()) / double(records) : 0.0);
    std::cout << render_table(t, parse_table_format(*info_format));
  });

  CLI::App* verify = command->add_subcommand("verify", "Read and check every chunk of a trace (checksums, records)");
  auto verify_path = std::make_shared<std::string>();
  verify->add_option("trace", *verify_path, "Trace file (.rtrace)")->required();
  verify->footer("Exit 0 when the file is sound, 1 naming the first damaged chunk and its byte offset.\n"
                 "Example:\n  rastrace trace verify frame.rtrace");
  verify->callback([=] {
    TraceReader reader(*verify_path);
    const std::uint64_t records = verify_trace(reader);
    std::cout << *verify_path << ": sound: " << reader.chunks().size() << " chunks, " << records << " records, "
              << reader.file_bytes() << " bytes";
    if (reader.frames() > 1) std::cout << ", " << reader.frames() << " frames";
    std::cout << "\n";
  });

  CLI::App* convert = command->add_subcommand("convert", "Convert a trace: .rtrace <-> .csv, .din -> .rtrace or .csv");
  auto in = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  convert->add_option("input", *in, "Trace file: .rtrace, .csv or .din")->required();
  convert->add_option("output", *out,
                      "Output: .rtrace, .csv, .din (extended din: byte addresses) or .oracleGeneral[.bin] "
                      "(libCacheSim binary), by extension")
      ->required();
  // Byte-address exports (cache_sim/trace_export.h).
  auto layout = std::make_shared<std::string>("linear");
  auto texel = std::make_shared<std::string>("4B");
  auto stride = std::make_shared<std::string>("32B");
  auto block = std::make_shared<std::string>("64B");
  auto vertices = std::make_shared<bool>(false);
  convert->add_option("--layout", *layout, "din/libCacheSim: texture layout (linear, block2..block16, morton)");
  convert->add_option("--texel", *texel, "din/libCacheSim: bytes per texel");
  convert->add_flag("--vertices", *vertices, "din/libCacheSim: export the vertex fetches instead of the texels");
  convert->add_option("--stride", *stride, "din/libCacheSim with --vertices: bytes per vertex");
  convert->add_option("--block", *block, "libCacheSim: bytes per object (the cache block)");
  convert->footer(
      "Examples:\n"
      "  rastrace trace convert frame.rtrace frame.csv\n"
      "  rastrace trace convert frame.csv frame.rtrace\n"
      "  rastrace trace convert gcc.din gcc.rtrace\n"
      "  rastrace trace convert frame.rtrace frame.din --layout block4\n"
      "  rastrace trace convert frame.rtrace frame.oracleGeneral.bin --layout block4 --block 64B");
  convert->callback([=] {
    const std::string extension = std::filesystem::path(*out).extension().string();
    if (std::filesystem::is_directory(*out))
      throw InputError("trace convert: output '" + *out + "' is a directory: expected a .rtrace or .csv file name");
    const std::string name = std::filesystem::path(*out).filename().string();
    const bool libcachesim = name.ends_with(".oracleGeneral") || name.ends_with(".oracleGeneral.bin");
    if (extension == ".din" || libcachesim) {
      AddressExportSpec spec;
      spec.vertices = *vertices;
      spec.layout = parse_layout(*layout);
      spec.layout.texel_bytes = static_cast<std::uint32_t>(parse_byte_size(*texel, "--texel"));
      spec.stride = static_cast<std::uint32_t>(parse_byte_size(*stride, "--stride"));
      const std::vector<std::uint64_t> addresses = trace_addresses(*in, spec);
      if (libcachesim) {
        const std::uint64_t block_bytes = parse_byte_size(*block, "--block");
        write_file_atomically(
            *out, [&](std::ostream& o) { write_libcachesim(addresses, static_cast<std::uint32_t>(block_bytes), o); });
      } else {
        write_file_atomically(*out, [&](std::ostream& o) { write_extended_din(addresses, access_bytes(spec), o); },
                              false);
      }
      std::cout << "wrote " << *out << " (" << addresses.size() << " accesses)\n";
      return;
    }
    const TraceSummary summary = summarize_trace(*in);
    if (extension == ".csv") {
      if (summary.format == TraceFileFormat::Container) {
        TraceReader reader(*in);
        write_file_atomically(
            *out, [&](std::ostream& o) { export_csv(reader, o); }, false);
      } else {
        // Through a temporary container: CSV export reads containers. It goes whatever happens.
        const std::string temporary = *out + ".rtrace.tmp";
        struct RemoveOnExit {
          std::string path;
          ~RemoveOnExit() {
            std::error_code ignored;
            std::filesystem::remove(path, ignored);
          }
        } remove_temporary{temporary};
        {
          TraceWriter writer(temporary, summary.metadata);
          replay_file(*in, writer);
        }
        TraceReader reader(temporary);
        write_file_atomically(
            *out, [&](std::ostream& o) { export_csv(reader, o); }, false);
      }
    } else if (extension == ".rtrace") {
      TraceWriter writer(*out, summary.metadata);
      replay_file(*in, writer);
    } else {
      throw InputError("trace convert: output '" + *out +
                       "': expected a .rtrace, .csv, .din or .oracleGeneral[.bin] file name");
    }
    std::cout << "wrote " << *out << "\n";
  });
}

}  // namespace rastrace
