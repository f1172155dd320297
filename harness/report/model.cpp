#include "harness/report/model.h"

#include <cstdio>
#include <sstream>

#include "core/text.h"

namespace curvbench::report {

namespace {

std::string hashes(int level) {
  return std::string(static_cast<size_t>(level), '#');
}

// A cell in a markdown table: '|' escaped, line breaks removed.
std::string md_cell(const Cell& c) {
  std::string t;
  for (char ch : c.text) {
    if (ch == '|')
      t += "\\|";
    else if (ch == '\n')
      t += ' ';
    else
      t += ch;
  }
  if (!c.href.empty()) t = "[" + t + "](" + c.href + ")";
  if ((c.best || c.strong) && !t.empty()) t = "**" + t + "**";
  return t;
}

bool is_numeric(const Table& t, size_t col) {
  return col < t.numeric.size() ? t.numeric[col] : col > 0;
}

void markdown_table(std::ostringstream& out, const Table& t) {
  if (!t.caption.empty()) out << t.caption << "\n\n";
  out << "|";
  for (const auto& c : t.columns) out << " " << md_cell(Cell(c)) << " |";
  out << "\n|";
  for (size_t i = 0; i < t.columns.size(); ++i) out << (is_numeric(t, i) ? "---:|" : "---|");
  out << "\n";
  for (const auto& row : t.rows) {
    out << "|";
    for (size_t i = 0; i < t.columns.size(); ++i)
      out << " " << (i < row.size() ? md_cell(row[i]) : std::string()) << " |";
    out << "\n";
  }
  out << "\n";
}

std::string link_target(const std::string& target, std::string (*link)(const std::string&)) {
  return link ? link(target) : target;
}

// Inline markdown of one line (already split into blocks) as HTML.
std::string inline_html(const std::string& s, std::string (*link)(const std::string&)) {
  std::string out;
  size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (c == '`') {
      const size_t end = s.find('`', i + 1);
      if (end != std::string::npos) {
        out += "<code>" + escape_html(s.substr(i + 1, end - i - 1)) + "</code>";
        i = end + 1;
        continue;
      }
    } else if (c == '*' && i + 1 < s.size() && s[i + 1] == '*') {
      const size_t end = s.find("**", i + 2);
      if (end != std::string::npos && end > i + 2) {
        out += "<strong>" + inline_html(s.substr(i + 2, end - i - 2), link) + "</strong>";
        i = end + 2;
        continue;
      }
    } else if (c == '*' && i + 1 < s.size() && s[i + 1] != ' ') {
      const size_t end = s.find('*', i + 1);
      if (end != std::string::npos && end > i + 1) {
        out += "<em>" + inline_html(s.substr(i + 1, end - i - 1), link) + "</em>";
        i = end + 1;
        continue;
      }
    } else if ((c == '[' || (c == '!' && i + 1 < s.size() && s[i + 1] == '['))) {
      const bool image = c == '!';
      const size_t open = image ? i + 1 : i;
      const size_t close = s.find("](", open);
      const size_t end = close == std::string::npos ? close : s.find(')', close + 2);
      if (close != std::string::npos && end != std::string::npos && s.find('\n', open) > end) {
        const std::string label = s.substr(open + 1, close - open - 1);
        const std::string target = s.substr(close + 2, end - close - 2);
        if (image) {
          out += "<img src=\"" + escape_html(target) + "\" alt=\"" + escape_html(label) +
                 "\" loading=\"lazy\">";
        } else {
          const std::string to = link_target(target, link);
          out += to.empty()
                     ? inline_html(label, link)
                     : "<a href=\"" + escape_html(to) + "\">" + inline_html(label, link) + "</a>";
        }
        i = end + 1;
        continue;
      }
    } else if (c == '\\' && i + 1 < s.size()) {
      out += escape_html(std::string(1, s[i + 1]));
      i += 2;
      continue;
    }
    out += escape_html(std::string(1, c));
    ++i;
  }
  return out;
}

// Splits a markdown table line "| a | b |" into its cells (escaped '|' kept).
std::vector<std::string> split_row(const std::string& line) {
  std::vector<std::string> cells;
  std::string cur;
  size_t i = line.find('|') + 1;
  for (; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
      cur += '|';
      ++i;
    } else if (line[i] == '|') {
      cells.push_back(cur);
      cur.clear();
    } else {
      cur += line[i];
    }
  }
  for (auto& c : cells) {
    const size_t a = c.find_first_not_of(' ');
    const size_t b = c.find_last_not_of(' ');
    c = a == std::string::npos ? "" : c.substr(a, b - a + 1);
  }
  return cells;
}

}  // namespace

