// Least-squares conformal maps of a ring patch; see lscm_parameterization.h.
#include "methods/fits/lscm_parameterization.h"

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/OpenNL/linear_solver.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Two_vertices_parameterizer_3.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace curvbench {

// ---- RingPatch ---------------------------------------------------------------------------------

RingPatch::RingPatch(const Mesh& mesh)
    : mesh_(&mesh),
      local_(static_cast<size_t>(mesh.num_vertices()), -1),
      face_local_(static_cast<size_t>(mesh.num_faces()), -1) {
  globals_.reserve(128);
  face_globals_.reserve(256);
  positions_.reserve(128);
  faces_.reserve(3 * 256);
}

bool RingPatch::build(int centre, std::span<const int> neighbours, std::span<const int> faces) {
  for (int g : globals_) local_[static_cast<size_t>(g)] = -1;
  for (int g : face_globals_) face_local_[static_cast<size_t>(g)] = -1;
  globals_.clear();
  face_globals_.clear();
  positions_.clear();
  faces_.clear();
  cut_ = false;
  ring_size_ = 1 + static_cast<int>(neighbours.size());
  const int nv = mesh_->num_vertices();
  const auto add = [&](int g) {
    if (g < 0 || g >= nv || local_[static_cast<size_t>(g)] >= 0) return false;  // duplicate
    local_[static_cast<size_t>(g)] = static_cast<int>(globals_.size());
    globals_.push_back(g);
    positions_.push_back(mesh_->position(g));
    return true;
  };
  if (!add(centre)) return false;
  for (int g : neighbours)
    if (!add(g)) return false;
  const int nf = mesh_->num_faces();
  for (int f : faces) {
    if (f < 0 || f >= nf || face_local_[static_cast<size_t>(f)] >= 0) return false;
    face_local_[static_cast<size_t>(f)] = static_cast<int>(face_globals_.size());
    face_globals_.push_back(f);
    for (int k = 0; k < 3; ++k) {
      const int l = local_[static_cast<size_t>(mesh_->face_vertex(f, k))];
      if (l < 0) return false;
      faces_.push_back(l);
    }
  }
  if (num_vertices() < 3 || faces_.empty()) return false;
  if (is_disk()) return true;
  return cut_to_disk() && num_vertices() >= 3 && is_disk();
}

// Greedy disk growth (see the header): the patch stays a disk after each accepted face, because
// a triangle glued to a disk along one boundary edge with a new third vertex, or along two
// consecutive boundary edges (in a disk the two boundary edges at a vertex are consecutive on
// its one boundary loop), leaves a disk. The patch is then renumbered to its own vertices, the
// centre first and the others in ring order.
bool RingPatch::cut_to_disk() {
  const int n = num_vertices();
  const int nf = num_faces();
  const size_t un = static_cast<size_t>(n);
  directed_.assign(un * un, 0);
  in_patch_.assign(un, 0);
  accepted_.clear();
  pending_.clear();
  const auto directed = [&](int a, int b) -> unsigned char& {
    return directed_[static_cast<size_t>(a) * un + static_cast<size_t>(b)];
  };
  enum Verdict { accept, later, never };
  const auto judge = [&](int f) {
    const int v[3] = {face_vertex(f, 0), face_vertex(f, 1), face_vertex(f, 2)};
    if (accepted_.empty()) return v[0] == 0 || v[1] == 0 || v[2] == 0 ? accept : later;
    int shared = 0, opposite = -1;
    for (int k = 0; k < 3; ++k) {
      const int a = v[k], b = v[(k + 1) % 3];
      // a -> b already in the patch: an edge used twice the same way (inconsistent orientation)
      // or an interior edge (its third face): never a disk.
      if (directed(a, b)) return never;
      if (directed(b, a)) {
        ++shared;
        opposite = v[(k + 2) % 3];
      }
    }
    if (shared == 1) return in_patch_[static_cast<size_t>(opposite)] ? later : accept;
    if (shared == 2) return accept;
    return shared == 0 ? later : never;  // 3: the face would close the surface
  };
  const auto take = [&](int f) {
    for (int k = 0; k < 3; ++k) {
      const int a = face_vertex(f, k), b = face_vertex(f, (k + 1) % 3);
      directed(a, b) = 1;
      in_patch_[static_cast<size_t>(a)] = 1;
    }
    accepted_.push_back(f);
  };
  for (int f = 0; f < nf; ++f) {
    const Verdict verdict = judge(f);
    if (verdict == later) pending_.push_back(f);
    if (verdict != accept) continue;
    take(f);
    // Earlier faces first: retry the waiting ones until none fits.
    for (bool progress = true; progress;) {
      progress = false;
      size_t keep = 0;
      for (size_t i = 0; i < pending_.size(); ++i) {
        const int g = pending_[i];
        const Verdict again = judge(g);
        if (again == accept) {
          take(g);
          progress = true;
        } else if (again == later) {
          pending_[keep++] = g;
        }
      }
      pending_.resize(keep);
    }
  }
  if (accepted_.empty()) return false;
  std::sort(accepted_.begin(), accepted_.end());

  // Renumber: patch vertex j <- ring vertex ring_index_[j] (centre first: every face accepted
  // first contains it); in_patch_ becomes the new index + 1.
  ring_index_.clear();
  for (int i = 0; i < n; ++i) {
    if (!in_patch_[static_cast<size_t>(i)]) {
      local_[static_cast<size_t>(globals_[static_cast<size_t>(i)])] = -1;
      continue;
    }
    const int j = static_cast<int>(ring_index_.size());
    ring_index_.push_back(i);
    local_[static_cast<size_t>(globals_[static_cast<size_t>(i)])] = j;
    globals_[static_cast<size_t>(j)] = globals_[static_cast<size_t>(i)];
    positions_[static_cast<size_t>(j)] = positions_[static_cast<size_t>(i)];
  }
  globals_.resize(ring_index_.size());
  positions_.resize(ring_index_.size());
  for (int f = 0; f < nf; ++f)
    face_local_[static_cast<size_t>(face_globals_[static_cast<size_t>(f)])] = -1;
  for (size_t j = 0; j < accepted_.size(); ++j) {
    const int f = accepted_[j];
    const int g = face_globals_[static_cast<size_t>(f)];
    face_globals_[j] = g;
    face_local_[static_cast<size_t>(g)] = static_cast<int>(j);
    for (int k = 0; k < 3; ++k)
      faces_[3 * j + static_cast<size_t>(k)] =
          local_[static_cast<size_t>(mesh_->face_vertex(g, k))];
  }
  face_globals_.resize(accepted_.size());
  faces_.resize(3 * accepted_.size());
  cut_ = true;
  return ring_index_[0] == 0;
}

void RingPatch::to_ring(std::span<const Vec2> patch_uv, std::vector<Vec2>& ring_uv) const {
  ring_uv.assign(static_cast<size_t>(ring_size_),
                 Vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
  for (int i = 0; i < num_vertices(); ++i)
    ring_uv[static_cast<size_t>(ring_index(i))] = patch_uv[static_cast<size_t>(i)];
}

// Halfedge h = 3f + k runs from face_vertex(f, k) to face_vertex(f, (k+1)%3). A connected,
// orientable, edge- and vertex-manifold surface with one boundary loop and V - E + F = 1 is a disk.
bool RingPatch::is_disk() {
  const int n = num_vertices();
  const int nf = num_faces();
  const int nh = 3 * nf;
  const auto at = [](std::vector<int>& a, int i) -> int& { return a[static_cast<size_t>(i)]; };
  const auto from = [&](int h) { return faces_[static_cast<size_t>(h)]; };
  const auto to = [&](int h) { return faces_[static_cast<size_t>(h - h % 3 + (h % 3 + 1) % 3)]; };
  const auto prev = [](int h) { return h - h % 3 + (h % 3 + 2) % 3; };

  // Twins from the mesh's face adjacency; where the mesh has none (a mesh boundary edge or a
  // non-manifold edge) by a scan of the patch. A repeated directed edge (an edge with > 2 patch
  // faces, or inconsistent orientation) fails.
  twin_.assign(static_cast<size_t>(nh), -1);
  for (int f = 0; f < nf; ++f) {
    const int gf = face_globals_[static_cast<size_t>(f)];
    for (int k = 0; k < 3; ++k) {
      const int h = 3 * f + k, a = from(h), b = to(h);
      const int g = mesh_->face_neighbor(gf, k);
      if (g >= 0) {
        const int gl = face_local_[static_cast<size_t>(g)];
        if (gl < 0) continue;  // a boundary edge of the patch
        int t = -1;
        for (int j = 3 * gl; j < 3 * gl + 3; ++j)
          if (from(j) == b && to(j) == a) t = j;
        if (t < 0) return false;  // the neighbour runs the edge the same way
        at(twin_, h) = t;
        continue;
      }
      for (int j = 0; j < nh; ++j) {
        if (j == h) continue;
        if (from(j) == a && to(j) == b) return false;
        if (from(j) == b && to(j) == a) {
          if (at(twin_, h) >= 0) return false;
          at(twin_, h) = j;
        }
      }
    }
  }

  valence_.assign(static_cast<size_t>(n), 0);
  some_out_.assign(static_cast<size_t>(n), -1);
  boundary_out_.assign(static_cast<size_t>(n), -1);
  boundary_count_.assign(static_cast<size_t>(n), 0);
  int boundary_halfedges = 0;
  for (int h = 0; h < nh; ++h) {
    const int a = from(h);
    ++at(valence_, a);
    at(some_out_, a) = h;
    if (at(twin_, h) < 0) {
      ++boundary_halfedges;
      ++at(boundary_count_, a);
      at(boundary_out_, a) = h;
    }
  }
  if (boundary_halfedges == 0) return false;  // closed

  // Vertex manifoldness: the faces around each vertex form one fan. An open fan is walked from
  // its outgoing boundary halfedge, a closed one from any outgoing halfedge.
  for (int v = 0; v < n; ++v) {
    const int valence = at(valence_, v);
    if (valence == 0 || at(boundary_count_, v) > 1) return false;
    const int start = at(boundary_out_, v) >= 0 ? at(boundary_out_, v) : at(some_out_, v);
    int count = 0;
    int h = start;
    do {
      if (++count > valence) return false;
      const int r = at(twin_, prev(h));
      if (r < 0) break;
      h = r;
    } while (h != start);
    if (count != valence) return false;
  }

  // One boundary loop: every boundary vertex has exactly one outgoing boundary halfedge.
  {
    int h = -1;
    for (int v = 0; v < n && h < 0; ++v) h = at(boundary_out_, v);
    int length = 0;
    int g = h;
    do {
      if (++length > boundary_halfedges) return false;
      g = at(boundary_out_, to(g));
    } while (g != h);
    if (length != boundary_halfedges) return false;
  }

  // Connected (faces through twins); valence_ becomes the visited flags, some_out_ the stack.
  {
    valence_.assign(static_cast<size_t>(nf), 0);
    some_out_.clear();
    some_out_.push_back(0);
    valence_[0] = 1;
    int reached = 1;
    while (!some_out_.empty()) {
      const int f = some_out_.back();
      some_out_.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int t = at(twin_, 3 * f + k);
        if (t < 0 || at(valence_, t / 3)) continue;
        at(valence_, t / 3) = 1;
        ++reached;
        some_out_.push_back(t / 3);
      }
    }
    if (reached != nf) return false;
  }

  const int edges = (nh + boundary_halfedges) / 2;
  return n - edges + nf == 1;
}

// ---- normalisation -----------------------------------------------------------------------------

double mapped_signed_area(const RingPatch& patch, std::span<const Vec2> uv) {
  double area = 0.0;
  for (int f = 0; f < patch.num_faces(); ++f) {
    const Vec2& a = uv[static_cast<size_t>(patch.face_vertex(f, 0))];
    const Vec2 e1 = uv[static_cast<size_t>(patch.face_vertex(f, 1))] - a;
    const Vec2 e2 = uv[static_cast<size_t>(patch.face_vertex(f, 2))] - a;
    area += 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
  }
  return area;
}

bool normalise_patch_map(const RingPatch& patch, std::span<Vec2> uv) {
  if (uv.empty()) return false;
  const Vec2 origin = uv[0];
  for (Vec2& p : uv) {
    if (!p.allFinite()) return false;
    p -= origin;
  }
  const double area = mapped_signed_area(patch, uv);
  if (!std::isfinite(area) || area == 0.0) return false;
  if (area < 0.0)
    for (Vec2& p : uv) p.y() = -p.y();
  return true;
}

// ---- in-house LSCM -----------------------------------------------------------------------------

namespace {

// Solves A x = b in place (b becomes x) for the Hermitian positive definite n x n matrix A,
// given by its lower triangle in column-major order, via A = L L^H (right-looking; overwrites
// the lower triangle with L). Returns false if a pivot is not positive. Works on the interleaved
// (re, im) doubles of std::complex (layout guaranteed by the standard) with contiguous inner
// loops: small systems (n <= ~100), no allocation.
bool cholesky_solve(std::complex<double>* matrix, int n, std::complex<double>* rhs) {
  double* a = reinterpret_cast<double*>(matrix);
  double* b = reinterpret_cast<double*>(rhs);
  const size_t ld = 2 * static_cast<size_t>(n);
  const auto col = [a, ld](int j) { return a + ld * static_cast<size_t>(j); };
  for (int j = 0; j < n; ++j) {
    double* cj = col(j);
    const double d = cj[2 * j];
    if (!(d > 0.0) || !std::isfinite(d)) return false;
    const double s = std::sqrt(d), inv = 1.0 / s;
    cj[2 * j] = s;
    cj[2 * j + 1] = 0.0;
    for (int i = 2 * (j + 1); i < 2 * n; ++i) cj[i] *= inv;
    for (int c = j + 1; c < n; ++c) {  // A(i,c) -= L(i,j) conj(L(c,j)), i >= c
      double* cc = col(c);
      const double lr = cj[2 * c], li = cj[2 * c + 1];
      for (int i = c; i < n; ++i) {
        const double xr = cj[2 * i], xi = cj[2 * i + 1];
        cc[2 * i] -= xr * lr + xi * li;
        cc[2 * i + 1] -= xi * lr - xr * li;
      }
    }
  }
  for (int k = 0; k < n; ++k) {  // L y = b
    const double* ck = col(k);
    const double inv = 1.0 / ck[2 * k];
    const double yr = b[2 * k] * inv, yi = b[2 * k + 1] * inv;
    b[2 * k] = yr;
    b[2 * k + 1] = yi;
    for (int i = k + 1; i < n; ++i) {
      b[2 * i] -= ck[2 * i] * yr - ck[2 * i + 1] * yi;
      b[2 * i + 1] -= ck[2 * i] * yi + ck[2 * i + 1] * yr;
    }
  }
  for (int i = n - 1; i >= 0; --i) {  // L^H x = y
    const double* ci = col(i);
    double re = b[2 * i], im = b[2 * i + 1];
    for (int k = i + 1; k < n; ++k) {  // -= conj(L(k,i)) x_k
      re -= ci[2 * k] * b[2 * k] + ci[2 * k + 1] * b[2 * k + 1];
      im -= ci[2 * k] * b[2 * k + 1] - ci[2 * k + 1] * b[2 * k];
    }
    const double inv = 1.0 / ci[2 * i];
    b[2 * i] = re * inv;
    b[2 * i + 1] = im * inv;
  }
  return true;
}

// CGAL Two_vertices_parameterizer_3::parameterize (CGAL 5.5), the same comparisons: project on
// the longest and second-longest axes of the bounding box, take the vertices with the smallest
// and the largest projection on the longest one (ties broken by the second one).
void choose_pins(const RingPatch& patch, LscmPins pins, int& p, int& q) {
  const int n = patch.num_vertices();
  p = 0;
  q = 0;
  if (pins == LscmPins::farthest_pair) {
    double best = -1.0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const double d2 = (patch.position(i) - patch.position(j)).squaredNorm();
        if (d2 > best) {
          best = d2;
          p = i;
          q = j;
        }
      }
    return;
  }
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (int i = 0; i < n; ++i) {
    lo = lo.cwiseMin(patch.position(i));
    hi = hi.cwiseMax(patch.position(i));
  }
  const Vec3 d = hi - lo;
  int a1, a2;  // longest and second-longest axis, as CGAL decides them
  if (d.x() < d.y() && d.x() < d.z()) {
    a1 = d.y() > d.z() ? 1 : 2;
    a2 = d.y() > d.z() ? 2 : 1;
  } else if (d.y() < d.x() && d.y() < d.z()) {
    a1 = d.x() > d.z() ? 0 : 2;
    a2 = d.x() > d.z() ? 2 : 0;
  } else {
    a1 = d.x() > d.y() ? 0 : 1;
    a2 = d.x() > d.y() ? 1 : 0;
  }
  double umin = std::numeric_limits<double>::infinity(), umax = -umin, vmin = umin, vmax = -umin;
  for (int i = 0; i < n; ++i) {
    const double u = (patch.position(i)[a1] - lo[a1]) / d[a1];
    const double v = (patch.position(i)[a2] - lo[a2]) / d[a2];
    if (u < umin || (u == umin && v < vmin)) {
      p = i;
      umin = u;
      vmin = v;
    }
    if (u > umax || (u == umax && v > vmax)) {
      q = i;
      umax = u;
      vmax = v;
    }
  }
}

}  // namespace

