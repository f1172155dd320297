#include "harness/report/well_shaped_torus_table.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <vector>

#include "core/build_info.h"
#include "harness/model/paper_tables.h"
#include "harness/model/results_table.h"
#include "mesh/mesh_checks.h"
#include "meshgen/generate.h"

namespace curvbench {

void write_well_shaped_torus_csv(const std::string& path) {
  std::ostringstream out;
  out << provenance_comment() << "\n"
      << "family,level,vertices,paper_vertices,faces,mean_edge_length,min_angle_deg,"
         "max_angle_deg,valence_histogram\n";
  for (const std::string& family : kWellShapedTorusFamilies)
    for (int level = 1; level <= max_mesh_level(family); ++level) {
      MeshSpec spec;
      spec.family = family;
      spec.level = level;
      const Mesh m = generate_mesh(spec).mesh;
      double edge_sum = 0.0;
      for (int f = 0; f < m.num_faces(); ++f)
        for (int k = 0; k < 3; ++k)  // each edge twice (closed mesh)
          edge_sum +=
              (m.position(m.face_vertex(f, k)) - m.position(m.face_vertex(f, (k + 1) % 3))).norm();
      std::string hist;
      const std::vector<int> counts = valence_histogram(m);
      for (size_t valence = 0; valence < counts.size(); ++valence) {
        if (counts[valence] == 0) continue;
        if (!hist.empty()) hist += ' ';
        hist += std::to_string(valence);
        hist += ':';
        hist += std::to_string(counts[valence]);
      }
      const MeshQuality q = mesh_quality(m);
      out << family << ',' << level << ',' << m.num_vertices() << ','
          << paper::kTable5[static_cast<size_t>(level - 1)].vertices << ',' << m.num_faces() << ','
          << format_double(edge_sum / (3.0 * m.num_faces())) << ','
          << format_double(q.min_angle_deg) << ',' << format_double(q.max_angle_deg) << ',' << hist
          << "\n";
    }
  write_file_atomic(path, out.str());
}

report::Section well_shaped_torus_section(const std::string& csv_path) {
  report::Section s{"well-shaped-torus", "", {}};
  if (!std::filesystem::exists(csv_path)) return s;
  const CsvTable t = read_csv_table(csv_path);
  s.title = "Well-shaped torus meshes (the paper's Table 5 meshes)";
  s.text(
      "`torus-unstructured`: CGAL Delaunay refinement of the implicit torus (R = 1, r = 0.3), "
      "every vertex projected onto the torus (docs/mesh_families.md); the stand-in for the "
      "paper's unstructured GAMBIT meshes, used for Figs. 3-7, Table 5 and the claims on the "
      "well-shaped torus. `torus-jittered` and `torus-structured` remain as extra rows.\n\n"
      "`torus-unstructured-minval5`: the same meshes with every valence-4 vertex removed by edge "
      "flips (a reading of \"GAMBIT well-shaped\", docs/claims.md); the claims are evaluated "
      "on it as well (CLAIMS.md, reading well-shaped-torus).");
  report::Table tab;
  tab.id = "well-shaped-torus";
  tab.columns = {"family",           "level",        "#verts (ours / paper)", "#faces",
                 "mean edge length", "angles (deg)", "valence: count"};
  tab.numeric = {false, true, true, true, true, true, false};
  const size_t cfam = t.col("family"), cl = t.col("level"), cv = t.col("vertices"),
               cp = t.col("paper_vertices"), cf = t.col("faces"), ch = t.col("mean_edge_length"),
               cmin = t.col("min_angle_deg"), cmax = t.col("max_angle_deg"),
               chist = t.col("valence_histogram");
  for (size_t i = 0; i < t.rows.size(); ++i) {
    char angles[64], h[32], rel[32];
    std::snprintf(angles, sizeof angles, "%.1f - %.1f", t.number(i, cmin), t.number(i, cmax));
    std::snprintf(h, sizeof h, "%.4f", t.number(i, ch));
    const double dv = (t.number(i, cv) - t.number(i, cp)) / t.number(i, cp) * 100.0;
    std::snprintf(rel, sizeof rel, " (%+.1f%%)", dv);
    tab.add({"`" + t.text(i, cfam) + "`", report::Cell::number(t.number(i, cl), t.text(i, cl)),
             report::Cell::number(t.number(i, cv), t.text(i, cv) + " / " + t.text(i, cp) + rel),
             report::Cell::number(t.number(i, cf), t.text(i, cf)),
             report::Cell::number(t.number(i, ch), h),
             // The smallest angle is the number (the quality the paper's meshes are chosen for).
             report::Cell::number(t.number(i, cmin), angles), t.text(i, chist)});
  }
  return s.table(std::move(tab));
}

}  // namespace curvbench
