// LSCM ring maps (methods/fits/lscm_parameterization.h) and the LSCM-d estimators "lscm" (CGAL map)
// and "lscm-fast" (in-house map), docs/algorithms.md §8.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "core/errors.h"
#include "mesh/rings.h"
#include "meshgen/bump_grid.h"
#include "meshgen/torus_structured.h"
#include "method_test_util.h"
#include "methods/estimator.h"
#include "methods/fits/lscm.h"
#include "methods/fits/lscm_parameterization.h"
#include "real_mesh_util.h"

namespace curvbench {
namespace {

using testing::grid_mesh;
using testing::icosphere;
using testing::rotation;

constexpr LscmMapOptions kCgalCompatible{LscmPins::bounding_box, false};

// Best similarity U ~ a z + b (complex a, b; orientation preserving) in least squares; returns
// max_i |U_i - a z_i - b| / (|a| * max_i |z_i - z_0|), i.e. relative to the patch size.
double similarity_residual(const std::vector<Vec2>& z, const std::vector<Vec2>& U) {
  const Eigen::Index n = static_cast<Eigen::Index>(z.size());
  Eigen::MatrixXcd A(n, 2);
  Eigen::VectorXcd y(n);
  double size = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    A(i, 0) = std::complex<double>(z[static_cast<size_t>(i)].x(), z[static_cast<size_t>(i)].y());
    A(i, 1) = 1.0;
    y(i) = std::complex<double>(U[static_cast<size_t>(i)].x(), U[static_cast<size_t>(i)].y());
    size = std::max(size, (z[static_cast<size_t>(i)] - z[0]).norm());
  }
  const Eigen::VectorXcd ab = A.colPivHouseholderQr().solve(y);
  return (A * ab - y).cwiseAbs().maxCoeff() / (std::abs(ab(0)) * size);
}

// A jittered valence-6 grid in a tilted plane, with the in-plane coordinates of every vertex.
struct PlanarPatch {
  Mesh mesh;
  Mat3 R;
  int centre;
};

PlanarPatch planar_patch() {
  const Mat3 R = rotation(0.3, 1.1, -0.7);
  const Vec3 o(0.2, -0.4, 1.5);
  PlanarPatch p{grid_mesh(8, 0.1, false, 0.3, 17,
                          [&](double x, double y) { return Vec3(o + R * Vec3(x, y, 0.0)); }),
                R, 4 * 9 + 4};
  return p;
}

std::vector<Vec2> in_plane(const PlanarPatch& p, const RingCollector& rc) {
  std::vector<Vec2> z;
  const Vec3 o = p.mesh.position(rc.center());
  auto add = [&](int w) {
    const Vec3 q = p.R.transpose() * (p.mesh.position(w) - o);
    z.emplace_back(q.x(), q.y());
  };
  add(rc.center());
  for (int w : rc.neighbours()) add(w);
  return z;
}

TEST(LscmMap, PlanarPatchIsReproducedUpToASimilarity) {
  const PlanarPatch p = planar_patch();
  RingCollector rc(p.mesh);
  for (double ring : {1.0, 1.5, 2.0, 3.0}) {
    rc.collect(p.centre, ring);
    const std::vector<Vec2> z = in_plane(p, rc);
    std::vector<Vec2> uv;
    LscmMap fast(p.mesh);
    ASSERT_TRUE(fast.map(p.centre, rc.neighbours(), rc.faces(), uv));
    EXPECT_EQ(uv.size(), z.size());
    EXPECT_EQ(uv[0], Vec2::Zero());
    EXPECT_GT(mapped_signed_area(fast.patch(), uv), 0.0);
    EXPECT_LT(similarity_residual(z, uv), 1e-12) << "ring " << ring;

    LscmMap compatible(p.mesh, kCgalCompatible);
    ASSERT_TRUE(compatible.map(p.centre, rc.neighbours(), rc.faces(), uv));
    EXPECT_LT(similarity_residual(z, uv), 1e-12) << "ring " << ring;

    CgalLscmMap cgal(p.mesh);
    ASSERT_TRUE(cgal.map(p.centre, rc.neighbours(), rc.faces(), uv));
    EXPECT_EQ(uv[0], Vec2::Zero());
    EXPECT_GT(mapped_signed_area(cgal.patch(), uv), 0.0);
    EXPECT_LT(similarity_residual(z, uv), 1e-10) << "ring " << ring;
  }
}

// On a curved patch the LSCM minimiser depends on which two vertices are pinned. With CGAL's
// pins and CGAL's (unnormalised) energy the in-house map is CGAL's map up to a similarity;
// with other pins or Levy's area normalisation it differs, but only slightly.
TEST(LscmMap, CurvedPatchCgalAndInHouseAgreeWithTheSamePinsAndEnergy) {
  const Mesh sphere = icosphere(3, 2.0);
  const GeneratedMesh torus = torus_structured(1, true, 5);
  for (const Mesh* mesh : {&sphere, &torus.mesh}) {
    RingCollector rc(*mesh);
    CgalLscmMap cgal(*mesh);
    LscmMap compatible(*mesh, kCgalCompatible);
    LscmMap farthest_unnormalised(*mesh, {LscmPins::farthest_pair, false});
    LscmMap levy(*mesh);
    double worst_same = 0.0, worst_other = 0.0, worst_levy = 0.0;
    for (int v = 0; v < mesh->num_vertices(); v += 37) {
      for (double ring : {1.5, 2.0, 2.5}) {
        rc.collect(v, ring);
        std::vector<Vec2> a, b, c, d;
        ASSERT_TRUE(cgal.map(v, rc.neighbours(), rc.faces(), a));
        ASSERT_TRUE(compatible.map(v, rc.neighbours(), rc.faces(), b));
        ASSERT_TRUE(farthest_unnormalised.map(v, rc.neighbours(), rc.faces(), c));
        ASSERT_TRUE(levy.map(v, rc.neighbours(), rc.faces(), d));
        worst_same = std::max(worst_same, similarity_residual(a, b));
        worst_other = std::max(worst_other, similarity_residual(a, c));
        worst_levy = std::max(worst_levy, similarity_residual(a, d));
      }
    }
    std::printf(
        "similarity residual vs CGAL (max): same pins/energy %.2e, farthest pins %.2e, "
        "default in-house %.2e\n",
        worst_same, worst_other, worst_levy);
    EXPECT_LT(worst_same, 1e-10);
    // Where the farthest pair is another pair of vertices the map is genuinely different (far
    // above round-off), though close: the patches are nearly developable.
    EXPECT_GT(worst_other, 1e-6);
    EXPECT_LT(worst_other, 1e-2);
    EXPECT_LT(worst_levy, 1e-2);
  }
}

TEST(LscmMap, OpenNlConjugateGradientsAgreeWithLdltToTheirTolerance) {
  const Mesh sphere = icosphere(3, 2.0);
  RingCollector rc(sphere);
  CgalLscmMap ldlt(sphere), cg(sphere, CgalLscmSolver::opennl_cg);
  double worst = 0.0;
  for (int v = 0; v < sphere.num_vertices(); v += 29) {
    for (double ring : {2.0, 3.5}) {
      rc.collect(v, ring);
      std::vector<Vec2> a, b;
      ASSERT_TRUE(ldlt.map(v, rc.neighbours(), rc.faces(), a));
      ASSERT_TRUE(cg.map(v, rc.neighbours(), rc.faces(), b));
      worst = std::max(worst, similarity_residual(a, b));
    }
  }
  std::printf("OpenNL CG vs Eigen LDLT: similarity residual %.2e\n", worst);
  // CG stops at a relative residual of 1e-6; on these small systems it ends far below that.
  EXPECT_LT(worst, 1e-4);
}

TEST(LscmMap, NormalisationTranslatesAndFlipsClockwiseMaps) {
  const PlanarPatch p = planar_patch();
  RingCollector rc(p.mesh);
  rc.collect(p.centre, 1.0);
  RingPatch patch(p.mesh);
  ASSERT_TRUE(patch.build(p.centre, rc.neighbours(), rc.faces()));
  std::vector<Vec2> z = in_plane(p, rc);
  for (Vec2& q : z) q = Vec2(3.0 + q.x(), 1.0 - q.y());  // mirrored and shifted
  EXPECT_LT(mapped_signed_area(patch, z), 0.0);
  ASSERT_TRUE(normalise_patch_map(patch, z));
  EXPECT_EQ(z[0], Vec2::Zero());
  EXPECT_GT(mapped_signed_area(patch, z), 0.0);
  EXPECT_LT(similarity_residual(in_plane(p, rc), z), 1e-14);
  std::vector<Vec2> flat(z.size(), Vec2(1.0, 2.0));
  EXPECT_FALSE(normalise_patch_map(patch, flat));  // zero area
  z[3].x() = std::nan("");
  EXPECT_FALSE(normalise_patch_map(patch, z));
}

// The orientation of the map follows the faces: reversing every face mirrors the map.
TEST(LscmMap, MapFollowsTheFaceOrientation) {
  const PlanarPatch p = planar_patch();
  FaceMatrix F = p.mesh.faces();
  F.col(1).swap(F.col(2));
  const Mesh flipped(p.mesh.vertices(), F);
  RingCollector rc(p.mesh), rf(flipped);
  rc.collect(p.centre, 2.0);
  rf.collect(p.centre, 2.0);
  std::vector<Vec2> z = in_plane(p, rc), uv;
  for (Vec2& q : z) q.y() = -q.y();
  LscmMap fast(flipped);
  CgalLscmMap cgal(flipped);
  ASSERT_TRUE(fast.map(p.centre, rf.neighbours(), rf.faces(), uv));
  EXPECT_LT(similarity_residual(z, uv), 1e-12);
  ASSERT_TRUE(cgal.map(p.centre, rf.neighbours(), rf.faces(), uv));
  EXPECT_LT(similarity_residual(z, uv), 1e-10);
}

// Rows of uv that are finite; the others must be NaN in both coordinates.
int finite_rows(const std::vector<Vec2>& uv) {
  int finite = 0;
  for (const Vec2& p : uv) {
    if (p.allFinite()) {
      ++finite;
    } else {
      EXPECT_TRUE(std::isnan(p.x()) && std::isnan(p.y()));
    }
  }
  return finite;
}

TEST(LscmMap, RejectsInvalidRings) {
  const PlanarPatch p = planar_patch();
  RingCollector rc(p.mesh);
  rc.collect(p.centre, 2.0);
  const std::vector<int> nb(rc.neighbours().begin(), rc.neighbours().end());
  const std::vector<int> faces(rc.faces().begin(), rc.faces().end());
  LscmMap fast(p.mesh);
  CgalLscmMap cgal(p.mesh);
  std::vector<Vec2> uv;
  auto both = [&](int c, const std::vector<int>& n, const std::vector<int>& f) {
    const bool a = fast.map(c, n, f, uv);
    const bool b = cgal.map(c, n, f, uv);
    EXPECT_EQ(a, b);
    return a;
  };
  EXPECT_TRUE(both(p.centre, nb, faces));
  EXPECT_FALSE(fast.patch().cut());
  // A face whose vertex is not listed, a repeated vertex, a repeated face, no faces, invalid
  // indices.
  std::vector<int> missing_vertex = nb;
  missing_vertex.pop_back();
  EXPECT_FALSE(both(p.centre, missing_vertex, faces));
  std::vector<int> repeated_vertex = nb;
  repeated_vertex.push_back(nb[0]);
  EXPECT_FALSE(both(p.centre, repeated_vertex, faces));
  std::vector<int> repeated_face = faces;
  repeated_face.push_back(faces[0]);
  EXPECT_FALSE(both(p.centre, nb, repeated_face));
  EXPECT_FALSE(both(p.centre, {}, {}));
  EXPECT_FALSE(both(p.centre, {nb[0]}, {faces[0]}));
  EXPECT_FALSE(both(-1, nb, faces));
  EXPECT_FALSE(both(p.centre, nb, {-1}));

  // A bowtie whose first triangle has three coincident corners: the disk cut keeps only it, and
  // both maps refuse it (CGAL's border parameterizer would crash on it).
  VertexMatrix V(5, 3);
  V << 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, -1, 0;
  FaceMatrix F(2, 3);
  F << 0, 1, 2, 0, 3, 4;
  const Mesh collapsed(V, F);
  LscmMap f2(collapsed);
  CgalLscmMap c2(collapsed);
  const std::vector<int> n{1, 2, 3, 4}, fs{0, 1};
  EXPECT_FALSE(f2.map(0, n, fs, uv));
  EXPECT_FALSE(c2.map(0, n, fs, uv));
}

// A ring that is not a disk is cut to one around the centre: the patch's own vertices are mapped
// (still exactly, up to a similarity, on a plane), the others get NaN.
TEST(LscmMap, CutsRingsThatAreNotDisks) {
  const PlanarPatch p = planar_patch();
  RingCollector rc(p.mesh);
  rc.collect(p.centre, 2.0);
  const std::vector<int> nb(rc.neighbours().begin(), rc.neighbours().end());
  const std::vector<int> faces(rc.faces().begin(), rc.faces().end());
  const std::vector<Vec2> z = in_plane(p, rc);
  LscmMap fast(p.mesh);
  CgalLscmMap cgal(p.mesh);
  std::vector<Vec2> uv;
  const auto finite_part = [](const std::vector<Vec2>& a, const std::vector<Vec2>& mask) {
    std::vector<Vec2> out;
    for (size_t i = 0; i < a.size(); ++i)
      if (mask[i].allFinite()) out.push_back(a[i]);
    return out;
  };

  // An annulus: drop one face incident on the centre (its vertices stay in other faces). The cut
  // keeps every vertex and all faces but two: one face alone cannot open an annulus whose hole
  // touches its outer boundary only through interior edges (removing it leaves a pinch vertex),
  // a strip of two from the hole to the outer boundary can.
  std::vector<int> holed = faces;
  holed.erase(holed.begin());
  for (bool use_cgal : {false, true}) {
    const bool ok =
        use_cgal ? cgal.map(p.centre, nb, holed, uv) : fast.map(p.centre, nb, holed, uv);
    ASSERT_TRUE(ok);
    const RingPatch& patch = use_cgal ? cgal.patch() : fast.patch();
    EXPECT_TRUE(patch.cut());
    EXPECT_EQ(patch.num_vertices(), 1 + static_cast<int>(nb.size()));
    EXPECT_EQ(patch.num_faces(), static_cast<int>(holed.size()) - 2);
    EXPECT_EQ(finite_rows(uv), static_cast<int>(uv.size()));
    EXPECT_EQ(uv[0], Vec2::Zero());
    EXPECT_LT(similarity_residual(z, uv), 1e-10);
  }

  // A listed vertex in no face: left out (NaN), the rest mapped as before.
  std::vector<int> extra_vertex = nb;
  extra_vertex.push_back(0);  // a grid corner, far from the ring
  ASSERT_TRUE(fast.map(p.centre, extra_vertex, faces, uv));
  EXPECT_TRUE(fast.patch().cut());
  ASSERT_EQ(uv.size(), extra_vertex.size() + 1);
  EXPECT_EQ(finite_rows(uv), static_cast<int>(nb.size()) + 1);
  EXPECT_FALSE(uv.back().allFinite());
  uv.pop_back();
  EXPECT_LT(similarity_residual(z, uv), 1e-12);

  // A bowtie (two triangles sharing only a vertex): the first triangle.
  {
    VertexMatrix V(5, 3);
    V << 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0;
    FaceMatrix F(2, 3);
    F << 0, 1, 2, 0, 3, 4;
    const Mesh bowtie(V, F);
    LscmMap f2(bowtie);
    CgalLscmMap c2(bowtie);
    const std::vector<int> n{1, 2, 3, 4}, fs{0, 1};
    for (bool use_cgal : {false, true}) {
      ASSERT_TRUE(use_cgal ? c2.map(0, n, fs, uv) : f2.map(0, n, fs, uv));
      ASSERT_EQ(uv.size(), 5u);
      EXPECT_EQ(finite_rows(uv), 3);
      EXPECT_TRUE(uv[1].allFinite() && uv[2].allFinite());
    }
    EXPECT_TRUE(f2.patch().cut());
    EXPECT_EQ(f2.patch().num_faces(), 1);
    // Each triangle alone is a disk.
    EXPECT_TRUE(f2.map(0, std::vector<int>{1, 2}, std::vector<int>{0}, uv));
    EXPECT_FALSE(f2.patch().cut());
  }
  // An edge with three faces (non-manifold in the mesh): the first two (opposite directions)
  // form the disk; two faces running the edge the same way never join.
  {
    VertexMatrix V(5, 3);
    V << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1;
    FaceMatrix F(3, 3);
    F << 0, 1, 2, 1, 0, 3, 1, 0, 4;
    const Mesh fin(V, F);
    ASSERT_EQ(fin.num_nonmanifold_edges(), 1);
    LscmMap f2(fin);
    CgalLscmMap c2(fin);
    const std::vector<int> all{0, 1, 2};
    for (bool use_cgal : {false, true}) {
      ASSERT_TRUE(use_cgal ? c2.map(0, std::vector<int>{1, 2, 3, 4}, all, uv)
                           : f2.map(0, std::vector<int>{1, 2, 3, 4}, all, uv));
      EXPECT_EQ(finite_rows(uv), 4);
      EXPECT_FALSE(uv[4].allFinite());  // vertex 4, only in the third face
    }
    EXPECT_TRUE(f2.map(0, std::vector<int>{1, 2, 3}, std::vector<int>{0, 1}, uv));
    EXPECT_FALSE(f2.patch().cut());
    ASSERT_TRUE(f2.map(0, std::vector<int>{1, 3, 4}, std::vector<int>{1, 2}, uv));  // same way
    EXPECT_TRUE(f2.patch().cut());
    EXPECT_EQ(f2.patch().num_faces(), 1);
    EXPECT_EQ(finite_rows(uv), 3);
  }
  // A closed patch (the whole icosahedron): all faces but one, every vertex, centre interior.
  {
    const Mesh ico = icosphere(0, 1.0);
    RingCollector r(ico);
    r.collect(0, 3.0);
    ASSERT_EQ(r.faces().size(), 20u);
    LscmMap f2(ico);
    CgalLscmMap c2(ico);
    for (bool use_cgal : {false, true}) {
      ASSERT_TRUE(use_cgal ? c2.map(0, r.neighbours(), r.faces(), uv)
                           : f2.map(0, r.neighbours(), r.faces(), uv));
      EXPECT_EQ(finite_rows(uv), 12);
      const RingPatch& patch = use_cgal ? c2.patch() : f2.patch();
      EXPECT_TRUE(patch.cut());
      EXPECT_EQ(patch.num_faces(), 19);
      int star = 0;
      for (int f = 0; f < patch.num_faces(); ++f)
        for (int k = 0; k < 3; ++k) star += patch.face_vertex(f, k) == 0;
      EXPECT_EQ(star, 5);  // the centre's whole star: the centre is interior
      EXPECT_GT(mapped_signed_area(patch, finite_part(uv, uv)), 0.0);
    }
  }
  // Inconsistent orientation: one face of the star flipped. The cut starts from it and cannot
  // join its neighbours across the edges they run the same way.
  {
    const Mesh ico = icosphere(0, 1.0);
    RingCollector r(ico);
    r.collect(0, 1.0);
    FaceMatrix F = ico.faces();
    const int f0 = r.faces()[0];
    std::swap(F(f0, 1), F(f0, 2));
    const Mesh bad(ico.vertices(), F);
    RingCollector rb(bad);
    rb.collect(0, 1.0);
    LscmMap f3(bad);
    ASSERT_TRUE(f3.map(0, rb.neighbours(), rb.faces(), uv));
    EXPECT_TRUE(f3.patch().cut());
    EXPECT_EQ(f3.patch().num_faces(), 1);
  }
}

// ---- estimators ---------------------------------------------------------------------------------

struct SphereErrorsAndFailures {
  double k = 0.0, K = 0.0, normal = 0.0;
  int not_ok = 0;
};

SphereErrorsAndFailures sphere_errors_and_failures(const Mesh& mesh, const Estimator& est,
                                                   double a) {
  SphereErrorsAndFailures e;
  const std::vector<VertexEstimate> r = estimate_mesh(mesh, est);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const VertexEstimate& q = r[static_cast<size_t>(v)];
    if (q.status != VertexStatus::ok) ++e.not_ok;
    const Vec3 n = mesh.position(v).normalized();
    e.normal = std::max(e.normal, (q.normal - n).norm());
    e.k = std::max(
        {e.k, std::abs(q.k1 + 1.0 / a), std::abs(q.k2 + 1.0 / a), std::abs(q.H + 1.0 / a)});
    e.K = std::max(e.K, std::abs(q.K - 1.0 / (a * a)));
  }
  return e;
}

