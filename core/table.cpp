#include "core/table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/enum_names.h"

namespace rastrace {

namespace {

constexpr EnumName<TableFormat> kTableFormats[] = {{TableFormat::Markdown, "md"},
                                                   {TableFormat::Csv, "csv"},
                                                   {TableFormat::Latex, "latex"},
                                                   {TableFormat::Json, "json"},
                                                   {TableFormat::Markdown, "markdown"}};

}  // namespace

TableFormat parse_table_format(const std::string& text) { return parse_enum(text, kTableFormats, "table format"); }

void Table::add_row(std::vector<TableCell> row) {
  if (row.size() != columns.size())
    throw std::logic_error("table '" + title + "': row of " + std::to_string(row.size()) + " cells for " +
                           std::to_string(columns.size()) + " columns");
  rows.push_back(std::move(row));
}

namespace {

std::string format_number(double number, int precision) {
  if (std::isnan(number)) return "nan";
  if (std::isinf(number)) return number > 0 ? "inf" : "-inf";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", precision, number);
  return buffer;
}

std::string cell_text(const TableCell& cell, int precision) {
  if (const auto* text = std::get_if<std::string>(&cell.value)) return *text;
  if (const auto* integer = std::get_if<std::int64_t>(&cell.value)) return std::to_string(*integer);
  if (const auto* number = std::get_if<double>(&cell.value)) return format_number(*number, precision);
  return "";
}

bool is_numeric(const TableCell& cell) { return !std::holds_alternative<std::string>(cell.value); }

nlohmann::ordered_json cell_json(const TableCell& cell) {
  if (const auto* text = std::get_if<std::string>(&cell.value)) return *text;
  if (const auto* integer = std::get_if<std::int64_t>(&cell.value)) return *integer;
  if (const auto* number = std::get_if<double>(&cell.value)) {
    if (std::isfinite(*number)) return *number;
  }
  return nullptr;
}

const std::string& heading_of(const TableColumn& column) {
  return column.heading.empty() ? column.key : column.heading;
}

std::string csv_escape(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  quoted += '"';
  return quoted;
}

std::string latex_escape(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
      case '_':
      case '%':
      case '&':
      case '#':
      case '$':
      case '{':
      case '}':
        escaped += '\\';
        escaped += c;
        break;
      case '~':
        escaped += "\\textasciitilde{}";
        break;
      case '^':
        escaped += "\\textasciicircum{}";
        break;
      case '\\':
        escaped += "\\textbackslash{}";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

std::string markdown(const Table& table) {
  std::string out = "## " + table.title + "\n\n";
  for (const auto& [key, value] : table.parameters) out += "- " + key + ": " + cell_text(value, 6) + "\n";
  if (!table.parameters.empty()) out += "\n";
  std::string header = "|", rule = "|";
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    header += " " + heading_of(table.columns[c]) + " |";
    const bool numeric = !table.rows.empty() && is_numeric(table.rows.front()[c]);
    rule += numeric ? " ---: |" : " --- |";
  }
  out += header + "\n" + rule + "\n";
  for (const auto& row : table.rows) {
    out += "|";
    for (std::size_t c = 0; c < row.size(); ++c) out += " " + cell_text(row[c], table.columns[c].precision) + " |";
    out += "\n";
  }
  return out;
}

std::string csv(const Table& table) {
  std::string out = "# " + table.title + "\n";
  if (!table.kind.empty()) out += "# kind: " + table.kind + "\n";
  for (const auto& [key, value] : table.parameters) out += "# " + key + ": " + cell_text(value, 6) + "\n";
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (c) out += ',';
    out += csv_escape(table.columns[c].key);
  }
  out += "\n";
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      // CSV is for machines: full precision for floating-point cells.
      const int precision = std::holds_alternative<double>(row[c].value) ? 9 : table.columns[c].precision;
      if (c) out += ',';
      out += csv_escape(cell_text(row[c], precision));
    }
    out += "\n";
  }
  return out;
}

std::string latex(const Table& table) {
  std::string out = "% " + table.title + "\n";
  for (const auto& [key, value] : table.parameters) out += "% " + key + ": " + cell_text(value, 6) + "\n";
  out += "\\begin{tabular}{";
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const bool numeric = !table.rows.empty() && is_numeric(table.rows.front()[c]);
    out += numeric ? "r" : "l";
  }
  out += "}\n\\toprule\n";
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (c) out += " & ";
    out += latex_escape(heading_of(table.columns[c]));
  }
  out += " \\\\\n\\midrule\n";
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) out += " & ";
      out += latex_escape(cell_text(row[c], table.columns[c].precision));
    }
    out += " \\\\\n";
  }
  out += "\\bottomrule\n\\end{tabular}\n";
  return out;
}

void append_json_rows(const Table& table, nlohmann::ordered_json& rows) {
  for (const auto& row : table.rows) {
    nlohmann::ordered_json object = nlohmann::ordered_json::object();
    if (!table.kind.empty()) object["kind"] = table.kind;
    for (std::size_t c = 0; c < row.size(); ++c) object[table.columns[c].key] = cell_json(row[c]);
    for (const auto& [key, value] : table.parameters)
      if (!object.contains(key)) object[key] = cell_json(value);
    rows.push_back(std::move(object));
  }
}

// The keys of a table's JSON rows, in order.
std::vector<std::string> json_keys(const Table& table) {
  std::vector<std::string> keys;
  for (const TableColumn& column : table.columns) keys.push_back(column.key);
  for (const auto& [key, value] : table.parameters)
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  return keys;
}

// One schema per kind: a consumer splitting the rows by "kind" gets tables of fixed keys.
void check_kinds(std::span<const Table> tables) {
  std::map<std::string, std::vector<std::string>> keys_of_kind;
  for (const Table& table : tables) {
    if (table.kind.empty()) {
      if (tables.size() > 1)
        throw std::logic_error("table '" + table.title + "' has no kind in an output of several tables");
      continue;
    }
    const std::vector<std::string> keys = json_keys(table);
    if (std::find(keys.begin(), keys.end(), "kind") != keys.end())
      throw std::logic_error("table '" + table.title + "' has a kind and a column or parameter named kind");
    const auto [it, inserted] = keys_of_kind.emplace(table.kind, keys);
    if (!inserted && it->second != keys)
      throw std::logic_error("tables of kind '" + table.kind + "' with different keys ('" + table.title + "')");
  }
}

}  // namespace

std::string render_tables(std::span<const Table> tables, TableFormat format) {
  check_kinds(tables);
  if (format == TableFormat::Json) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const Table& table : tables) append_json_rows(table, rows);
    return rows.dump(2) + "\n";
  }
  std::string out;
  for (const Table& table : tables) {
    if (!out.empty()) out += "\n";
    switch (format) {
      case TableFormat::Markdown:
        out += markdown(table);
        break;
      case TableFormat::Csv:
        out += csv(table);
        break;
      case TableFormat::Latex:
        out += latex(table);
        break;
      case TableFormat::Json:
        break;
    }
  }
  return out;
}

std::string render_table(const Table& table, TableFormat format) {
  return render_tables(std::span<const Table>(&table, 1), format);
}

}  // namespace rastrace
