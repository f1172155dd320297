// The Python module `curvbench` (pybind11): numpy arrays in and out over the library.
//
//   estimate(V, F, method="lhf", **options) -> Estimate   (options: the estimator option table,
//            include/curvbench/estimator_options.h: degree=4, rings=2.5, vertex_normals="max", ...)
//   read_mesh(path) -> (V, F)
//   mesh(family, level, noise_order=0, seed=1, **options) -> (V, F, Exact)   (options: the mesh
//            options, mesh_options(): aspect=16, density=4)
//   score(exact_or_mesh, estimate, vertex_set="all") -> {quantity: {"L2", "Linf", ...}}
//   recommend(V, F, noise=None, results=None) -> dict   (the advice of `curvbench recommend`;
//            estimate(V, F, method="auto") follows it and keeps it in Estimate.recommendation)
//   methods(), __version__
//
// Everything goes through the public C++ API (include/curvbench/curvbench.h), the only
// curvbench header included here. Input arrays are read in place (any real dtype for V, any
// integer dtype for F, any strides) into the API's Eigen matrices; the GIL is released while
// estimating. Errors: curvbench.Error (a ValueError) with subclasses MeshError (bad mesh or file:
// the library's InputError) and UsageError (bad method, degree, option), with the command line's
// one-line messages.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "curvbench/curvbench.h"

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

// V as an n x 3 double matrix: one conversion from any real dtype and any strides.
Eigen::MatrixXd to_vertices(const py::handle& h) {
  const py::array a = as_array(h, "V");
  check_shape(a, "V", "n");
  const char kind = a.dtype().kind();
  const auto n = a.shape(0);
  Eigen::MatrixXd V(n, 3);
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

// F as an m x 3 int matrix from any integer dtype and any strides; indices outside the int
// range get the mesh's own out-of-range message.
Eigen::MatrixXi to_faces(const py::handle& h, py::ssize_t n) {
  const py::array a = as_array(h, "F");
  check_shape(a, "F", "m");
  const char kind = a.dtype().kind();
  const auto m = a.shape(0);
  Eigen::MatrixXi F(m, 3);
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

// An n x 3 matrix as an (n, 3) numpy array of T.
template <typename T, typename Matrix>
py::array_t<T> rows_array(const Matrix& m) {
  py::array_t<T> out({static_cast<py::ssize_t>(m.rows()), py::ssize_t{3}});
  auto r = out.template mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < 3; ++j) r(i, j) = static_cast<T>(m(i, j));
  return out;
}

// A vector as an (n,) numpy array of T.
template <typename T, typename Vector>
py::array_t<T> vector_array(const Vector& v) {
  py::array_t<T> out(static_cast<py::ssize_t>(v.size()));
  auto r = out.template mutable_unchecked<1>();
  for (Eigen::Index i = 0; i < v.size(); ++i) r(i) = static_cast<T>(v(i));
  return out;
}

/// The result of estimate(): numpy arrays plus the estimates themselves (for score()).
struct PyEstimate {
  std::string method;
  EstimateResult estimates;
  py::object normal, k1, k2, H, K, d1, d2, degree, points, ring, status, status_code;
  py::object recommendation = py::none();  ///< method="auto": the advice it followed
};

// The advice as recommend() returns it and Estimate.recommendation holds it.
py::dict advice_dict(const MeshAdvice& a) {
  py::dict d;
  d["quality"] = a.quality;
  d["quality_reason"] = a.quality_reason;
  d["sigma_over_h"] = a.sigma_over_h;
  d["noise"] = a.noise_estimated ? "estimated" : "given";
  d["noise_level"] = a.noise_level;
  d["swept"] = a.swept;
  py::dict options;
  if (a.swept && !a.parameter.empty()) {
    std::string key = a.parameter;
    for (char& c : key)
      if (c == '-') c = '_';
    options[key.c_str()] = a.radius;
  }
  const auto text = [&](const std::string& s) {
    return a.swept ? py::object(py::str(s)) : py::none();
  };
  d["method"] = text(a.method);
  d["options"] = options;
  d["label"] = text(a.label);
  d["quantity"] = text(a.quantity);
  d["norm"] = text(a.norm);
  d["error"] = a.swept ? py::object(py::float_(a.error)) : py::none();
  d["experiment"] = text(a.experiment);
  d["family"] = text(a.family);
  d["level"] = a.swept ? py::object(py::int_(a.level)) : py::none();
  d["table"] = a.table;
  d["provenance"] = a.provenance;
  // The advice from mesh features (docs/advice.md): the normals' choice, the curvature's error
  // range and cross-validated regret, the features out of the sweeps' range.
  const auto number = [](double x) {
    return std::isfinite(x) ? py::object(py::float_(x)) : py::object(py::none());
  };
  py::dict normal_options;
  if (!a.normal_parameter.empty()) {
    std::string key = a.normal_parameter;
    for (char& c : key)
      if (c == '-') c = '_';
    normal_options[key.c_str()] = a.normal_radius;
  }
  d["normal_method"] = a.normal_method.empty() ? py::object(py::none()) : py::str(a.normal_method);
  d["normal_options"] = normal_options;
  d["normal_label"] = a.normal_label.empty() ? py::object(py::none()) : py::str(a.normal_label);
  d["error_low"] = number(a.error_low);
  d["error_high"] = number(a.error_high);
  d["regret_median"] = number(a.regret_median);
  d["regret_worst"] = number(a.regret_worst);
  d["out_of_range"] = a.out_of_range;
  d["measured"] = a.measured;
  d["normal_predicted"] = number(a.normal_predicted);
  return d;
}

/// The exact quantities of a generated mesh, plus the mesh (for vertex sets in score()).
struct PyExact {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  ExactQuantities exact;
  std::string surface, description;
  py::object point, normal, k1, k2, H, K, d1, d2;
};

// The status names of the codes (status_name), as a numpy array of str.
py::array numpy_status_names(const py::array_t<std::uint8_t>& codes) {
  const py::module_ np = py::module_::import("numpy");
  py::tuple words(kStatusCount);
  for (int i = 0; i < kStatusCount; ++i) words[i] = status_name(static_cast<Status>(i));
  return np.attr("array")(words).attr("__getitem__")(codes);
}

// A keyword argument as the option table's typed value (set_estimator_option checks its type).
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
  for (const OptionDescription& o : estimator_options()) {
    std::string value = o.default_text;
    if (o.type == "bool") value = value == "yes" ? "True" : "False";
    if (o.type == "choice" || o.type == "text") value = "'" + value + "'";
    s += o.python_name + " (default " + value + "): " + o.help + ".\n";
  }
  return s;
}

