#include "harness/report/pages.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "core/build_info.h"
#include "core/errors.h"
#include "harness/report/advice.h"
#include "harness/report/plot_styles.h"
#include "harness/report/recommend_table.h"
#include "harness/report/site_assets.h"
#include "mesh/io.h"
#include "methods/estimator.h"

namespace curvbench {

namespace fs = std::filesystem;

namespace {

// ---- shared helpers ----------------------------------------------------------------------

const char* kQuantityWords[][2] = {{"normal", "normals"}, {"H", "H"}, {"K", "K"}, {"d1", "d1"}};

// The first sentence of a text (up to ". "), at most `cap` characters.
std::string first_sentence(const std::string& text, size_t cap = 220) {
  std::string s = text.substr(0, text.find('\n'));
  const size_t dot = s.find(". ");
  if (dot != std::string::npos) s = s.substr(0, dot + 1);
  if (s.size() > cap) s = s.substr(0, cap - 3) + "...";
  return s;
}

// A Why line in one line: its verdict on the cause and the finding's name, e.g. "localised: the
// size, not the direction" or "no cause found (tried: the paper's level-halving rate)".
std::string one_line_cause(const std::string& why) {
  const auto label = [](const std::string& text) {
    std::string s = text.substr(0, text.find_first_of(":(;"));
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
  };
  const std::string none = "No cause found. ";
  const std::string localised = "Localised (where the miss is, not why): ";
  const std::string tried = "Tried: ";
  if (why.rfind(none, 0) == 0) {
    const std::string rest = why.substr(none.size());
    if (rest.rfind(localised, 0) == 0)
      return "localised, no cause: " + label(rest.substr(localised.size())) + ".";
    if (rest.rfind(tried, 0) == 0)
      return "no cause found (tried: " + label(rest.substr(tried.size())) + ", ...)";
    return "no cause found";
  }
  if (why.rfind("Cause", 0) == 0) {
    const size_t colon = why.find("): ");
    return "cause: " + (colon == std::string::npos ? label(why) : label(why.substr(colon + 3))) +
           ".";
  }
  std::string s = first_sentence(why);
  if (!s.empty() && s.back() != '.') s += '.';
  return s;
}

// The lowest error per (class, quantity), L2, among rows: the winner of each cell.
const LeaderRow* winner(const std::vector<LeaderRow>& board, const std::string& cls,
                        const std::string& quantity) {
  const LeaderRow* best = nullptr;
  for (const LeaderRow& r : board)
    if (r.mesh_class == cls && r.quantity == quantity && r.norm == "L2" && std::isfinite(r.error) &&
        (best == nullptr || r.error < best->error))
      best = &r;
  return best;
}

std::string details_link(const std::string& section_id) {
  return "report/" + section_id + ".md";
}

// The first line of a results CSV: "# curvbench ... (git abc) ..., generated <date>".
std::string provenance_of(const std::string& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  return line.rfind("# ", 0) == 0 ? line.substr(2) : "";
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      return colon == std::string::npos ? "" : line.substr(colon + 2);
    }
  return "unknown CPU";
}

// Speed against CGAL's jet at the finest level of Table 5: per degree, the paper fits' time
// over the jet's of the same degree.
report::Table speed_table(const std::string& dir) {
  report::Table tab;
  const std::string csv = dir + "/table5_timing.csv";
  if (!fs::exists(csv)) return tab;
  const CsvTable t = read_csv_table(csv);
  const size_t cm = t.col("method"), cl = t.col("level"), ct = t.col("threads"),
               cs = t.col("seconds"), cv = t.col("verts"), cmesh = t.col("mesh");
  int finest = 0;
  for (size_t i = 0; i < t.rows.size(); ++i)
    if (t.text(i, cmesh) == "torus-unstructured") finest = std::max(finest, t.integer(i, cl));
  std::map<std::string, double> seconds;
  std::vector<std::string> order;
  int verts = 0;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    if (t.text(i, cmesh) != "torus-unstructured" || t.integer(i, cl) != finest ||
        t.integer(i, ct) != 1)
      continue;
    const std::string m = t.text(i, cm);
    // The registry's estimators only (bench variants such as "LHF-2 scalar" are in Table 5).
    if (m.find(' ') != std::string::npos || method_group(m) == MethodGroup::outside) continue;
    if (!seconds.count(m)) order.push_back(m);
    const double s = t.number(i, cs);
    seconds[m] = seconds.count(m) ? std::min(seconds[m], s) : s;
    verts = t.integer(i, cv);
  }
  tab.caption = "Well-shaped torus, level " + std::to_string(finest) + " (" +
                std::to_string(verts) +
                " vertices), one thread, from results/table5_timing.csv (`make bench`).";
  tab.columns = {"method", "seconds", "us/vertex", "jet of its degree / it"};
  for (const std::string& m : order) {
    const size_t dash = m.rfind('-');
    const std::string degree = dash == std::string::npos ? "" : m.substr(dash + 1);
    // The jet (MethodGroup::jet) of the same degree.
    auto jet = seconds.end();
    for (auto it = seconds.begin(); it != seconds.end(); ++it)
      if (method_group(it->first) == MethodGroup::jet && it->first.ends_with("-" + degree))
        jet = it;
    const double s = seconds[m];
    std::vector<report::Cell> row{
        m, report::Cell::number(s, scientific(s)),
        report::Cell::number(1e6 * s / verts, two_decimals(1e6 * s / verts))};
    if (jet != seconds.end() && m != jet->first)
      row.push_back(report::Cell::number(jet->second / s, two_decimals(jet->second / s) + "x"));
    else
      row.push_back("-");
    tab.add(std::move(row));
  }
  return tab;
}

}  // namespace

