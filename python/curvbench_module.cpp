// The Python module `curvbench` (pybind11): numpy arrays in and out over the library.
//
//   estimate(V, F, method="lhf", **options) -> Estimate   (options: the estimator option table,
//            include/curvbench/estimator_options.h: degree=4, rings=2.5, vertex_normals="max", ...)
//   read_mesh(path) -> (V, F)
//   mesh(family, level, noise_order=0, seed=1, **options) -> (V, F, Exact)   (options: the mesh
//            option table of meshgen/generate.h: aspect=16, density=4)
//   score(exact_or_mesh, estimate, vertex_set="all") -> {quantity: {"L2", "Linf", ...}}
//   recommend(V, F, noise=None, results=None) -> dict   (the advice of `curvbench recommend`;
//            estimate(V, F, method="auto") follows it and keeps it in Estimate.recommendation)
//   methods(), __version__
//
// Input arrays are read in place (any real dtype for V, any integer dtype for F, any strides)
// and converted once, straight into the mesh the estimators run on; the GIL is released while
// estimating. Errors: curvbench.Error (a ValueError) with subclasses MeshError (bad mesh or file:
// the library's InputError) and UsageError (bad method, degree, option), with the command line's
// one-line messages.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "api/make_api_estimator.h"
#include "core/errors.h"
#include "core/text.h"
#include "curvbench/curvbench.h"
#include "harness/metrics.h"
#include "harness/recommend_table.h"
#include "mesh/io.h"
#include "mesh/mesh.h"
#include "meshgen/generate.h"
#include "methods/estimate_oriented.h"
#include "methods/estimator.h"
#include "methods/option_schema.h"

namespace py = pybind11;
using namespace curvbench;

namespace {

const char* kConventions = R"(
Conventions (paper §2; docs/methods.md): B = n . x_uu with outward (closed) or upward
(height field) normals, so a sphere of radius r has k1 = k2 = H = -1/r; k1 >= k2, d1 goes with
k1, H = (k1 + k2) / 2, K = k1 k2.)";

// Element (i, j) of a 2-D array of dtype T, honouring its strides.
template <typename T>
T at(const py::array& a, py::ssize_t i, py::ssize_t j) {
  const auto* base = static_cast<const char*>(a.data());
  return *reinterpret_cast<const T*>(base + i * a.strides(0) + j * a.strides(1));
}

py::array as_array(const py::handle& h, const char* name) {
  py::array a = py::array::ensure(h);
  if (!a) throw InputError(std::string(name) + ": expected a numpy array or a nested sequence");
  return a;
}

void check_shape(const py::array& a, const char* name, const char* what) {
  if (a.ndim() != 2 || a.shape(1) != 3) {
    // Appends, not operator+: GCC 12's LTO warns falsely on the temporaries (-Wstringop-overflow).
    std::string shape = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d)
      shape.append(d ? ", " : "").append(std::to_string(a.shape(d)));
    shape.append(a.ndim() == 1 ? ",)" : ")");
    throw InputError(std::string(name) + ": expected shape (" + what + ", 3), got " + shape);
  }
}

std::string dtype_name(const py::array& a) {
  return py::str(a.dtype()).cast<std::string>();
}

// V as the mesh's n x 3 double matrix: one conversion from any real dtype and any strides.
VertexMatrix to_vertices(const py::handle& h) {
  const py::array a = as_array(h, "V");
  check_shape(a, "V", "n");
  const char kind = a.dtype().kind();
  const auto n = a.shape(0);
  VertexMatrix V(n, 3);
  const auto fill = [&](auto tag) {
    using T = decltype(tag);
    for (py::ssize_t i = 0; i < n; ++i)
      for (py::ssize_t j = 0; j < 3; ++j) V(i, j) = static_cast<double>(at<T>(a, i, j));
  };
  const auto size = a.itemsize();
  if (kind == 'f' && size == 8)
    fill(double{});
  else if (kind == 'f' && size == 4)
    fill(float{});
  else if (kind == 'i' && size == 4)
    fill(std::int32_t{});
  else if (kind == 'i' && size == 8)
    fill(std::int64_t{});
  else
    throw InputError("V: expected float64 or float32 coordinates (or int32/int64), got " +
                     dtype_name(a));
  return V;
}

