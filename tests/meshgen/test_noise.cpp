// Seeded random numbers (meshgen/random.h) and controlled normal noise (docs/algorithms.md §10.3).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "core/errors.h"
#include "meshgen/bump_grid.h"
#include "meshgen/noise.h"
#include "meshgen/random.h"
#include "meshgen/torus_structured.h"
#include "tests/meshgen/identical_matrices.h"

namespace curvbench {
namespace {

TEST(Random, EngineIsTheStandardMt19937_64) {
  // First output of mt19937_64 with the default seed 5489 (fixed by the C++ standard).
  Rng rng(5489);
  EXPECT_EQ(rng.uniform01(), static_cast<double>(14514284786278117030ULL >> 11) * 0x1.0p-53);
  Rng a(42), b(42), c(43);
  for (int i = 0; i < 100; ++i) {
    const double x = a.normal();
    EXPECT_EQ(x, b.normal());
    EXPECT_NE(x, c.normal());
  }
  EXPECT_NE(derive_seed(1, 1), derive_seed(1, 2));
  EXPECT_NE(derive_seed(1, 1), derive_seed(2, 1));
}

TEST(Random, UniformAndNormalMoments) {
  // Tolerances: 5 standard errors of the sample statistic for n = 200000 draws.
  const int n = 200000;
  Rng rng(2024);
  double su = 0, umin = 1, umax = 0;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform01();
    su += u;
    umin = std::min(umin, u);
    umax = std::max(umax, u);
  }
  EXPECT_GE(umin, 0.0);
  EXPECT_LT(umax, 1.0);
  EXPECT_NEAR(su / n, 0.5, 5 * std::sqrt(1.0 / 12 / n));
  double s1 = 0, s2 = 0, s4 = 0;
  int within1 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.normal();
    ASSERT_TRUE(std::isfinite(x));
    s1 += x;
    s2 += x * x;
    s4 += x * x * x * x;
    if (std::abs(x) < 1) ++within1;
  }
  EXPECT_NEAR(s1 / n, 0.0, 5 / std::sqrt(n));
  EXPECT_NEAR(s2 / n, 1.0, 5 * std::sqrt(2.0 / n));
  EXPECT_NEAR(s4 / n, 3.0, 5 * std::sqrt(96.0 / n));  // Var(x^4) = 105 - 9 = 96
  const double p = 0.682689492137;                    // P(|x| < 1)
  EXPECT_NEAR(static_cast<double>(within1) / n, p, 5 * std::sqrt(p * (1 - p) / n));
}

// Signed normal displacements divided by h^k, i.e. the alpha_i, of a noisy mesh.
std::vector<double> alphas(const GeneratedMesh& clean, const GeneratedMesh& noisy, int k) {
  const double hk = std::pow(clean.mesh.mean_edge_length(), k);
  std::vector<double> a;
  for (int i = 0; i < clean.mesh.num_vertices(); ++i) {
    const Vec3 d = noisy.mesh.position(i) - clean.mesh.position(i);
    const Vec3 n = clean.surface->evaluate(clean.exact_points.row(i).transpose()).normal;
    // |x + delta| rounds at ~1e-16 absolute, so the cross product is at rounding level.
    EXPECT_LE(d.cross(n).norm(), 2e-15) << "displacement not along the exact normal";
    a.push_back(d.dot(n) / hk);
  }
  return a;
}

double rms(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v * v;
  return std::sqrt(s / x.size());
}