LscmMap::LscmMap(const Mesh& mesh, LscmMapOptions options) : options_(options), patch_(mesh) {}

bool LscmMap::map(int centre, std::span<const int> neighbours, std::span<const int> faces,
                  std::vector<Vec2>& uv) {
  if (!patch_.build(centre, neighbours, faces)) return false;
  const int n = patch_.num_vertices();
  const int nf = patch_.num_faces();
  int p, q;
  choose_pins(patch_, options_.pins, p, q);
  if (p == q || !((patch_.position(p) - patch_.position(q)).squaredNorm() > 0.0)) return false;

  unknown_.assign(static_cast<size_t>(n), -1);
  int nu = 0;
  for (int i = 0; i < n; ++i)
    if (i != p && i != q) unknown_[static_cast<size_t>(i)] = nu++;
  matrix_.assign(static_cast<size_t>(nu) * static_cast<size_t>(nu), 0.0);
  rhs_.assign(static_cast<size_t>(nu), 0.0);

  double area_floor = 0.0;
  if (options_.area_normalised) {
    double total = 0.0;
    for (int f = 0; f < nf; ++f) {
      const Vec3& x0 = patch_.position(patch_.face_vertex(f, 0));
      total += 0.5 * (patch_.position(patch_.face_vertex(f, 1)) - x0)
                         .cross(patch_.position(patch_.face_vertex(f, 2)) - x0)
                         .norm();
    }
    area_floor = 1e-6 * total / nf;
    if (!(area_floor > 0.0) || !std::isfinite(area_floor)) return false;
  }

  // Normal equations of min |A_free U_free + A_q * 1|^2 (pin p at 0, q at 1); A has one complex
  // row sqrt(s_T) W_T per triangle. Lower triangle of the Hermitian matrix, column-major.
  for (int f = 0; f < nf; ++f) {
    const int idx[3] = {patch_.face_vertex(f, 0), patch_.face_vertex(f, 1),
                        patch_.face_vertex(f, 2)};
    const Vec3 e1 = patch_.position(idx[1]) - patch_.position(idx[0]);
    const Vec3 e2 = patch_.position(idx[2]) - patch_.position(idx[0]);
    const double l1 = e1.norm();
    const double twice_area = e1.cross(e2).norm();
    // Counter-clockwise local coordinates z0 = 0, z1 = (l1, 0), z2 = (x2, y2), as in CGAL.
    const double x2 = l1 > 0.0 ? e2.dot(e1) / l1 : 0.0;
    const double y2 = l1 > 0.0 ? twice_area / l1 : 0.0;
    const std::complex<double> z1(l1, 0.0), z2(x2, y2);
    const std::complex<double> w[3] = {z2 - z1, -z2, z1};  // (z2 - z1, z0 - z2, z1 - z0)
    const double s = options_.area_normalised ? 1.0 / std::max(0.5 * twice_area, area_floor) : 1.0;
    for (int j = 0; j < 3; ++j) {
      const int uj = unknown_[static_cast<size_t>(idx[j])];
      if (uj < 0) continue;
      const std::complex<double> cw = s * std::conj(w[j]);
      for (int l = 0; l < 3; ++l) {
        const int ul = unknown_[static_cast<size_t>(idx[l])];
        if (ul >= 0) {
          if (uj >= ul)
            matrix_[static_cast<size_t>(uj) + static_cast<size_t>(ul) * nu] += cw * w[l];
        } else if (idx[l] == q) {
          rhs_[static_cast<size_t>(uj)] -= cw * w[l];
        }
      }
    }
  }

  if (!cholesky_solve(matrix_.data(), nu, rhs_.data())) return false;
  patch_uv_.resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const int ui = unknown_[static_cast<size_t>(i)];
    if (ui >= 0)
      patch_uv_[static_cast<size_t>(i)] =
          Vec2(rhs_[static_cast<size_t>(ui)].real(), rhs_[static_cast<size_t>(ui)].imag());
    else
      patch_uv_[static_cast<size_t>(i)] = Vec2(i == q ? 1.0 : 0.0, 0.0);
  }
  if (!normalise_patch_map(patch_, patch_uv_)) return false;
  patch_.to_ring(patch_uv_, uv);
  return true;
}

