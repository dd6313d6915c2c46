// The cross-check of the edge stage: the same adjacency primitives drawn by a real geometry shader
// on GL_TRIANGLES_ADJACENCY (OSMesa, llvmpipe, a GL 3.2 core context), which emits the silhouette
// edges as lines, against rastrace's pipeline + EdgeStage. The shader uses the same facing test
// (sign of det[x y w], from the face's lowest vertex id) and reads the vertex ids to decode duplicated indices. Lines
// can differ by a pixel where the two rasterizers round a line's position differently (edge ownership), so the pixels
// are compared exactly and within one pixel.
#include <GL/glcorearb.h>
#include <GL/osmesa.h>

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/type_ptr.hpp>

#include "adjacency_fixture.h"
#include "experiments/adjacency_experiment.h"
#include "reorder/adjacency/order.h"

namespace rastrace {
namespace {

constexpr int kSize = 512;

const char* kVertexShader = R"(#version 150 core
in vec3 position;
uniform mat4 mvp;
flat out int vid;
void main() {
  gl_Position = mvp * vec4(position, 1.0);
  vid = gl_VertexID;
})";

const char* kGeometryShader = R"(#version 150 core
layout(triangles_adjacency) in;
layout(line_strip, max_vertices = 6) out;
flat in int vid[];
float orientation(vec4 a, vec4 b, vec4 c) {
  return a.x * (b.y * c.w - b.w * c.y) - a.y * (b.x * c.w - b.w * c.x) + a.w * (b.x * c.y - b.y * c.x);
}
// Facing from the lowest vertex id, as the edge stage does, so a face rounds the same way
// in every primitive.
bool front(int a, int b, int c) {
  if (vid[b] < vid[a] && vid[b] < vid[c]) return orientation(gl_in[b].gl_Position, gl_in[c].gl_Position, gl_in[a].gl_Position) > 0.0;
  if (vid[c] < vid[a] && vid[c] < vid[b]) return orientation(gl_in[c].gl_Position, gl_in[a].gl_Position, gl_in[b].gl_Position) > 0.0;
  return orientation(gl_in[a].gl_Position, gl_in[b].gl_Position, gl_in[c].gl_Position) > 0.0;
}
void main() {
  if (vid[0] == vid[2] || vid[2] == vid[4] || vid[0] == vid[4]) return;
  bool cover_front = front(0, 2, 4);
  for (int e = 0; e < 3; ++e) {
    int s = 2 * e, a = 2 * e + 1, t = (2 * e + 2) % 6;
    if (vid[a] == vid[t]) continue;  // covered by another primitive
    bool draw = vid[a] == vid[s] ||   // boundary edge
                front(s, a, t) != cover_front;
    if (!draw) continue;
    gl_Position = gl_in[s].gl_Position;
    EmitVertex();
    gl_Position = gl_in[t].gl_Position;
    EmitVertex();
    EndPrimitive();
  }
})";

const char* kFragmentShader = R"(#version 150 core
out vec4 colour;
void main() { colour = vec4(1.0); })";

template <typename F>
F gl(const char* name) {
  F f = reinterpret_cast<F>(OSMesaGetProcAddress(name));
  if (!f) ADD_FAILURE() << "OSMesa has no " << name;
  return f;
}

