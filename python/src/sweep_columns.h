// A byte-cache sweep's result as numpy columns, written by the sweep's worker threads as each
// job's rows are done (cache_sim/sweep.h, SweepRowSink) and handed to numpy without a copy.
//
// Converting the rows after the sweep meant a second pass over them (a SweepRow is about 180
// bytes: 180 MB for 10^6 rows, long out of the CPU caches) and 100 MB of fresh column memory to
// touch: 50-130 ms of CPU for 10^6 rows on the virtual machine of docs/PERFORMANCE.md. Here each
// row is copied into the columns while the worker that finished it still has it in its cache,
// and what remains after the sweep is wrapping the buffers, independent of the number of rows.
//
// The text columns (policy, layout) hold one Python string per distinct value, as the JSON
// output's text. The workers run without the GIL, so they write the cells' pointers and count
// them; release() then adds the counted references to each string at once.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "cache_sim/sweep.h"
#include "column_memory.h"

namespace rastrace::python {

namespace py = pybind11;

class SweepColumns final : public SweepRowSink {
 public:
  // GIL held: the Python strings of the spec's policies and layouts.
  explicit SweepColumns(const SweepSpec& spec);

  void begin(std::size_t rows) override;
  void done(const SweepRows& rows, const std::vector<std::size_t>& indices) override;

  std::size_t rows() const { return rows_; }
  // GIL held, once, after the sweep: the columns keyed like byte_cache_table (experiments/
  // cache_report.h), in its order; without compulsory, capacity and conflict unless every row
  // has them (the JSON output has nulls there).
  py::dict release();

 private:
  // The int64 columns, in the order of byte_cache_table; miss_rate (float64) goes between
  // misses and bytes_fetched.
  enum Integer { Size, Line, Assoc, Accesses, Hits, Misses, BytesFetched, Compulsory, Capacity, Conflict, kIntegers };

  std::size_t rows_ = 0;
  bool released_ = false;
  std::array<ColumnMemory, kIntegers> integers_;
  ColumnMemory miss_rate_, policy_cells_, layout_cells_;
  // Text cells by ReplacementPolicy and by SweepRow::layout_index; equal names share one object.
  std::array<py::object, 4> policy_strings_;
  std::vector<py::object> layout_strings_;
  // References the cells hold, counted by the workers, given to the strings in release().
  std::array<std::atomic<std::size_t>, 4> policy_references_{};
  std::vector<std::atomic<std::size_t>> layout_references_;
  std::atomic<bool> three_c_{true};
};

}  // namespace rastrace::python