// ---- REPORT.md -------------------------------------------------------------------------------

std::string summary_markdown(const ReportContent& content, const std::vector<LeaderRow>& board,
                             const ClaimsView& claims, const std::string& dir) {
  std::ostringstream md;
  md << "# curvbench results\n\n"
     << "Reproduction of the numerical experiments of Wang, Jiao et al., *An Analysis and "
        "Comparison of Parameterization-Based Computation of Differential Quantities for "
        "Discrete Surfaces* (CAGD 2009), §5, and the estimators in common use measured the same "
        "way. Generated by "
     << build_info() << " on " << utc_timestamp()
     << ". Regenerate with `make experiments`; re-render from the CSVs with `make site`.\n\n"
     << "**Read the results on the site:** open [site/index.html](site/index.html) in a browser "
        "(it works offline, from the file). This page is the summary; every table and plot is in "
        "[report/](report/) as markdown too.\n\n";

  report::Section wins{"wins", "Which estimator wins where", {}};
  wins.text(
      "The smallest finest-level L2 error per mesh class and quantity, with the "
      "estimator's convergence rate log(e1/eN)/log(h1/hN) in brackets. A class with "
      "several meshes counts each estimator's worst mesh. Every estimator, all norms and "
      "the time per vertex: the [leaderboard](site/index.html) "
      "(results/leaderboard.csv).");
  report::Table wt;
  wt.columns = {"mesh class"};
  for (const auto& q : kQuantityWords) wt.columns.push_back(q[1]);
  for (const MeshClassRule& cls : mesh_classes()) {
    std::vector<report::Cell> row{cls.title};
    bool any = false;
    for (const auto& q : kQuantityWords) {
      const LeaderRow* w = winner(board, cls.id, q[0]);
      any = any || w != nullptr;
      row.push_back(w == nullptr ? report::Cell("-")
                                 : report::Cell::link(w->method + " " + scientific(w->error) +
                                                          " (" + two_decimals(w->rate) + ")",
                                                      details_link(w->experiment)));
    }
    if (any) wt.add(std::move(row));
  }
  wins.table(std::move(wt));
  md << report::to_markdown(wins);

  report::Section paper{"paper", "What of the paper holds", {}};
  paper.text(claims.counts_markdown);
  paper.text(
      "Every claim with its band, evidence and verdict under each alternative reading: "
      "[CLAIMS.md](CLAIMS.md). The misses under the adopted readings, each with its Why line "
      "in one line (a cause only where removing it reproduces the claim):");
  std::string misses;
  for (const ClaimView& c : claims.claims)
    if (c.verdict == "not reproduced")
      misses += "- **" + c.id + "** " + first_sentence(c.statement, 90) + " " +
                (c.why.empty() ? "(no cause recorded)" : one_line_cause(c.why)) + "\n";
  paper.text(misses.empty() ? "- none\n" : misses);
  md << report::to_markdown(paper);

  report::Section speed{"speed", "Speed against CGAL's jet", {}};
  report::Table st = speed_table(dir);
  if (st.rows.empty())
    speed.text("Not measured yet: run `make bench`.");
  else
    speed
        .text(
            "Times of the whole estimation; the last column is how many times faster than "
            "CGAL's Jet_fitting_3 of the same degree. Every timing: "
            "[report/paper-tables.md](report/paper-tables.md).")
        .table(std::move(st));
  md << report::to_markdown(speed);
  if (!content.point_cloud_summary.blocks.empty())
    md << report::to_markdown(content.point_cloud_summary);

  report::Section advice{"advice", "Which estimator for my mesh", {}};
  advice.text(
      "`curvbench recommend MESH` measures a mesh's features and noise and prints, for normals "
      "and for curvatures, the estimator and radius learned from the swept meshes nearest in "
      "those features, the error range cross-validation measured there, whether the mesh lies "
      "outside what the sweeps cover, and the `curvbench estimate` command to run; `curvbench "
      "estimate MESH --method auto` runs it. `--measure` measures the choice on the mesh "
      "itself instead: every swept case run on it and on copies perturbed by its noise "
      "(docs/advice.md). The tables behind it: "
      "[report/sweeps.md](report/sweeps.md) and the site's advice page; how far the advice "
      "holds on meshes it never saw: below.");
  md << report::to_markdown(advice);
  if (const auto validation = cross_validation_section_of(dir))
    md << report::to_markdown(*validation);

  report::Section details{"details", "Details", {}};
  std::string list = "- [Paper tables 2, 4 and 5](report/paper-tables.md)\n";
  for (const report::Section& s : content.experiments)
    list += "- [" + s.title + "](" + details_link(s.id) + ")\n";
  list +=
      "- [The estimators in common use and the meshes that break them]"
      "(report/field-studies.md)\n"
      "- [Neighbourhoods that shrink more slowly than h](report/radius-scaling.md)\n"
      "- [Sweeps at a fixed mesh, and choosing an estimator](report/sweeps.md)\n"
      "- [Point clouds: estimators without connectivity](report/point-cloud-study.md)\n"
      "- [Real meshes](REAL_MESHES.md)\n";
  details.text(list);
  md << report::to_markdown(details);
  return md.str();
}

