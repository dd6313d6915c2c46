#include "column_memory.h"

#include <sys/mman.h>

#include <cstdint>
#include <new>
#include <vector>

namespace rastrace::python {

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

std::size_t round_up(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

}  // namespace

void* map_column_memory(std::size_t bytes) {
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

void unmap_column_memory(void* memory, std::size_t bytes) { munmap(memory, round_up(bytes)); }

py::array new_object_column(std::size_t rows) {
  const std::size_t bytes = rows * sizeof(PyObject*);
  if (bytes < kHugeColumnBytes) return py::array(py::dtype("O"), std::vector<py::ssize_t>{static_cast<py::ssize_t>(rows)});
  struct Cells {
    PyObject** cells;
    std::size_t rows;
  };
  auto* cells = new Cells{static_cast<PyObject**>(map_column_memory(bytes)), rows};  // zero: null cells
  py::capsule owner(cells, [](void* p) {  // runs with the GIL held, as every deallocation
    auto* c = static_cast<Cells*>(p);
    for (std::size_t i = 0; i < c->rows; ++i) Py_XDECREF(c->cells[i]);
    unmap_column_memory(c->cells, c->rows * sizeof(PyObject*));
    delete c;
  });
  return py::array(py::dtype("O"), {static_cast<py::ssize_t>(rows)}, {static_cast<py::ssize_t>(sizeof(PyObject*))},
                   cells->cells, owner);
}

}  // namespace rastrace::python
