// The well-shaped torus meshes (torus-unstructured and torus-unstructured-minval5, levels 1-4;
// docs/mesh_families.md) next to the paper's vertex counts (Table 5):
// results/torus_unstructured.csv and its REPORT.md section.
//
// CSV columns: family,level,vertices,paper_vertices,faces,mean_edge_length,min_angle_deg,
//              max_angle_deg,valence_histogram   (e.g. "4:12 5:301 6:802", valence:count)
#pragma once

#include <string>
#include <vector>

#include "harness/report/model.h"

namespace curvbench {

/// The families of the table: the adopted well-shaped torus and its reading without valence 4.
inline const std::vector<std::string> kWellShapedTorusFamilies = {"torus-unstructured",
                                                                  "torus-unstructured-minval5"};

/// Generates levels 1-4 of each family and writes the CSV atomically.
void write_well_shaped_torus_csv(const std::string& path);

/// The report's section from that CSV (id "well-shaped-torus"): its words and the table, each
/// cell with its number (vertices, faces, mean edge length, smallest angle); no title and no
/// blocks if the file does not exist.
report::Section well_shaped_torus_section(const std::string& csv_path);

}  // namespace curvbench