std::string write_markdown_report(const ReportContent& content, const std::vector<LeaderRow>& board,
                                  const ClaimsView& claims, const ReportFiles& files) {
  const std::string dir = files.results_dir;
  const fs::path details = fs::path(dir) / "report";
  fs::create_directories(details);
  const auto page = [&](const std::string& id, const std::string& title,
                        const std::vector<report::Section>& sections) {
    std::string md = title.empty() ? "" : "# " + title + "\n\n";
    md += "Part of the [curvbench results](../REPORT.md). Generated by " + build_info() + " on " +
          utc_timestamp() + ".\n\n";
    for (const report::Section& s : sections) md += report::to_markdown(s, 2, "../");
    write_file_atomic((details / (id + ".md")).string(), md);
  };
  page("paper-tables", "The paper's tables", content.paper);
  for (const report::Section& s : content.experiments) page(s.id, "", {s});
  const std::map<std::string, std::string> study_titles = {
      {"field-studies", "The estimators in common use"},
      {"radius-scaling", "Neighbourhoods that shrink more slowly than h"},
      {"sweeps", "Sweeps at a fixed mesh"},
      {"point-cloud-study", "Point clouds"}};
  for (const report::Section& s : content.studies) {
    const auto t = study_titles.find(s.id);
    page(s.id, t == study_titles.end() ? s.id : t->second, {s});
  }
  const std::string path = dir + "/REPORT.md";
  write_file_atomic(path, summary_markdown(content, board, claims, dir));
  return path;
}

// ---- the site --------------------------------------------------------------------------------