TEST(LscmEstimator, SphereOfRadiusTwoConvergesToMinusOneHalf) {
  EstimatorOptions o;
  o.degree = 2;
  for (const char* name : {"lscm", "lscm-fast"}) {
    const auto est = make_estimator(name, o);
    SphereErrorsAndFailures prev;
    for (int level = 2; level <= 4; ++level) {
      const Mesh mesh = icosphere(level, 2.0);
      const SphereErrorsAndFailures e = sphere_errors_and_failures(mesh, *est, 2.0);
      std::printf(
          "%s-2 sphere level %d (%d vertices): max |k+0.5| %.3e, |K-0.25| %.3e, "
          "|n-n*| %.3e\n",
          name, level, mesh.num_vertices(), e.k, e.K, e.normal);
      EXPECT_EQ(e.not_ok, 0);
      EXPECT_LT(e.k, 0.05);  // curvatures near -0.5 (k = +0.5 would mean the wrong sign)
      EXPECT_LT(e.normal, 0.01);
      if (level > 2) {  // each level halves h: the errors must shrink
        EXPECT_LT(e.k, 0.75 * prev.k);
        EXPECT_LT(e.K, 0.75 * prev.K);
        EXPECT_LT(e.normal, 0.75 * prev.normal);
      }
      prev = e;
    }
  }
}

