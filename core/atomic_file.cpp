#include "core/atomic_file.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>

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

void remove_stale_temporaries(const std::filesystem::path& path) {
  // ".tmp.<pid>.<name>" beside <path>, left by a writer that was killed: removed when that
  // process is gone (kill(pid, 0) fails with ESRCH), never while it may still be writing.
  const std::string suffix = "." + path.filename().string();
  const std::filesystem::path folder = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  std::error_code error;
  std::filesystem::directory_iterator it(folder, error);
  if (error) return;
  for (const std::filesystem::directory_entry& entry : it) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(".tmp.") || name.size() <= 5 + suffix.size() || !name.ends_with(suffix)) continue;
    const std::string pid_text = name.substr(5, name.size() - 5 - suffix.size());
    if (pid_text.empty() || pid_text.size() > 9 ||
        pid_text.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const pid_t pid = static_cast<pid_t>(std::stol(pid_text));
    if (pid == ::getpid() || pid <= 0) continue;
    if (::kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    std::filesystem::remove(entry.path(), ignored);
  }
}

AtomicFile::AtomicFile(std::filesystem::path path, bool binary)
    : path_(std::move(path)), temporary_(temporary_name(path_)) {
  remove_stale_temporaries(path_);
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
  remove_stale_temporaries(path);
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
