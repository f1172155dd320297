// The batched fitting kernel (methods/kernels/batched_fit.h, EstimatorOptions::kernel) against the
// scalar reference path: LHF-1..4 and LOP-1..4 on every generated mesh family, on meshes with
// boundaries and irregular valences, with options that change the rows, and with a QR
// tolerance that sends many vertices back to the scalar path; and its determinism (threads,
// ranges).
//
// Agreement measure, per quantity: |a - b| <= 1e-10 max(|a|, |b|, scale), scale = 1 for the unit
// vectors (normal, d1, d2) and the largest |k1|, |k2| of the mesh (scalar run) for the
// curvatures (k1, k2, H; its square for K). Status, degree, points and ring must be equal.
// Principal directions are compared up to a common sign (a direction is a line; its sign follows
// the fitted gradient, which is rounding noise at a symmetric stencil) and only where they are
// defined to that accuracy: away from umbilics, |k1 - k2| > 1e-4 scale. At a (near-)umbilic point
// such as the top of the bump the directions are not determined by the data and may turn by any
// angle under a change of the last bits of the fit (their rounding error is about eps scale / |k1 -
// k2|).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "meshgen/generate.h"
#include "method_test_util.h"
#include "methods/estimator.h"

namespace curvbench {
namespace {

constexpr double kTol = 1e-10;

std::vector<VertexEstimate> run_with_kernel(const Mesh& mesh, const std::string& method,
                                            EstimatorOptions o, Kernel kernel, int threads = 1) {
  o.kernel = kernel;
  o.threads = threads;
  return estimate_mesh(mesh, *make_estimator(method, o));
}

bool close(double a, double b, double scale) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::abs(a - b) <= kTol * std::max({std::abs(a), std::abs(b), scale});
}

bool close(const Vec3& a, const Vec3& b, double scale) {
  for (int i = 0; i < 3; ++i)
    if (!close(a(i), b(i), scale)) return false;
  return true;
}

struct Comparison {
  int differing = 0;  // vertices outside the measure (or with another status, degree, ...)
  int compared_directions = 0;
  std::string first;  // the first such vertex, for the failure message
};

// Batched (b) against scalar (s), every vertex (see the file comment).
Comparison compare(const std::vector<VertexEstimate>& s, const std::vector<VertexEstimate>& b) {
  Comparison c;
  double kmax = 0.0;
  for (const VertexEstimate& e : s)
    if (std::isfinite(e.k1) && std::isfinite(e.k2))
      kmax = std::max({kmax, std::abs(e.k1), std::abs(e.k2)});
  for (size_t v = 0; v < s.size(); ++v) {
    const VertexEstimate& x = s[v];
    const VertexEstimate& y = b[v];
    bool same = x.status == y.status && x.degree == y.degree && x.points == y.points &&
                x.ring == y.ring && close(x.normal, y.normal, 1.0) && close(x.k1, y.k1, kmax) &&
                close(x.k2, y.k2, kmax) && close(x.H, y.H, kmax) && close(x.K, y.K, kmax * kmax);
    if (same && std::isfinite(x.k1) && std::abs(x.k1 - x.k2) > 1e-4 * kmax) {
      ++c.compared_directions;
      // Up to a common sign: d1 is a line (sign arbitrary, shape_operator.h); it follows the
      // direction of the fitted gradient, which at a symmetric stencil is rounding noise
      // (|grad| ~ 1e-17 on the structured torus), and d2 = normal x d1 follows d1. An
      // eigenvector moves by up to |dS| / |k1 - k2| when the shape operator moves by dS: with the
      // curvatures equal to kTol kmax, the directions are to kTol kmax / |k1 - k2| (near an
      // umbilic, e.g. the sphere's points, far more than kTol).
      const double scale = std::max(1.0, kmax / std::abs(x.k1 - x.k2));
      same = (close(x.d1, y.d1, scale) && close(x.d2, y.d2, scale)) ||
             (close(x.d1, Vec3(-y.d1), scale) && close(x.d2, Vec3(-y.d2), scale));
    }
    if (!same) {
      if (c.differing++ == 0) {
        std::ostringstream os;
        os.precision(17);
        os << "vertex " << v << ": status " << to_string(x.status) << "/" << to_string(y.status)
           << " points " << x.points << "/" << y.points << " k1 " << x.k1 << "/" << y.k1 << " k2 "
           << x.k2 << "/" << y.k2 << " n " << x.normal.transpose() << "/" << y.normal.transpose()
           << " d1 " << x.d1.transpose() << "/" << y.d1.transpose();
        c.first = os.str();
      }
    }
  }
  return c;
}

const char* const kMethods[] = {"lhf", "lop"};

// Every family at level 1, plus a noisy bump (noise order 2, as the experiments use).
std::vector<std::pair<std::string, Mesh>> family_meshes() {
  std::vector<std::pair<std::string, Mesh>> out;
  for (const std::string& f : mesh_families())
    out.emplace_back(f, generate_mesh({f, 1, 0, 1, false}).mesh);
  out.emplace_back("bump-48 noisy", generate_mesh({"bump-48", 1, 2, 7, false}).mesh);
  return out;
}

TEST(BatchedFit, EqualsScalarOnEveryFamily) {
  for (const auto& [name, mesh] : family_meshes()) {
    for (const char* method : kMethods) {
      for (int d = 1; d <= 4; ++d) {
        EstimatorOptions o;
        o.degree = d;
        o.noisy = name.find("noisy") != std::string::npos;
        const auto s = run_with_kernel(mesh, method, o, Kernel::scalar);
        const auto b = run_with_kernel(mesh, method, o, Kernel::batched);
        const Comparison c = compare(s, b);
        EXPECT_EQ(c.differing, 0) << name << " " << method << "-" << d << ": " << c.first;
        if (d >= 2) {  // degree 1 fits no second derivatives: k1 = k2 = 0, no directions
          EXPECT_GT(c.compared_directions, 0) << name << " " << method << "-" << d;
        }
      }
    }
  }
}

// Boundaries and valences 4 and 8, jittered interior (irregular stencils), on a curved sheet.
TEST(BatchedFit, EqualsScalarOnBoundariesAndIrregularValences) {
  const auto sheet = [](double x, double y) {
    return Vec3(x, y, 0.3 * std::sin(2.0 * x) * std::cos(1.5 * y) + 0.1 * x * y);
  };
  const Mesh meshes[] = {testing::grid_mesh(12, 0.1, true, 0.3, 5, sheet),
                         testing::grid_mesh(9, 0.15, false, 0.35, 9, sheet)};
  for (const Mesh& mesh : meshes)
    for (const char* method : kMethods)
      for (int d = 1; d <= 4; ++d) {
        EstimatorOptions o;
        o.degree = d;
        const Comparison c = compare(run_with_kernel(mesh, method, o, Kernel::scalar),
                                     run_with_kernel(mesh, method, o, Kernel::batched));
        EXPECT_EQ(c.differing, 0) << method << "-" << d << ": " << c.first;
      }
}

// Options that change the rows and weights (centre row, safeguard, ring, no growth), and a QR
// tolerance so high that many lanes fail the safeguard and take the scalar path (degree
// reduction and growth included).
TEST(BatchedFit, EqualsScalarWithOtherOptionsAndFallbacks) {
  const Mesh mesh = generate_mesh({"bump-irregular", 1, 0, 1, false}).mesh;
  int reduced = 0;
  for (const char* method : kMethods)
    for (int d = 1; d <= 4; ++d)
      for (int variant = 0; variant < 5; ++variant) {
        EstimatorOptions o;
        o.degree = d;
        if (variant == 0) o.include_centre = false;
        if (variant == 1) o.normal_safeguard = false;
        if (variant == 2) o.rings = 2.0;
        if (variant == 3) o.adaptive = false;
        if (variant == 4) o.qr_tolerance = 0.2;
        const auto s = run_with_kernel(mesh, method, o, Kernel::scalar);
        const Comparison c = compare(s, run_with_kernel(mesh, method, o, Kernel::batched));
        EXPECT_EQ(c.differing, 0) << method << "-" << d << " variant " << variant << ": "
                                  << c.first;
        if (variant == 4)
          for (const VertexEstimate& e : s) reduced += e.status == VertexStatus::degree_reduced;
      }
  EXPECT_GT(reduced, 0) << "the high tolerance should reduce degrees (scalar fallback untested)";
}

// bump-48 level 4, degree 4: at boundary vertices whose ring lies on four grid lines the
// safeguard's condition test (||R^-1||_F > 1 / tol, safeguarded_qr.cpp) fails while every |R_jj|
// passes; the batched kernel must send those lanes to the scalar path.
TEST(BatchedFit, EqualsScalarWhereTheConditionTestFires) {
  const Mesh mesh = generate_mesh({"bump-48", 4, 0, 1, false}).mesh;
  for (const char* method : kMethods) {
    EstimatorOptions o;
    o.degree = 4;
    const auto s = run_with_kernel(mesh, method, o, Kernel::scalar);
    const Comparison c = compare(s, run_with_kernel(mesh, method, o, Kernel::batched));
    EXPECT_EQ(c.differing, 0) << method << "-4: " << c.first;
    // Vertex 64 = (0.5, 0): its 3-ring (28 rows) lies on four grid lines; the fit grows the
    // ring to 3.5 and keeps degree 4.
    EXPECT_EQ(s[64].degree, 4) << method;
    EXPECT_EQ(s[64].ring, 3.5) << method;
    EXPECT_GT(s[64].points, 28) << method;
    // qr-condition=no (the |R_jj| test alone): the batch keeps those lanes too, and the vertex
    // keeps its 3-ring at degree 4.
    o.qr_condition = false;
    const auto rjj = run_with_kernel(mesh, method, o, Kernel::scalar);
    const Comparison c_rjj = compare(rjj, run_with_kernel(mesh, method, o, Kernel::batched));
    EXPECT_EQ(c_rjj.differing, 0) << method << "-4 qr-condition=no: " << c_rjj.first;
    EXPECT_EQ(rjj[64].degree, 4) << method;
    EXPECT_EQ(rjj[64].ring, 3.0) << method;
    EXPECT_EQ(rjj[64].points, 28) << method;
  }
}

bool same_bytes(const std::vector<VertexEstimate>& a, const std::vector<VertexEstimate>& b) {
  if (a.size() != b.size()) return false;
  for (size_t v = 0; v < a.size(); ++v) {
    const VertexEstimate& x = a[v];
    const VertexEstimate& y = b[v];
    const double xs[] = {x.normal(0), x.normal(1), x.normal(2), x.k1,    x.k2,    x.H,     x.K,
                         x.d1(0),     x.d1(1),     x.d1(2),     x.d2(0), x.d2(1), x.d2(2), x.ring};
    const double ys[] = {y.normal(0), y.normal(1), y.normal(2), y.k1,    y.k2,    y.H,     y.K,
                         y.d1(0),     y.d1(1),     y.d1(2),     y.d2(0), y.d2(1), y.d2(2), y.ring};
    if (std::memcmp(xs, ys, sizeof xs) != 0 || x.status != y.status || x.degree != y.degree ||
        x.points != y.points)
      return false;
  }
  return true;
}

// A lane's result must not depend on which vertices share its batch (their row counts set the
// batch's padding): ranges split at offsets that are not multiples of the batch width regroup
// the lanes, on meshes with irregular valences and a boundary.
TEST(BatchedFit, SameBytesForAnyThreadCountAndRangeSplit) {
  for (const char* family : {"torus-unstructured", "bump-irregular"}) {
    const Mesh mesh = generate_mesh({family, 1, 0, 1, false}).mesh;
    for (const char* method : kMethods)
      for (int d : {2, 4}) {
        EstimatorOptions o;
        o.degree = d;
        const auto one = run_with_kernel(mesh, method, o, Kernel::batched, 1);
        EXPECT_TRUE(same_bytes(one, run_with_kernel(mesh, method, o, Kernel::batched, 2)))
            << family << method << d;
        o.kernel = Kernel::batched;
        o.threads = 2;
        const auto est = make_estimator(method, o);
        MeshEstimation me(mesh, *est);
        for (int shift : {1, 3, 6}) {
          std::vector<VertexEstimate> split(static_cast<size_t>(mesh.num_vertices()));
          const int half = mesh.num_vertices() / 2 + shift;
          me.run(0, std::span(split).first(static_cast<size_t>(half)));
          me.run(half, std::span(split).subspan(static_cast<size_t>(half)));
          EXPECT_TRUE(same_bytes(one, split)) << family << method << d << " shift " << shift;
        }
      }
  }
}

}  // namespace
}  // namespace curvbench