double max_difference(const std::vector<VertexEstimate>& a, const std::vector<VertexEstimate>& b,
                      double& normal) {
  double k = 0.0;
  normal = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].status, b[i].status);
    EXPECT_EQ(a[i].degree, b[i].degree);
    EXPECT_EQ(a[i].points, b[i].points);
    normal = std::max(normal, (a[i].normal - b[i].normal).norm());
    k = std::max({k, std::abs(a[i].k1 - b[i].k1), std::abs(a[i].k2 - b[i].k2),
                  std::abs(a[i].H - b[i].H), std::abs(a[i].K - b[i].K)});
  }
  return k;
}

// The fit is invariant under similarities of (u, v), so equal maps up to a similarity give equal
// estimates: lscm-fast with CGAL's pins and energy reproduces lscm.
TEST(LscmEstimator, FastWithCgalPinsAndEnergyReproducesCgal) {
  const GeneratedMesh torus = torus_structured(1, true, 3);
  for (int d : {2, 3, 4}) {
    EstimatorOptions o;
    o.degree = d;
    const auto cgal = make_estimator("lscm", o);
    LscmSettings s;
    s.fast_map = kCgalCompatible;
    const auto fast = make_lscm_estimator_with(o, false, s);
    const auto a = estimate_mesh(torus.mesh, *cgal);
    const auto b = estimate_mesh(torus.mesh, *fast);
    double dn;
    const double dk = max_difference(a, b, dn);
    std::printf("lscm-%d vs compatible lscm-fast-%d: max |dk| %.2e, |dn| %.2e\n", d, d, dk, dn);
    EXPECT_LT(dk, 1e-8);
    EXPECT_LT(dn, 1e-10);
  }
}