TEST(Noise, AmplitudeScalesAsHToTheK) {
  for (int k : {2, 3}) {
    double prev_rms = 0, prev_h = 0;
    int prev_n = 0;
    for (int level = 2; level <= 4; ++level) {
      const GeneratedMesh clean = bump_48(level);
      const GeneratedMesh noisy = add_noise(clean, k, 11);
      const std::vector<double> a = alphas(clean, noisy, k);
      const int n = static_cast<int>(a.size());
      // alpha = 0.1 xi: RMS(alpha) = 0.1 within 5 standard errors (rel. s.e. of an RMS:
      // 1/sqrt(2n)).
      const double r = rms(a);
      EXPECT_NEAR(r / 0.1, 1.0, 5 / std::sqrt(2.0 * n)) << "k=" << k << " level=" << level;
      double mean = 0;
      for (double v : a) mean += v;
      EXPECT_NEAR(mean / n, 0.0, 5 * 0.1 / std::sqrt(n));
      // Between levels the RMS displacement drops by (h_L / h_{L+1})^k ~ 2^k; the sampling
      // error of the ratio of two RMS is sqrt(1/(2 n_L) + 1/(2 n_{L+1})) relative.
      const double h = clean.mesh.mean_edge_length();
      const double disp = r * std::pow(h, k);
      if (level > 2) {
        const double tol = 5 * std::sqrt(0.5 / n + 0.5 / prev_n);
        EXPECT_NEAR((prev_rms / disp) / std::pow(prev_h / h, k), 1.0, tol);
        EXPECT_NEAR(prev_h / h, 2.0, 0.02);  // so the ratio is 2^k up to (1 +- 1%)^k
      }
      prev_rms = disp;
      prev_h = h;
      prev_n = n;
    }
  }
}

TEST(Noise, KeepsExactPointsAndConnectivityAndIsDeterministic) {
  const GeneratedMesh clean = bump_48(2);
  const GeneratedMesh a = add_noise(clean, 2, 3);
  const GeneratedMesh b = add_noise(clean, 2, 3);
  const GeneratedMesh c = add_noise(clean, 2, 4);
  EXPECT_EQ(a.exact_points, clean.exact_points);
  EXPECT_TRUE(test::identical(a.mesh.faces(), clean.mesh.faces()));
  EXPECT_EQ(a.surface, clean.surface);
  EXPECT_EQ(a.family, clean.family);
  EXPECT_EQ(a.level, clean.level);
  EXPECT_NE(a.description.find("h^2"), std::string::npos);
  EXPECT_NE(a.description.find("seed=3"), std::string::npos);
  ASSERT_EQ(a.mesh.num_vertices(), b.mesh.num_vertices());
  EXPECT_EQ(std::memcmp(a.mesh.vertices().data(), b.mesh.vertices().data(),
                        sizeof(double) * 3 * a.mesh.num_vertices()),
            0);
  EXPECT_FALSE(test::identical(a.mesh.vertices(), c.mesh.vertices()));
  // Every vertex moves, boundary vertices included.
  for (int i = 0; i < clean.mesh.num_vertices(); ++i)
    ASSERT_NE(a.mesh.position(i), clean.mesh.position(i)) << "vertex " << i;
  // alpha_scale 0 is the identity.
  EXPECT_TRUE(
      test::identical(add_noise(clean, 3, 3, {NoiseDistribution::gaussian, 0.0}).mesh.vertices(),
                      clean.mesh.vertices()));
}

// The readings of "alpha between 0 and 0.1 with Gaussian distribution" (docs/claims.md): uniform
// gives a one-signed alpha in [0, scale) with mean scale/2 and RMS scale/sqrt(3); a Gaussian of
// scale 0.1/3 has RMS 0.1/3. Each within 5 standard errors, on the same vertices and seed.
TEST(Noise, TheAlphaReadingsHaveTheirDistributions) {
  const GeneratedMesh clean = bump_48(3);
  const int k = 3;
  const std::vector<double> u =
      alphas(clean, add_noise(clean, k, 11, {NoiseDistribution::uniform, 0.1}), k);
  const double n = static_cast<double>(u.size());
  double mean = 0.0;
  for (double a : u) {
    EXPECT_GE(a, -1e-12);
    EXPECT_LT(a, 0.1 + 1e-12);
    mean += a / n;
  }
  // U[0, 0.1): mean 0.05, standard deviation 0.1/sqrt(12).
  EXPECT_NEAR(mean, 0.05, 5 * 0.1 / std::sqrt(12.0 * n));
  EXPECT_NEAR(rms(u) / (0.1 / std::sqrt(3.0)), 1.0, 5 / std::sqrt(n));
  const std::vector<double> g =
      alphas(clean, add_noise(clean, k, 11, {NoiseDistribution::gaussian, 0.1 / 3}), k);
  EXPECT_NEAR(rms(g) / (0.1 / 3), 1.0, 5 / std::sqrt(2.0 * n));
  // The same seed draws the same xi: the Gaussian reading of scale 0.1/3 is the default / 3.
  const std::vector<double> d = alphas(clean, add_noise(clean, k, 11), k);
  for (size_t i = 0; i < d.size(); ++i) EXPECT_NEAR(g[i], d[i] / 3, 1e-9) << i;
  EXPECT_EQ(parse_noise_distribution("uniform"), NoiseDistribution::uniform);
  EXPECT_THROW(parse_noise_distribution("laplace"), UsageError);
}

