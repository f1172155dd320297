// docs/cli.md and docs/methods.md carry the option table as option_table_markdown() writes it,
// between their marker lines, so that neither can drift from include/curvbench/estimator_options.h
// (`curvbench methods --options --markdown flags|spellings` prints the text to paste).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "methods/option_schema.h"

namespace curvbench {
namespace {

std::string between_markers(const std::string& doc_name, const std::string& what) {
  std::ifstream in(std::string(CURVBENCH_SOURCE_DIR) + "/docs/" + doc_name);
  EXPECT_TRUE(in) << doc_name;
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string begin = "<!-- " + what + ": begin -->\n", end = "<!-- " + what + ": end -->";
  const auto a = doc.find(begin), b = doc.find(end);
  EXPECT_NE(a, std::string::npos) << doc_name << " lacks " << begin;
  EXPECT_NE(b, std::string::npos) << doc_name << " lacks " << end;
  if (a == std::string::npos || b == std::string::npos || b < a) return "";
  return doc.substr(a + begin.size(), b - a - begin.size());
}

TEST(OptionDocs, CliMdCarriesTheFlagsTable) {
  EXPECT_EQ(between_markers("cli.md", "option table"),
            option_table_markdown(OptionTableStyle::flags))
      << "regenerate: build/curvbench methods --options --markdown flags";
}

TEST(OptionDocs, MethodsMdCarriesTheSpellingsTable) {
  EXPECT_EQ(between_markers("methods.md", "option spellings"),
            option_table_markdown(OptionTableStyle::spellings))
      << "regenerate: build/curvbench methods --options --markdown spellings";
}

// Every option appears in both tables, each flag once, and a '|' inside a cell is escaped (a
// raw one would split the row).
TEST(OptionDocs, EveryOptionHasOneRowWithItsCellsIntact) {
  for (const OptionTableStyle style : {OptionTableStyle::flags, OptionTableStyle::spellings}) {
    const std::string md = option_table_markdown(style);
    const size_t columns = style == OptionTableStyle::flags ? 4 : 5;
    size_t rows = 0, pos = 0;
    while ((pos = md.find('\n', pos)) != std::string::npos) ++rows, ++pos;
    EXPECT_EQ(rows, estimator_option_schema().size() + 2);
    size_t start = 0;
    while (start < md.size()) {
      const size_t nl = md.find('\n', start);
      const std::string line = md.substr(start, nl - start);
      size_t bars = 0;
      for (size_t i = 0; i < line.size(); ++i)
        if (line[i] == '|' && (i == 0 || line[i - 1] != '\\')) ++bars;
      EXPECT_EQ(bars, columns + 1) << line;
      start = nl + 1;
    }
    for (const OptionInfo& o : estimator_option_schema())
      EXPECT_NE(md.find(o.name), std::string::npos) << o.name;
  }
}

}  // namespace
}  // namespace curvbench
