// Neighbourhood tables (mesh/neighbourhood_table.h): every row equals RingCollector's
// neighbourhood of the vertex on meshes with boundaries, irregular valences, non-manifold edges
// and small components, for the neighbourhoods the methods use; the arrays do not depend on the
// thread count; estimates with and without the cache have the same bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"
#include "mesh/neighbourhood_table.h"
#include "mesh/rings.h"
#include "meshgen/generate.h"
#include "method_test_util.h"
#include "methods/estimator.h"

namespace curvbench {
namespace {

using testing::bitwise_equal;
using testing::grid_mesh;

// Small components and odd connectivity: a lone triangle, two triangles on an edge, an open fan
// of five, a "book" of three triangles on one (non-manifold) edge, an isolated vertex, and a 3 x 3
// grid with a boundary.
Mesh small_components() {
  std::vector<Vec3> P;
  std::vector<std::array<int, 3>> T;
  auto add = [&](double x, double y, double z) {
    P.emplace_back(x, y, z);
    return static_cast<int>(P.size()) - 1;
  };
  {  // lone triangle
    const int a = add(0, 0, 0), b = add(1, 0, 0), c = add(0, 1, 0);
    T.push_back({a, b, c});
  }
  {  // two triangles
    const int a = add(3, 0, 0), b = add(4, 0, 0), c = add(3, 1, 0), d = add(4, 1, 0.2);
    T.push_back({a, b, c});
    T.push_back({b, d, c});
  }
  {  // open fan of five around a centre
    const int c = add(6, 0, 0.1);
    int prev = add(7, 0, 0);
    for (int k = 1; k <= 5; ++k) {
      const double t = 0.25 * 3.14159265358979 * k;
      const int next = add(6 + std::cos(t), std::sin(t), 0.05 * k);
      T.push_back({c, prev, next});
      prev = next;
    }
  }
  {  // book: three triangles on the edge (a, b)
    const int a = add(9, 0, 0), b = add(9, 1, 0);
    T.push_back({a, b, add(10, 0.5, 0)});
    T.push_back({b, a, add(8, 0.5, 0)});
    T.push_back({a, b, add(9, 0.5, 1)});
  }
  add(20, 20, 20);  // isolated vertex
  {                 // 3 x 3 grid
    const int first = static_cast<int>(P.size());
    for (int j = 0; j <= 3; ++j)
      for (int i = 0; i <= 3; ++i) add(12 + i, j, 0.1 * i * j);
    auto id = [first](int i, int j) { return first + j * 4 + i; };
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        T.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        T.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
  }
  VertexMatrix V(static_cast<Eigen::Index>(P.size()), 3);
  for (size_t i = 0; i < P.size(); ++i) V.row(static_cast<Eigen::Index>(i)) = P[i].transpose();
  FaceMatrix F(static_cast<Eigen::Index>(T.size()), 3);
  for (size_t f = 0; f < T.size(); ++f)
    F.row(static_cast<Eigen::Index>(f)) << T[f][0], T[f][1], T[f][2];
  return Mesh(V, F, "small components");
}

struct NamedMesh {
  std::string name;
  Mesh mesh;
};

const std::vector<NamedMesh>& test_meshes() {
  static const std::vector<NamedMesh> meshes = [] {
    std::vector<NamedMesh> m;
    m.push_back({"torus-unstructured-1", generate_mesh({"torus-unstructured", 1}).mesh});
    m.push_back({"bump-irregular-1", generate_mesh({"bump-irregular", 1}).mesh});
    m.push_back({"torus-iso-projected-2", generate_mesh({"torus-iso-projected", 2}).mesh});
    m.push_back({"four-eight-grid", grid_mesh(14, 1.0 / 14, true, 0.2, 7, [](double x, double y) {
                   return Vec3(x, y, 0.2 * std::sin(3 * x) * std::cos(2 * y));
                 })});
    m.push_back({"small-components", small_components()});
    return m;
  }();
  return meshes;
}

// The starting neighbourhoods of the methods: Xu's 1-ring, and LHF-1..4, Jet-2..4 and LSCM-2..4
// with and without --noisy and adaptive growth.
std::vector<NeighbourhoodSpec> method_specs() {
  std::vector<NeighbourhoodSpec> specs = {NeighbourhoodSpec::fixed(1.0)};
  for (const char* name : {"lhf-1", "lhf-2", "lhf-3", "lhf-4", "jet-2", "jet-3", "jet-4", "lscm-2",
                           "lscm-3", "lscm-4"})
    for (bool noisy : {false, true})
      for (bool adaptive : {true, false}) {
        EstimatorOptions o;
        o.noisy = noisy;
        o.adaptive = adaptive;
        const NeighbourhoodSpec s = make_estimator(name, o)->neighbourhood_spec();
        if (std::find(specs.begin(), specs.end(), s) == specs.end()) specs.push_back(s);
      }
  return specs;
}

std::string describe(const NeighbourhoodSpec& s) {
  return "ring " + std::to_string(s.ring) + (s.adaptive ? " adaptive" : " fixed") + " min " +
         std::to_string(s.min_neighbours) + " max " + std::to_string(s.max_ring);
}

bool same_rows(const NeighbourhoodTable& a, const NeighbourhoodTable& b) {
  if (a.num_vertices() != b.num_vertices() || a.has_faces() != b.has_faces()) return false;
  for (int v = 0; v < a.num_vertices(); ++v)
    if (!std::ranges::equal(a.neighbours(v), b.neighbours(v)) ||
        !std::ranges::equal(a.faces(v), b.faces(v)) || a.num_faces(v) != b.num_faces(v) ||
        a.ring(v) != b.ring(v))
      return false;
  return true;
}

TEST(NeighbourhoodTable, MethodSpecsAreDistinctAndIncludeTheDefaults) {
  const auto specs = method_specs();
  // Fixed rings 1, 1.5, 2, 2.5, 3 (Xu's 1-ring among them); adaptive (r0, min_neighbours(d),
  // 2 r0) for d = 1..4 with r0 = (d+1)/2, and + 0.5 when noisy. LHF-d, Jet-d and LSCM-d share.
  EXPECT_EQ(specs.size(), 13u);
  EXPECT_NE(std::find(specs.begin(), specs.end(), NeighbourhoodSpec::at_least(1.5, 9, 3.0)),
            specs.end());
}

TEST(NeighbourhoodTable, RowsEqualTheCollector) {
  const auto specs = method_specs();
  for (const NamedMesh& m : test_meshes()) {
    RingCollector rc(m.mesh);
    for (const NeighbourhoodSpec& spec : specs) {
      const NeighbourhoodTable t(m.mesh, spec, true, 2);
      ASSERT_EQ(t.num_vertices(), m.mesh.num_vertices());
      EXPECT_TRUE(t.has_faces());
      EXPECT_EQ(t.spec(), spec);
      int bad = 0;
      for (int v = 0; v < m.mesh.num_vertices(); ++v) {
        const double ring = rc.collect(v, spec);
        bad += !std::ranges::equal(t.neighbours(v), rc.neighbours()) ||
               !std::ranges::equal(t.faces(v), rc.faces()) || t.num_faces(v) != rc.num_faces() ||
               t.ring(v) != ring;
      }
      EXPECT_EQ(bad, 0) << m.name << ", " << describe(spec);
      // Without faces: the same neighbours and rings, no faces.
      const NeighbourhoodTable n(m.mesh, spec, false, 2);
      EXPECT_FALSE(n.has_faces());
      for (int v = 0; v < m.mesh.num_vertices(); ++v) {
        ASSERT_TRUE(std::ranges::equal(n.neighbours(v), t.neighbours(v))) << m.name << " " << v;
        ASSERT_EQ(n.ring(v), t.ring(v));
        ASSERT_TRUE(n.faces(v).empty());
        ASSERT_EQ(n.num_faces(v), t.num_faces(v));
      }
      EXPECT_LT(n.bytes(), t.bytes());
    }
  }
}

TEST(NeighbourhoodTable, SameArraysForAnyThreadCount) {
  // Several blocks of 1024 vertices, so that threads really split the work.
  const Mesh mesh = generate_mesh({"torus-unstructured", 2}).mesh;
  ASSERT_GT(mesh.num_vertices(), 3 * 1024);
  for (const NeighbourhoodSpec& spec :
       {NeighbourhoodSpec::at_least(1.5, 9, 3.0), NeighbourhoodSpec::fixed(2.5)}) {
    const NeighbourhoodTable one(mesh, spec, true, 1);
    for (int threads : {2, 3, 8}) {
      const NeighbourhoodTable many(mesh, spec, true, threads);
      EXPECT_TRUE(same_rows(one, many)) << describe(spec) << ", " << threads << " threads";
      EXPECT_EQ(one.bytes(), many.bytes());
    }
  }
}

TEST(NeighbourhoodTable, AssignedRowGrowsLikeACollectedOne) {
  const Mesh& mesh = test_meshes()[1].mesh;  // bump-irregular: boundary and irregular valences
  const NeighbourhoodTable t(mesh, NeighbourhoodSpec::at_least(1.5, 9, 3.0), true, 2);
  RingCollector served(mesh), collected(mesh);
  for (int v = 0; v < mesh.num_vertices(); v += 7) {
    t.assign(served, v);
    collected.collect(v, t.spec());
    EXPECT_EQ(served.center(), v);
    for (int step = 0; step < 3; ++step) {
      EXPECT_EQ(served.grow(), collected.grow());
      ASSERT_TRUE(std::ranges::equal(served.neighbours(), collected.neighbours())) << v;
      ASSERT_TRUE(std::ranges::equal(served.faces(), collected.faces())) << v;
      ASSERT_EQ(served.ring(), collected.ring());
    }
  }
}

TEST(NeighbourhoodTable, RejectsRingsTheCollectorRejects) {
  const Mesh& mesh = test_meshes()[4].mesh;
  EXPECT_THROW(NeighbourhoodTable(mesh, NeighbourhoodSpec::fixed(1.25), false, 1), UsageError);
  EXPECT_THROW(NeighbourhoodTable(mesh, NeighbourhoodSpec::fixed(0.5), false, 1), UsageError);
  EXPECT_THROW(NeighbourhoodTable(mesh, NeighbourhoodSpec::at_least(1.0, 5, 1e6), false, 1),
               UsageError);
  NeighbourhoodCache cache(mesh);
  EXPECT_EQ(cache.get(NeighbourhoodSpec::at_least(1.0, 5, 1e6), false, 1), nullptr);
}

TEST(NeighbourhoodCache, OneTablePerSpecFacesReplaceNoFaces) {
  const Mesh& mesh = test_meshes()[0].mesh;
  NeighbourhoodCache cache(mesh);
  const auto spec = NeighbourhoodSpec::at_least(1.5, 9, 3.0);
  const auto plain = cache.get(spec, false, 2);
  ASSERT_NE(plain, nullptr);
  EXPECT_FALSE(plain->has_faces());
  EXPECT_EQ(cache.get(spec, false, 1), plain);  // reused
  const auto with_faces = cache.get(spec, true, 2);
  EXPECT_TRUE(with_faces->has_faces());
  EXPECT_EQ(cache.get(spec, false, 2), with_faces);  // faces serve a request without
  EXPECT_EQ(cache.num_tables(), 1);
  EXPECT_EQ(cache.bytes(), with_faces->bytes());
  EXPECT_TRUE(std::ranges::equal(plain->neighbours(5), with_faces->neighbours(5)));  // kept alive
  cache.get(NeighbourhoodSpec::fixed(1.0), false, 2);
  EXPECT_EQ(cache.num_tables(), 2);
}

// Every ring-based method with the cache (shared by all methods of a mesh, as the harness does)
// gives the same bits as without; the cache holds one table per spec.
TEST(NeighbourhoodCache, EstimatesBitIdenticalWithAndWithoutTheCache) {
  struct Case {
    const char* method;
    bool noisy;
    bool adaptive;
  };
  const Case cases[] = {
      {"lhf-1", false, true}, {"lhf-2", false, true},       {"lhf-2", true, true},
      {"lhf-3", false, true}, {"lhf-3", false, false},      {"lhf-4", false, true},
      {"lop-2", false, true}, {"lscm-fast-2", false, true}, {"lscm-fast-3", true, true},
      {"jet-2", false, true}, {"jet-3", false, false},      {"jet-4", false, true},
      {"xu-2", false, true}};
  int grown = 0, reduced_or_failed = 0;
  for (const NamedMesh& m : test_meshes()) {
    NeighbourhoodCache cache(m.mesh);
    for (const Case& c : cases) {
      EstimatorOptions o;
      o.noisy = c.noisy;
      o.adaptive = c.adaptive;
      o.threads = 2;
      const auto est = make_estimator(c.method, o);
      const auto plain = estimate_mesh(m.mesh, *est);
      const auto cached = estimate_mesh(m.mesh, *est, &cache);
      ASSERT_EQ(plain.size(), cached.size());
      int diff = 0;
      for (size_t v = 0; v < plain.size(); ++v) {
        diff += bitwise_equal(plain[v], cached[v]) ? 0 : 1;
        grown += plain[v].ring > est->neighbourhood_spec().ring;
        reduced_or_failed += plain[v].status == VertexStatus::degree_reduced ||
                             plain[v].status == VertexStatus::failed;
      }
      EXPECT_EQ(diff, 0) << m.name << ", " << c.method << (c.noisy ? " noisy" : "")
                         << (c.adaptive ? "" : " fixed");
    }
    // One table per spec: (1, 5, 2) LHF-1; (1.5, 9, 3) LHF-2, LOP-2, LSCM-2, Jet-2; (2, 9, 4)
    // noisy LHF-2; (2, 15, 4) LHF-3; fixed 2 LHF-3, Jet-3; (2.5, 23, 5) LHF-4, Jet-4;
    // (2.5, 15, 5) noisy LSCM-3. Xu-2 reads none.
    EXPECT_EQ(cache.num_tables(), 7) << m.name;
  }
  // The growth paths after a table row (point-count growth, rank-failure growth, Jet's growth)
  // were exercised.
  EXPECT_GT(grown, 0);
  EXPECT_GT(reduced_or_failed, 0);
}

// Reports the approximate normals MeshEstimation hands to the methods.
class NormalProbe final : public Estimator {
 public:
  explicit NormalProbe(int threads) : Estimator(options(threads)) {}
  std::string name() const override { return "normal-probe"; }
  bool takes_degree() const override { return false; }
  std::unique_ptr<Workspace> make_workspace(const Mesh&) const override {
    return std::make_unique<Workspace>();
  }
  void estimate(const MeshContext& ctx, int v, Workspace&, VertexEstimate& out) const override {
    out.normal = ctx.approx_normals.row(v).transpose();
  }

