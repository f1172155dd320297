// The report model: every part of the results (REPORT.md, results/report/<experiment>.md, the
// pages of results/site/) is a list of sections, each holding its content as data (tables as
// typed rows, plots as series) and rendered by one of two renderers, markdown or HTML. A section
// is built once; nothing renders the same content twice.
//
//   Section  id, title, blocks
//   Block    Heading | Text (inline markdown, lists) | Table (cells with their numbers) |
//            Plot (series of points; a PNG of it for markdown when gnuplot rendered one)
#pragma once

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "core/text.h"

namespace curvbench::report {

/// One table cell: its text (inline markdown) and, when it shows a number, the number (sorting
/// and "best" marks on the site). `href` makes the cell a link.
struct Cell {
  std::string text;
  double value = std::nan("");
  std::string href;
  bool best = false;    ///< the best value of its column (bold in markdown, marked on the site)
  bool strong = false;  ///< emphasised (bold in markdown and on the site)

  Cell() = default;
  Cell(std::string t) : text(std::move(t)) {}  // NOLINT: a plain string is a text cell
  Cell(const char* t) : text(t) {}             // NOLINT
  static Cell number(double v, std::string shown) {
    Cell c(std::move(shown));
    c.value = v;
    return c;
  }
  static Cell link(std::string shown, std::string target) {
    Cell c(std::move(shown));
    c.href = std::move(target);
    return c;
  }
};

struct Table {
  std::string id;       ///< anchor on the site ("" = none)
  std::string caption;  ///< inline markdown above the table ("" = none)
  std::vector<std::string> columns;
  std::vector<std::vector<Cell>> rows;
  bool sortable = false;  ///< the site lets a reader sort by any column
  /// Which columns are numbers (right-aligned); empty = every column but the first.
  std::vector<bool> numeric;

  Table& add(std::vector<Cell> row) {
    rows.push_back(std::move(row));
    return *this;
  }
};

/// A point of a plot; `note` is shown on hover (level, vertices, case).
struct Point {
  double x = 0.0, y = 0.0;
  std::string note;
};

struct Series {
  std::string label;
  std::vector<Point> points;
  std::string color;         ///< "#rrggbb" (plot_styles.h), "" = the renderer's choice
  int marker = 7;            ///< gnuplot point type (plot_styles.h); 0 = no markers
  int dash = 1;              ///< gnuplot dash type: 1 solid, 2 dashed, 3 dotted, ...
  bool points_only = false;  ///< a scatter series (no line between the points)
};

struct Plot {
  std::string id;  ///< unique on its page
  std::string title;
  std::string x_label = "mean edge length h";
  std::string y_label = "error";
  bool log_x = true, log_y = true;
  bool reverse_x = true;  ///< h decreasing to the right
  std::vector<Series> series;
  /// A PNG of the same plot for the markdown renderer (relative to the markdown file), "" = none.
  std::string image;
};

struct Heading {
  int level = 3;  ///< relative: 1 = the section's own sub-heading level
  std::string text;
};

/// Inline markdown: paragraphs separated by blank lines, "- " list items, `code`, **bold**,
/// *italic*, [links](target) and ![images](src).
struct Text {
  std::string markdown;
};

using Block = std::variant<Heading, Text, Table, Plot>;

struct Section {
  std::string id;  ///< anchor and, for an experiment, the file name of its page
  std::string title;
  std::vector<Block> blocks;

  Section& heading(std::string text, int level = 1) {
    blocks.emplace_back(Heading{level, std::move(text)});
    return *this;
  }
  Section& text(std::string markdown) {
    if (!markdown.empty()) blocks.emplace_back(Text{std::move(markdown)});
    return *this;
  }
  Section& table(Table t) {
    blocks.emplace_back(std::move(t));
    return *this;
  }
  Section& plot(Plot p) {
    blocks.emplace_back(std::move(p));
    return *this;
  }
};

/// Markdown of a section; its title is a heading of `level` (2 = "##"), its headings below it.
/// A plot's image path (relative to the results folder) is prefixed with `image_prefix` (e.g.
/// "../" for a file in results/report/).
std::string to_markdown(const Section& section, int level = 2,
                        const std::string& image_prefix = "");

/// How links are rewritten for the site: a link to "<x>.md" of the report folder becomes the
/// page that renders it.
struct HtmlOptions {
  int level = 2;
  /// Maps a markdown link target to its site target ("" = drop the link, keep the text).
  std::string (*link)(const std::string& target) = nullptr;
};

/// HTML of a section (a <section> element). Plots become <canvas> elements with a
/// data-plot attribute naming their id; their data is written by plots_json().
std::string to_html(const Section& section, const HtmlOptions& options = {});

/// The plots of the sections as one JSON object {id: {title, x, y, logx, logy, reverse,
/// series: [{label, color, marker, dash, points_only, data: [[x, y, note], ...]}]}}.
std::string plots_json(const std::vector<Section>& sections);

/// Inline markdown of a Text block as HTML (escaped; links rewritten by `link` if given).
std::string markdown_to_html(const std::string& markdown,
                             std::string (*link)(const std::string&) = nullptr);

/// Text escaped for HTML element content and attribute values.
std::string escape_html(const std::string& s);
// JSON strings and numbers: core/text.h json_string, json_number.
using curvbench::json_number;
using curvbench::json_string;

}  // namespace curvbench::report
