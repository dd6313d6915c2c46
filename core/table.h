// Result tables as papers print them: Markdown, CSV, LaTeX (booktabs) or JSON.
// Every table carries the parameters that produced it; each format states them:
//   md: a bullet list under the title; csv: "# key: value" comment lines; latex: "% key: value"
//   comments; json: every row object also holds the parameters (rows are self-describing).
// Output is deterministic: the same table renders to the same bytes.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace rastrace {

enum class TableFormat { Markdown, Csv, Latex, Json };

// "md" (or "markdown"), "csv", "latex", "json"; throws InputError otherwise.
TableFormat parse_table_format(const std::string& text);

struct TableCell {
  std::variant<std::monostate, std::string, std::int64_t, double> value;

  TableCell() = default;
  TableCell(std::string text) : value(std::move(text)) {}
  TableCell(const char* text) : value(std::string(text)) {}
  TableCell(double number) : value(number) {}
  TableCell(float number) : value(static_cast<double>(number)) {}
  template <typename Integer>
  requires std::is_integral_v<Integer> TableCell(Integer number) : value(static_cast<std::int64_t>(number)) {}

  bool operator==(const TableCell&) const = default;
};

struct TableColumn {
  std::string key;      // JSON key and CSV header: snake_case ("miss_rate")
  std::string heading;  // Markdown/LaTeX heading ("miss rate"); the key when empty
  int precision = 3;    // digits after the point for floating-point cells (text formats)
};

struct Table {
  std::string title;
  // What one row is, in snake_case ("texture_cache", "frame_traffic"): each JSON row carries it as
  // "kind", so that an output of several tables splits into one schema per kind. Every table of
  // such an output must have one, and tables of one kind the same keys.
  std::string kind;
  std::vector<std::pair<std::string, TableCell>> parameters;  // stated in every format
  std::vector<TableColumn> columns;
  std::vector<std::vector<TableCell>> rows;  // each row has one cell per column

  void add_row(std::vector<TableCell> row);  // throws std::logic_error on a wrong cell count
};

// Several tables in one output: text formats separate them by a blank line (CSV states each
// table's kind in its comment lines); JSON gives one array holding every table's rows, each with
// its table's "kind". Throws std::logic_error when several tables lack a kind, or when two tables
// of one kind have different keys.
std::string render_tables(std::span<const Table> tables, TableFormat format);
std::string render_table(const Table& table, TableFormat format);

}  // namespace rastrace
