#include "harness/report/causes.h"

#include <filesystem>
#include <map>
#include <sstream>

#include "core/text.h"

namespace curvbench {

void cause_tables(const Experiment& e, const std::string& results_dir, report::Section& out) {
  const std::string path = results_dir + "/errors_by_cause/" + e.name + ".csv";
  if (!std::filesystem::exists(path)) return;
  const std::vector<CauseRow> rows = read_cause_csv(path);
  bool intro = false;
  for (const ExperimentMesh& m : e.meshes) {
    // Methods in first-seen order, each with its row per bin.
    std::vector<std::string> methods;
    std::map<std::string, std::map<std::string, const CauseRow*>> of;  // method -> "cause/bin"
    for (const CauseRow& r : rows) {
      if (r.family != m.label()) continue;
      if (!of.count(r.method)) methods.push_back(r.method);
      of[r.method][std::string(r.cause) + "/" + r.bin] = &r;
    }
    if (methods.empty()) continue;
    if (!intro) {
      std::ostringstream words;
      words << "Relative L2 error in H (|e|_2/|H|_2) over the vertices of each bin (after Gatzke "
               "and Grimm 2006): by valence, by the smallest angle of the triangles around the "
               "vertex (degrees), and by the sign of the exact Gaussian curvature (K~0: |K| at "
               "most "
            << kTinyGaussian
            << " times the mesh's largest |K|). The row *vertices* counts each bin's vertices in "
               "the vertex set of most methods; a method scored over another set names it in "
               "brackets; `-`: an empty bin. Source: `errors_by_cause/"
            << e.name << ".csv`.";
      out.heading("Errors by cause at the finest level").text(words.str());
      intro = true;
    }
    const CauseRow& first = *of[methods.front()].begin()->second;
    // The counts are those of the vertex set of most methods (ties: the first seen); a method
    // scored over another set (Xu-2 and the 1-ring operators on open meshes: the interior)
    // names it.
    std::map<std::string, int> set_count;
    std::string set = first.vertex_set;
    for (const std::string& method : methods) {
      const std::string& s = of[method].begin()->second->vertex_set;
      if (++set_count[s] > set_count[set]) set = s;
    }
    const std::string* counted_by = &methods.front();
    for (const std::string& method : methods)
      if (of[method].begin()->second->vertex_set == set) {
        counted_by = &method;
        break;
      }
    report::Table tab;
    tab.caption = "**`" + m.label() + "`**, level " + std::to_string(first.level) + " (" +
                  std::to_string(first.vertices) + " vertices)";
    tab.columns = {"method"};
    for (const CauseBin& b : cause_bins())
      tab.columns.push_back((std::string(b.cause) == "valence" ? "val " : "") + std::string(b.bin) +
                            (std::string(b.cause) == "min-angle" ? "°" : ""));
    std::vector<report::Cell> count_row{"*vertices (" + set + ")*"};
    const auto& counts = of[*counted_by];
    for (const CauseBin& b : cause_bins()) {
      const auto it = counts.find(std::string(b.cause) + "/" + b.bin);
      const int n = it == counts.end() ? 0 : it->second->counted + it->second->excluded;
      count_row.push_back(report::Cell::number(n, std::to_string(n)));
    }
    tab.add(std::move(count_row));
    for (const std::string& method : methods) {
      const auto& cells = of[method];
      const std::string& own = cells.begin()->second->vertex_set;
      std::vector<report::Cell> row{method + (own != set ? " (" + own + ")" : std::string())};
      for (const CauseBin& b : cause_bins()) {
        const auto it = cells.find(std::string(b.cause) + "/" + b.bin);
        row.push_back(it == cells.end() ? report::Cell("-")
                                        : report::Cell::number(it->second->error,
                                                               scientific(it->second->error, "-")));
      }
      tab.add(std::move(row));
    }
    out.table(std::move(tab));
  }
}

}  // namespace curvbench