// The registered "lscm-fast" uses CGAL's pins and energy, so it reproduces "lscm" (the issue:
// both must give the same parameterization up to similarity).
TEST(LscmEstimator, RegisteredFastReproducesCgal) {
  const GeneratedMesh torus = torus_structured(2, true, 3);
  EstimatorOptions o;
  const auto a = estimate_mesh(torus.mesh, *make_estimator("lscm-2", o));
  const auto b = estimate_mesh(torus.mesh, *make_estimator("lscm-fast-2", o));
  double dn;
  const double dk = max_difference(a, b, dn);
  EXPECT_LT(dk, 1e-8);
  EXPECT_LT(dn, 1e-10);
}

// docs/algorithms.md §8's variant (farthest pins, Levy's energy) is a different map on curved
// patches, but differs from lscm by far less than either differs from the exact values.
TEST(LscmEstimator, NotesVariantIsCloseToCgal) {
  const GeneratedMesh torus = torus_structured(2, true, 3);
  EstimatorOptions o;
  o.degree = 2;
  const auto a = estimate_mesh(torus.mesh, *make_estimator("lscm-2", o));
  LscmSettings s;
  s.fast_map = LscmMapOptions{LscmPins::farthest_pair, true};
  const auto b = estimate_mesh(torus.mesh, *make_lscm_estimator_with(o, false, s));
  double dn;
  const double dk = max_difference(a, b, dn);
  double err = 0.0;
  for (int v = 0; v < torus.mesh.num_vertices(); ++v) {
    const SurfacePoint x = torus.surface->evaluate(torus.exact_points.row(v).transpose());
    err = std::max(err, std::abs(a[static_cast<size_t>(v)].H - x.H));
  }
  std::printf(
      "lscm-2 vs notes-variant lscm-fast-2 (torus level 2, jittered): max |dk| %.2e, |dn| %.2e; "
      "lscm-2 max |H error| %.2e\n",
      dk, dn, err);
  EXPECT_GT(dk, 1e-8);  // genuinely a different map
  EXPECT_LT(dk, 0.2 * err);
}

