#include "column_memory.h"

#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <new>
#include <utility>

namespace rastrace::python {

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

std::size_t round_up(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

void* map_huge(std::size_t bytes) {
  const std::size_t length = round_up(bytes);
  // Map one huge page more than needed, then give back the unaligned head and the tail.
  void* raw = mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start) munmap(raw, aligned - start);
  if (const std::size_t tail = start + length + kHugePage - (aligned + length); tail > 0)
    munmap(reinterpret_cast<void*>(aligned + length), tail);
  void* memory = reinterpret_cast<void*>(aligned);
  // Advice only: without transparent huge pages (or with them off) the mapping works as usual.
#ifdef MADV_HUGEPAGE
  madvise(memory, length, MADV_HUGEPAGE);
#endif
  return memory;
}

// What a capsule owns: the memory, and whether its cells are references to release.
struct OwnedColumn {
  void* data;
  std::size_t bytes;
  bool mapped;
  std::size_t object_cells;  // 0 for numeric columns
};

void free_memory(void* data, std::size_t bytes, bool mapped) {
  if (mapped)
    munmap(data, round_up(bytes));
  else
    std::free(data);
}

}  // namespace

ColumnMemory::ColumnMemory(std::size_t bytes) : bytes_(bytes), mapped_(bytes >= kHugeColumnBytes) {
  data_ = mapped_ ? map_huge(bytes) : std::calloc(bytes ? bytes : 1, 1);
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