// F as the mesh's m x 3 int matrix from any integer dtype and any strides; indices outside the
// int range get the mesh's own out-of-range message.
FaceMatrix to_faces(const py::handle& h, py::ssize_t n) {
  const py::array a = as_array(h, "F");
  check_shape(a, "F", "m");
  const char kind = a.dtype().kind();
  const auto m = a.shape(0);
  FaceMatrix F(m, 3);
  const auto fill = [&](auto tag) {
    using T = decltype(tag);
    for (py::ssize_t i = 0; i < m; ++i)
      for (py::ssize_t j = 0; j < 3; ++j) {
        const T x = at<T>(a, i, j);
        if constexpr (sizeof(T) > sizeof(int) || !std::is_signed_v<T>) {
          if (x > static_cast<T>(INT_MAX) ||
              (std::is_signed_v<T> && static_cast<long long>(x) < INT_MIN))
            throw InputError("mesh: face " + std::to_string(i) + " references vertex " +
                             std::to_string(x) + ", out of range [0, " + std::to_string(n) + ")");
        }
        F(i, j) = static_cast<int>(x);
      }
  };
  const auto size = a.itemsize();
  if (kind == 'i' && size == 4)
    fill(std::int32_t{});
  else if (kind == 'i' && size == 8)
    fill(std::int64_t{});
  else if (kind == 'u' && size == 4)
    fill(std::uint32_t{});
  else if (kind == 'u' && size == 8)
    fill(std::uint64_t{});
  else
    throw InputError("F: expected integer vertex indices (int32/int64), got " + dtype_name(a));
  return F;
}

