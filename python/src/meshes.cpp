// load_mesh and load_scene: the loaders `rastrace info`, `vcache` and `render` use, with the
// geometry as numpy arrays (copies: the Mesh stays usable by every other function).
#include "meshes.h"

#include <cstring>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "columns.h"
#include "scenes/mesh_spec.h"
#include "scenes/scene_io.h"

namespace rastrace::python {

namespace {

template <typename Vec>
py::array_t<float> vectors(const std::vector<Vec>& values) {
  constexpr py::ssize_t width = Vec::length();
  std::vector<float> flat(values.size() * width);
  if (!values.empty()) std::memcpy(flat.data(), values.data(), flat.size() * sizeof(float));
  return to_array(std::move(flat), {static_cast<py::ssize_t>(values.size()), width});
}

py::array_t<std::uint32_t> copy_u32(const std::vector<std::uint32_t>& values, std::vector<py::ssize_t> shape = {}) {
  return to_array(std::vector<std::uint32_t>(values), std::move(shape));
}

}  // namespace

const Mesh& mesh_argument(py::handle object, std::optional<Mesh>& storage) {
  if (py::isinstance<Mesh>(object)) return object.cast<const Mesh&>();
  if (py::isinstance<py::str>(object) || py::hasattr(object, "__fspath__")) {
    const std::string spec = py::str(object);
    py::gil_scoped_release release;
    storage.emplace(load_mesh_spec(spec));
    return *storage;
  }
  throw py::type_error("expected a rastrace.Mesh or a mesh spec (a file, builtin:NAME or grid:WxH)");
}

void bind_meshes(py::module_& m) {
  py::class_<Mesh>(m, "Mesh", "A triangle mesh as rastrace loads it (positions, UVs, normals, faces, materials).")
      .def_readonly("name", &Mesh::name)
      .def_property_readonly("vertex_count", &Mesh::vertex_count)
      .def_property_readonly("face_count", &Mesh::face_count)
      .def_property_readonly(
          "positions", [](const Mesh& mesh) { return vectors(mesh.positions); }, "float32 array (vertices, 3)")
      .def_property_readonly(
          "normals", [](const Mesh& mesh) { return vectors(mesh.normals); },
          "float32 array (vertices, 3), or (0, 3) when the mesh has none")
      .def_property_readonly(
          "uvs", [](const Mesh& mesh) { return vectors(mesh.uvs); },
          "float32 array (vertices, 2), or (0, 2) when the mesh has none")
      .def_property_readonly(
          "indices",
          [](const Mesh& mesh) {
            return copy_u32(mesh.indices, {static_cast<py::ssize_t>(mesh.face_count()), 3});
          },
          "uint32 array (faces, 3), counter-clockwise front faces")
      .def_property_readonly(
          "face_material", [](const Mesh& mesh) { return copy_u32(mesh.face_material); },
          "uint32 array (faces), or empty when every face has material 0")
      .def("__repr__", [](const Mesh& mesh) {
        return "<rastrace.Mesh " + mesh.name + ": " + std::to_string(mesh.vertex_count()) + " vertices, " +
               std::to_string(mesh.face_count()) + " faces>";
      });

  py::class_<Scene>(m, "Scene", "A scene: objects (meshes with transforms), textures, camera and frame size.")
      .def_readonly("name", &Scene::name)
      .def_readonly("width", &Scene::width)
      .def_readonly("height", &Scene::height)
      .def_property_readonly(
          "meshes",
          [](const Scene& scene) {
            py::list meshes;
            for (const SceneObject& object : scene.objects) meshes.append(py::cast(object.mesh));
            return meshes;
          },
          "Each object's mesh (in model space), in object order")
      .def_property_readonly("texture_count", [](const Scene& scene) { return scene.textures.size(); })
      .def("__repr__", [](const Scene& scene) {
        return "<rastrace.Scene " + scene.name + ": " + std::to_string(scene.objects.size()) + " objects, " +
               std::to_string(scene.textures.size()) + " textures, " + std::to_string(scene.width) + "x" +
               std::to_string(scene.height) + ">";
      });

  m.def(
      "load_mesh", [](const std::string& spec) { return load_mesh_spec(spec); }, py::arg("spec"),
      py::call_guard<py::gil_scoped_release>(),
      "Loads a mesh: a file (OFF, PLY, OBJ, glTF, ...), builtin:NAME (a scene merged into one mesh) or grid:WxH.");
  m.def(
      "load_scene", [](const std::string& spec) { return load_scene(spec); }, py::arg("spec"),
      py::call_guard<py::gil_scoped_release>(),
      "Loads a scene: builtin:NAME, a JSON scene (docs/scene-format.md) or a mesh file framed by a default camera.");
}

}  // namespace rastrace::python
