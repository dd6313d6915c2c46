#include "sweep_columns.h"

#include <map>
#include <stdexcept>

namespace rastrace::python {

SweepColumns::SweepColumns(const SweepSpec& spec) {
  for (std::size_t p = 0; p < policy_strings_.size(); ++p)
    policy_strings_[p] = py::str(to_string(static_cast<ReplacementPolicy>(p)));
  const std::size_t layouts = spec.source == SweepSource::Texel ? spec.layouts.size() : 1;
  std::map<std::string, py::object> by_name;
  for (std::size_t l = 0; l < layouts; ++l) {
    const std::string name = sweep_layout_name(spec, l);
    auto it = by_name.find(name);
    if (it == by_name.end()) it = by_name.emplace(name, py::str(name)).first;
    layout_strings_.push_back(it->second);
  }
  layout_references_ = std::vector<std::atomic<std::size_t>>(layouts);
}

void SweepColumns::begin(std::size_t rows) {
  rows_ = rows;
  for (ColumnMemory& column : integers_) column = ColumnMemory(rows * sizeof(std::int64_t));
  miss_rate_ = ColumnMemory(rows * sizeof(double));
  policy_cells_ = ColumnMemory(rows * sizeof(PyObject*));
  layout_cells_ = ColumnMemory(rows * sizeof(PyObject*));
}

void SweepColumns::done(const SweepRows& rows, const std::vector<std::size_t>& indices) {
  std::int64_t* out[kIntegers];
  for (int k = 0; k < kIntegers; ++k) out[k] = integers_[k].as<std::int64_t>();
  double* const rate = miss_rate_.as<double>();
  PyObject** const policy = policy_cells_.as<PyObject*>();
  PyObject** const layout = layout_cells_.as<PyObject*>();
  std::array<std::size_t, 4> policy_count{};
  std::vector<std::size_t> layout_count(layout_strings_.size());
  bool three_c = true;
  for (const std::size_t i : indices) {
    const SweepRow& r = rows[i];
    const auto p = static_cast<std::size_t>(r.cache.policy);
    if (i >= rows_ || p >= policy_strings_.size() || r.layout_index >= layout_strings_.size())
      throw std::logic_error("sweep row outside the columns planned for it");
    out[Size][i] = static_cast<std::int64_t>(r.cache.size_bytes);
    out[Line][i] = r.cache.line_bytes;
    out[Assoc][i] = r.cache.assoc;
    out[Accesses][i] = static_cast<std::int64_t>(r.stats.accesses);
    out[Hits][i] = static_cast<std::int64_t>(r.stats.hits);
    out[Misses][i] = static_cast<std::int64_t>(r.stats.misses);
    rate[i] = r.stats.miss_rate();
    out[BytesFetched][i] = static_cast<std::int64_t>(r.stats.bytes_fetched);
    out[Compulsory][i] = static_cast<std::int64_t>(r.stats.compulsory);
    out[Capacity][i] = r.stats.capacity;
    out[Conflict][i] = r.stats.conflict;
    three_c = three_c && r.stats.has_three_c;
    // Reading an object's address needs no GIL; its reference is added in release().
    policy[i] = policy_strings_[p].ptr();
    layout[i] = layout_strings_[r.layout_index].ptr();
    ++policy_count[p];
    ++layout_count[r.layout_index];
  }
  for (std::size_t p = 0; p < policy_count.size(); ++p) policy_references_[p] += policy_count[p];
  for (std::size_t l = 0; l < layout_count.size(); ++l) layout_references_[l] += layout_count[l];
  if (!three_c) three_c_ = false;
}

namespace {

// `count` references at once (one per cell that holds the object), where a loop of Py_INCREF
// would take milliseconds for 10^6 cells.
void add_references(const py::object& object, std::size_t count) {
#ifdef Py_GIL_DISABLED
  for (std::size_t i = 0; i < count; ++i) Py_INCREF(object.ptr());
#else
  // Immortal objects (Python 3.12+) keep their count: Py_SET_REFCNT ignores them.
  Py_SET_REFCNT(object.ptr(), Py_REFCNT(object.ptr()) + static_cast<Py_ssize_t>(count));
#endif
}

}  // namespace

py::dict SweepColumns::release() {
  if (released_) throw std::logic_error("sweep columns handed to numpy twice");
  released_ = true;
  // The cells own their references before numpy arrays (whose owners release them) exist.
  for (std::size_t p = 0; p < policy_strings_.size(); ++p) add_references(policy_strings_[p], policy_references_[p]);
  for (std::size_t l = 0; l < layout_strings_.size(); ++l) add_references(layout_strings_[l], layout_references_[l]);
  const auto integer = [&](Integer k) { return std::move(integers_[k]).to_array<std::int64_t>(rows_); };
  py::dict columns;
  columns["size_bytes"] = integer(Size);
  columns["line_bytes"] = integer(Line);
  columns["assoc"] = integer(Assoc);
  columns["policy"] = std::move(policy_cells_).to_object_array(rows_);
  columns["layout"] = std::move(layout_cells_).to_object_array(rows_);
  columns["accesses"] = integer(Accesses);
  columns["hits"] = integer(Hits);
  columns["misses"] = integer(Misses);
  columns["miss_rate"] = std::move(miss_rate_).to_array<double>(rows_);
  columns["bytes_fetched"] = integer(BytesFetched);
  if (three_c_) {  // sweeps always compute the split; without it the JSON has nulls
    columns["compulsory"] = integer(Compulsory);
    columns["capacity"] = integer(Capacity);
    columns["conflict"] = integer(Conflict);
  }
  return columns;
}

}  // namespace rastrace::python
