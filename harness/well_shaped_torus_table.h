// The well-shaped torus meshes (torus-unstructured, levels 1-4; docs/mesh_families.md) next to
// the paper's vertex counts (Table 5): results/torus_unstructured.csv and its REPORT.md section.
//
// CSV columns: level,vertices,paper_vertices,faces,mean_edge_length,min_angle_deg,max_angle_deg,
//              valence_histogram   (e.g. "4:12 5:301 6:802 7:210 8:13", valence:count)
#pragma once

#include <string>

namespace curvbench {

/// Generates levels 1-4 (cached in the process for the experiments that follow) and writes the
/// CSV atomically.
void write_well_shaped_torus_csv(const std::string& path);

/// The REPORT.md section from that CSV; "" if the file does not exist.
std::string well_shaped_torus_markdown(const std::string& csv_path);

}  // namespace curvbench