// ---- CGAL LSCM ---------------------------------------------------------------------------------

namespace {

namespace smp = CGAL::Surface_mesh_parameterization;
using CgalKernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;
using CgalVertex = CgalMesh::Vertex_index;
using CgalBorder = smp::Two_vertices_parameterizer_3<CgalMesh>;
using EigenLdltTraits = CGAL::Eigen_solver_traits<
    Eigen::SimplicialLDLT<CGAL::Eigen_sparse_symmetric_matrix<double>::EigenType>>;
using OpenNlTraits = OpenNL::SymmetricLinearSolverTraits<double>;

}  // namespace

struct CgalLscmMap::Impl {
  CgalMesh mesh;
  CgalMesh::Property_map<CgalVertex, CgalKernel::Point_2> uv;
  CgalMesh::Property_map<CgalVertex, bool> pinned;

  Impl() {
    // A defined default matters: CGAL's Point_2() leaves its coordinates uninitialised, and the
    // OpenNL conjugate-gradient solver starts from the map's current values.
    uv = mesh.add_property_map<CgalVertex, CgalKernel::Point_2>("v:curvbench_uv",
                                                                CgalKernel::Point_2(0.0, 0.0))
             .first;
    pinned = mesh.add_property_map<CgalVertex, bool>("v:curvbench_pinned", false).first;
  }

