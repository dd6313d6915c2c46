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

TEST(Table, SeveralTablesShareOneJsonArray) {
  const Table tables[] = {sample_table(), sample_table()};
  EXPECT_EQ(nlohmann::json::parse(render_tables(tables, TableFormat::Json)).size(), 4u);
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
