// One row of results/diag-safeguard-fires.csv: a vertex whose first stencil the safeguarded
// QR's condition test cuts (harness/run/safeguard_fires.h computes them; the claims read them),
// and the cases (meshes and methods) the diagnostic looks at.
#pragma once

#include <string>
#include <vector>

namespace curvbench {

struct SafeguardFire {
  std::string family, method;
  int level = 0;
  int vertices = 0;  ///< of the mesh
  int vertex = -1;   ///< the vertex whose stencil the test cuts
  double x = 0, y = 0, z = 0;
  bool boundary = false;  ///< on the boundary (Mesh::is_boundary_vertex)
  int rows = 0;           ///< of the first stencil
  int column_rank = 0;    ///< columns the |R_jj| test keeps
  int rank = 0;           ///< columns the condition test keeps
  double condition = 0;   ///< sqrt(k) ||R_k^-1||_F of the column_rank columns (QrSolveResult)
  /// The estimate with the condition test (the adopted safeguard) and without (qr-condition=no).
  int degree = 0, degree_rjj_only = 0;
  double ring = 0, ring_rjj_only = 0;
  int points = 0, points_rjj_only = 0;
};

/// One mesh of the table: a family at some levels, with the methods to run (ring fits, e.g.
/// "lhf-4", "lscm-4", or with options: "lhf-4 rings=3.5"; the CSV's method is the label and the
/// options, "LHF-4 rings=3.5").
struct SafeguardFireCase {
  std::string family;
  std::vector<int> levels;
  std::vector<std::string> methods;
};

/// The cases `make experiments` writes: bump-48 and bump-irregular at levels 1-4, LHF-4 and
/// LSCM-4 (the fits of claims D5 and D6), and on bump-48 LHF-4 at 3.5 rings (diag-d6-level5's
/// fixed stencil).
std::vector<SafeguardFireCase> default_safeguard_fire_cases();

/// The CSV text (provenance comment, header, rows) and its reader.
std::string safeguard_fires_csv(const std::vector<SafeguardFire>& rows);
std::vector<SafeguardFire> read_safeguard_fires_csv(const std::string& path);

}  // namespace curvbench
