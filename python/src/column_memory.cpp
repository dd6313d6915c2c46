#include "column_memory.h"

#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>

#include "core/huge_page_allocator.h"

namespace rastrace::python {

namespace {

// Columns from kHugeColumnBytes on are blocks of the huge-page allocator (2 MiB-aligned
// mappings of their own, advised MADV_HUGEPAGE, zero-filled as fresh mappings are).
using HugeBlocks = HugePageAllocator<std::byte>;
static_assert(kHugeColumnBytes >= HugeBlocks::kHugePage, "columns that big are mappings of their own");

// What a capsule owns: the memory, and whether its cells are references to release.
struct OwnedColumn {
  void* data;
  std::size_t bytes;
  bool mapped;
  std::size_t object_cells;  // 0 for numeric columns
};

void free_memory(void* data, std::size_t bytes, bool mapped) {
  if (mapped)
    HugeBlocks{}.deallocate(static_cast<std::byte*>(data), bytes);
  else
    std::free(data);
}

}  // namespace

ColumnMemory::ColumnMemory(std::size_t bytes) : bytes_(bytes), mapped_(bytes >= kHugeColumnBytes) {
  data_ = mapped_ ? static_cast<void*>(HugeBlocks{}.allocate(bytes)) : std::calloc(bytes ? bytes : 1, 1);
  if (data_ == nullptr) throw std::bad_alloc();
}

ColumnMemory::ColumnMemory(ColumnMemory&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), bytes_(other.bytes_), mapped_(other.mapped_) {}

ColumnMemory& ColumnMemory::operator=(ColumnMemory&& other) noexcept {
  if (this != &other) {
    free();
    data_ = std::exchange(other.data_, nullptr);
    bytes_ = other.bytes_;
    mapped_ = other.mapped_;
  }
  return *this;
}

ColumnMemory::~ColumnMemory() { free(); }

void ColumnMemory::free() noexcept {
  if (data_ != nullptr) free_memory(data_, bytes_, mapped_);
  data_ = nullptr;
}

py::capsule ColumnMemory::release_to_capsule(std::size_t rows, bool object_cells) && {
  auto* owned = new OwnedColumn{data_, bytes_, mapped_, object_cells ? rows : 0};
  data_ = nullptr;
  return py::capsule(owned, [](void* p) {  // runs with the GIL held, as every deallocation
    auto* column = static_cast<OwnedColumn*>(p);
    auto* const cells = static_cast<PyObject**>(column->data);
    for (std::size_t i = 0; i < column->object_cells; ++i) Py_XDECREF(cells[i]);
    free_memory(column->data, column->bytes, column->mapped);
    delete column;
  });
}

py::array ColumnMemory::to_object_array(std::size_t rows) && {
  auto* const cells = static_cast<PyObject**>(data_);
  py::capsule owner = std::move(*this).release_to_capsule(rows, true);
  return py::array(py::dtype("O"), {static_cast<py::ssize_t>(rows)}, {static_cast<py::ssize_t>(sizeof(PyObject*))},
                   cells, owner);
}

py::array new_object_column(std::size_t rows) {
  return ColumnMemory(rows * sizeof(PyObject*)).to_object_array(rows);
}

}  // namespace rastrace::python
