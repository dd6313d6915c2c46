#include "core/atomic_file.h"

#include <unistd.h>

#include <system_error>

#include "core/error.h"

namespace rastrace {

namespace {

std::filesystem::path temporary_name(const std::filesystem::path& path) {
  // Keep the extension last so that writers choosing a format by extension still see it.
  std::filesystem::path tmp = path;
  tmp.replace_filename(".tmp." + std::to_string(::getpid()) + "." + path.filename().string());
  return tmp;
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path path, bool binary)
    : path_(std::move(path)), temporary_(temporary_name(path_)) {
  out_.open(temporary_, binary ? std::ios::binary | std::ios::out : std::ios::out);
  if (!out_) throw_in_file(path_.string(), "cannot open for writing");
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw_in_file(path_.string(), "write failed");
  out_.close();
  std::error_code error;
  std::filesystem::rename(temporary_, path_, error);
  if (error) throw_in_file(path_.string(), "cannot rename temporary file: " + error.message());
  committed_ = true;
}

void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                           bool binary) {
  AtomicFile file(path, binary);
  write(file.stream());
  file.commit();
}

void write_via_temporary(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write) {
  const std::filesystem::path tmp = temporary_name(path);
  try {
    write(tmp);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  std::error_code error;
  std::filesystem::rename(tmp, path, error);
  if (error) {
    std::filesystem::remove(tmp, error);
    throw_in_file(path.string(), "cannot write");
  }
}

}  // namespace rastrace
