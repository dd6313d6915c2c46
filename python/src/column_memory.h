// Memory for the numeric columns of large results (a sweep of 10^6 rows: 8 MB per column).
//
// A fresh page costs a fault at its first touch, and a 4 KiB fault is expensive (about 14 us on
// the virtual machine of docs/PERFORMANCE.md, "Python": 100 MB of columns took 380 ms of faults).
// numpy advises transparent huge pages for its large arrays, but it gets them from malloc, whose
// large blocks are mappings aligned to 4 KiB only: a 2 MiB page fits only where a whole aligned
// 2 MiB range lies inside, and the rest of each 8 MB column still faults page by page. A column
// here is its own mapping, aligned to 2 MiB and rounded up to it, advised MADV_HUGEPAGE: with
// transparent huge pages on ("always" or "madvise"), four faults fill an 8 MB column.
#pragma once

#include <cstddef>

#include <pybind11/numpy.h>

namespace rastrace::python {

namespace py = pybind11;

// Below this size a column is an ordinary numpy array: a 2 MiB granule would waste too much.
inline constexpr std::size_t kHugeColumnBytes = std::size_t{4} << 20;

// `bytes` (rounded up to 2 MiB) of zero-filled memory in a mapping of its own, 2 MiB-aligned and
// advised for huge pages; throws std::bad_alloc when the system has none.
void* map_column_memory(std::size_t bytes);
void unmap_column_memory(void* memory, std::size_t bytes);

// An uninitialized 1-D column of `rows` values: huge-page memory owned by the array (through a
// capsule, freed with the last view) from kHugeColumnBytes on, numpy's allocation below that.
template <typename T>
py::array_t<T> new_column(std::size_t rows) {
  const std::size_t bytes = rows * sizeof(T);
  if (bytes < kHugeColumnBytes) return py::array_t<T>(static_cast<py::ssize_t>(rows));
  struct Mapping {
    void* memory;
    std::size_t bytes;
  };
  auto* mapping = new Mapping{map_column_memory(bytes), bytes};
  py::capsule owner(mapping, [](void* p) {
    auto* m = static_cast<Mapping*>(p);
    unmap_column_memory(m->memory, m->bytes);
    delete m;
  });
  return py::array_t<T>({static_cast<py::ssize_t>(rows)}, {static_cast<py::ssize_t>(sizeof(T))},
                        static_cast<T*>(mapping->memory), owner);
}

// A 1-D object column of `rows` null cells, in huge-page memory from kHugeColumnBytes on. The
// array does not own that memory (a capsule does), and numpy releases the cells of owned memory
// only: the capsule releases them when the last view goes.
py::array new_object_column(std::size_t rows);

}  // namespace rastrace::python