 private:
  static EstimatorOptions options(int threads) {
    EstimatorOptions o;
    o.threads = threads;
    return o;
  }
};

TEST(MeshEstimation, ApproximateNormalsAreTheMeshsAreaWeightedNormalsBitForBit) {
  for (const NamedMesh& m : test_meshes()) {
    const VertexMatrix ref = m.mesh.area_weighted_normals();
    for (int threads : {1, 2, 3}) {
      const auto res = estimate_mesh(m.mesh, NormalProbe(threads));
      int diff = 0;
      for (int v = 0; v < m.mesh.num_vertices(); ++v)
        for (int k = 0; k < 3; ++k) {
          const double a = ref(v, k), b = res[static_cast<size_t>(v)].normal(k);
          diff += std::memcmp(&a, &b, sizeof(double)) != 0;
        }
      EXPECT_EQ(diff, 0) << m.name << ", " << threads << " threads";
    }
  }
}

TEST(NeighbourhoodCache, MeshEstimationRejectsACacheOfAnotherMesh) {
  NeighbourhoodCache cache(test_meshes()[0].mesh);
  const auto est = make_estimator("lhf-2", {});
  EXPECT_THROW(MeshEstimation(test_meshes()[1].mesh, *est, &cache), std::invalid_argument);
}

}  // namespace
}  // namespace curvbench