  template <class SolverTraits>
  bool run(CgalMesh::Halfedge_index border) {
    smp::LSCM_parameterizer_3<CgalMesh, CgalBorder, SolverTraits> parameterizer;
    return parameterizer.parameterize(mesh, border, uv, get(boost::vertex_index, mesh), pinned) ==
           smp::OK;
  }
};

CgalLscmMap::CgalLscmMap(const Mesh& mesh, CgalLscmSolver solver)
    : patch_(mesh), solver_(solver), impl_(std::make_unique<Impl>()) {}

CgalLscmMap::~CgalLscmMap() = default;

bool CgalLscmMap::map(int centre, std::span<const int> neighbours, std::span<const int> faces,
                      std::vector<Vec2>& uv) {
  if (!patch_.build(centre, neighbours, faces)) return false;
  // CGAL's border parameterizer does not check its pins: a patch whose vertices all coincide
  // (e.g. a cut down to one zero-area face) would crash it.
  int p, q;
  choose_pins(patch_, LscmPins::bounding_box, p, q);
  if (p == q || !((patch_.position(p) - patch_.position(q)).squaredNorm() > 0.0)) return false;
  try {
    CgalMesh& sm = impl_->mesh;
    sm.clear_without_removing_property_maps();
    const int n = patch_.num_vertices();
    for (int i = 0; i < n; ++i) {
      const Vec3& x = patch_.position(i);
      sm.add_vertex(CgalKernel::Point_3(x.x(), x.y(), x.z()));
    }
    for (int f = 0; f < patch_.num_faces(); ++f) {
      const CgalMesh::Face_index added =
          sm.add_face(CgalVertex(patch_.face_vertex(f, 0)), CgalVertex(patch_.face_vertex(f, 1)),
                      CgalVertex(patch_.face_vertex(f, 2)));
      if (added == CgalMesh::null_face()) return false;
    }
    CgalMesh::Halfedge_index border;
    for (CgalMesh::Halfedge_index h : sm.halfedges())
      if (sm.is_border(h)) {
        border = h;
        break;
      }
    if (border == CgalMesh::null_halfedge()) return false;
    const bool ok = solver_ == CgalLscmSolver::eigen_ldlt ? impl_->run<EigenLdltTraits>(border)
                                                          : impl_->run<OpenNlTraits>(border);
    if (!ok) return false;
    patch_uv_.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
      const CgalKernel::Point_2& x = impl_->uv[CgalVertex(i)];
      patch_uv_[static_cast<size_t>(i)] = Vec2(x.x(), x.y());
    }
  } catch (...) {
    return false;
  }
  if (!normalise_patch_map(patch_, patch_uv_)) return false;
  patch_.to_ring(patch_uv_, uv);
  return true;
}

}  // namespace curvbench