std::string escape_html(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string markdown_to_html(const std::string& markdown, std::string (*link)(const std::string&)) {
  std::istringstream in(markdown);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  std::ostringstream out;
  size_t i = 0;
  const auto starts = [](const std::string& l, const char* p) { return l.rfind(p, 0) == 0; };
  while (i < lines.size()) {
    const std::string& l = lines[i];
    if (l.empty()) {
      ++i;
    } else if (starts(l, "#")) {
      size_t n = 0;
      while (n < l.size() && l[n] == '#') ++n;
      const int level = static_cast<int>(std::min<size_t>(n, 6));
      out << "<h" << level << ">" << inline_html(l.substr(std::min(n + 1, l.size())), link) << "</h"
          << level << ">\n";
      ++i;
    } else if (starts(l, "- ") || starts(l, "* ")) {
      // A list; items indented by two spaces and starting "- " form a nested list of the item
      // before them (one level, as the report writes them); other indented lines continue it.
      out << "<ul>\n";
      bool nested = false;
      while (i < lines.size() &&
             (starts(lines[i], "- ") || starts(lines[i], "* ") || starts(lines[i], "  "))) {
        const bool sub = starts(lines[i], "  - ");
        std::string item = lines[i].substr(sub ? 4 : 2);
        ++i;
        while (i < lines.size() && starts(lines[i], "  ") && !starts(lines[i], "  - "))
          item.append(" ").append(lines[i++], sub ? 4 : 2);
        if (sub && !nested) out << "<ul>\n";
        if (!sub && nested) out << "</ul></li>\n";
        nested = sub;
        out << "<li>" << inline_html(item, link);
        // An item closes at once unless a nested list follows it.
        const bool opens = !sub && i < lines.size() && starts(lines[i], "  - ");
        out << (opens ? "\n" : "</li>\n");
      }
      if (nested) out << "</ul></li>\n";
      out << "</ul>\n";
    } else if (starts(l, "|")) {
      std::vector<std::vector<std::string>> rows;
      std::vector<bool> right;
      while (i < lines.size() && starts(lines[i], "|")) {
        const auto cells = split_row(lines[i]);
        const bool rule = !cells.empty() && cells[0].find("---") != std::string::npos &&
                          cells[0].find_first_not_of("-: ") == std::string::npos;
        if (rule)
          for (const auto& c : cells) right.push_back(!c.empty() && c.back() == ':');
        else
          rows.push_back(cells);
        ++i;
      }
      out << "<div class=\"table-wrap\"><table>\n";
      for (size_t r = 0; r < rows.size(); ++r) {
        out << "<tr>";
        for (size_t c = 0; c < rows[r].size(); ++c) {
          const char* tag = r == 0 ? "th" : "td";
          out << "<" << tag << (c < right.size() && right[c] ? " class=\"num\"" : "") << ">"
              << inline_html(rows[r][c], link) << "</" << tag << ">";
        }
        out << "</tr>\n";
      }
      out << "</table></div>\n";
    } else {
      std::string para = l;
      ++i;
      while (i < lines.size() && !lines[i].empty() && !starts(lines[i], "#") &&
             !starts(lines[i], "- ") && !starts(lines[i], "|"))
        para += " " + lines[i++];
      out << "<p>" << inline_html(para, link) << "</p>\n";
    }
  }
  return out.str();
}

std::string to_markdown(const Section& section, int level, const std::string& image_prefix) {
  std::ostringstream out;
  if (!section.title.empty()) out << hashes(level) << " " << section.title << "\n\n";
  for (const Block& b : section.blocks) {
    if (const auto* h = std::get_if<Heading>(&b)) {
      out << hashes(level + h->level) << " " << h->text << "\n\n";
    } else if (const auto* t = std::get_if<Text>(&b)) {
      out << t->markdown;
      if (t->markdown.empty() || t->markdown.back() != '\n') out << "\n";
      out << "\n";
    } else if (const auto* tab = std::get_if<Table>(&b)) {
      markdown_table(out, *tab);
    } else if (const auto* p = std::get_if<Plot>(&b)) {
      if (!p->image.empty()) {
        std::string svg = p->image;
        if (svg.size() > 4 && svg.compare(svg.size() - 4, 4, ".png") == 0)
          svg.replace(svg.size() - 4, 4, ".svg");
        out << "![" << p->id << "](" << image_prefix << p->image << ") ([svg](" << image_prefix
            << svg << "))\n\n";
      }
    }
  }
  return out.str();
}

std::string to_html(const Section& section, const HtmlOptions& options) {
  std::ostringstream out;
  out << "<section" << (section.id.empty() ? "" : " id=\"" + escape_html(section.id) + "\"")
      << ">\n";
  const int level = std::min(options.level, 6);
  if (!section.title.empty())
    out << "<h" << level << ">" << inline_html(section.title, options.link) << "</h" << level
        << ">\n";
  for (const Block& b : section.blocks) {
    if (const auto* h = std::get_if<Heading>(&b)) {
      const int l = std::min(level + h->level, 6);
      out << "<h" << l << ">" << inline_html(h->text, options.link) << "</h" << l << ">\n";
    } else if (const auto* t = std::get_if<Text>(&b)) {
      out << markdown_to_html(t->markdown, options.link);
    } else if (const auto* tab = std::get_if<Table>(&b)) {
      if (!tab->caption.empty())
        out << "<p class=\"caption\">" << inline_html(tab->caption, options.link) << "</p>\n";
      out << "<div class=\"table-wrap\"><table"
          << (tab->id.empty() ? "" : " id=\"" + escape_html(tab->id) + "\"")
          << (tab->sortable ? " class=\"sortable\"" : "") << ">\n<thead><tr>";
      for (size_t c = 0; c < tab->columns.size(); ++c)
        out << "<th" << (is_numeric(*tab, c) ? " class=\"num\"" : "") << ">"
            << inline_html(tab->columns[c], options.link) << "</th>";
      out << "</tr></thead>\n<tbody>\n";
      for (const auto& row : tab->rows) {
        out << "<tr>";
        for (size_t c = 0; c < tab->columns.size(); ++c) {
          const Cell cell = c < row.size() ? row[c] : Cell();
          std::string cls = is_numeric(*tab, c) ? "num" : "";
          if (cell.best) cls += cls.empty() ? "best" : " best";
          out << "<td" << (cls.empty() ? "" : " class=\"" + cls + "\"")
              << (std::isfinite(cell.value) ? " data-value=\"" + json_number(cell.value) + "\""
                                            : "")
              << ">";
          std::string text = inline_html(cell.text, options.link);
          if (cell.strong) text = "<strong>" + text + "</strong>";
          const std::string to = cell.href.empty() ? "" : link_target(cell.href, options.link);
          out << (to.empty() ? text : "<a href=\"" + escape_html(to) + "\">" + text + "</a>")
              << "</td>";
        }
        out << "</tr>\n";
      }
      out << "</tbody></table></div>\n";
    } else if (const auto* p = std::get_if<Plot>(&b)) {
      out << "<figure class=\"chart\"><canvas data-plot=\"" << escape_html(p->id)
          << "\" role=\"img\" aria-label=\"" << escape_html(p->title) << "\"></canvas></figure>\n";
    }
  }
  out << "</section>\n";
  return out.str();
}

std::string plots_json(const std::vector<Section>& sections) {
  std::ostringstream out;
  out << "{";
  bool first = true;
  for (const Section& s : sections)
    for (const Block& b : s.blocks) {
      const auto* p = std::get_if<Plot>(&b);
      if (p == nullptr) continue;
      out << (first ? "" : ",") << "\n"
          << json_string(p->id) << ":{\"title\":" << json_string(p->title)
          << ",\"x\":" << json_string(p->x_label) << ",\"y\":" << json_string(p->y_label)
          << ",\"logx\":" << (p->log_x ? "true" : "false")
          << ",\"logy\":" << (p->log_y ? "true" : "false")
          << ",\"reverse\":" << (p->reverse_x ? "true" : "false") << ",\"series\":[";
      first = false;
      for (size_t i = 0; i < p->series.size(); ++i) {
        const Series& se = p->series[i];
        out << (i ? "," : "") << "{\"label\":" << json_string(se.label)
            << ",\"color\":" << json_string(se.color) << ",\"marker\":" << se.marker
            << ",\"dash\":" << se.dash << ",\"points_only\":" << (se.points_only ? "true" : "false")
            << ",\"data\":[";
        for (size_t k = 0; k < se.points.size(); ++k)
          out << (k ? "," : "") << "[" << json_number(se.points[k].x) << ","
              << json_number(se.points[k].y) << "," << json_string(se.points[k].note) << "]";
        out << "]}";
      }
      out << "]}";
    }
  out << "\n}";
  return out.str();
}

}  // namespace curvbench::report
