#include "reference/osmesa_renderer.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <stdexcept>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <glm/gtc/type_ptr.hpp>

#include "core/enum_names.h"
#include "core/error.h"
#include "pipeline/render_scene.h"
#include "reference/gl_texture_format.h"

namespace rastrace {

namespace {

constexpr EnumName<ReferenceDriver> kDrivers[] = {{ReferenceDriver::Softpipe, "softpipe"},
                                                  {ReferenceDriver::Llvmpipe, "llvmpipe"}};

}  // namespace

ReferenceDriver parse_reference_driver(const std::string& text) { return parse_enum(text, kDrivers, "OSMesa driver"); }

const char* to_string(ReferenceDriver driver) { return enum_to_string(driver, kDrivers); }

namespace {

// The scene is checked in the parent so that bad input is an InputError, not a child's failure.
void validate(const Scene& scene) {
  if (scene.width < 1 || scene.height < 1 || scene.width > 16384 || scene.height > 16384)
    throw InputError(scene.name + ": image size " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                     ": expected 1..16384 pixels on each side");
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    for (std::size_t i = 0; i < mesh.indices.size(); ++i)
      if (mesh.indices[i] >= mesh.vertex_count())
        throw InputError(mesh.name + ": index " + std::to_string(i) + ": vertex " + std::to_string(mesh.indices[i]) +
                         " >= vertex count " + std::to_string(mesh.vertex_count()));
    const std::size_t materials = std::max<std::size_t>(mesh.materials.size(), 1);
    for (std::size_t f = 0; f < mesh.face_material.size(); ++f)
      if (mesh.face_material[f] >= materials)
        throw InputError(mesh.name + ": face " + std::to_string(f) + " uses material " +
                         std::to_string(mesh.face_material[f]) + " of " + std::to_string(mesh.materials.size()));
    for (const Material& material : mesh.materials)
      if (material.texture >= 0 && (static_cast<std::size_t>(material.texture) >= scene.textures.size() ||
                                    scene.textures[static_cast<std::size_t>(material.texture)].levels.empty()))
        throw InputError(mesh.name + ": material '" + material.name + "' uses texture " +
                         std::to_string(material.texture) + " but " + std::to_string(scene.textures.size()) +
                         " textures are loaded");
  }
}

GLenum gl_filter(TextureFilter filter) {
  switch (filter) {
    case TextureFilter::Nearest:
      return GL_NEAREST;
    case TextureFilter::Linear:
      return GL_LINEAR;
    case TextureFilter::NearestMipmapNearest:
      return GL_NEAREST_MIPMAP_NEAREST;
    case TextureFilter::LinearMipmapNearest:
      return GL_LINEAR_MIPMAP_NEAREST;
    case TextureFilter::LinearMipmapLinear:
      return GL_LINEAR_MIPMAP_LINEAR;
  }
  return GL_LINEAR;
}

GLenum gl_wrap(TextureWrap wrap) { return wrap == TextureWrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE; }

struct Run {  // consecutive faces with one material: one glDrawElements
  std::size_t first_face, faces;
  std::uint32_t material;
};

struct GpuObject {
  GLuint buffers[4] = {0, 0, 0, 0};  // positions, normals, uvs, indices
  bool normals = false, uvs = false;
  std::vector<Run> runs;
};

void put(std::vector<char>& out, const void* data, std::size_t size) {
  if (size == 0) return;
  const std::size_t at = out.size();
  out.resize(at + size);
  std::memcpy(out.data() + at, data, size);
}

// Every level of the bound texture: a compressed texture's own blocks (so Mesa decodes the same
// bits texcodec did), else rastrace's RGBA8 mip chain. Returns an error message or "".
std::string upload_levels(const Texture& texture) {
  const bool compressed = is_compressed(texture.format) && texture.blocks.size() == texture.levels.size();
  const GlCompressedFormat gl = gl_compressed_format(texture.format);
  if (compressed && !has_gl_extension(gl.extension))
    return std::string("the driver does not expose ") + gl.extension + " for " + to_string(texture.format) +
           " textures";
  for (std::size_t level = 0; level < texture.levels.size(); ++level) {
    const Image& image = texture.levels[level];
    if (compressed)
      glCompressedTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(level), gl.internal_format, image.width, image.height, 0,
                             static_cast<GLsizei>(texture.blocks[level].size()), texture.blocks[level].data());
    else
      glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(level), GL_RGBA8, image.width, image.height, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, image.rgba.data());
  }
  if (glGetError() != GL_NO_ERROR) return "uploading texture " + texture.name + " failed";
  return "";
}

