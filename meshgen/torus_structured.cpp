#include "meshgen/torus_structured.h"

#include <cstdio>
#include <numbers>
#include <string>

#include "core/errors.h"
#include "meshgen/random.h"
#include "surfaces/torus.h"

namespace curvbench {

namespace {
constexpr double kJitterCells = 0.15;  // docs/algorithms.md §10.1(b) [CH]
// Levels 1-4 (V = 1408 .. 90112) are those of docs/algorithms.md §10.1(b); 5 and 6 (360448 and
// 1441792 vertices) are beyond the paper, for the linear-scaling benchmark (docs/performance.md).
constexpr int kMaxLevel = 6;
}  // namespace

int torus_structured_rows(int level) {
  return 22 << (level - 1);
}
int torus_structured_columns(int level) {
  return 64 << (level - 1);
}

namespace {
// Band j joins row j to row j + 1 (row `rows`, if any, is row 0 again: a closed tube).
FaceMatrix staggered_faces(int nu, int bands, int rows) {
  auto idx = [nu, rows](int i, int j) { return (j % rows) * nu + (i % nu); };
  FaceMatrix F(2 * nu * bands, 3);
  int f = 0;
  for (int j = 0; j < bands; ++j) {
    for (int i = 0; i < nu; ++i) {
      if (j % 2 == 0) {
        F.row(f++) << idx(i, j), idx(i + 1, j), idx(i, j + 1);
        F.row(f++) << idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1);
      } else {
        F.row(f++) << idx(i, j), idx(i + 1, j + 1), idx(i, j + 1);
        F.row(f++) << idx(i, j), idx(i + 1, j), idx(i + 1, j + 1);
      }
    }
  }
  return F;
}
}  // namespace

FaceMatrix staggered_torus_faces(int nu, int nv) {
  return staggered_faces(nu, nv, nv);
}

FaceMatrix staggered_tube_faces(int nu, int bands) {
  return staggered_faces(nu, bands, bands + 1);
}

GeneratedMesh torus_structured(int level, bool jitter, std::uint64_t seed) {
  if (level < 1 || level > kMaxLevel)
    throw UsageError("torus-structured: level " + std::to_string(level) + " out of range [1, " +
                     std::to_string(kMaxLevel) + "]");
  const int nv = torus_structured_rows(level);
  const int nu = torus_structured_columns(level);
  const double R = 1.0, r = 0.3;
  SurfacePtr torus = make_torus(R, r);

  const double du = 2.0 * std::numbers::pi / nu;
  const double dv = 2.0 * std::numbers::pi / nv;
  Rng rng(derive_seed(seed, static_cast<std::uint64_t>(level)));
  VertexMatrix V(nu * nv, 3);
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      double u = (i + 0.5 * (j % 2)) * du;
      double v = j * dv;
      if (jitter) {
        u += rng.uniform(-kJitterCells, kJitterCells) * du;
        v += rng.uniform(-kJitterCells, kJitterCells) * dv;
      }
      V.row(j * nu + i) = torus->position(u, v).transpose();
    }
  }

  FaceMatrix F = staggered_torus_faces(nu, nv);

  GeneratedMesh out;
  out.exact_points = V;
  out.mesh = Mesh(std::move(V), std::move(F), "torus-structured");
  out.surface = std::move(torus);
  out.family = "torus-structured";
  out.level = level;
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "torus-structured level %d: torus R=1 r=0.3, staggered structured mesh "
                "(docs/algorithms.md 10.1b), n_u=%d n_v=%d, jitter=%s",
                level, nu, nv, jitter ? "U(-0.15,0.15) cells" : "off");
  out.description = buf;
  if (jitter) out.description += " seed=" + std::to_string(seed);
  return out;
}

}  // namespace curvbench
