// Where a point set's starting normals come from (option point-normals, docs/point_sets.md):
// pca and jet oriented over the neighbour graph, or the normals the file gives (file), whose
// signs the fits then follow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/errors.h"
#include "mesh/io.h"
#include "mesh/mesh.h"
#include "meshgen/point_samples.h"
#include "methods/estimator.h"
#include "methods/option_schema.h"
#include "points/point_normals.h"
#include "points/point_search.h"
#include "surfaces/torus.h"

namespace curvbench {
namespace {

constexpr double kRadius = 2.0;

// Points of a radius-2 sphere (directions of a torus sample: irregular, deterministic).
VertexMatrix sphere_points(int n) {
  const VertexMatrix T = sample_torus_points(n, 1.0, 0.5, 7);
  VertexMatrix V(n, 3);
  for (int i = 0; i < n; ++i) V.row(i) = kRadius * T.row(i).normalized();
  return V;
}

Mesh point_set_with_normals(VertexMatrix V, VertexMatrix normals = {}) {
  Mesh mesh(std::move(V), FaceMatrix(0, 3), "sphere.pwn");
  mesh.set_given_normals(std::move(normals));
  return mesh;
}

EstimatorOptions with_source(const std::string& source) {
  EstimatorOptions o;
  set_option(o, "point-normals", source);
  return o;
}

struct SignCount {
  int ok = 0, outward = 0, h_outward = 0, h_inward = 0;
};

// Estimated points whose normal points outward, and whose H is -1/r (outward normals) or +1/r
// (inward), each within 0.05.
SignCount count_signs(const Mesh& mesh, const std::vector<VertexEstimate>& est) {
  SignCount c;
  for (int i = 0; i < mesh.num_vertices(); ++i) {
    const VertexEstimate& o = est[static_cast<size_t>(i)];
    if (o.status != VertexStatus::ok) continue;
    ++c.ok;
    c.outward += o.normal.dot(mesh.position(i)) > 0.0;
    c.h_outward += std::abs(o.H + 1.0 / kRadius) < 0.05;
    c.h_inward += std::abs(o.H - 1.0 / kRadius) < 0.05;
  }
  return c;
}

TEST(PointNormalSources, OptionParsesAndDefaultsToPca) {
  const OptionInfo& info = option_info("point-normals");
  EXPECT_EQ(option_text(EstimatorOptions{}, info), "pca");
  for (const std::string text : {"jet", "file", "pca"})
    EXPECT_EQ(option_text(with_source(text), info), text);
  EXPECT_THROW(with_source("vcm"), UsageError);
}

// Each source on a sphere point set: outward normals, and H = -1/r at every point (APSS's H is
// as good as its normals: next test; with PCA's, 4 of these 2000 points get a small H > 0).
TEST(PointNormalSources, EverySourceGivesOutwardNormalsOnASphere) {
  const VertexMatrix V = sphere_points(2000);
  // The file's normals: outward, of lengths 0.5 to 2 (normalised by the reader's user).
  VertexMatrix given(V.rows(), 3);
  for (int i = 0; i < V.rows(); ++i) given.row(i) = (0.25 + (i % 7) * 0.25) * V.row(i);
  const Mesh mesh = point_set_with_normals(V, given);
  for (const std::string source : {"pca", "jet", "file"})
    for (const std::string method : {"lhf-2", "jet-2", "apss"}) {
      SCOPED_TRACE(source + " " + method);
      const auto est = estimate_mesh(mesh, *make_estimator(method, with_source(source)));
      const SignCount c = count_signs(mesh, est);
      EXPECT_EQ(c.ok, V.rows());
      EXPECT_EQ(c.outward, V.rows());
      if (method != "apss") {
        EXPECT_EQ(c.h_outward, V.rows());
      }
    }
}

// RMS of H + 1/r over the points.
double sphere_h_rms(const std::vector<VertexEstimate>& est) {
  double sum = 0.0;
  for (const VertexEstimate& o : est) sum += (o.H + 1.0 / kRadius) * (o.H + 1.0 / kRadius);
  return std::sqrt(sum / static_cast<double>(est.size()));
}

// APSS fits a sphere to the points and their normals, so its H is as good as the normals: exact
// with the exact normals (file), close with the jet's, off by a third with PCA's. Measured RMS
// of H + 1/2 on this sample: PCA 1.6e-1, jet 6.7e-4, file 3e-15. Asserted: the file's below
// 1e-9 and the jet's below a tenth of PCA's.
TEST(PointNormalSources, ApssIsAsAccurateAsItsNormals) {
  const VertexMatrix V = sphere_points(2000);
  const Mesh mesh = point_set_with_normals(V, V);
  double rms[3];
  const char* const sources[3] = {"pca", "jet", "file"};
  for (int s = 0; s < 3; ++s)
    rms[s] = sphere_h_rms(estimate_mesh(mesh, *make_estimator("apss", with_source(sources[s]))));
  std::printf("APSS H RMS error: pca %.3e, jet %.3e, file %.3e\n", rms[0], rms[1], rms[2]);
  EXPECT_LT(rms[2], 1e-9);
  EXPECT_LT(rms[1], rms[0] / 10.0);
}

// The fits take the file's sign: normals flipped inward give inward fitted normals and H = +1/r
// (B = n . x_uu with n inward), where pca and jet still orient outward.
TEST(PointNormalSources, FileNormalsFlippedInwardFlipTheFits) {
  const VertexMatrix V = sphere_points(2000);
  const Mesh mesh = point_set_with_normals(V, -V);
  for (const std::string method : {"lhf-2", "lop-2", "jet-2", "apss"}) {
    SCOPED_TRACE(method);
    const SignCount c =
        count_signs(mesh, estimate_mesh(mesh, *make_estimator(method, with_source("file"))));
    EXPECT_EQ(c.ok, V.rows());
    EXPECT_EQ(c.outward, 0);
    EXPECT_EQ(c.h_inward, V.rows());
    const SignCount pca = count_signs(mesh, estimate_mesh(mesh, *make_estimator(method, {})));
    EXPECT_EQ(pca.outward, V.rows());
  }
}

// A zero or non-finite given normal leaves that point's sign undecided: status
// sign_undetermined, never a silent sign; the others are estimated.
TEST(PointNormalSources, ZeroOrNonFiniteFileNormalIsSignUndetermined) {
  const VertexMatrix V = sphere_points(500);
  VertexMatrix given = V;
  given.row(3).setZero();
  given(7, 1) = std::nan("");
  given(9, 2) = INFINITY;
  const Mesh mesh = point_set_with_normals(V, given);
  const auto est = estimate_mesh(mesh, *make_estimator("lhf-2", with_source("file")));
  for (int i = 0; i < V.rows(); ++i) {
    const bool bad = i == 3 || i == 7 || i == 9;
    EXPECT_EQ(est[static_cast<size_t>(i)].status,
              bad ? VertexStatus::sign_undetermined : VertexStatus::ok)
        << i;
    EXPECT_TRUE(std::isfinite(est[static_cast<size_t>(i)].H)) << i;
  }
}

// file without normals: one line naming the file; jet or file on a mesh: one line saying why.
TEST(PointNormalSources, MissingNormalsAndMeshesAreRefusedWithOneLine) {
  const Mesh bare = point_set_with_normals(sphere_points(100));
  try {
    estimate_mesh(bare, *make_estimator("lhf-2", with_source("file")));
    ADD_FAILURE() << "estimated without normals";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("sphere.pwn: point-normals=file", 0), 0u) << what;
    EXPECT_NE(what.find("without normals"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  FaceMatrix F(1, 3);
  F << 0, 1, 2;
  const Mesh mesh(sphere_points(10), F, "tri.off");
  for (const std::string source : {"jet", "file"}) {
    try {
      estimate_mesh(mesh, *make_estimator("lhf-2", with_source(source)));
      ADD_FAILURE() << source << " accepted on a mesh";
    } catch (const UsageError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("point-normals=" + source + " applies to point sets: tri.off", 0), 0u)
          << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  EXPECT_NO_THROW(estimate_mesh(mesh, *make_estimator("lhf-2", with_source("pca"))));
}

// A .pwn file end to end: the reader keeps the normals and `file` uses them (flipped inward in
// the file: the fitted normals are inward too).
TEST(PointNormalSources, PwnFileNormalsReachTheFit) {
  const VertexMatrix V = sphere_points(800);
  const std::filesystem::path path =
      std::filesystem::path(::testing::TempDir()) / "point_normal_sources_inward.pwn";
  {
    std::ofstream out(path);
    out.precision(17);
    for (int i = 0; i < V.rows(); ++i)
      out << V(i, 0) << ' ' << V(i, 1) << ' ' << V(i, 2) << ' ' << -V(i, 0) << ' ' << -V(i, 1)
          << ' ' << -V(i, 2) << '\n';
  }
  const Mesh mesh = read_mesh(path.string());
  std::filesystem::remove(path);
  const SignCount c =
      count_signs(mesh, estimate_mesh(mesh, *make_estimator("lhf-2", with_source("file"))));
  EXPECT_EQ(c.ok, V.rows());
  EXPECT_EQ(c.outward, 0);
  EXPECT_EQ(c.h_inward, V.rows());
}

// The jet's normals do not depend on the thread count.
TEST(PointNormalSources, JetNormalsDoNotDependOnThreads) {
  const VertexMatrix V = sample_torus_points(3000, 1.0, 0.4, 11);
  const PointSearch search(V);
  const PointNormals one = oriented_jet_normals(search, 1);
  const PointNormals two = oriented_jet_normals(search, 2);
  ASSERT_EQ(std::memcmp(one.normals.data(), two.normals.data(),
                        sizeof(double) * static_cast<size_t>(one.normals.size())),
            0);
  EXPECT_EQ(one.undetermined, two.undetermined);
}

// RMS angle (radians) between the starting normals and the exact ones, and how many point to
// the wrong side.
struct AngleError {
  double rms = 0.0;
  int wrong_side = 0;
};

AngleError torus_normal_error(const PointNormals& pn, const VertexMatrix& V, const Torus& torus) {
  AngleError e;
  for (int i = 0; i < V.rows(); ++i) {
    const Vec3 exact = torus.evaluate(V.row(i).transpose()).normal;
    const Vec3 n = pn.normals.row(i).transpose();
    e.wrong_side += n.dot(exact) <= 0.0;
    const double angle = std::atan2(n.cross(exact).norm(), std::abs(n.dot(exact)));
    e.rms += angle * angle;
  }
  e.rms = std::sqrt(e.rms / static_cast<double>(V.rows()));
  return e;
}

// On noise-free torus samples (R = 1, r = 0.4) the jet's normals are more accurate than PCA's
// (same 16 neighbours): PCA's error is O(h) (the plane through curved points), the degree-2
// jet's O(h^2). Measured RMS angles (rad): 4k points PCA 4.67e-2, jet 4.46e-3; 16k PCA 2.30e-2,
// jet 1.09e-3. Asserted: the jet at most a third of PCA's at each size, every normal outward.
TEST(PointNormalSources, JetNormalsBeatPcaOnANoiseFreeTorus) {
  const Torus torus(1.0, 0.4);
  for (const int n : {4000, 16000}) {
    SCOPED_TRACE(n);
    const VertexMatrix V = sample_torus_points(n, 1.0, 0.4, 20261127);
    const PointSearch search(V);
    const AngleError pca = torus_normal_error(oriented_pca_normals(search, 2), V, torus);
    const AngleError jet = torus_normal_error(oriented_jet_normals(search, 2), V, torus);
    std::printf("n=%d normal RMS angle: PCA %.3e, jet %.3e\n", n, pca.rms, jet.rms);
    EXPECT_EQ(pca.wrong_side, 0);
    EXPECT_EQ(jet.wrong_side, 0);
    EXPECT_LT(jet.rms, pca.rms / 3.0);
  }
}

}  // namespace
}  // namespace curvbench
