#include "meshgen/marching_cubes.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "core/errors.h"
#include "meshgen/marching_cubes_tables.h"

namespace curvbench {

std::vector<double> matlab_linspace(double a, double b, int n) {
  if (n < 2) throw UsageError("linspace: need at least 2 points, got " + std::to_string(n));
  std::vector<double> v(n);
  for (int i = 0; i < n - 1; ++i) v[i] = a + (i * (b - a)) / (n - 1);
  v[n - 1] = b;
  return v;
}

namespace {

void check_axis(std::span<const double> a, const char* name) {
  if (a.size() < 2)
    throw UsageError(std::string("marching_cubes: axis ") + name + " needs at least 2 points");
  if (a.size() > 1u << 15)
    throw UsageError(std::string("marching_cubes: axis ") + name + " has too many points");
  for (size_t i = 0; i + 1 < a.size(); ++i) {
    if (!(a[i] < a[i + 1]))
      throw UsageError(std::string("marching_cubes: axis ") + name + " is not strictly increasing");
  }
}

// Asymptotic decider on one cube face with corner values c[0..3] in cyclic order, two diagonal
// corners inside (< 0): the outside corners are connected iff the bilinear interpolant is >= 0
// at its saddle, i.e. iff f_out1 * f_out2 >= f_in1 * f_in2. The products commute exactly, so both
// cells sharing the face get the same answer.
bool outside_connected(double c0, double c1, double c2, double c3) {
  const double p02 = c0 * c2, p13 = c1 * c3;
  return c0 < 0.0 ? p13 >= p02 : p02 >= p13;
}

}  // namespace

IsosurfaceMesh marching_cubes(std::span<const double> x, std::span<const double> y,
                              std::span<const double> z,
                              const std::function<double(double, double, double)>& f) {
  check_axis(x, "x");
  check_axis(y, "y");
  check_axis(z, "z");
  const int nx = static_cast<int>(x.size()), ny = static_cast<int>(y.size()),
            nz = static_cast<int>(z.size());
  const mc::CaseTables& tables = mc::case_tables();

  std::vector<double> s0(static_cast<size_t>(nx) * ny), s1(s0.size());
  std::vector<int> xe0(static_cast<size_t>(nx - 1) * ny, -1), xe1(xe0.size(), -1);
  std::vector<int> ye0(static_cast<size_t>(nx) * (ny - 1), -1), ye1(ye0.size(), -1);
  std::vector<int> ze(static_cast<size_t>(nx) * ny, -1);
  std::vector<double> verts;  // 3 per vertex
  std::vector<int> tris;      // 3 per face
  int ambiguous = 0, centers = 0;

  std::vector<std::uint8_t> in0(s0.size()), in1(s0.size());  // 1 iff inside (f < 0)
  auto sample_slice = [&](int k, std::vector<double>& s, std::vector<std::uint8_t>& in) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const double v = f(x[i], y[j], z[k]);
        if (!std::isfinite(v)) {
          std::ostringstream msg;
          msg << "marching_cubes: sample (" << i << ", " << j << ", " << k << ") at (" << x[i]
              << ", " << y[j] << ", " << z[k] << ") is not finite";
          throw InputError(msg.str());
        }
        s[static_cast<size_t>(j) * nx + i] = v;
        in[static_cast<size_t>(j) * nx + i] = v < 0.0 ? 1 : 0;
      }
    }
  };
  // Vertex on the grid edge from a to b (a the lower index), t = (0 - f_a)/(f_b - f_a).
  auto add_vertex = [&](double xa, double ya, double za, double xb, double yb, double zb, double fa,
                        double fb) {
    const double t = (0.0 - fa) / (fb - fa);  // fa, fb differ in sign: fb - fa != 0
    verts.push_back(xa + t * (xb - xa));
    verts.push_back(ya + t * (yb - ya));
    verts.push_back(za + t * (zb - za));
    return static_cast<int>(verts.size() / 3 - 1);
  };
  auto slice_edges = [&](int k, const std::vector<double>& s, std::vector<int>& xe,
                         std::vector<int>& ye) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i + 1 < nx; ++i) {
        const double fa = s[j * nx + i], fb = s[j * nx + i + 1];
        xe[j * (nx - 1) + i] = (fa < 0.0) != (fb < 0.0)
                                   ? add_vertex(x[i], y[j], z[k], x[i + 1], y[j], z[k], fa, fb)
                                   : -1;
      }
    }
    for (int j = 0; j + 1 < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const double fa = s[j * nx + i], fb = s[(j + 1) * nx + i];
        ye[j * nx + i] = (fa < 0.0) != (fb < 0.0)
                             ? add_vertex(x[i], y[j], z[k], x[i], y[j + 1], z[k], fa, fb)
                             : -1;
      }
    }
  };

  sample_slice(0, s0, in0);
  slice_edges(0, s0, xe0, ye0);
  for (int k = 0; k + 1 < nz; ++k) {
    sample_slice(k + 1, s1, in1);
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const double fa = s0[j * nx + i], fb = s1[j * nx + i];
        ze[j * nx + i] = (fa < 0.0) != (fb < 0.0)
                             ? add_vertex(x[i], y[j], z[k], x[i], y[j], z[k + 1], fa, fb)
                             : -1;
      }
    }
    slice_edges(k + 1, s1, xe1, ye1);

    for (int j = 0; j + 1 < ny; ++j) {
      for (int i = 0; i + 1 < nx; ++i) {
        const int p = j * nx + i, q = p + nx;
        const int cube_case = in0[p] | in0[p + 1] << 1 | in0[q + 1] << 2 | in0[q] << 3 |
                              in1[p] << 4 | in1[p + 1] << 5 | in1[q + 1] << 6 | in1[q] << 7;
        if (cube_case == 0 || cube_case == 255) continue;
        const std::array<double, 8> v = {s0[p], s0[p + 1], s0[q + 1], s0[q],
                                         s1[p], s1[p + 1], s1[q + 1], s1[q]};

        int decisions = 0;
        const int amb = tables.ambiguous_faces(cube_case);
        for (int fq = 0; amb != 0 && fq < 6; ++fq) {
          if (!((amb >> fq) & 1)) continue;
          const auto& fc = mc::kFaceCorner[fq];
          if (outside_connected(v[fc[0]], v[fc[1]], v[fc[2]], v[fc[3]])) decisions |= 1 << fq;
          // Count each grid face once: the '+' faces, and '-' faces on the grid boundary.
          const bool plus = fq % 2 == 1;
          const bool low_boundary =
              (fq == 0 && k == 0) || (fq == 2 && j == 0) || (fq == 4 && i == 0);
          if (plus || low_boundary) ++ambiguous;
        }

        const int xr = j * (nx - 1) + i;
        const std::array<int, 12> edge_vertex = {xe0[xr], ye0[p + 1], xe0[xr + (nx - 1)], ye0[p],
                                                 xe1[xr], ye1[p + 1], xe1[xr + (nx - 1)], ye1[p],
                                                 ze[p],   ze[p + 1],  ze[q + 1],          ze[q]};
        for (std::int8_t e : tables.triangles(cube_case, decisions)) tris.push_back(edge_vertex[e]);
        const auto centered = tables.centered_polygons(cube_case, decisions);
        for (size_t r = 0; r < centered.size(); r += centered[r] + 1) {
          const int len = centered[r];
          double cx = 0.0, cy = 0.0, cz = 0.0;
          for (int m = 1; m <= len; ++m) {
            const size_t vi = 3 * static_cast<size_t>(edge_vertex[centered[r + m]]);
            cx += verts[vi];
            cy += verts[vi + 1];
            cz += verts[vi + 2];
          }
          verts.insert(verts.end(), {cx / len, cy / len, cz / len});
          const int center = static_cast<int>(verts.size() / 3 - 1);
          ++centers;
          for (int m = 1; m <= len; ++m) {
            tris.insert(tris.end(), {edge_vertex[centered[r + m]],
                                     edge_vertex[centered[r + 1 + m % len]], center});
          }
        }
      }
    }
    std::swap(s0, s1);
    std::swap(in0, in1);
    std::swap(xe0, xe1);
    std::swap(ye0, ye1);
  }

  IsosurfaceMesh out;
  const Eigen::Index nv = static_cast<Eigen::Index>(verts.size() / 3);
  const Eigen::Index nf = static_cast<Eigen::Index>(tris.size() / 3);
  out.vertices = Eigen::Map<const VertexMatrix>(verts.data(), nv, 3);
  out.faces = Eigen::Map<const FaceMatrix>(tris.data(), nf, 3);
  out.ambiguous_faces = ambiguous;
  out.center_vertices = centers;
  return out;
}

}  // namespace curvbench
