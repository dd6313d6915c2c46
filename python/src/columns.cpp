#include "columns.h"

#include <cmath>
#include <limits>
#include <variant>

#include "column_memory.h"

namespace rastrace::python {

TextColumn::TextColumn(std::size_t rows) : array_(new_object_column(rows)) {}

void TextColumn::set(std::size_t row, std::string_view text) {
  // Sorted sweep rows repeat the previous row's text: no lookup then.
  if (last_ == nullptr || text != last_text_) {
    auto it = strings_.find(std::string(text));
    if (it == strings_.end()) it = strings_.emplace(std::string(text), py::str(text.data(), text.size())).first;
    last_text_ = it->first;
    last_ = it->second.ptr();
  }
  // A fresh object array holds null cells: replace the cell with a new reference.
  PyObject** cells = static_cast<PyObject**>(array_.mutable_data());
  Py_INCREF(last_);
  PyObject* value = last_;
  Py_XDECREF(cells[row]);
  cells[row] = value;
}

py::object to_python(const TableCell& cell) {
  return std::visit(
      [](const auto& value) -> py::object {
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, std::monostate>)
          return py::none();
        else
          return py::cast(value);
      },
      cell.value);
}

py::object table_columns(const Table& table) {
  py::dict columns;
  const std::size_t rows = table.rows.size();
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    bool text = false, real = false, empty = false;
    for (const auto& row : table.rows) {
      text |= std::holds_alternative<std::string>(row[c].value);
      real |= std::holds_alternative<double>(row[c].value);
      empty |= std::holds_alternative<std::monostate>(row[c].value);
    }
    const std::string& key = table.columns[c].key;
    if (text) {
      TextColumn column(rows);
      for (std::size_t r = 0; r < rows; ++r) {
        const TableCell& cell = table.rows[r][c];
        if (const auto* s = std::get_if<std::string>(&cell.value)) column.set(r, *s);
      }
      columns[key.c_str()] = column.release();
    } else if (real || empty) {
      std::vector<double> values(rows, std::numeric_limits<double>::quiet_NaN());
      for (std::size_t r = 0; r < rows; ++r) {
        const TableCell& cell = table.rows[r][c];
        if (const auto* d = std::get_if<double>(&cell.value)) values[r] = *d;
        if (const auto* i = std::get_if<std::int64_t>(&cell.value)) values[r] = static_cast<double>(*i);
      }
      columns[key.c_str()] = to_array(std::move(values));
    } else {
      std::vector<std::int64_t> values(rows);
      for (std::size_t r = 0; r < rows; ++r) values[r] = std::get<std::int64_t>(table.rows[r][c].value);
      columns[key.c_str()] = to_array(std::move(values));
    }
  }
  return make_columns(columns, table.title, table.parameters);
}

py::object make_columns(py::dict columns, const std::string& title,
                        const std::vector<std::pair<std::string, TableCell>>& parameters) {
  py::dict parameter_dict;
  for (const auto& [key, value] : parameters) parameter_dict[key.c_str()] = to_python(value);
  return py::module_::import("rastrace._columns").attr("Columns")(columns, title, parameter_dict);
}

}  // namespace rastrace::python
