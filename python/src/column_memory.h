// Memory for the columns of large results (a sweep of 10^6 rows: 8 MB per column).
//
// A fresh page costs a fault at its first touch, and a 4 KiB fault is expensive (about 14 us on
// the virtual machine of docs/PERFORMANCE.md, "Python": 100 MB of columns took 380 ms of faults).
// numpy advises transparent huge pages for its large arrays, but it gets them from malloc, whose
// large blocks are mappings aligned to 4 KiB only: a 2 MiB page fits only where a whole aligned
// 2 MiB range lies inside, and the rest of each 8 MB column still faults page by page. A column
// here is its own mapping, aligned to 2 MiB and rounded up to it, advised MADV_HUGEPAGE: with
// transparent huge pages on ("always" or "madvise"), four faults fill an 8 MB column.
//
// The memory is taken without the GIL (a sweep's worker threads fill it as rows finish,
// sweep_columns.h) and handed to numpy afterwards without a copy.
#pragma once

#include <cstddef>

#include <pybind11/numpy.h>

namespace rastrace::python {

namespace py = pybind11;

// Below this size a column is ordinary heap memory: a 2 MiB granule would waste too much.
inline constexpr std::size_t kHugeColumnBytes = std::size_t{4} << 20;

// Zero-filled memory for one column, owned until handed to numpy; needs no GIL.
class ColumnMemory {
 public:
  ColumnMemory() = default;
  // `bytes` of zeros: from kHugeColumnBytes on a mapping of its own (rounded up to 2 MiB,
  // 2 MiB-aligned, advised for huge pages: core/huge_page_allocator.h), below that from the
  // heap. Throws std::bad_alloc.
  explicit ColumnMemory(std::size_t bytes);
  ColumnMemory(ColumnMemory&& other) noexcept;
  ColumnMemory& operator=(ColumnMemory&& other) noexcept;
  ~ColumnMemory();

  template <typename T>
  T* as() const {
    return static_cast<T*>(data_);
  }

  // GIL held: a 1-D array of `rows` values over this memory, which the array now owns (through
  // a capsule, freed with the last view).
  template <typename T>
  py::array_t<T> to_array(std::size_t rows) && {
    T* const values = as<T>();
    py::capsule owner = std::move(*this).release_to_capsule(rows, false);
    return py::array_t<T>({static_cast<py::ssize_t>(rows)}, {static_cast<py::ssize_t>(sizeof(T))}, values, owner);
  }
  // GIL held: a 1-D object array of `rows` cells (each a reference the array now owns, or null).
  // numpy releases the cells of memory it allocated only: the capsule releases these when the
  // last view goes.
  py::array to_object_array(std::size_t rows) &&;

 private:
  py::capsule release_to_capsule(std::size_t rows, bool object_cells) &&;
  void free() noexcept;

  void* data_ = nullptr;
  std::size_t bytes_ = 0;
  bool mapped_ = false;
};

// An uninitialized 1-D column of `rows` values (zeros, in fact), in huge-page memory from
// kHugeColumnBytes on.
template <typename T>
py::array_t<T> new_column(std::size_t rows) {
  return ColumnMemory(rows * sizeof(T)).to_array<T>(rows);
}

// A 1-D object column of `rows` null cells, in huge-page memory from kHugeColumnBytes on.
py::array new_object_column(std::size_t rows);

}  // namespace rastrace::python
