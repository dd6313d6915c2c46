// Results as Python sees them: tables become a `rastrace.Columns` (a dict of numpy columns that
// pandas.DataFrame takes as is, keyed like the JSON output, with the table's title and parameters
// as attributes), vectors become numpy arrays without a copy.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "core/table.h"

namespace rastrace::python {

namespace py = pybind11;

// Hands the vector's buffer to numpy (no copy); the array owns it.
template <typename T>
py::array_t<T> to_array(std::vector<T>&& values, std::vector<py::ssize_t> shape = {}) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  if (shape.empty()) shape = {static_cast<py::ssize_t>(owned->size())};
  return py::array_t<T>(shape, owned->data(), owner);
}

// A column of text with few distinct values (policy, layout): an object array whose cells share
// one Python string per distinct value.
class TextColumn {
 public:
  explicit TextColumn(std::size_t rows);
  void set(std::size_t row, std::string_view text);
  py::array release() { return std::move(array_); }

 private:
  py::array array_;
  std::unordered_map<std::string, py::object> strings_;  // node-based: keys and values stay put
  std::string_view last_text_;
  PyObject* last_ = nullptr;
};

// The Python value of a table parameter or cell.
py::object to_python(const TableCell& cell);
// Every column of the table: int64 (float64 with NaN where a cell is empty), float64, or text.
py::object table_columns(const Table& table);
// Wraps columns (name -> numpy array) as rastrace.Columns with the title and parameters.
py::object make_columns(py::dict columns, const std::string& title,
                        const std::vector<std::pair<std::string, TableCell>>& parameters);

}  // namespace rastrace::python