// Everything the child does; returns the message to send back (status first).
std::vector<char> render_in_child(const Scene& scene, const ReferenceOptions& options) {
  std::vector<char> message;
  auto fail = [&](const std::string& text) {
    message.clear();
    const std::uint32_t status = 1, length = static_cast<std::uint32_t>(text.size());
    put(message, &status, 4);
    put(message, &length, 4);
    put(message, text.data(), text.size());
    return message;
  };
  setenv("GALLIUM_DRIVER", to_string(options.driver), 1);
  if (options.llvmpipe_threads >= 0) setenv("LP_NUM_THREADS", std::to_string(options.llvmpipe_threads).c_str(), 1);

  const int width = scene.width, height = scene.height;
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!context) return fail("OSMesaCreateContextExt failed");
  std::vector<std::uint8_t> buffer(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  if (!OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, width, height))
    return fail("OSMesaMakeCurrent failed");
  const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));

  // Textures: rastrace's own mip chain, level by level.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  std::vector<GLuint> textures(scene.textures.size(), 0);
  if (!textures.empty()) glGenTextures(static_cast<GLsizei>(textures.size()), textures.data());
  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    const Texture& texture = scene.textures[t];
    glBindTexture(GL_TEXTURE_2D, textures[t]);
    if (const std::string error = upload_levels(texture); !error.empty()) return fail(error);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(texture.levels.size()) - 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(gl_filter(options.sampler.min_filter)));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(gl_filter(options.sampler.mag_filter)));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, static_cast<GLint>(gl_wrap(options.sampler.wrap_s)));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, static_cast<GLint>(gl_wrap(options.sampler.wrap_t)));
    // Only when asked: 1 is GL's default, and setting it could change a driver's shader variant.
    if (options.sampler.max_anisotropy > 1)
      glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT,
                      static_cast<GLfloat>(options.sampler.max_anisotropy));
  }
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

  // Geometry in buffer objects, uploaded once (the timing measures drawing, not uploads).
  std::vector<GpuObject> objects(scene.objects.size());
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const Mesh& mesh = scene.objects[o].mesh;
    GpuObject& gpu = objects[o];
    glGenBuffers(4, gpu.buffers);
    glBindBuffer(GL_ARRAY_BUFFER, gpu.buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.positions.size() * sizeof(glm::vec3)),
                 mesh.positions.data(), GL_STATIC_DRAW);
    gpu.normals = mesh.normals.size() == mesh.vertex_count() && mesh.vertex_count() > 0;
    if (gpu.normals) {
      glBindBuffer(GL_ARRAY_BUFFER, gpu.buffers[1]);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.normals.size() * sizeof(glm::vec3)),
                   mesh.normals.data(), GL_STATIC_DRAW);
    }
    gpu.uvs = mesh.uvs.size() == mesh.vertex_count() && mesh.vertex_count() > 0;
    if (gpu.uvs) {
      glBindBuffer(GL_ARRAY_BUFFER, gpu.buffers[2]);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.uvs.size() * sizeof(glm::vec2)), mesh.uvs.data(),
                   GL_STATIC_DRAW);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.buffers[3]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.face_count() * 3 * sizeof(std::uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const std::uint32_t m = mesh.material_of(f);
      if (gpu.runs.empty() || gpu.runs.back().material != m) gpu.runs.push_back(Run{f, 0, m});
      ++gpu.runs.back().faces;
    }
  }

  const CameraMatrices camera = camera_matrices(scene);
  const glm::vec4 clear = options.clear_colour.value_or(scene.background);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClearDepth(1.0);
  glClearColor(clear.r, clear.g, clear.b, clear.a);
  glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
  glShadeModel(GL_SMOOTH);
  glDisable(GL_DITHER);
  if (options.cull == CullMode::None) {
    glDisable(GL_CULL_FACE);
  } else {
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glCullFace(options.cull == CullMode::Back ? GL_BACK : GL_FRONT);
  }
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(glm::value_ptr(camera.projection));
  if (options.lighting.enabled) {
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const glm::vec3 d = options.lighting.direction;
    const GLfloat position[4] = {d.x, d.y, d.z, 0.0f};
    const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f}, black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    const GLfloat ambient[4] = {options.lighting.ambient, options.lighting.ambient, options.lighting.ambient, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_AMBIENT, black);
    glLightfv(GL_LIGHT0, GL_SPECULAR, black);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
  }

  auto draw_frame = [&] {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
      const SceneObject& object = scene.objects[o];
      const GpuObject& gpu = objects[o];
      glMatrixMode(GL_MODELVIEW);
      const glm::mat4 model_view = camera.view * object.transform;
      glLoadMatrixf(glm::value_ptr(model_view));
      glEnableClientState(GL_VERTEX_ARRAY);
      glBindBuffer(GL_ARRAY_BUFFER, gpu.buffers[0]);
      glVertexPointer(3, GL_FLOAT, 0, nullptr);
      if (gpu.normals) {
        glEnableClientState(GL_NORMAL_ARRAY);
        glBindBuffer(GL_ARRAY_BUFFER, gpu.buffers[1]);
        glNormalPointer(GL_FLOAT, 0, nullptr);
      } else {
        glDisableClientState(GL_NORMAL_ARRAY);
        glNormal3f(0.0f, 0.0f, 1.0f);
      }
      if (gpu.uvs) {
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glBindBuffer(GL_ARRAY_BUFFER, gpu.buffers[2]);
        glTexCoordPointer(2, GL_FLOAT, 0, nullptr);
      } else {
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
      }
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.buffers[3]);
      for (const Run& run : gpu.runs) {
        const Mesh& mesh = object.mesh;
        const Material material = run.material < mesh.materials.size() ? mesh.materials[run.material] : Material{};
        if (material.texture >= 0 && gpu.uvs) {
          glEnable(GL_TEXTURE_2D);
          glBindTexture(GL_TEXTURE_2D, textures[static_cast<std::size_t>(material.texture)]);
        } else {
          glDisable(GL_TEXTURE_2D);
        }
        glColor4f(material.diffuse.r, material.diffuse.g, material.diffuse.b, material.diffuse.a);
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(run.faces * 3), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(run.first_face * 3 * sizeof(std::uint32_t)));
      }
    }
    glFinish();
  };

  auto cpu_now = [] {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  };
  double best = 1e300, first = 0.0, best_cpu = 1e300;
  for (int frame = 0; frame < std::max(1, options.frames); ++frame) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = cpu_now();
    draw_frame();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best_cpu = std::min(best_cpu, cpu_now() - cpu_start);
    if (frame == 0) first = seconds;
    best = std::min(best, seconds);
  }
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) return fail("OpenGL error " + std::to_string(error) + " while drawing");

  const std::uint32_t status = 0, length = static_cast<std::uint32_t>(renderer.size());
  const std::int32_t size[2] = {width, height};
  put(message, &status, 4);
  put(message, size, 8);
  put(message, &best, 8);
  put(message, &first, 8);
  put(message, &best_cpu, 8);
  put(message, &length, 4);
  put(message, renderer.data(), renderer.size());
  // OSMesa's row 0 is the bottom row: send the rows top first.
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = height - 1; y >= 0; --y) put(message, buffer.data() + static_cast<std::size_t>(y) * row, row);
  OSMesaDestroyContext(context);
  return message;
}