// Draws the primitives with the geometry shader; returns the image with row 0 at the top
// (one byte per pixel: lit or not), or an empty vector with a failure recorded.
std::vector<std::uint8_t> draw_with_geometry_shader(const Mesh& mesh, const std::vector<std::uint32_t>& indices,
                                                    const glm::mat4& mvp, std::string* renderer) {
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            2,
                            0};
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context) {
    ADD_FAILURE() << "no GL 3.2 core context from OSMesa";
    return {};
  }
  std::vector<std::uint8_t> rgba(std::size_t(kSize) * kSize * 4, 0);
  std::vector<std::uint8_t> lit;
  if (!OSMesaMakeCurrent(context, rgba.data(), GL_UNSIGNED_BYTE, kSize, kSize)) {
    ADD_FAILURE() << "OSMesaMakeCurrent failed";
    OSMesaDestroyContext(context);
    return {};
  }
  [&] {
    auto CreateShader = gl<PFNGLCREATESHADERPROC>("glCreateShader");
    auto ShaderSource = gl<PFNGLSHADERSOURCEPROC>("glShaderSource");
    auto CompileShader = gl<PFNGLCOMPILESHADERPROC>("glCompileShader");
    auto GetShaderiv = gl<PFNGLGETSHADERIVPROC>("glGetShaderiv");
    auto GetShaderInfoLog = gl<PFNGLGETSHADERINFOLOGPROC>("glGetShaderInfoLog");
    auto CreateProgram = gl<PFNGLCREATEPROGRAMPROC>("glCreateProgram");
    auto AttachShader = gl<PFNGLATTACHSHADERPROC>("glAttachShader");
    auto BindAttribLocation = gl<PFNGLBINDATTRIBLOCATIONPROC>("glBindAttribLocation");
    auto LinkProgram = gl<PFNGLLINKPROGRAMPROC>("glLinkProgram");
    auto GetProgramiv = gl<PFNGLGETPROGRAMIVPROC>("glGetProgramiv");
    auto UseProgram = gl<PFNGLUSEPROGRAMPROC>("glUseProgram");
    auto GetUniformLocation = gl<PFNGLGETUNIFORMLOCATIONPROC>("glGetUniformLocation");
    auto UniformMatrix4fv = gl<PFNGLUNIFORMMATRIX4FVPROC>("glUniformMatrix4fv");
    auto GenVertexArrays = gl<PFNGLGENVERTEXARRAYSPROC>("glGenVertexArrays");
    auto BindVertexArray = gl<PFNGLBINDVERTEXARRAYPROC>("glBindVertexArray");
    auto GenBuffers = gl<PFNGLGENBUFFERSPROC>("glGenBuffers");
    auto BindBuffer = gl<PFNGLBINDBUFFERPROC>("glBindBuffer");
    auto BufferData = gl<PFNGLBUFFERDATAPROC>("glBufferData");
    auto EnableVertexAttribArray = gl<PFNGLENABLEVERTEXATTRIBARRAYPROC>("glEnableVertexAttribArray");
    auto VertexAttribPointer = gl<PFNGLVERTEXATTRIBPOINTERPROC>("glVertexAttribPointer");
    if (::testing::Test::HasFailure()) return;
    *renderer = std::string(reinterpret_cast<const char*>(glGetString(GL_VERSION))) + " / " +
                reinterpret_cast<const char*>(glGetString(GL_RENDERER));

    auto compile = [&](GLenum type, const char* source) {
      const GLuint shader = CreateShader(type);
      ShaderSource(shader, 1, &source, nullptr);
      CompileShader(shader);
      GLint ok = 0;
      GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
      if (!ok) {
        char log[2048] = {};
        GetShaderInfoLog(shader, sizeof log, nullptr, log);
        ADD_FAILURE() << "shader: " << log;
      }
      return shader;
    };
    const GLuint program = CreateProgram();
    AttachShader(program, compile(GL_VERTEX_SHADER, kVertexShader));
    AttachShader(program, compile(GL_GEOMETRY_SHADER, kGeometryShader));
    AttachShader(program, compile(GL_FRAGMENT_SHADER, kFragmentShader));
    BindAttribLocation(program, 0, "position");
    LinkProgram(program);
    GLint linked = 0;
    GetProgramiv(program, GL_LINK_STATUS, &linked);
    ASSERT_TRUE(linked);
    UseProgram(program);
    UniformMatrix4fv(GetUniformLocation(program, "mvp"), 1, GL_FALSE, glm::value_ptr(mvp));

    GLuint vao = 0, buffers[2] = {};
    GenVertexArrays(1, &vao);
    BindVertexArray(vao);
    GenBuffers(2, buffers);
    BindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.positions.size() * sizeof(glm::vec3)), mesh.positions.data(),
               GL_STATIC_DRAW);
    EnableVertexAttribArray(0);
    VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    BindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
    BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * 4), indices.data(), GL_STATIC_DRAW);

    glViewport(0, 0, kSize, kSize);
    glDisable(GL_DEPTH_TEST);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES_ADJACENCY, GLsizei(indices.size()), GL_UNSIGNED_INT, nullptr);
    glFinish();
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    lit.assign(std::size_t(kSize) * kSize, 0);
    for (int row = 0; row < kSize; ++row)  // OSMesa's row 0 is the bottom
      for (int x = 0; x < kSize; ++x)
        lit[std::size_t(kSize - 1 - row) * kSize + x] = rgba[4 * (std::size_t(row) * kSize + x)] > 127;
  }();
  OSMesaDestroyContext(context);
  return lit;
}

