#include "experiments/sweep_parts.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/json_integer.h"

namespace rastrace {

namespace {

using Json = nlohmann::ordered_json;
constexpr int kPartFormat = 1;

// JSON has no NaN or infinity; those doubles travel as {"double": "nan"}.
Json cell_to_json(const TableCell& cell) {
  return std::visit(
      [](const auto& v) -> Json {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>) {
          return nullptr;
        } else if constexpr (std::is_same_v<T, double>) {
          if (std::isfinite(v)) return v;
          return Json{{"double", std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf"}};
        } else {
          return v;
        }
      },
      cell.value);
}

TableCell cell_from_json(const Json& j) {
  if (j.is_null()) return {};
  if (j.is_string()) return j.get<std::string>();
  if (j.is_number_integer()) return j.get<std::int64_t>();
  if (j.is_number_float()) return j.get<double>();
  if (j.is_object() && j.size() == 1 && j.contains("double")) {
    const std::string text = j.at("double").get<std::string>();
    if (text == "nan") return std::nan("");
    if (text == "inf") return HUGE_VAL;
    if (text == "-inf") return -HUGE_VAL;
  }
  throw InputError("a table cell: expected null, a string, a number or {\"double\": \"nan\"|\"inf\"|\"-inf\"}");
}

Json table_to_json(const Table& table, const std::vector<std::size_t>& configurations) {
  Json parameters = Json::array(), columns = Json::array(), rows = Json::array();
  for (const auto& [key, value] : table.parameters) parameters.push_back(Json::array({key, cell_to_json(value)}));
  for (const TableColumn& c : table.columns)
    columns.push_back({{"key", c.key}, {"heading", c.heading}, {"precision", c.precision}});
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    Json cells = Json::array();
    for (const TableCell& cell : table.rows[r]) cells.push_back(cell_to_json(cell));
    rows.push_back({{"configuration", configurations[r]}, {"cells", cells}});
  }
  return {{"title", table.title}, {"parameters", parameters}, {"columns", columns}, {"rows", rows}};
}

}  // namespace

std::string sweep_part_json(const SweepPart& part) {
  const Json j = {{"rastrace_sweep_part", kPartFormat},
                  {"version", part.version},
                  {"trace_digest", part.trace_digest},
                  {"configuration", part.configuration},
                  {"shard", part.shard.index},
                  {"shards", part.shard.count},
                  {"configurations", part.configurations},
                  {"skipped", part.skipped},
                  {"table", table_to_json(part.table, part.row_configurations)}};
  return j.dump(1) + "\n";
}

SweepPart read_sweep_part(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_in_file(path, "cannot open for reading");
  std::string key = "(the document)";
  try {
    const Json j = Json::parse(in, nullptr, true, false);
    const auto at = [&](const Json& object, const char* name) -> const Json& {
      key = name;
      if (!object.is_object() || !object.contains(name)) throw InputError("missing");
      return object.at(name);
    };
    if (json_integer<int>(at(j, "rastrace_sweep_part"), "rastrace_sweep_part") != kPartFormat)
      throw InputError("expected part format " + std::to_string(kPartFormat));
    SweepPart part;
    part.version = at(j, "version").get<std::string>();
    part.trace_digest = at(j, "trace_digest").get<std::string>();
    part.configuration = at(j, "configuration").get<std::string>();
    part.shard.index = json_integer<std::uint32_t>(at(j, "shard"), "shard");
    part.shard.count = json_integer<std::uint32_t>(at(j, "shards"), "shards");
    if (part.shard.index < 1 || part.shard.index > part.shard.count) throw InputError("expected 1 <= shard <= shards");
    part.configurations = json_integer<std::size_t>(at(j, "configurations"), "configurations");
    part.skipped = at(j, "skipped").get<std::vector<std::string>>();
    const Json& table = at(j, "table");
    part.table.title = at(table, "title").get<std::string>();
    for (const Json& p : at(table, "parameters")) {
      key = "table.parameters";
      part.table.parameters.emplace_back(p.at(0).get<std::string>(), cell_from_json(p.at(1)));
    }
    for (const Json& c : at(table, "columns"))
      part.table.columns.push_back(
          {at(c, "key").get<std::string>(), at(c, "heading").get<std::string>(), json_integer<int>(at(c, "precision"), "precision")});
    for (const Json& r : at(table, "rows")) {
      const std::size_t configuration = json_integer<std::size_t>(at(r, "configuration"), "configuration");
      if (configuration >= part.configurations) throw InputError("expected a configuration below configurations");
      std::vector<TableCell> cells;
      for (const Json& cell : at(r, "cells")) cells.push_back(cell_from_json(cell));
      key = "table.rows";
      if (cells.size() != part.table.columns.size()) throw InputError("expected one cell per column");
      part.table.rows.push_back(std::move(cells));
      part.row_configurations.push_back(configuration);
    }
    return part;
  } catch (const nlohmann::json::exception& e) {
    throw_in_file(path, "not a sweep part (" + key + "): " + std::string(e.what()).substr(0, 200));
  } catch (const InputError& e) {
    throw_in_file(path, "sweep part, key " + key + ": " + e.what());
  }
}

namespace {

// A sampled sweep's `method` says how its own rows were found, so two shards of one sweep may
// state different ones: it is left out of the comparison and stated again for the merged rows.
constexpr const char* kMethod = "method";

using Parameters = std::vector<std::pair<std::string, TableCell>>;

Parameters without_method(const Parameters& parameters) {
  Parameters out;
  for (const auto& parameter : parameters)
    if (parameter.first != kMethod) out.push_back(parameter);
  return out;
}

// The method of the merged rows, from their estimated_by column (as sweep_method states it).
void restate_method(Table& table) {
  const auto column = std::find_if(table.columns.begin(), table.columns.end(),
                                   [](const TableColumn& c) { return c.key == "estimated_by"; });
  const auto parameter = std::find_if(table.parameters.begin(), table.parameters.end(),
                                      [](const auto& p) { return p.first == kMethod; });
  if (column == table.columns.end() || parameter == table.parameters.end()) return;
  const std::size_t c = static_cast<std::size_t>(column - table.columns.begin());
  bool estimated = false, simulated = false;
  for (const auto& row : table.rows) (row[c] == TableCell("exact") ? simulated : estimated) = true;
  parameter->second = sweep_method(estimated, simulated);
}

}  // namespace

MergedSweep merge_sweep_parts(const std::vector<SweepPart>& parts, const std::vector<std::string>& paths) {
  if (parts.empty()) throw InputError("merge: expected at least one part");
  const SweepPart& first = parts.front();
  const auto differs = [&](std::size_t i, const std::string& what, const std::string& a, const std::string& b) {
    throw InputError("merge: " + paths[i] + " has " + what + " " + b + ", " + paths[0] + " has " + a +
                     ": parts of different sweeps cannot be merged");
  };
  std::map<std::uint32_t, std::size_t> shards;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const SweepPart& p = parts[i];
    if (p.version != first.version) differs(i, "version", first.version, p.version);
    if (p.trace_digest != first.trace_digest) differs(i, "trace digest", first.trace_digest, p.trace_digest);
    if (p.configuration != first.configuration) differs(i, "configuration", first.configuration, p.configuration);
    if (p.shard.count != first.shard.count)
      differs(i, "shard count", std::to_string(first.shard.count), std::to_string(p.shard.count));
    if (p.configurations != first.configurations || p.table.title != first.table.title ||
        p.table.columns.size() != first.table.columns.size())
      differs(i, "a configuration set of", std::to_string(first.configurations), std::to_string(p.configurations));
    if (without_method(p.table.parameters) != without_method(first.table.parameters))
      throw InputError("merge: " + paths[i] + " and " + paths[0] + " state different parameters");
    const auto [at, inserted] = shards.emplace(p.shard.index, i);
    if (!inserted)
      throw InputError("merge: " + paths[at->second] + " and " + paths[i] + " are both shard " +
                       std::to_string(p.shard.index) + "/" + std::to_string(p.shard.count));
  }
  if (shards.size() != first.shard.count) {
    std::string missing;
    for (std::uint32_t k = 1; k <= first.shard.count; ++k)
      if (!shards.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    throw InputError("merge: shards " + missing + " of " + std::to_string(first.shard.count) + " are missing");
  }

  MergedSweep merged;
  merged.table.title = first.table.title;
  merged.table.parameters = first.table.parameters;
  merged.table.columns = first.table.columns;
  std::vector<std::pair<std::size_t, const std::vector<TableCell>*>> rows;
  for (const SweepPart& p : parts) {
    for (std::size_t r = 0; r < p.table.rows.size(); ++r) {
      if (!p.shard.owns(p.row_configurations[r]))
        throw InputError("merge: shard " + std::to_string(p.shard.index) + " holds configuration " +
                         std::to_string(p.row_configurations[r]) + ", which belongs to another shard");
      rows.emplace_back(p.row_configurations[r], &p.table.rows[r]);
    }
  }
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [configuration, cells] : rows) merged.table.rows.push_back(*cells);
  restate_method(merged.table);
  // Each part lists the impossible combinations it owns; they are told shard by shard.
  for (std::uint32_t k = 1; k <= first.shard.count; ++k)
    for (const std::string& s : parts[shards[k]].skipped) merged.skipped.push_back(s);
  return merged;
}

}  // namespace rastrace
