// Running OSMesa work in a forked child process. OSMesa binds its Gallium driver (softpipe or
// llvmpipe) once per process, at the first context creation, and the reference renderer asks for
// either driver in children of its own (reference/osmesa_renderer.h): a context made in the
// calling process would pin the driver for every later child. So GL work runs in a child that
// returns bytes through a pipe.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rastrace::texcodec {

// Forks; the child makes a 1x1 OSMesa context current (default driver), runs `work` and sends its
// bytes back. `work` may throw: its message comes back as std::runtime_error naming `what`.
std::vector<std::uint8_t> run_in_gl_child(const std::string& what,
                                          const std::function<std::vector<std::uint8_t>()>& work);

}  // namespace rastrace::texcodec