PyEstimate py_estimate(const py::handle& V, const py::handle& F, const std::string& method,
                       const py::kwargs& kwargs) {
  EstimateOptions o;
  o.method = method;
  const std::vector<OptionDescription> table = estimator_options();
  for (const auto& [key, value] : kwargs) {
    if (value.is_none()) continue;  // None: the default
    const std::string name = key.cast<std::string>();
    const auto known = [&] {
      for (const OptionDescription& info : table)
        if (info.python_name == name) return true;
      return false;
    };
    if (!known()) {
      std::string valid;
      for (const OptionDescription& info : table)
        valid += (valid.empty() ? "" : ", ") + info.python_name;
      throw UsageError("unknown option '" + name + "' (valid: " + valid + ")");
    }
    set_estimator_option(o, name, option_value(value));
  }
  const Eigen::MatrixXd Vm = to_vertices(V);
  // F None: a point set (docs/point_sets.md).
  const Eigen::MatrixXi Fm = F.is_none() ? Eigen::MatrixXi(0, 3) : to_faces(F, Vm.rows());
  PyEstimate r;
  {
    py::gil_scoped_release unlocked;
    r.estimates = estimate(Vm, Fm, o);
  }
  const EstimateResult& e = r.estimates;
  if (e.recommendation) r.recommendation = advice_dict(*e.recommendation);
  r.method = e.method;
  r.normal = rows_array<double>(e.normal);
  r.d1 = rows_array<double>(e.d1);
  r.d2 = rows_array<double>(e.d2);
  r.k1 = vector_array<double>(e.k1);
  r.k2 = vector_array<double>(e.k2);
  r.H = vector_array<double>(e.H);
  r.K = vector_array<double>(e.K);
  r.degree = vector_array<std::int32_t>(e.degree);
  r.points = vector_array<std::int32_t>(e.points);
  r.ring = vector_array<double>(e.ring);
  py::array_t<std::uint8_t> codes(static_cast<py::ssize_t>(e.status.size()));
  auto c = codes.mutable_unchecked<1>();
  for (size_t i = 0; i < e.status.size(); ++i) c(i) = static_cast<std::uint8_t>(e.status[i]);
  r.status_code = codes;
  r.status = numpy_status_names(codes);
  return r;
}

py::dict py_recommend(const py::handle& V, const py::handle& F, std::optional<double> noise,
                      std::optional<std::string> results, bool measure, int threads) {
  const Eigen::MatrixXd Vm = to_vertices(V);
  const Eigen::MatrixXi Fm = to_faces(F, Vm.rows());
  RecommendOptions o;
  if (noise) o.noise = *noise;
  if (results) o.results = *results;
  o.measure = measure;
  o.threads = threads;
  std::optional<MeshAdvice> advice;
  {
    py::gil_scoped_release unlocked;
    advice = recommend(Vm, Fm, o);
  }
  return advice_dict(*advice);
}

py::tuple mesh_arrays(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  return py::make_tuple(rows_array<double>(V), rows_array<std::int32_t>(F));
}