TEST(Noise, ClosedSurfaceAlongOutwardNormal) {
  const GeneratedMesh clean = torus_structured(1);
  const GeneratedMesh noisy = add_noise(clean, 2, 9);
  const std::vector<double> a = alphas(clean, noisy, 2);
  EXPECT_NEAR(rms(a) / 0.1, 1.0, 5 / std::sqrt(2.0 * a.size()));
  EXPECT_EQ(noisy.mesh.euler_characteristic(), 0);
}

TEST(Noise, BadArgumentsThrow) {
  const GeneratedMesh clean = bump_48(1);
  EXPECT_THROW(add_noise(clean, 0, 1), UsageError);
  EXPECT_THROW(add_noise(clean, 2, 1, {NoiseDistribution::gaussian, -0.1}), UsageError);
  EXPECT_THROW(add_noise(clean, 2, 1, {NoiseDistribution::gaussian, std::nan("")}), UsageError);
  GeneratedMesh no_surface = clean;
  no_surface.surface = nullptr;
  EXPECT_THROW(add_noise(no_surface, 2, 1), UsageError);
}

// The models of the noise sweeps (noise.h): sigma = scale h (order 1) in three directions, two
// zero-mean distributions, and outliers. torus_structured(2): vertices on the torus, so the
// exact points are the vertices.
GeneratedMesh sweep_torus() {
  return torus_structured(2);
}

TEST(NoiseModels, NormalIsAlongTheExactNormalWithRmsSigma) {
  const GeneratedMesh clean = sweep_torus();
  for (auto dist : {NoiseDistribution::gaussian, NoiseDistribution::uniform_centred}) {
    NoiseModel m;
    m.distribution = dist;
    m.scale = 0.03;
    const std::vector<double> a = alphas(clean, add_noise(clean, 1, 5, m), 1);
    const double n = static_cast<double>(a.size());
    EXPECT_NEAR(rms(a) / 0.03, 1.0, 5 / std::sqrt(n)) << to_string(dist);
    double mean = 0;
    for (double v : a) mean += v / n;
    EXPECT_NEAR(mean, 0.0, 5 * 0.03 / std::sqrt(n));
    if (dist == NoiseDistribution::uniform_centred) {
      for (double v : a) ASSERT_LE(std::abs(v), std::sqrt(3.0) * 0.03 + 1e-12);
    }
  }
}

TEST(NoiseModels, IsotropicMovesInEveryDirection) {
  const GeneratedMesh clean = sweep_torus();
  NoiseModel m;
  m.scale = 0.05;
  m.direction = NoiseDirection::isotropic;
  const GeneratedMesh noisy = add_noise(clean, 1, 5, m);
  EXPECT_EQ(noisy.exact_points, clean.exact_points);
  const double sigma = 0.05 * clean.mesh.mean_edge_length();
  double sn = 0, st = 0, sx = 0, sy = 0, sz = 0;
  const int n = clean.mesh.num_vertices();
  for (int i = 0; i < n; ++i) {
    const Vec3 d = noisy.mesh.position(i) - clean.mesh.position(i);
    const Vec3 nrm = clean.surface->evaluate(clean.exact_points.row(i).transpose()).normal;
    const double dn = d.dot(nrm);
    sn += dn * dn;
    st += (d - dn * nrm).squaredNorm();
    sx += d.x() * d.x();
    sy += d.y() * d.y();
    sz += d.z() * d.z();
  }
  // Normal component RMS sigma, tangential RMS sqrt(2) sigma, each axis sigma (5 s.e.).
  const double tol = 5 / std::sqrt(2.0 * n);
  EXPECT_NEAR(std::sqrt(sn / n) / sigma, 1.0, tol);
  EXPECT_NEAR(std::sqrt(st / (2 * n)) / sigma, 1.0, tol);
  for (double s : {sx, sy, sz}) EXPECT_NEAR(std::sqrt(s / n) / sigma, 1.0, tol);
}