namespace {

struct SitePage {
  std::string file, nav, title;
};
const SitePage kPages[] = {
    {"index.html", "Leaderboard", "Leaderboard: which estimator, on which mesh"},
    {"convergence.html", "Convergence", "Convergence, per experiment"},
    {"cost.html", "Accuracy vs cost", "Accuracy against cost"},
    {"paper.html", "The paper", "The paper: tables and claims"},
    {"real-meshes.html", "Real meshes", "Real meshes"},
    {"advice.html", "Which estimator for my mesh", "Which estimator for my mesh"},
    {"studies.html", "Studies", "The field studies, radius scaling, sweeps and point clouds"},
};

// Markdown links of the report rewritten for the site: report/<x>.md and <x>.md of an
// experiment -> exp-<x>.html; CLAIMS.md -> paper.html; plots and other files -> dropped (the site
// draws its own charts).
std::string site_link(const std::string& target) {
  std::string t = target;
  const size_t hash = t.find('#');
  const std::string anchor = hash == std::string::npos ? "" : t.substr(hash);
  t = t.substr(0, hash);
  if (t.empty()) return anchor;
  if (t.rfind("http://", 0) == 0 || t.rfind("https://", 0) == 0) return target;
  if (t.find("CLAIMS.md") != std::string::npos) return "paper.html#claims";
  if (t.find("REAL_MESHES.md") != std::string::npos) return "real-meshes.html";
  if (t.find("REPORT.md") != std::string::npos) return "index.html";
  if (t.find("realmeshes/") != std::string::npos)
    return "realmeshes/" + fs::path(t).filename().string();
  if (t.size() > 3 && t.compare(t.size() - 3, 3, ".md") == 0) {
    const std::string stem = fs::path(t).stem().string();
    if (stem == "paper-tables") return "paper.html";
    if (stem == "field-studies" || stem == "radius-scaling" || stem == "sweeps" ||
        stem == "point-cloud-study")
      return "studies.html#" + stem;
    return "exp-" + stem + ".html" + anchor;
  }
  if (t.rfind("site/", 0) == 0) return t.substr(5);
  return "";
}

struct Provenance {
  std::string source;  ///< the results' own provenance line
  std::string cpu, rendered, command;
};

std::string page_html(const SitePage& page, const std::string& body, const std::string& data,
                      const Provenance& prov, bool with_chart) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<title>" << report::escape_html(page.title) << " - curvbench</title>\n"
      << "<link rel=\"stylesheet\" href=\"assets/site.css\">\n</head>\n<body>\n<header>\n"
      << "<a class=\"brand\" href=\"index.html\">curvbench</a>\n<nav>";
  for (const SitePage& p : kPages)
    out << "<a href=\"" << p.file << "\"" << (p.file == page.file ? " class=\"current\"" : "")
        << ">" << report::escape_html(p.nav) << "</a>";
  out << "</nav>\n</header>\n<main>\n<h1>" << report::escape_html(page.title) << "</h1>\n"
      << body
      << "</main>\n<footer>\n<p class=\"provenance\">Results: " << report::escape_html(prov.source)
      << ". Rendered on " << report::escape_html(prov.cpu) << ", "
      << report::escape_html(prov.rendered) << ". Reproduce: <code>"
      << report::escape_html(prov.command) << "</code> (re-render: <code>make site</code>)."
      << "</p>\n</footer>\n"
      << "<script type=\"application/json\" id=\"site-data\">" << data << "</script>\n";
  if (with_chart) out << "<script src=\"assets/chart.min.js\"></script>\n";
  out << "<script src=\"assets/site.js\"></script>\n</body>\n</html>\n";
  return out.str();
}

std::string sections_html(const std::vector<report::Section>& sections, int level = 2) {
  std::string out;
  for (const report::Section& s : sections) out += report::to_html(s, {level, &site_link});
  return out;
}

std::string data_json(const std::vector<report::Section>& sections, const std::string& extra = "") {
  return "{\"plots\":" + report::plots_json(sections) + (extra.empty() ? "" : "," + extra) + "}";
}