TEST(LscmEstimator, NoNanOnAMeshWithBoundaryAndThreadIndependent) {
  const GeneratedMesh bump = bump_48(1);
  for (const char* name : {"lscm-2", "lscm-fast-2", "lscm-fast-4", "lscm-cg-4"}) {
    EstimatorOptions o1, o2;
    o1.threads = 1;
    o2.threads = 2;
    const auto r1 = estimate_mesh(bump.mesh, *make_estimator(name, o1));
    const auto r2 = estimate_mesh(bump.mesh, *make_estimator(name, o2));
    int failed = 0;
    for (size_t i = 0; i < r1.size(); ++i) {
      const VertexEstimate& q = r1[i];
      EXPECT_TRUE(q.normal.allFinite() && std::isfinite(q.k1) && std::isfinite(q.k2) &&
                  std::isfinite(q.H) && std::isfinite(q.K) && q.d1.allFinite() && q.d2.allFinite())
          << name << " vertex " << i;
      EXPECT_NE(q.status, VertexStatus::excluded);
      if (q.status == VertexStatus::failed) ++failed;
      EXPECT_EQ(q.k1, r2[i].k1);
      EXPECT_EQ(q.normal, r2[i].normal);
      EXPECT_EQ(q.d1, r2[i].d1);
    }
    EXPECT_EQ(failed, 0) << name;
  }
}