TEST(NoiseModels, TangentialStaysOnTheSurfaceAndMovesTheExactPoint) {
  const GeneratedMesh clean = sweep_torus();
  for (auto dist : {NoiseDistribution::gaussian, NoiseDistribution::uniform_centred}) {
    NoiseModel m;
    m.scale = 0.1;
    m.distribution = dist;
    m.direction = NoiseDirection::tangential;
    const GeneratedMesh noisy = add_noise(clean, 1, 5, m);
    const double sigma = 0.1 * clean.mesh.mean_edge_length();
    double s2 = 0;
    const int n = clean.mesh.num_vertices();
    for (int i = 0; i < n; ++i) {
      const Vec3 x = noisy.mesh.position(i);
      ASSERT_LE((clean.surface->project(x) - x).norm(), 1e-12) << "vertex off the surface " << i;
      ASSERT_EQ(Vec3(noisy.exact_points.row(i).transpose()), x) << "exact point stays behind";
      const Vec3 d = x - clean.mesh.position(i);
      const Vec3 nrm = clean.surface->evaluate(clean.exact_points.row(i).transpose()).normal;
      // Tangent to first order: the normal part is the surface's sag k |d|^2 / 2, |k| <= 1/r.
      ASSERT_LE(std::abs(d.dot(nrm)), d.squaredNorm() / 0.3 + 1e-15) << i;
      s2 += d.squaredNorm();
    }
    EXPECT_NEAR(std::sqrt(s2 / (2 * n)) / sigma, 1.0, 5 / std::sqrt(2.0 * n)) << to_string(dist);
  }
}

TEST(NoiseModels, OutliersMoveRoundPNVerticesBy3h) {
  const GeneratedMesh clean = sweep_torus();
  const double h = clean.mesh.mean_edge_length();
  const int n = clean.mesh.num_vertices();
  for (double p : {0.001, 0.01, 0.5, 1.0}) {
    NoiseModel m;
    m.outlier_fraction = p;
    const GeneratedMesh noisy = add_noise(clean, 1, 5, m);
    EXPECT_EQ(noisy.exact_points, clean.exact_points);
    int moved = 0, up = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3 d = noisy.mesh.position(i) - clean.mesh.position(i);
      if (d.norm() == 0.0) continue;
      ++moved;
      const Vec3 nrm = clean.surface->evaluate(clean.exact_points.row(i).transpose()).normal;
      EXPECT_NEAR(d.norm(), 3 * h, 1e-12);
      EXPECT_NEAR(std::abs(d.dot(nrm)), 3 * h, 1e-12);
      up += d.dot(nrm) > 0;
    }
    EXPECT_EQ(moved, std::llround(p * n)) << "p=" << p;
    if (p >= 0.5) {  // both signs, about half each (5 s.e.)
      EXPECT_NEAR(static_cast<double>(up) / moved, 0.5, 5 * 0.5 / std::sqrt(moved));
    }
  }
}