std::string leaderboard_json(const std::vector<LeaderRow>& board) {
  std::ostringstream out;
  out << "\"classes\":[";
  for (size_t i = 0; i < mesh_classes().size(); ++i)
    out << (i ? "," : "") << "{\"id\":" << report::json_string(mesh_classes()[i].id)
        << ",\"title\":" << report::json_string(mesh_classes()[i].title) << "}";
  out << "],\"rows\":[";
  for (size_t i = 0; i < board.size(); ++i) {
    const LeaderRow& r = board[i];
    out << (i ? "," : "") << "\n[" << report::json_string(r.method) << ","
        << report::json_string(r.group) << "," << report::json_string(r.mesh_class) << ","
        << report::json_string(r.quantity) << "," << report::json_string(r.norm) << ","
        << report::json_number(r.error) << "," << report::json_number(r.rate) << ","
        << report::json_number(r.us_per_vertex) << "," << report::json_string(r.experiment) << ","
        << report::json_string(r.meshes) << "]";
  }
  out << "]";
  return out.str();
}

// Accuracy against cost: per mesh and noise, the L2 error in H against microseconds per vertex of
// every case of the sweeps and the field studies at the mesh's finest level (each estimator and
// radius one point; a coarser level would only add points dominated by the finest), one series
// per method, and the Pareto frontier (the cases no other case beats in both time and error).
std::vector<report::Section> cost_sections(const std::vector<Experiment>& experiments,
                                           const std::string& dir) {
  struct P {
    double us, error;
    std::string method, label, note;
  };
  struct Group {
    std::string title;
    std::vector<P> points;
  };
  std::map<std::tuple<std::string, std::string, std::string>, Group> groups;
  std::vector<std::tuple<std::string, std::string, std::string>> order;
  for (const Experiment& e : experiments) {
    if (e.report != ReportSection::field && e.report != ReportSection::hard &&
        e.report != ReportSection::sweeps)
      continue;
    const std::string csv = dir + "/" + e.name + ".csv", tcsv = dir + "/timings/" + e.name + ".csv";
    if (!fs::exists(csv) || !fs::exists(tcsv)) continue;
    std::map<std::tuple<std::string, int, std::string>, double> us;
    for (const TimingRow& t : read_timing_csv(tcsv))
      if (t.vertices > 0 && std::isfinite(t.seconds))
        us[{t.family, t.level, t.method}] = 1e6 * t.seconds / t.vertices;
    const std::vector<ErrorRow> rows = read_error_csv(csv);
    std::map<std::pair<std::string, std::string>, int> finest;  // (family, noise) -> level
    for (const ErrorRow& r : rows) {
      int& f = finest[{r.family, r.noise}];
      f = std::max(f, r.level);
    }
    for (const ErrorRow& r : rows) {
      if (r.quantity != "H" || r.norm != "L2" || r.vertex_set != "all" ||
          r.level != finest[{r.family, r.noise}])
        continue;
      const auto t = us.find({r.family, r.level, r.method});
      if (t == us.end() || !std::isfinite(r.error) || r.error <= 0) continue;
      std::string cls;
      for (const MeshClassRule& c : mesh_classes())
        if (c.member(e.report, r.family, r.noise, "all")) {
          cls = c.title + ": ";
          break;
        }
      const auto key = std::make_tuple(e.name, r.family, r.noise);
      auto [it, inserted] = groups.try_emplace(key);
      if (inserted) {
        order.push_back(key);
        it->second.title = cls + r.family + " level " + std::to_string(r.level) + " (" +
                           std::to_string(r.vertices) + " vertices), noise " + r.noise + ", " +
                           e.name;
      }
      const std::string method = r.method.substr(0, r.method.find(' '));
      it->second.points.push_back({t->second, r.error, method, r.method, r.method});
    }
  }
  std::vector<report::Section> out;
  int n = 0;
  for (const auto& key : order) {
    const Group& g = groups[key];
    report::Section s;
    s.id = "cost-" + std::to_string(++n);
    s.title = g.title;
    report::Plot plot;
    plot.id = s.id;
    plot.title = "L2 error in H against time per vertex: " + g.title;
    plot.x_label = "time per vertex (microseconds)";
    plot.y_label = "L2 error in H";
    plot.reverse_x = false;
    std::vector<std::string> methods;
    for (const P& p : g.points)
      if (std::find(methods.begin(), methods.end(), p.method) == methods.end())
        methods.push_back(p.method);
    const std::vector<PlotStyle> styles = plot_styles(methods);
    for (size_t i = 0; i < methods.size(); ++i) {
      report::Series se;
      se.label = methods[i];
      se.color = styles[i].colour;
      se.marker = styles[i].marker;
      se.points_only = true;
      for (const P& p : g.points)
        if (p.method == methods[i]) se.points.push_back({p.us, p.error, p.note});
      plot.series.push_back(std::move(se));
    }
    std::vector<P> sorted = g.points;
    std::sort(sorted.begin(), sorted.end(), [](const P& a, const P& b) {
      return a.us < b.us || (a.us == b.us && a.error < b.error);
    });
    report::Series front;
    front.label = "Pareto frontier";
    front.color = "#000000";
    front.marker = 0;
    front.dash = 2;
    report::Table tab;
    tab.caption =
        "The Pareto frontier, cheapest first: no other case is both cheaper and more "
        "accurate.";
    tab.columns = {"case", "us/vertex", "L2 error in H"};
    double best = INFINITY;
    for (const P& p : sorted)
      if (p.error < best) {
        best = p.error;
        front.points.push_back({p.us, p.error, p.note});
        tab.add({p.label, report::Cell::number(p.us, two_decimals(p.us)),
                 report::Cell::number(p.error, scientific(p.error))});
      }
    plot.series.push_back(std::move(front));
    s.text(std::to_string(g.points.size()) + " cases (estimator and radius).");
    s.plot(std::move(plot));
    s.table(std::move(tab));
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<report::Section> claims_sections(const ClaimsView& view) {
  report::Section s{"claims", "Every claim", {}};
  s.text(view.counts_markdown);
  s.text(
      "The verdict under the adopted readings and re-read bands (the band fixed in advance and "
      "its verdict where it was re-read), under the paper's level-halving rate formula, and "
      "under every alternative reading that changes it; the Why line of a miss; the pages "
      "that hold its numbers. The full evidence: results/CLAIMS.md.");
  report::Table tab;
  tab.id = "claims-table";
  tab.sortable = true;
  tab.numeric = std::vector<bool>(7, false);
  tab.columns = {"claim",
                 "verdict",
                 "band",
                 "paper's rate formula",
                 "readings that change its evidence (adopted; others)",
                 "why",
                 "numbers"};
  for (const ClaimView& c : view.claims) {
    std::string readings;
    for (const ClaimView::Reading& r : c.readings) {
      readings += (readings.empty() ? "" : "; ") + r.id + ": " + r.adopted + " (adopted)";
      for (const auto& [choice, verdict] : r.alternatives)
        readings += ", " + choice + " " + verdict;
    }
    std::string links;
    for (const std::string& e : c.experiments)
      links += (links.empty() ? "" : ", ") + std::string("[") + e + "](report/" + e + ".md)";
    std::string band = c.band, verdict = c.verdict;
    if (!c.original_band.empty()) {
      band += " (fixed in advance: " + c.original_band + ")";
      verdict += " (fixed band: " + c.original_verdict + ")";
    }
    tab.add({"**" + c.id + "** " + c.statement, verdict, band, c.halving_verdict,
             readings.empty() ? "none" : readings, c.why, links});
  }
  s.table(std::move(tab));
  return {s};
}

std::vector<report::Section> advice_sections(const std::string& dir) {
  report::Section s{"recommendations", "Recommendations", {}};
  const std::string csv = dir + "/recommendations.csv";
  if (!fs::exists(csv)) {
    s.text(
        "Not run yet: recommendations.csv is written by the radius sweeps of "
        "`make experiments`.");
    return {s};
  }
  const CsvTable t = read_csv_table(csv);
  s.text(
      "Per mesh class and noise level (sigma/h along the normal), the most accurate "
      "estimator and radius of the radius sweeps in the L2 error of H, and the cheapest within "
      "2x of it, each with the command that runs it (the class table; `curvbench recommend "
      "MESH` learns from every swept mesh by its features, cross-validated below, and falls "
      "back on this row without `advice_cases.csv`).");
  report::Table tab;
  tab.id = "advice-table";
  tab.sortable = true;
  tab.columns = {"class", "sigma/h", "most accurate", "error", "command", "cheapest within 2x",
                 "error"};
  tab.numeric = {false, true, false, true, false, false, true};
  const size_t cq = t.col("quality"), cs = t.col("sigma_over_h"), cst = t.col("status"),
               cb = t.col("best_label"), ce = t.col("best_error"), cc = t.col("cheapest_label"),
               cce = t.col("cheapest_error");
  for (size_t i = 0; i < t.rows.size(); ++i) {
    if (t.text(i, cst) != "swept") {
      tab.add({t.text(i, cq), report::Cell::number(t.number(i, cs), t.text(i, cs)), "not swept", "",
               "", "", ""});
      continue;
    }
    const std::string best = t.text(i, cb);
    tab.add({t.text(i, cq), report::Cell::number(t.number(i, cs), t.text(i, cs)), best,
             report::Cell::number(t.number(i, ce), scientific(t.number(i, ce))),
             "`" +
                 estimate_command("curvbench", "MESH", estimator_choice(best), false,
                                  advice_output_path("MESH")) +
                 "`",
             t.text(i, cc), report::Cell::number(t.number(i, cce), scientific(t.number(i, cce)))});
  }
  s.table(std::move(tab));
  if (const auto validation = cross_validation_section_of(dir)) return {s, *validation};
  return {s};
}

void copy_file_checked(const std::string& from, const fs::path& to) {
  if (!fs::exists(from))
    throw InputError(from + ": not found (install Debian's libjs-chart.js: make deps)");
  fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw InputError(path.string() + ": cannot write");
}

}  // namespace

std::string write_site(const std::vector<Experiment>& experiments, const ReportContent& content,
                       const std::vector<LeaderRow>& board, const ClaimsView& claims,
                       const ReportFiles& files) {
  const std::string dir = files.results_dir;
  const fs::path site = files.site_dir.empty() ? fs::path(dir) / "site" : fs::path(files.site_dir);
  const fs::path tmp = site.string() + ".tmp." + std::to_string(::getpid());
  fs::remove_all(tmp);
  fs::create_directories(tmp / "assets");
  try {
    copy_file_checked(files.chart_js, tmp / "assets" / "chart.min.js");
    write_text(tmp / "assets" / "site.js", site_assets::kScript);
    write_text(tmp / "assets" / "site.css", site_assets::kStyle);
    Provenance prov;
    prov.source = provenance_of(dir + "/leaderboard.csv");
    if (prov.source.empty()) prov.source = build_info();
    prov.cpu = cpu_model();
    prov.rendered = "rendered " + utc_timestamp();
    prov.command = files.command;
    const auto write_page = [&](const SitePage& page, const std::string& body,
                                const std::vector<report::Section>& sections,
                                const std::string& extra = "") {
      bool charts = !extra.empty();
      for (const auto& s : sections)
        for (const auto& b : s.blocks) charts = charts || std::holds_alternative<report::Plot>(b);
      write_text(tmp / page.file, page_html(page, body, data_json(sections, extra), prov, charts));
    };

    // Leaderboard.
    {
      int reproduced = 0;
      for (const ClaimView& c : claims.claims)
        reproduced += (c.original_band.empty() ? c.verdict : c.original_verdict) == "reproduced";
      std::string intro =
          "<p class=\"lead\">Every estimator on meshes with exact answers: its L2 or Linf error "
          "at the finest level, its convergence rate log(e1/eN)/log(h1/hN), and its time per "
          "vertex, per mesh class. A class with several meshes shows the estimator's worst. "
          "Click a column to sort; the view's state is in the address, so it can be linked. "
          "The paper's claims: " +
          std::to_string(reproduced) + " of " + std::to_string(claims.claims.size()) +
          " reproduced under the bands fixed in advance and the adopted readings (<a "
          "href=\"paper.html#claims\">the counts and every claim</a>).</p>\n"
          "<div id=\"leaderboard-controls\" class=\"controls\"></div>\n"
          "<div class=\"table-wrap\"><table id=\"leaderboard\" class=\"leaderboard\"></table>"
          "</div>\n<p class=\"note\">Data: results/leaderboard.csv. Best value per column "
          "marked.</p>\n";
      write_page(kPages[0], intro, {}, leaderboard_json(board));
    }
    // Convergence: the list, and one page per experiment.
    {
      report::Section list{"experiments", "", {}};
      report::Table tab;
      tab.id = "experiment-list";
      tab.columns = {"experiment", "plots"};
      for (const report::Section& s : content.experiments) {
        int plots = 0;
        for (const auto& b : s.blocks) plots += std::holds_alternative<report::Plot>(b);
        tab.add({report::Cell::link(s.title, "exp-" + s.id + ".html"),
                 report::Cell::number(plots, std::to_string(plots))});
        const SitePage page{"exp-" + s.id + ".html", "Convergence", s.title};
        report::Section body = s;
        body.title.clear();
        write_page(page,
                   "<p class=\"lead\">Error against the mean edge length h, log-log, one series "
                   "per estimator with its rate in the legend; dashed lines are the O(h^p) "
                   "slopes. Click a legend entry to hide a series; hover a point for its level "
                   "and mesh. <a href=\"convergence.html\">All experiments</a>.</p>\n" +
                       sections_html({body}),
                   {body});
      }
      list.table(std::move(tab));
      write_page(kPages[1],
                 "<p class=\"lead\">One page per experiment of the paper's §5 and beyond.</p>\n" +
                     sections_html({list}),
                 {list});
    }
    // Accuracy against cost.
    {
      const std::vector<report::Section> cost = cost_sections(experiments, dir);
      write_page(kPages[2],
                 "<p class=\"lead\">The L2 error in H against the time per vertex of every "
                 "estimator and radius of the sweeps and the field studies, one chart per mesh "
                 "(at its finest level) and noise, titled with the mesh's class. The dashed "
                 "black line is the Pareto frontier: the cases that no other case beats in both "
                 "time and error. Lower left is better; hover a point for its case.</p>\n" +
                     sections_html(cost),
                 cost);
    }
    // The paper.
    {
      std::vector<report::Section> sections = content.paper;
      for (auto& s : claims_sections(claims)) sections.push_back(std::move(s));
      write_page(kPages[3], sections_html(sections), sections);
    }
    // Real meshes.
    {
      const std::string md_path = dir + "/REAL_MESHES.md";
      std::string body = "<p>Not run yet: <code>make realmeshes</code>.</p>\n";
      if (fs::exists(md_path)) {
        // The corpus's robustness tables first (between REAL_MESHES.md's corpus markers), then
        // the per-mesh sections with their pictures; the file's own title is the page's.
        std::string md = read_file(md_path);
        if (md.rfind("# ", 0) == 0) md = md.substr(md.find('\n') + 1);
        const std::string begin = "<!-- corpus: begin -->", end = "<!-- corpus: end -->";
        const size_t b = md.find(begin), e = md.find(end);
        if (b != std::string::npos && e != std::string::npos && b < e) {
          const std::string corpus = md.substr(b + begin.size(), e - b - begin.size());
          md = corpus + "\n" + md.substr(0, b) + md.substr(e + end.size());
        }
        body = report::markdown_to_html(md, &site_link);
        if (fs::exists(fs::path(dir) / "realmeshes")) {
          fs::create_directories(tmp / "realmeshes");
          for (const auto& f : fs::directory_iterator(fs::path(dir) / "realmeshes"))
            if (f.path().extension() == ".png")
              fs::copy_file(f.path(), tmp / "realmeshes" / f.path().filename());
        }
      }
      write_page(kPages[4], body, {});
    }
    {
      const auto sections = advice_sections(dir);
      write_page(kPages[5], sections_html(sections), sections);
    }
    { write_page(kPages[6], sections_html(content.studies), content.studies); }
  } catch (...) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    throw;
  }
  // Swap into place: the old site is removed only once the new one is complete.
  const fs::path old = site.string() + ".old." + std::to_string(::getpid());
  if (fs::exists(site)) fs::rename(site, old);
  fs::rename(tmp, site);
  std::error_code ec;
  fs::remove_all(old, ec);
  return (site / "index.html").string();
}

}  // namespace curvbench