py::array_t<double> vec3_array(const std::vector<VertexEstimate>& est, Vec3 VertexEstimate::*f) {
  py::array_t<double> out({static_cast<py::ssize_t>(est.size()), py::ssize_t{3}});
  auto r = out.mutable_unchecked<2>();
  for (size_t i = 0; i < est.size(); ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = (est[i].*f)(j);
  return out;
}

template <typename T, typename F>
py::array_t<T> column(size_t n, F value) {
  py::array_t<T> out(static_cast<py::ssize_t>(n));
  auto r = out.template mutable_unchecked<1>();
  for (size_t i = 0; i < n; ++i) r(i) = value(i);
  return out;
}

/// The result of estimate(): numpy arrays plus the estimates themselves (for score()).
struct PyEstimate {
  std::string method;
  std::vector<VertexEstimate> estimates;
  py::object normal, k1, k2, H, K, d1, d2, degree, points, ring, status, status_code;
  py::object recommendation = py::none();  ///< method="auto": the advice it followed
};

// The advice as recommend() returns it and Estimate.recommendation holds it.
py::dict advice_dict(const Advice& a) {
  py::dict d;
  d["quality"] = a.mesh_class.quality;
  d["quality_reason"] = a.mesh_class.reason;
  d["sigma_over_h"] = a.sigma_over_h;
  d["noise"] = a.noise_estimated ? "estimated" : "given";
  d["noise_level"] = a.noise_level;
  d["swept"] = a.has_choice;
  py::dict options;
  if (a.has_choice && !a.choice.parameter.empty()) {
    std::string key = a.choice.parameter;
    for (char& c : key)
      if (c == '-') c = '_';
    options[key.c_str()] = a.choice.radius;
  }
  const RecommendationRow& r = a.row;
  d["method"] = a.has_choice ? py::object(py::str(a.choice.method)) : py::none();
  d["options"] = options;
  d["label"] = a.has_choice ? py::object(py::str(r.best_label)) : py::none();
  d["quantity"] = a.has_choice ? py::object(py::str(r.quantity)) : py::none();
  d["norm"] = a.has_choice ? py::object(py::str(r.norm)) : py::none();
  d["error"] = a.has_choice ? py::object(py::float_(r.best_error)) : py::none();
  d["experiment"] = a.has_choice ? py::object(py::str(r.experiment)) : py::none();
  d["family"] = a.has_choice ? py::object(py::str(r.family)) : py::none();
  d["level"] = a.has_choice ? py::object(py::int_(r.level)) : py::none();
  d["table"] = a.table;
  d["provenance"] = a.provenance;
  return d;
}

/// The exact quantities of a generated mesh, plus the mesh (for vertex sets in score()).
struct PyExact {
  std::shared_ptr<const Mesh> mesh;
  std::vector<SurfacePoint> exact;
  std::string surface, description;
  py::object point, normal, k1, k2, H, K, d1, d2;
};

py::array numpy_status_names(const py::array_t<std::uint8_t>& codes) {
  const py::module_ np = py::module_::import("numpy");
  const py::object names =
      np.attr("array")(py::make_tuple("ok", "degree_reduced", "failed", "excluded", "disk_cut",
                                      "sign_undetermined", "partial", "reprojected"));
  return names.attr("__getitem__")(codes);
}

// A keyword argument as the option table's typed value (set_option checks it against the type).
OptionValue option_value(const py::handle& x) {
  if (py::isinstance<py::bool_>(x)) return x.cast<bool>();
  if (py::hasattr(x, "dtype") && x.attr("dtype").attr("kind").cast<std::string>() == "b")
    return x.attr("item")().cast<bool>();  // numpy.bool_
  if (py::isinstance<py::str>(x)) return x.cast<std::string>();
  if (py::isinstance<py::float_>(x)) return x.cast<double>();
  if (py::hasattr(x, "__index__")) return x.attr("__index__")().cast<long long>();
  throw UsageError("expected a bool, a number or a string, got " +
                   py::str(py::type::of(x)).cast<std::string>());
}

// Every option of the table as estimate()'s docstring lists it.
std::string options_doc() {
  std::string s;
  for (const OptionInfo& o : estimator_option_schema()) {
    std::string value = o.default_text;
    if (o.type == OptionType::boolean) value = value == "yes" ? "True" : "False";
    if (o.type == OptionType::choice || o.type == OptionType::text) value = "'" + value + "'";
    s += o.python_name + " (default " + value + "): " + o.help + ".\n";
  }
  return s;
}

PyEstimate py_estimate(const py::handle& V, const py::handle& F, const std::string& method,
                       const py::kwargs& kwargs) {
  EstimateOptions o;
  o.method = method;
  for (const auto& [key, value] : kwargs) {
    if (value.is_none()) continue;  // None: the default
    const std::string name = key.cast<std::string>();
    const auto known = [&] {
      for (const OptionInfo& info : estimator_option_schema())
        if (info.python_name == name) return true;
      return false;
    };
    if (!known()) {
      std::string valid;
      for (const OptionInfo& info : estimator_option_schema())
        valid += (valid.empty() ? "" : ", ") + info.python_name;
      throw UsageError("unknown option '" + name + "' (valid: " + valid + ")");
    }
    set_option_value(o, name, option_value(value));
  }
  // method="auto": the estimator of the advice for the mesh, chosen once the mesh is made.
  const bool automatic = is_auto_method(method);
  std::unique_ptr<Estimator> est = automatic ? nullptr : make_api_estimator(o);
  VertexMatrix Vm = to_vertices(V);
  // F None: a point set (docs/point_sets.md).
  FaceMatrix Fm = F.is_none() ? FaceMatrix(0, 3) : to_faces(F, Vm.rows());
  PyEstimate r;
  std::optional<Advice> advice;
  {
    py::gil_scoped_release unlocked;
    Mesh mesh(std::move(Vm), std::move(Fm), "mesh");
    if (automatic) {
      advice = advise(mesh, std::nan(""), default_recommendations());
      if (!advice->has_choice)
        throw InputError(advice->table + ": no sweep ran for " + advice->mesh_class.quality +
                         " meshes at sigma/h " + format_g(advice->noise_level) +
                         ", so method='auto' has no choice; name the method");
      EstimateOptions chosen;
      static_cast<EstimatorOptions&>(chosen) = auto_options(advice->choice, o, true);
      chosen.method = advice->choice.method;
      est = make_api_estimator(chosen);
    }
    r.estimates = estimate_oriented(std::move(mesh), *est).estimates;
  }
  if (advice) r.recommendation = advice_dict(*advice);
  const auto& e = r.estimates;
  const size_t n = e.size();
  r.method = est->label();
  r.normal = vec3_array(e, &VertexEstimate::normal);
  r.d1 = vec3_array(e, &VertexEstimate::d1);
  r.d2 = vec3_array(e, &VertexEstimate::d2);
  r.k1 = column<double>(n, [&](size_t i) { return e[i].k1; });
  r.k2 = column<double>(n, [&](size_t i) { return e[i].k2; });
  r.H = column<double>(n, [&](size_t i) { return e[i].H; });
  r.K = column<double>(n, [&](size_t i) { return e[i].K; });
  r.degree = column<std::int32_t>(n, [&](size_t i) { return e[i].degree; });
  r.points = column<std::int32_t>(n, [&](size_t i) { return e[i].points; });
  r.ring = column<double>(n, [&](size_t i) { return e[i].ring; });
  const auto codes =
      column<std::uint8_t>(n, [&](size_t i) { return static_cast<std::uint8_t>(e[i].status); });
  r.status_code = codes;
  r.status = numpy_status_names(codes);
  return r;
}

py::dict py_recommend(const py::handle& V, const py::handle& F, std::optional<double> noise,
                      std::optional<std::string> results) {
  VertexMatrix Vm = to_vertices(V);
  FaceMatrix Fm = to_faces(F, Vm.rows());
  std::optional<Advice> advice;
  {
    py::gil_scoped_release unlocked;
    const RecommendationTable table =
        results ? read_recommendations_csv(*results) : default_recommendations();
    const Mesh mesh(std::move(Vm), std::move(Fm), "mesh");
    advice = advise(mesh, noise ? *noise : std::nan(""), table);
  }
  return advice_dict(*advice);
}

py::tuple mesh_arrays(const Mesh& mesh) {
  py::array_t<double> V({static_cast<py::ssize_t>(mesh.num_vertices()), py::ssize_t{3}});
  py::array_t<std::int32_t> F({static_cast<py::ssize_t>(mesh.num_faces()), py::ssize_t{3}});
  std::copy(mesh.vertices().data(), mesh.vertices().data() + mesh.vertices().size(),
            V.mutable_data());
  std::copy(mesh.faces().data(), mesh.faces().data() + mesh.faces().size(), F.mutable_data());
  return py::make_tuple(V, F);
}

py::tuple py_read_mesh(const std::string& path) {
  MeshReadReport report;
  const Mesh mesh = read_mesh(path, &report);
  for (const std::string& w : read_warnings(path, report))
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
  return mesh_arrays(mesh);
}

py::tuple py_mesh(const std::string& family, int level, int noise_order, std::uint64_t seed,
                  const py::kwargs& kwargs) {
  MeshSpec spec;
  spec.family = family;
  spec.level = level;
  spec.noise_order = noise_order;
  spec.seed = seed;
  for (const auto& [key, value] : kwargs) {
    if (value.is_none()) continue;  // None: the default
    const std::string name = key.cast<std::string>();
    const bool number = !py::isinstance<py::bool_>(value) &&
                        (py::hasattr(value, "__index__") || py::hasattr(value, "__float__"));
    if (!number)
      throw UsageError("mesh option " + name + ": expected a number, got " +
                       py::str(py::type::of(value)).cast<std::string>());
    set_mesh_option(spec.shape, name, value.cast<double>());
  }
  GeneratedMesh g = generate_mesh(spec);
  PyExact x;
  const int n = g.mesh.num_vertices();
  x.exact.resize(n);
  for (int v = 0; v < n; ++v) x.exact[v] = g.surface->evaluate(g.exact_points.row(v).transpose());
  x.surface = g.surface->name();
  x.description = g.description;
  const auto vec3 = [&](Vec3 SurfacePoint::*f) {
    py::array_t<double> out({static_cast<py::ssize_t>(n), py::ssize_t{3}});
    auto r = out.mutable_unchecked<2>();
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < 3; ++j) r(i, j) = (x.exact[i].*f)(j);
    return out;
  };
  const auto scalar = [&](double SurfacePoint::*f) {
    return column<double>(n, [&](size_t i) { return x.exact[i].*f; });
  };
  x.point = vec3(&SurfacePoint::point);
  x.normal = vec3(&SurfacePoint::normal);
  x.d1 = vec3(&SurfacePoint::d1);
  x.d2 = vec3(&SurfacePoint::d2);
  x.k1 = scalar(&SurfacePoint::k1);
  x.k2 = scalar(&SurfacePoint::k2);
  x.H = scalar(&SurfacePoint::H);
  x.K = scalar(&SurfacePoint::K);
  const py::tuple vf = mesh_arrays(g.mesh);
  x.mesh = std::make_shared<const Mesh>(std::move(g.mesh));
  return py::make_tuple(vf[0], vf[1], py::cast(std::move(x)));
}