bool write_all(int fd, const char* data, std::size_t size) {
  while (size) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

template <typename T>
T take(const std::vector<char>& in, std::size_t& at) {
  if (at + sizeof(T) > in.size()) throw std::runtime_error("OSMesa reference: truncated reply from the child process");
  T value;
  std::memcpy(&value, in.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

}  // namespace

ReferenceImage render_reference(const Scene& scene, const ReferenceOptions& options) {
  validate(scene);
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(std::string("OSMesa reference: pipe: ") + std::strerror(errno));
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("OSMesa reference: fork: ") + std::strerror(errno));
  }
  if (child == 0) {
    ::close(fds[0]);
    int code = 0;
    try {
      const std::vector<char> message = render_in_child(scene, options);
      if (!write_all(fds[1], message.data(), message.size())) code = 3;
    } catch (...) {
      code = 4;
    }
    ::close(fds[1]);
    ::_exit(code);  // no atexit handlers, no destructors of the parent's objects
  }
  ::close(fds[1]);
  std::vector<char> reply;
  char chunk[65536];
  for (;;) {
    const ssize_t n = ::read(fds[0], chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    const std::size_t at = reply.size();
    reply.resize(at + static_cast<std::size_t>(n));
    std::memcpy(reply.data() + at, chunk, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("OSMesa reference (" + std::string(to_string(options.driver)) +
                             "): the child process failed (status " + std::to_string(status) + ")");

  std::size_t at = 0;
  if (take<std::uint32_t>(reply, at) != 0) {
    const std::uint32_t length = take<std::uint32_t>(reply, at);
    throw std::runtime_error("OSMesa reference (" + std::string(to_string(options.driver)) +
                             "): " + std::string(reply.data() + at, std::min<std::size_t>(length, reply.size() - at)));
  }
  ReferenceImage image;
  image.width = take<std::int32_t>(reply, at);
  image.height = take<std::int32_t>(reply, at);
  image.best_frame_seconds = take<double>(reply, at);
  image.first_frame_seconds = take<double>(reply, at);
  image.best_frame_cpu_seconds = take<double>(reply, at);
  const std::uint32_t length = take<std::uint32_t>(reply, at);
  if (at + length > reply.size()) throw std::runtime_error("OSMesa reference: truncated reply from the child process");
  image.renderer.assign(reply.data() + at, length);
  at += length;
  const std::size_t bytes = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4;
  if (reply.size() - at != bytes) throw std::runtime_error("OSMesa reference: truncated image from the child process");
  image.rgba.assign(reply.begin() + static_cast<std::ptrdiff_t>(at), reply.end());
  if (image.renderer.rfind(to_string(options.driver), 0) != 0)
    throw std::runtime_error("OSMesa reference: asked for " + std::string(to_string(options.driver)) +
                             " but Mesa answered with '" + image.renderer + "'");
  return image;
}

}  // namespace rastrace
