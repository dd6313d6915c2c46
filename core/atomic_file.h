// Output files appear whole or not at all: data goes to ".tmp.<pid>.<name>" beside <path> and is renamed
// over <path> only by commit(). An AtomicFile destroyed without commit() removes its temporary;
// one left by a killed process is removed by the next writer to the same path.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace rastrace {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path, bool binary = true);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  // The temporary file's name, for libraries that write by file name (OpenImageIO, gnuplot).
  const std::filesystem::path& temporary_path() const { return temporary_; }
  // Flushes, checks for write errors, and renames the temporary over the final path.
  void commit();

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

// Writes a whole file through an AtomicFile.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                           bool binary = true);

// Removes ".tmp.<pid>.<name>" files beside `path` whose process is no longer running (left by a
// killed writer). Every AtomicFile and write_via_temporary() does this for its own path.
void remove_stale_temporaries(const std::filesystem::path& path);

// For writers that take a file name: calls write(temporary name), then renames it over path.
void write_via_temporary(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write);

}  // namespace rastrace