py::dict py_score(const py::object& exact_or_mesh, const PyEstimate& est,
                  const std::string& vertex_set) {
  py::object ex = exact_or_mesh;
  if (py::isinstance<py::tuple>(ex) && py::len(ex) == 3) ex = ex.cast<py::tuple>()[2];
  if (!py::isinstance<PyExact>(ex))
    throw UsageError("score: expected the Exact of curvbench.mesh() or its (V, F, exact) tuple");
  const PyExact& x = ex.cast<const PyExact&>();
  if (x.exact.size() != est.estimates.size())
    throw InputError("score: the estimate has " + std::to_string(est.estimates.size()) +
                     " vertices, the exact answer " + std::to_string(x.exact.size()));
  const std::vector<int> vertices = select_vertices(*x.mesh, parse_vertex_set(vertex_set));
  py::dict out;
  for (Quantity q :
       {Quantity::normal, Quantity::H, Quantity::K, Quantity::k1, Quantity::k2, Quantity::d1}) {
    py::dict row;
    for (Norm norm : {Norm::L2, Norm::Linf}) {
      const ErrorValue ev = compute_error(q, norm, est.estimates, x.exact, vertices);
      row[to_string(norm)] = ev.value;
      row["counted"] = ev.vertices;
      row["excluded"] = ev.excluded;
    }
    out[to_string(q)] = row;
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(curvbench, m) {
  m.doc() = std::string(
                "curvbench: per-vertex normals, principal curvatures and directions of triangle "
                "meshes with 14 estimators (the local polynomial fits LHF, LOP, Xu and LSCM of "
                "Wang, Jiao et al., CAGD 2009; CGAL's jet fitting; seven discrete operators: "
                "methods()), and test meshes with exact answers.\n\n"
                "Errors raise curvbench.Error (a ValueError): MeshError for bad mesh data or "
                "files, UsageError for bad options; the messages are those of the curvbench "
                "command.") +
            kConventions;
  m.attr("__version__") = curvbench::version();

  static py::exception<std::runtime_error> error(m, "Error", PyExc_ValueError);
  error.doc() = "Base of curvbench's errors; a ValueError.";
  static py::exception<InputError> mesh_error(m, "MeshError", error.ptr());
  mesh_error.doc() =
      "Bad mesh data or file: wrong shape or dtype, index out of range, repeated vertex in a "
      "face, NaN/Inf coordinate, unreadable or malformed file.";
  static py::exception<UsageError> usage_error(m, "UsageError", error.ptr());
  usage_error.doc() = "Bad options: unknown method, unsupported degree, inconsistent options.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      mesh_error(e.what());
    } catch (const UsageError& e) {
      usage_error(e.what());
    }
  });

  py::class_<PyEstimate>(m, "Estimate",
                         "Per-vertex estimates of curvbench.estimate(); row/entry i is vertex i.")
      .def_readonly("method", &PyEstimate::method, "Label with degree, e.g. 'LHF-2'.")
      .def_readonly("normal", &PyEstimate::normal, "(n, 3) float64 unit normals.")
      .def_readonly("k1", &PyEstimate::k1, "(n,) float64 larger principal curvature.")
      .def_readonly("k2", &PyEstimate::k2, "(n,) float64 smaller principal curvature.")
      .def_readonly("H", &PyEstimate::H, "(n,) float64 mean curvature (k1 + k2) / 2.")
      .def_readonly("K", &PyEstimate::K, "(n,) float64 Gaussian curvature k1 k2.")
      .def_readonly("d1", &PyEstimate::d1, "(n, 3) float64 principal direction of k1.")
      .def_readonly("d2", &PyEstimate::d2, "(n, 3) float64 principal direction of k2.")
      .def_readonly("degree", &PyEstimate::degree, "(n,) int32 fitting degree actually used.")
      .def_readonly("points", &PyEstimate::points, "(n,) int32 points in each fit.")
      .def_readonly("ring", &PyEstimate::ring, "(n,) float64 ring actually used.")
      .def_readonly(
          "status", &PyEstimate::status,
          "(n,) str: 'ok', 'degree_reduced' (finite values at a lower degree), "
          "'failed' (no estimate: every value NaN), 'excluded' (NaN by design, e.g. Xu "
          "at a boundary vertex), 'disk_cut' (fitted on part of a ring that was not a "
          "disk), 'sign_undetermined' (finite, but the surface there cannot be "
          "oriented) or 'partial' (what can be determined there is finite, the rest "
          "NaN, e.g. Meyer's directions where its tensor fit is singular) or 'reprojected' "
          "(LSCM: the map folded the ring, fitted on its projection instead).")
      .def_readonly(
          "status_code", &PyEstimate::status_code,
          "(n,) uint8 status as 0 ok, 1 degree_reduced, 2 failed, 3 excluded, 4 disk_cut, "
          "5 sign_undetermined, 6 partial, 7 reprojected.")
      .def_readonly("recommendation", &PyEstimate::recommendation,
                    "method='auto': the advice it followed, as curvbench.recommend() returns it "
                    "(method, options, label, the mesh's quality and noise, the sweep's error); "
                    "None for a named method.")
      .def("__len__", [](const PyEstimate& e) { return e.estimates.size(); })
      .def("__repr__", [](const PyEstimate& e) {
        return "<curvbench.Estimate " + e.method + " of " + std::to_string(e.estimates.size()) +
               " vertices>";
      });

  py::class_<PyExact>(m, "Exact",
                      "Exact quantities of a generated mesh (curvbench.mesh()); row i is vertex i.")
      .def_readonly("surface", &PyExact::surface, "Name of the analytic surface.")
      .def_readonly("description", &PyExact::description, "Parameters, seed and noise.")
      .def_readonly("point", &PyExact::point,
                    "(n, 3) the exact surface point each vertex stands for (the vertex itself "
                    "unless noise was added).")
      .def_readonly("normal", &PyExact::normal, "(n, 3) exact unit normals.")
      .def_readonly("k1", &PyExact::k1, "(n,) exact larger principal curvature.")
      .def_readonly("k2", &PyExact::k2, "(n,) exact smaller principal curvature.")
      .def_readonly("H", &PyExact::H, "(n,) exact mean curvature.")
      .def_readonly("K", &PyExact::K, "(n,) exact Gaussian curvature.")
      .def_readonly("d1", &PyExact::d1, "(n, 3) exact principal direction of k1.")
      .def_readonly("d2", &PyExact::d2, "(n, 3) exact principal direction of k2.");

  m.def("estimate", &py_estimate, py::arg("V"), py::arg("F") = py::none(), py::arg("method") = "lhf",
        (std::string(R"(Estimate normals, principal curvatures and directions at every vertex.

V: (n, 3) vertex positions, float64 or float32 (int32/int64 accepted), any strides.
F: (m, 3) triangles as 0-based vertex indices, any integer dtype, any strides; None (the
default): V is a point set, estimated with a method that needs no faces (lhf, lop, jet) on
its k nearest neighbours (neighbourhood='knn=20', 'radius=0.1' or 'radius=2.5s').
method: a name of curvbench.methods(), case-insensitive; 'LHF-4' attaches the degree; or
'auto': the estimator and radius curvbench.recommend() gives the mesh (then only threads and
kernel may be given; the choice is in the result's recommendation).
**options: any estimator option below, by keyword (None: its default). An option set for a
method that does not take it raises UsageError, as on the command line.
)") + options_doc() +
         std::string(R"(
Returns a curvbench.Estimate: normal (n,3), k1, k2, H, K (n,), d1, d2 (n,3), degree, points,
ring (n,), status (n,) str and status_code (n,) uint8, method (label), recommendation (a dict
for method='auto', else None). Identical, bit for bit, to `curvbench estimate` on the same mesh.
The GIL is released while estimating.

Raises MeshError (a ValueError) for a wrong shape or dtype, an index out of range, a face
repeating a vertex or a NaN/Inf coordinate; UsageError for an unknown method, an unsupported
degree, a degree contradicting the method name, or an option of another method.)") +
         kConventions)
            .c_str());

  m.def("read_mesh", &py_read_mesh, py::arg("path"),
        R"(Read an OFF, OBJ or PLY file; polygons are fan-triangulated.

Returns (V, F): V (n, 3) float64, F (m, 3) int32. Elements the reader drops (faces with fewer
than 3 vertices or a repeated index) are reported as UserWarning with the command line's text.
Raises MeshError naming the file for an unreadable or malformed file.)");

  std::string mesh_options_doc;
  for (const MeshOptionInfo& o : mesh_option_table())
    mesh_options_doc += o.name + " (default " + format_g(o.default_value) + "): " + o.help + ".\n";
  static const std::string mesh_doc =
      R"(Generate a test mesh with its exact answer (as `curvbench mesh`).

family: one of the mesh families ('torus-structured', 'torus-iso', 'bump-48', ...; an
unknown name raises UsageError listing them); level: 1 = coarsest; noise_order: k >= 1 adds
alpha h^k normal noise (0 = none); seed: for the noise, jitter and irregular points.
Returns (V, F, exact): V (n, 3) float64, F (m, 3) int32, exact a curvbench.Exact.

Mesh options (keyword arguments; only for the families that take them, else UsageError):
)" + mesh_options_doc;
  m.def("mesh", &py_mesh, py::arg("family"), py::arg("level"), py::arg("noise_order") = 0,
        py::arg("seed") = 1, mesh_doc.c_str());

  m.def("score", &py_score, py::arg("exact_or_mesh"), py::arg("estimate"),
        py::arg("vertex_set") = "all",
        R"(Errors of an estimate against the exact answer, as the harness computes them.

exact_or_mesh: the Exact of curvbench.mesh(), or its whole (V, F, exact) tuple.
estimate: a curvbench.Estimate on the same mesh.
vertex_set: 'all', 'interior' or 'boundary-ring'.
Returns {quantity: {'L2': e, 'Linf': e, 'counted': vertices, 'excluded': vertices}} for the
quantities 'normal' (absolute RMS and max), 'H', 'K', 'k1', 'k2' (relative norm ratios) and 'd1'
(over non-umbilic vertices); excluded estimates (NaN by design) are left out and counted.)");

  m.def("recommend", &py_recommend, py::arg("V"), py::arg("F"), py::arg("noise") = py::none(),
        py::arg("results") = py::none(),
        R"(The estimator and radius recommended for a mesh, as `curvbench recommend`.

V, F: as for estimate(). noise: the mesh's noise sigma/h along the normal (None: estimated from
the residuals of a degree-4 fit at each vertex). results: a folder holding the
recommendations.csv to read (None: the table installed with curvbench, or the source tree's).
Returns a dict: quality and quality_reason (the mesh's class and why), sigma_over_h, noise
('estimated' or 'given'), noise_level (the table's nearest level), swept (False: no sweep ran at
that level, and the fields of the choice are None), method and options (estimate(V, F,
method=d['method'], **d['options']) runs the choice), label (the sweep's case), quantity, norm and
error (the error the sweep measured), experiment, family and level (the mesh it measured on),
table and provenance (the file read and its first comment line).
Raises MeshError for a mesh it cannot classify (under 50 vertices, non-manifold) and for a
missing, truncated or foreign table; UsageError for a negative noise.)");

  m.def("methods", &curvbench::methods, "Names accepted as estimate(method=...), without degree.");
}