py::tuple py_read_mesh(const std::string& path) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  std::vector<std::string> warnings;
  read_mesh(path, V, F, &warnings);
  for (const std::string& w : warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
  return mesh_arrays(V, F);
}

py::tuple py_mesh(const std::string& family, int level, int noise_order, std::uint64_t seed,
                  const py::kwargs& kwargs) {
  TestMeshOptions o;
  o.family = family;
  o.level = level;
  o.noise_order = noise_order;
  o.seed = seed;
  for (const auto& [key, value] : kwargs) {
    if (value.is_none()) continue;  // None: the default
    const std::string name = key.cast<std::string>();
    const bool number = !py::isinstance<py::bool_>(value) &&
                        (py::hasattr(value, "__index__") || py::hasattr(value, "__float__"));
    if (!number)
      throw UsageError("mesh option " + name + ": expected a number, got " +
                       py::str(py::type::of(value)).cast<std::string>());
    o.shape.emplace_back(name, value.cast<double>());
  }
  TestMesh g = generate_mesh(o);
  PyExact x;
  const ExactQuantities& q = g.exact;
  x.point = rows_array<double>(q.point);
  x.normal = rows_array<double>(q.normal);
  x.d1 = rows_array<double>(q.d1);
  x.d2 = rows_array<double>(q.d2);
  x.k1 = vector_array<double>(q.k1);
  x.k2 = vector_array<double>(q.k2);
  x.H = vector_array<double>(q.H);
  x.K = vector_array<double>(q.K);
  x.surface = g.surface;
  x.description = g.description;
  const py::tuple vf = mesh_arrays(g.V, g.F);
  x.V = std::move(g.V);
  x.F = std::move(g.F);
  x.exact = std::move(g.exact);
  return py::make_tuple(vf[0], vf[1], py::cast(std::move(x)));
}

py::dict py_score(const py::object& exact_or_mesh, const PyEstimate& est,
                  const std::string& vertex_set) {
  py::object ex = exact_or_mesh;
  if (py::isinstance<py::tuple>(ex) && py::len(ex) == 3) ex = ex.cast<py::tuple>()[2];
  if (!py::isinstance<PyExact>(ex))
    throw UsageError("score: expected the Exact of curvbench.mesh() or its (V, F, exact) tuple");
  const PyExact& x = ex.cast<const PyExact&>();
  py::dict out;
  for (const QuantityError& q : score(x.V, x.F, x.exact, est.estimates, vertex_set)) {
    py::dict row;
    row["L2"] = q.L2;
    row["Linf"] = q.Linf;
    row["counted"] = q.counted;
    row["excluded"] = q.excluded;
    out[q.quantity.c_str()] = row;
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
          "(LSCM: the map folded the ring, fitted on its projection instead) or "
          "'normal_fallback' (an operator fed a fit's normals: the fit gave none at a vertex "
          "this estimate reads, the operator's own normal stood in).")
      .def_readonly(
          "status_code", &PyEstimate::status_code,
          "(n,) uint8 status as 0 ok, 1 degree_reduced, 2 failed, 3 excluded, 4 disk_cut, "
          "5 sign_undetermined, 6 partial, 7 reprojected, 8 normal_fallback.")
      .def_readonly("recommendation", &PyEstimate::recommendation,
                    "method='auto': the advice it followed, as curvbench.recommend() returns it "
                    "(method, options, label, the mesh's quality and noise, the sweep's error); "
                    "None for a named method.")
      .def("__len__", [](const PyEstimate& e) { return e.estimates.status.size(); })
      .def("__repr__", [](const PyEstimate& e) {
        return "<curvbench.Estimate " + e.method + " of " +
               std::to_string(e.estimates.status.size()) + " vertices>";
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

  m.def("estimate", &py_estimate, py::arg("V"), py::arg("F") = py::none(),
        py::arg("method") = "lhf",
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
  for (const MeshOptionDescription& o : mesh_options()) {
    char value[32];
    std::snprintf(value, sizeof value, "%g", o.default_value);
    mesh_options_doc += o.name + " (default " + value + "): " + o.help + ".\n";
  }
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
        py::arg("results") = py::none(), py::arg("measure") = false, py::arg("threads") = 0,
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
measure: also measure the advice on the mesh itself (as `curvbench recommend --measure`; each
swept case runs 3 times on it, with `threads` threads): then method, options and label are the
curvature choice measured on the mesh, error its predicted relative L2 error in H, normal_* the
normals' measured choice with normal_predicted its predicted RMS error, measured True, family
'', level 0, error_low and error_high None, and regret_median, regret_worst what the same
measurement did for H on the swept meshes.
Raises MeshError for a mesh it cannot classify (under 50 vertices, non-manifold) and for a
missing, truncated or foreign table; UsageError for a negative noise.)");

  m.def("methods", &curvbench::methods, "Names accepted as estimate(method=...), without degree.");
}