TEST(NoiseModels, DeterministicAndZeroSigmaIsTheIdentity) {
  const GeneratedMesh clean = sweep_torus();
  for (auto dir : {NoiseDirection::normal, NoiseDirection::isotropic, NoiseDirection::tangential}) {
    NoiseModel m;
    m.direction = dir;
    m.scale = 0.03;
    const GeneratedMesh a = add_noise(clean, 1, 7, m), b = add_noise(clean, 1, 7, m),
                        c = add_noise(clean, 1, 8, m);
    EXPECT_EQ(std::memcmp(a.mesh.vertices().data(), b.mesh.vertices().data(),
                          sizeof(double) * 3 * a.mesh.num_vertices()),
              0);
    EXPECT_FALSE(test::identical(a.mesh.vertices(), c.mesh.vertices()));
    m.scale = 0.0;
    const GeneratedMesh z = add_noise(clean, 1, 7, m);
    EXPECT_TRUE(test::identical(z.mesh.vertices(), clean.mesh.vertices())) << to_string(dir);
    EXPECT_EQ(z.exact_points, clean.exact_points);
  }
  NoiseModel none;
  none.outlier_fraction = 1e-9;  // round(p n) = 0
  EXPECT_TRUE(test::identical(add_noise(clean, 1, 7, none).mesh.vertices(), clean.mesh.vertices()));
}

// The noise level a label says is the level it was written for: the runner's typed columns and
// those of a row read back from its CSV agree, for every order, direction, distribution and the
// sweeps' scales.
TEST(NoiseModels, LabelReadsBackAsItsLevel) {
  for (int k = 0; k <= kMaxNoiseOrder; ++k)
    for (auto dir : {NoiseDirection::normal, NoiseDirection::isotropic, NoiseDirection::tangential})
      for (auto dist : {NoiseDistribution::gaussian, NoiseDistribution::uniform,
                        NoiseDistribution::uniform_centred})
        for (double scale : {0.0, 0.001, 0.003, 0.01, 0.03, 0.1, 0.3})
          for (double outliers : {0.0, 0.01}) {
            NoiseModel m{dist, scale, dir, outliers};
            const NoiseLevel written = noise_level(k, m);
            const NoiseLevel read = parse_noise_label(k == 0 ? "none" : noise_label(k, m));
            EXPECT_TRUE(written == read) << k << " " << (k == 0 ? "none" : noise_label(k, m));
          }
  EXPECT_EQ(noise_level(1, {NoiseDistribution::gaussian, 0.03}).sigma_over_h, 0.03);
  EXPECT_EQ(noise_level(1, {NoiseDistribution::gaussian, 0.03}).model, "normal gauss");
  EXPECT_TRUE(std::isnan(noise_level(2, {}).sigma_over_h));  // alpha h^2: not a sigma h
  EXPECT_EQ(noise_level(0, {}).sigma_over_h, 0.0);
}

TEST(NoiseModels, LabelsAndValidation) {
  NoiseModel m;
  EXPECT_EQ(noise_label(2, m), "h^2");  // the paper's labels, unchanged
  EXPECT_EQ(noise_label(3, {NoiseDistribution::uniform, 0.05}), "h^3");
  m.scale = 0.03;
  EXPECT_EQ(noise_label(1, m), "normal gauss 0.03h");
  m.direction = NoiseDirection::tangential;
  m.distribution = NoiseDistribution::uniform_centred;
  m.scale = 0.1;
  EXPECT_EQ(noise_label(1, m), "tangential uniform 0.1h");
  m.direction = NoiseDirection::isotropic;
  EXPECT_EQ(noise_label(2, m), "isotropic uniform 0.1h^2");
  m.outlier_fraction = 0.01;
  EXPECT_EQ(noise_label(1, m), "outliers 1%");
  m.outlier_fraction = 0.001;
  EXPECT_EQ(noise_label(1, m), "outliers 0.1%");
  EXPECT_EQ(parse_noise_direction("tangential"), NoiseDirection::tangential);
  EXPECT_EQ(parse_noise_distribution("uniform-centred"), NoiseDistribution::uniform_centred);
  const auto message = [](const NoiseModel& bad) {
    try {
      validate_noise_model(bad);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({NoiseDistribution::gaussian, -0.01}),
            "noise scale (sigma/h) -0.01 must be finite and >= 0");
  NoiseModel p;
  p.outlier_fraction = 1.5;
  EXPECT_EQ(message(p), "outlier fraction 1.5 is outside [0, 1]");
  p.outlier_fraction = -0.1;
  EXPECT_EQ(message(p), "outlier fraction -0.1 is outside [0, 1]");
  EXPECT_THROW(parse_noise_direction("radial"), UsageError);
}

}  // namespace
}  // namespace curvbench