// A tilted jittered plane with one grid cell removed: the rings of the vertices around the hole
// wrap around it and are cut to disks. On a plane every LSCM map is exact, so the cut
// fits must still give the plane's normal and zero curvature.
TEST(LscmEstimator, CutRingsAroundAHoleInAPlaneStayExact) {
  const Mat3 R = rotation(0.4, -0.9, 0.2);
  const int N = 10;
  const Mesh grid = grid_mesh(N, 0.1, false, 0.25, 5,
                              [&](double x, double y) { return Vec3(R * Vec3(x, y, 0.0)); });
  const int hole = 2 * (5 * N + 5);  // the two faces of cell (5, 5)
  FaceMatrix F(grid.num_faces() - 2, 3);
  for (int f = 0, g = 0; f < grid.num_faces(); ++f)
    if (f != hole && f != hole + 1) F.row(g++) = grid.faces().row(f);
  const Mesh plate(grid.vertices(), F);
  const Vec3 normal = R.col(2);
  EXPECT_GT(testing::rings_cut(plate, 2.0), 0);  // the 2-rings around the hole enclose it
  EXPECT_EQ(testing::rings_cut(grid, 2.0), 0);
  for (const char* method : {"lscm", "lscm-fast", "lscm-cg"})
    for (int degree = 2; degree <= 4; ++degree) {
      EstimatorOptions o;
      o.degree = degree;
      const auto res = estimate_mesh(plate, *make_estimator(method, o));
      for (int v = 0; v < plate.num_vertices(); ++v) {
        const VertexEstimate& q = res[static_cast<size_t>(v)];
        ASSERT_NE(q.status, VertexStatus::failed) << method << degree << " vertex " << v;
        EXPECT_LT((q.normal - normal).norm(), 1e-9) << method << degree << " vertex " << v;
        EXPECT_LT(0.1 * std::max(std::abs(q.k1), std::abs(q.k2)), 1e-8)
            << method << degree << " vertex " << v;
      }
      // Without the hole no ring is cut.
      for (const VertexEstimate& q : estimate_mesh(grid, *make_estimator(method, o)))
        EXPECT_NE(q.status, VertexStatus::disk_cut);
    }
}

