#include "texcodec/mesa_child.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <GL/gl.h>
#include <GL/osmesa.h>

namespace rastrace::texcodec {

namespace {

bool write_all(int fd, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

std::vector<std::uint8_t> read_all(int fd) {
  std::vector<std::uint8_t> data;
  std::uint8_t chunk[65536];
  for (;;) {
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    data.insert(data.end(), chunk, chunk + n);
  }
  return data;
}

// The child's reply: one status byte (0 ok, 1 error) then the bytes or the message.
[[noreturn]] void child_main(int fd, const std::function<std::vector<std::uint8_t>()>& work) {
  std::uint8_t status = 1;
  std::vector<std::uint8_t> reply;
  try {
    OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
    std::uint8_t pixel[4] = {0, 0, 0, 0};
    if (!context || !OSMesaMakeCurrent(context, pixel, GL_UNSIGNED_BYTE, 1, 1))
      throw std::runtime_error("no OSMesa context");
    reply = work();
    OSMesaDestroyContext(context);
    status = 0;
  } catch (const std::exception& error) {
    reply.assign(error.what(), error.what() + std::strlen(error.what()));
  }
  const bool ok = write_all(fd, &status, 1) && write_all(fd, reply.data(), reply.size());
  ::close(fd);
  ::_exit(ok ? 0 : 1);
}

}  // namespace

std::vector<std::uint8_t> run_in_gl_child(const std::string& what,
                                          const std::function<std::vector<std::uint8_t>()>& work) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(what + ": pipe: " + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(what + ": fork: " + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    child_main(fds[1], work);
  }
  ::close(fds[1]);
  std::vector<std::uint8_t> reply = read_all(fds[0]);
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (reply.empty() || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(what + ": the OSMesa child process failed");
  if (reply[0] != 0) throw std::runtime_error(what + ": " + std::string(reply.begin() + 1, reply.end()));
  reply.erase(reply.begin());
  return reply;
}

}  // namespace rastrace::texcodec