// The GL draw runs in a forked child that leaves with _exit: Mesa keeps a few hundred bytes per
// process that LeakSanitizer would report, and GALLIUM_DRIVER stays out of this process (as in
// reference/osmesa_renderer.h). The child's gtest failures print on its stdout; the parent sees
// an empty image.
std::vector<std::uint8_t> draw_in_child(const Mesh& mesh, const std::vector<std::uint32_t>& indices,
                                        const glm::mat4& mvp, std::string* renderer) {
  int fds[2];
  if (pipe(fds) != 0) return {};
  const pid_t child = fork();
  if (child < 0) return {};
  if (child == 0) {
    close(fds[0]);
    std::string name;
    const std::vector<std::uint8_t> lit = draw_with_geometry_shader(mesh, indices, mvp, &name);
    std::string message;
    if (!::testing::Test::HasFailure() && lit.size() == std::size_t(kSize) * kSize) {
      const std::uint32_t length = static_cast<std::uint32_t>(name.size());
      message.append(reinterpret_cast<const char*>(&length), 4).append(name);
      message.append(reinterpret_cast<const char*>(lit.data()), lit.size());
    }
    std::size_t done = 0;
    while (done < message.size()) {
      const ssize_t n = write(fds[1], message.data() + done, message.size() - done);
      if (n <= 0) break;
      done += std::size_t(n);
    }
    close(fds[1]);
    std::fflush(stdout);
    _exit(0);
  }
  close(fds[1]);
  std::string received;
  char buffer[65536];
  ssize_t n;
  while ((n = read(fds[0], buffer, sizeof buffer)) > 0) received.append(buffer, std::size_t(n));
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (received.size() < 4) return {};
  std::uint32_t length = 0;
  std::memcpy(&length, received.data(), 4);
  if (received.size() != 4 + length + std::size_t(kSize) * kSize) return {};
  *renderer = received.substr(4, length);
  return std::vector<std::uint8_t>(received.begin() + 4 + length, received.end());
}

// Fraction of the lit pixels of `a` that have a lit pixel of `b` within `radius`.
double matched_fraction(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, int radius,
                        std::size_t* count) {
  std::size_t lit = 0, matched = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (!a[std::size_t(y) * kSize + x]) continue;
      ++lit;
      bool found = false;
      for (int dy = -radius; dy <= radius && !found; ++dy)
        for (int dx = -radius; dx <= radius && !found; ++dx) {
          const int u = x + dx, v = y + dy;
          found = u >= 0 && v >= 0 && u < kSize && v < kSize && b[std::size_t(v) * kSize + u];
        }
      matched += found;
    }
  if (count) *count = lit;
  return lit ? double(matched) / double(lit) : 0.0;
}

TEST(OsmesaCrossCheck, GeometryShaderSilhouetteOfBunnyMatchesTheEdgeStage) {
  const auto& built = testing::built_mesh("bunny00.off");
  const Mesh& mesh = built.mesh;
  const AdjacencyPrimitives ordered = permute_primitives(
      built.build.primitives, order_adjacency(AdjacencyOrder::Careful, mesh, built.build.primitives, 24));
  const auto camera = frame_mesh(mesh, {0.3f, 0.2f, 1.0f}, 1.0f);

  Framebuffer lines(kSize, kSize);
  lines.clear(glm::vec4(0.0f));
  const auto ours = draw_edge_stage(mesh, ordered.indices, camera, {}, 24, &lines);
  std::vector<std::uint8_t> mine(std::size_t(kSize) * kSize);
  for (std::size_t i = 0; i < mine.size(); ++i) mine[i] = lines.colour()[4 * i] > 127;

  std::string renderer;
  const std::vector<std::uint8_t> theirs =
      draw_in_child(mesh, ordered.indices, camera.projection * camera.view, &renderer);
  ASSERT_FALSE(theirs.empty()) << "the geometry-shader draw failed (its messages are printed above)";
  std::size_t mine_lit = 0, theirs_lit = 0, same = 0;
  for (std::size_t i = 0; i < mine.size(); ++i) same += mine[i] && theirs[i];
  const double ours_near = matched_fraction(mine, theirs, 1, &mine_lit);
  const double theirs_near = matched_fraction(theirs, mine, 1, &theirs_lit);
  RecordProperty("renderer", renderer);
  std::cout << "[ silhouette ] " << renderer << ": " << ours.edges.silhouette_edges << " silhouette edges, " << mine_lit
            << " pixels (rastrace), " << theirs_lit << " (geometry shader), " << same
            << " identical; within 1 pixel: " << ours_near << " / " << theirs_near << "\n";
  EXPECT_GT(ours.edges.silhouette_edges, 1000u);
  EXPECT_GT(mine_lit, 1500u);  // 512 x 512: 1664 pixels, 1663 of them identical
  EXPECT_NEAR(double(mine_lit), double(theirs_lit), 0.01 * double(theirs_lit));
  EXPECT_GE(double(same), 0.99 * double(std::max(mine_lit, theirs_lit)));
  EXPECT_GE(ours_near, 0.999);
  EXPECT_GE(theirs_near, 0.999);
}

}  // namespace
}  // namespace rastrace