// A thin torus (tube of 4 edges): every ring of 2 rings or more wraps around the tube. Before
// the disk cut LSCM-3 and LSCM-4 failed on every vertex of it; now every vertex gets finite
// values, and the outer equator keeps the outward sign (both curvatures < 0 there).
TEST(LscmEstimator, ThinTorusRingsAreCutNotFailed) {
  const int nu = 48, nv = 4;
  const Mesh torus = testing::torus_grid(1.0, 0.08, nu, nv);
  ASSERT_EQ(testing::rings_cut(torus, 2.0), torus.num_vertices());
  for (const char* method : {"lscm", "lscm-fast", "lscm-cg"})
    for (int degree = 2; degree <= 4; ++degree) {
      EstimatorOptions o;
      o.degree = degree;
      const auto res = estimate_mesh(torus, *make_estimator(method, o));
      for (const VertexEstimate& q : res) {
        ASSERT_NE(q.status, VertexStatus::failed) << method << degree;
        ASSERT_TRUE(q.normal.allFinite() && std::isfinite(q.k1) && std::isfinite(q.k2) &&
                    q.d1.allFinite() && q.d2.allFinite());
      }
      for (int i = 0; i < nu; ++i) {  // j = 0: the outer equator, k = -1/r and -1/(R + r)
        const VertexEstimate& q = res[static_cast<size_t>(i)];
        EXPECT_LT(q.H, 0.0) << method << degree << " vertex " << i;
        EXPECT_GT(q.normal.dot(torus.position(i)), 0.0);
      }
    }
}

TEST(LscmEstimator, Registry) {
  EstimatorOptions o;
  EXPECT_EQ(make_estimator("LSCM-3", o)->label(), "LSCM-3");
  EXPECT_EQ(make_estimator("lscm-fast-2", o)->name(), "lscm-fast");
  EXPECT_EQ(make_estimator("lscm-fast", o)->label(), "LSCM-fast-2");
  EXPECT_THROW(make_estimator("lscm-7", o), UsageError);
  o.rings = 1.25;
  EXPECT_THROW(make_estimator("lscm", o), UsageError);
}

}  // namespace
}  // namespace curvbench
