// The Schwarz lantern families; see lantern.h.
#include "meshgen/lantern.h"

#include <cstdio>
#include <numbers>
#include <string>

#include "core/errors.h"
#include "meshgen/torus_structured.h"
#include "surfaces/cylinder.h"

namespace curvbench {

namespace {
constexpr double kHeight = 2.0;  // z in [-1, 1]
}  // namespace

LanternSize lantern_size(bool squeezed, int level) {
  if (squeezed) {
    constexpr int kSectors[] = {14, 20, 28, 40};  // about sqrt(2) per level
    const int n = kSectors[level - 1];
    return {n, n * n / 4};
  }
  const int n = 16 << (level - 1);
  return {n, n / 2};
}

GeneratedMesh lantern_mesh(LanternSize size) {
  const int n = size.sectors, m = size.slices;
  if (n < 3 || m < 1)
    throw UsageError("lantern: need at least 3 sectors and 1 slice (got " + std::to_string(n) +
                     " sectors, " + std::to_string(m) + " slices)");
  SurfacePtr cylinder = make_cylinder(1.0);
  const double du = 2.0 * std::numbers::pi / n;
  VertexMatrix V((m + 1) * n, 3);
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i < n; ++i)
      V.row(j * n + i) =
          cylinder->position((i + 0.5 * (j % 2)) * du, -0.5 * kHeight + kHeight * j / m)
              .transpose();
  // Band j joins ring j to ring j + 1; the offset ring's vertex i lies between the other's i
  // and i + 1. Corners in the order (u, then z) make x_u x x_z, the outward normal.
  FaceMatrix F = staggered_tube_faces(n, m);
  GeneratedMesh out;
  out.exact_points = V;
  out.mesh = Mesh(std::move(V), std::move(F), "lantern");
  out.surface = std::move(cylinder);
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "Schwarz lantern of the cylinder r=1, z in [-1,1]: %d sectors x %d slices, odd "
                "rings turned by pi/%d",
                n, m, n);
  out.description = buf;
  return out;
}

namespace {

GeneratedMesh lantern_family(const MeshSpec& spec, bool squeezed) {
  GeneratedMesh gm = lantern_mesh(lantern_size(squeezed, spec.level));
  gm.family = spec.family;
  gm.level = spec.level;
  gm.description = spec.family + " level " + std::to_string(spec.level) + ": " + gm.description;
  return gm;
}

}  // namespace

GeneratedMesh generate_lantern(const MeshSpec& spec) {
  return lantern_family(spec, false);
}

GeneratedMesh generate_lantern_squeezed(const MeshSpec& spec) {
  return lantern_family(spec, true);
}

}  // namespace curvbench
