// The report model (harness/report/model.h): one section, two renderers. The markdown and the
// HTML of a section carry the same cells, links and best marks; text is escaped; JSON numbers are
// shortest round-trip and non-finite ones null.
#include <gtest/gtest.h>

#include <string>

#include "harness/report/model.h"

namespace curvbench::report {
namespace {

Section sample() {
  Section s{"sample", "A sample", {}};
  s.heading("Sub");
  s.text("Some `code`, **bold** and a [link](report/fig03-05.md).\n- one\n- two");
  Table t;
  t.id = "t";
  t.columns = {"method", "error"};
  Cell best = Cell::number(1e-3, "1.00e-03");
  best.best = true;
  t.add({"LHF-2", best}).add({Cell::link("a|b", "x.md"), Cell::number(2e-3, "2.00e-03")});
  s.table(t);
  Plot p;
  p.id = "plot-1";
  p.title = "T";
  p.series.push_back({"LHF-2", {{0.5, 1e-3, "level 1"}, {0.25, 2.5e-4, "level 2"}}, "#ff0000"});
  s.plot(p);
  return s;
}

TEST(ReportModel, MarkdownRendersEveryBlock) {
  const std::string md = to_markdown(sample());
  EXPECT_NE(md.find("## A sample\n"), std::string::npos);
  EXPECT_NE(md.find("### Sub\n"), std::string::npos);
  EXPECT_NE(md.find("| method | error |\n|---|---:|\n"), std::string::npos);
  EXPECT_NE(md.find("| LHF-2 | **1.00e-03** |"), std::string::npos);
  EXPECT_NE(md.find("| [a\\|b](x.md) | 2.00e-03 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("plot-1"), std::string::npos) << "a plot without a PNG shows nothing";
  Section with_image = sample();
  std::get<Plot>(with_image.blocks.back()).image = "plots/p.png";
  EXPECT_NE(
      to_markdown(with_image, 2, "../").find("![plot-1](../plots/p.png) ([svg](../plots/p.svg))"),
      std::string::npos);
}

TEST(ReportModel, HtmlRendersTheSameCells) {
  const std::string html = to_html(sample());
  EXPECT_NE(html.find("<section id=\"sample\">"), std::string::npos);
  EXPECT_NE(html.find("<h2>A sample</h2>"), std::string::npos);
  EXPECT_NE(html.find("<h3>Sub</h3>"), std::string::npos);
  EXPECT_NE(html.find("<code>code</code>"), std::string::npos);
  EXPECT_NE(html.find("<strong>bold</strong>"), std::string::npos);
  EXPECT_NE(html.find("<li>one</li>\n<li>two</li>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num best\" data-value=\"0.001\">1.00e-03</td>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<a href=\"x.md\">a|b</a>"), std::string::npos);
  EXPECT_NE(html.find("<canvas data-plot=\"plot-1\""), std::string::npos);
  // Links are rewritten by the site's map.
  HtmlOptions o;
  o.link = [](const std::string& t) {
    return t == "report/fig03-05.md" ? std::string("exp.html") : std::string();
  };
  const std::string site = to_html(sample(), o);
  EXPECT_NE(site.find("<a href=\"exp.html\">link</a>"), std::string::npos);
  EXPECT_EQ(site.find("x.md"), std::string::npos) << "a link the map drops keeps its text only";
}

TEST(ReportModel, HtmlEscapesText) {
  Section s;
  s.text("a <script> & \"quote\"");
  const std::string html = to_html(s);
  EXPECT_NE(html.find("a &lt;script&gt; &amp; &quot;quote&quot;"), std::string::npos);
  EXPECT_EQ(html.find("<script>"), std::string::npos);
}

TEST(ReportModel, MarkdownTablesInTextBecomeHtmlTables) {
  const std::string html = markdown_to_html("| a | b |\n|---|---:|\n| x | 1 |\n");
  EXPECT_NE(html.find("<tr><th>a</th><th class=\"num\">b</th></tr>"), std::string::npos) << html;
  EXPECT_NE(html.find("<tr><td>x</td><td class=\"num\">1</td></tr>"), std::string::npos);
}

TEST(ReportModel, NestedListsNest) {
  const std::string html = markdown_to_html("- a\n- b:\n  - b1\n  - b2\n- c\n");
  EXPECT_EQ(html,
            "<ul>\n<li>a</li>\n<li>b:\n<ul>\n<li>b1</li>\n<li>b2</li>\n</ul></li>\n"
            "<li>c</li>\n</ul>\n");
}

TEST(ReportModel, JsonOfPlots) {
  EXPECT_EQ(json_number(0.1), "0.1");
  EXPECT_EQ(json_number(1e-300), "1e-300");
  EXPECT_EQ(json_number(std::nan("")), "null");
  EXPECT_EQ(json_string("a\"b\\c</script>"), "\"a\\\"b\\\\c<\\/script>\"");
  const std::string json = plots_json({sample()});
  EXPECT_NE(json.find("\"plot-1\":{\"title\":\"T\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"data\":[[0.5,0.001,\"level 1\"],[0.25,0.00025,\"level 2\"]]"),
            std::string::npos)
      << json;
}

}  // namespace
}  // namespace curvbench::report
