// `curvbench score MESH.ply --estimates EST.csv [--vertex-set all|interior|boundary-ring]
//  [--json]`: the errors of an outside estimator's per-vertex estimates against the exact
// quantities of a mesh written by `curvbench mesh` (harness/model/score.h).
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "harness/model/score.h"

namespace curvbench::cli {

namespace {

struct ScoreArgs {
  std::string mesh;
  std::string estimates;
  std::string vertex_set = "all";
  bool json = false;
};

}  // namespace

Command add_score_command(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "score",
      "Score per-vertex estimates from any program (CSV) against the exact quantities of a mesh "
      "written by `curvbench mesh`, with the errors of `curvbench run`");
  auto a = std::make_shared<ScoreArgs>();
  sub->add_option("MESH", a->mesh, "Mesh written by `curvbench mesh --output X.ply`")->required();
  sub->add_option("--estimates", a->estimates,
                  "CSV with a 'vertex' column (0-based) and any of nx,ny,nz,k1,k2,H,K,d1x,d1y,"
                  "d1z,d2x,d2y,d2z; 'nan' = the estimator failed at that vertex")
      ->required();
  sub->add_option("--vertex-set", a->vertex_set, "Vertices scored")
      ->check(CLI::IsMember({"all", "interior", "boundary-ring"}))
      ->capture_default_str();
  sub->add_flag("--json", a->json, "Print the errors as one JSON object");
  sub->footer(
      "Errors as in `curvbench run` (paper §5): normals absolute (L2 = RMS, Linf = max of "
      "|n~ - n|), curvatures relative (|k~ - k| / |k| in each norm), d1 up to sign over "
      "non-umbilic vertices. Vertices with NaN are counted as failed and left out of the "
      "errors. d2 columns are accepted and not scored. Exit 2 with a one-line message naming "
      "the row and column on a bad file.");
  return [a]() {
    const ScoreResult r = score_files(a->mesh, a->estimates, parse_vertex_set(a->vertex_set));
    const std::string out = a->json ? score_json(r, a->mesh, a->estimates) : score_text(r);
    std::fputs(out.c_str(), stdout);
    return 0;
  };
}

}  // namespace curvbench::cli
