#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/table.h"

namespace rastrace {
namespace {

Table sample_table() {
  Table table;
  table.title = "vertex cache";
  table.parameters = {{"mesh", "fandisk.off"}, {"policy", "fifo"}};
  table.columns = {{"algo", "algorithm", 3}, {"cache", "", 0}, {"acmr", "ACMR", 3}};
  table.add_row({"tipsy_x", 16, 0.6789});
  table.add_row({"forsyth", 16u, 0.7});
  return table;
}

TEST(Table, MarkdownStatesParametersAndRoundsToColumnPrecision) {
  EXPECT_EQ(render_table(sample_table(), TableFormat::Markdown),
            "## vertex cache\n\n- mesh: fandisk.off\n- policy: fifo\n\n"
            "| algorithm | cache | ACMR |\n| --- | ---: | ---: |\n"
            "| tipsy_x | 16 | 0.679 |\n| forsyth | 16 | 0.700 |\n");
}

TEST(Table, CsvHasParameterCommentsAndFullPrecision) {
  EXPECT_EQ(render_table(sample_table(), TableFormat::Csv),
            "# vertex cache\n# mesh: fandisk.off\n# policy: fifo\nalgo,cache,acmr\n"
            "tipsy_x,16,0.678900000\nforsyth,16,0.700000000\n");
}

TEST(Table, LatexEscapesUnderscoresAndUsesBooktabs) {
  const std::string latex = render_table(sample_table(), TableFormat::Latex);
  EXPECT_NE(latex.find("\\begin{tabular}{lrr}\n\\toprule\nalgorithm & cache & ACMR \\\\\n\\midrule\n"),
            std::string::npos);
  EXPECT_NE(latex.find("tipsy\\_x & 16 & 0.679 \\\\"), std::string::npos);
  EXPECT_NE(latex.find("% policy: fifo"), std::string::npos);
}

TEST(Table, JsonRowsCarryColumnsAndParametersWithTypes) {
  const auto rows = nlohmann::json::parse(render_table(sample_table(), TableFormat::Json));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["algo"], "tipsy_x");
  EXPECT_EQ(rows[0]["cache"], 16);
  EXPECT_DOUBLE_EQ(rows[0]["acmr"].get<double>(), 0.6789);
  EXPECT_EQ(rows[1]["policy"], "fifo");
}

TEST(Table, SeveralTablesShareOneJsonArrayEachRowNamingItsKind) {
  Table first = sample_table(), second = sample_table();
  first.kind = "vertex_cache";
  second.kind = "summary";
  second.columns.push_back({"extra", "", 0});
  for (auto& row : second.rows) row.emplace_back(7);
  const Table tables[] = {first, second};
  const auto rows = nlohmann::ordered_json::parse(render_tables(tables, TableFormat::Json));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].begin().key(), "kind");
  EXPECT_EQ(rows[1]["kind"], "vertex_cache");
  EXPECT_EQ(rows[2]["kind"], "summary");
  EXPECT_FALSE(rows[1].contains("extra"));
  EXPECT_EQ(rows[3]["extra"], 7);
  const std::string csv = render_tables(tables, TableFormat::Csv);
  EXPECT_NE(csv.find("# kind: vertex_cache\n"), std::string::npos);
  EXPECT_NE(csv.find("# kind: summary\n"), std::string::npos);
}

TEST(Table, SeveralTablesWithoutKindsOrOneKindOfTwoSchemasAreRejected) {
  const Table unnamed[] = {sample_table(), sample_table()};
  EXPECT_THROW(render_tables(unnamed, TableFormat::Json), std::logic_error);
  EXPECT_THROW(render_tables(unnamed, TableFormat::Markdown), std::logic_error);
  Table first = sample_table(), second = sample_table();
  first.kind = second.kind = "same";
  EXPECT_NO_THROW(render_tables(std::vector<Table>{first, second}, TableFormat::Json));
  second.parameters.emplace_back("seed", 3);
  EXPECT_THROW(render_tables(std::vector<Table>{first, second}, TableFormat::Json), std::logic_error);
  Table named = sample_table();
  named.kind = "vertex_cache";
  named.parameters.emplace_back("kind", "mine");  // would overwrite the row's kind
  EXPECT_THROW(render_table(named, TableFormat::Json), std::logic_error);
  // One table alone needs no kind: its rows are one schema.
  EXPECT_NO_THROW(render_table(sample_table(), TableFormat::Json));
}

TEST(Table, RowWithWrongCellCountIsRejected) {
  Table table = sample_table();
  EXPECT_THROW(table.add_row({"x"}), std::logic_error);
}

TEST(Table, UnknownFormatNamesTheChoices) {
  try {
    parse_table_format("xml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "unknown table format 'xml': expected md, csv, latex or json");
  }
}

}  // namespace
}  // namespace rastrace
