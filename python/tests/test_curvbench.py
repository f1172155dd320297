"""Tests of the Python module `curvbench` (run by ctest as python.pytest, with /usr/bin/python3).

Environment (set by ctest): PYTHONPATH = the build's python/ folder, CURVBENCH_EXE = the build's
curvbench command.
"""
import csv
import os
import subprocess
import threading

import numpy as np
import pytest

import curvbench

EXE = os.environ.get("CURVBENCH_EXE", "curvbench")
QUANTITIES = ("k1", "k2", "H", "K")
VECTORS = {"normal": ("nx", "ny", "nz"), "d1": ("d1x", "d1y", "d1z"), "d2": ("d2x", "d2y", "d2z")}


def cli(*args):
    return subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)


@pytest.fixture(scope="module")
def torus(tmp_path_factory):
    """A structured torus written by `curvbench mesh` (OFF, %.17g: reads back exactly)."""
    path = tmp_path_factory.mktemp("mesh") / "torus.off"
    r = cli("mesh", "--family", "torus-structured", "--level", "1", "--output", path)
    assert r.returncode == 0, r.stderr
    return str(path)


def read_cli_csv(path):
    rows = list(csv.DictReader(open(path)))
    return rows


def test_readme_example():
    # The Python example of docs/python.md, verbatim between the markers.
    # --- README example start ---
    import curvbench

    V, F, exact = curvbench.mesh("torus-structured", level=2)  # or: V, F = curvbench.read_mesh("my.ply")
    est = curvbench.estimate(V, F, method="lhf", degree=2)
    print(est.method, est.H[:3], est.status[:3])  # LHF-2 [...] ['ok' 'ok' 'ok']
    errors = curvbench.score(exact, est)
    print("H: relative L2 error %.2e, Linf %.2e" % (errors["H"]["L2"], errors["H"]["Linf"]))
    # --- README example end ---
    assert est.method == "LHF-2"
    assert 0 < errors["H"]["L2"] < 0.05
    assert errors["H"]["counted"] == len(V)


def test_bitwise_identical_to_the_command_line(torus, tmp_path):
    for method, extra in (("lhf", ["--degree", "2"]), ("lop", ["--degree", "3"]), ("xu", [])):
        out = tmp_path / f"{method}.csv"
        r = cli("estimate", torus, "--method", method, *extra, "--output", out)
        assert r.returncode == 0, r.stderr
        rows = read_cli_csv(out)
        V, F = curvbench.read_mesh(torus)
        degree = int(extra[1]) if extra else None
        est = curvbench.estimate(V, F, method=method, degree=degree)
        assert len(rows) == len(V) == len(est)
        for q in QUANTITIES:
            want = np.array([float(row[q]) for row in rows])
            got = getattr(est, q)
            assert np.array_equal(got, want, equal_nan=True), (method, q)
            assert np.array_equal(np.signbit(got), np.signbit(want)), (method, q)
        for name, cols in VECTORS.items():
            want = np.array([[float(row[c]) for c in cols] for row in rows])
            assert np.array_equal(getattr(est, name), want, equal_nan=True), (method, name)
        assert list(est.status) == [row["status"] for row in rows]
        assert est.degree.tolist() == [int(row["degree"]) for row in rows]
        assert est.points.tolist() == [int(row["points"]) for row in rows]


def test_shapes_dtypes_and_sign_convention():
    V, F, exact = curvbench.mesh("torus-structured", 1)
    assert V.shape[1] == 3 and V.dtype == np.float64
    assert F.shape[1] == 3 and F.dtype == np.int32
    est = curvbench.estimate(V, F)
    n = len(V)
    for name in ("normal", "d1", "d2"):
        assert getattr(est, name).shape == (n, 3) and getattr(est, name).dtype == np.float64
    for name in ("k1", "k2", "H", "K", "ring"):
        assert getattr(est, name).shape == (n,) and getattr(est, name).dtype == np.float64
    assert est.degree.dtype == np.int32 and est.points.dtype == np.int32
    assert est.status.shape == (n,) and est.status_code.dtype == np.uint8
    assert set(est.status) <= {
        "ok", "degree_reduced", "failed", "excluded", "disk_cut", "sign_undetermined", "partial",
        "reprojected", "normal_fallback"}
    assert np.all(est.k1 >= est.k2)
    # Outward normals on the closed torus: the estimate agrees with the exact normal.
    assert np.all(np.einsum("ij,ij->i", est.normal, exact.normal) > 0.9)
    assert exact.point.shape == (n, 3) and exact.surface


def test_sphere_convention_on_the_outer_equator_sign():
    # Sign table: outward normals, B = n . x_uu, so convex parts have negative k (sphere -1/r).
    V, F, exact = curvbench.mesh("torus-structured", 2)
    est = curvbench.estimate(V, F, method="lhf", degree=2)
    outer = np.argmax(np.linalg.norm(V[:, :2], axis=1))
    assert exact.k1[outer] < 0 and exact.k2[outer] < 0
    assert est.k1[outer] < 0 and est.k2[outer] < 0


def test_float32_int64_and_non_contiguous_input_give_the_same_result():
    V, F, _ = curvbench.mesh("torus-structured", 1)
    ref = curvbench.estimate(V, F)
    # float32 coordinates: converted (values change by rounding, so compare with float32 V).
    V32 = V.astype(np.float32)
    a = curvbench.estimate(V32, F.astype(np.int64))
    b = curvbench.estimate(V32.astype(np.float64), F)
    assert np.array_equal(a.H, b.H, equal_nan=True)
    # Fortran order and strided views read in place.
    assert np.array_equal(curvbench.estimate(np.asfortranarray(V), np.asfortranarray(F)).H, ref.H)
    wide = np.zeros((len(V), 6))
    wide[:, ::2] = V
    assert not wide[:, ::2].flags.c_contiguous
    assert np.array_equal(curvbench.estimate(wide[:, ::2], F).H, ref.H)
    assert np.array_equal(curvbench.estimate(V.tolist(), F.tolist()).H, ref.H)


def test_threads_do_not_change_the_bits_and_python_threads_run_concurrently():
    V, F, _ = curvbench.mesh("torus-structured", 2)
    one = curvbench.estimate(V, F, method="lhf", degree=3, threads=1)
    two = curvbench.estimate(V, F, method="lhf", degree=3, threads=2)
    assert one.H.tobytes() == two.H.tobytes() and one.normal.tobytes() == two.normal.tobytes()
    results = [None] * 4

    def work(i):
        results[i] = curvbench.estimate(V, F, method="LHF-3", threads=1)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        assert r.H.tobytes() == one.H.tobytes()


def test_score_matches_the_harness_definitions():
    V, F, exact = curvbench.mesh("bump-48", 2)
    est = curvbench.estimate(V, F, method="lhf", degree=2)
    s = curvbench.score((V, F, exact), est)
    h = est.H - exact.H
    assert s["H"]["L2"] == pytest.approx(np.linalg.norm(h) / np.linalg.norm(exact.H), rel=1e-12)
    assert s["H"]["Linf"] == pytest.approx(np.max(np.abs(h)) / np.max(np.abs(exact.H)), rel=1e-12)
    dn = np.linalg.norm(est.normal - exact.normal, axis=1)
    assert s["normal"]["L2"] == pytest.approx(np.sqrt(np.mean(dn**2)), rel=1e-12)
    interior = curvbench.score(exact, est, vertex_set="interior")
    assert interior["H"]["counted"] < s["H"]["counted"] == len(V)
    # Xu excludes boundary vertices (NaN by design): left out and counted.
    xu = curvbench.estimate(V, F, method="xu")
    sx = curvbench.score(exact, xu)
    assert sx["H"]["excluded"] == np.count_nonzero(xu.status == "excluded") > 0
    with pytest.raises(curvbench.UsageError, match="unknown vertex set 'inner'"):
        curvbench.score(exact, est, vertex_set="inner")
    with pytest.raises(curvbench.UsageError):
        curvbench.score({"H": exact.H}, est)
    V1, F1, exact1 = curvbench.mesh("bump-48", 1)
    with pytest.raises(curvbench.MeshError, match="vertices"):
        curvbench.score(exact1, est)


def error_line(*args):
    """The one-line message of `curvbench` for the same problem (stderr minus the prefix)."""
    r = cli(*args)
    assert r.returncode == 2
    return r.stderr.strip().split(": error: ", 1)[-1].split(": usage error: ", 1)[-1]


@pytest.mark.parametrize(
    "V, F, message",
    [
        (np.zeros((3, 2)), [[0, 1, 2]], r"V: expected shape \(n, 3\), got \(3, 2\)"),
        (np.zeros(9), [[0, 1, 2]], r"V: expected shape \(n, 3\), got \(9,\)"),
        (np.eye(3), [[0, 1]], r"F: expected shape \(m, 3\), got \(1, 2\)"),
        (np.eye(3), np.array([[0.0, 1.0, 2.0]]), "F: expected integer vertex indices"),
        (np.eye(3).astype(complex), [[0, 1, 2]], "V: expected float64 or float32"),
        (np.array([["a", "b", "c"]]), [[0, 1, 2]], "V: expected float64 or float32"),
        (np.eye(3), [[0, 1, 3]], r"mesh: face 0 references vertex 3, out of range \[0, 3\)"),
        (np.eye(3), [[0, -1, 2]], r"mesh: face 0 references vertex -1, out of range \[0, 3\)"),
        (np.eye(3), np.array([[0, 1, 2**40]]), r"references vertex 1099511627776, out of range"),
        (np.eye(3), [[0, 1, 1]], r"mesh: face 0 repeats a vertex \(0 1 1\)"),
        (np.array([[0, 0, 0], [1, 0, np.nan], [0, 1, 0]]), [[0, 1, 2]],
         r"mesh: vertex 1 has a non-finite coordinate"),
        (np.array([[0, 0, 0], [1, 0, np.inf], [0, 1, 0]]), [[0, 1, 2]],
         r"mesh: vertex 1 has a non-finite coordinate"),
    ],
)
def test_bad_arrays_raise_mesh_error(V, F, message):
    with pytest.raises(curvbench.MeshError, match=message) as e:
        curvbench.estimate(V, F)
    assert isinstance(e.value, ValueError) and isinstance(e.value, curvbench.Error)
    assert "\n" not in str(e.value)


def test_bad_options_raise_usage_error_with_the_command_line_message(torus, tmp_path):
    V, F = curvbench.read_mesh(torus)
    want = error_line("estimate", torus, "--method", "nosuch", "--output", tmp_path / "x.csv")
    with pytest.raises(curvbench.UsageError) as e:
        curvbench.estimate(V, F, method="nosuch")
    assert str(e.value) == want
    assert isinstance(e.value, ValueError)
    want = error_line("estimate", torus, "--method", "lhf", "--degree", "9", "--output",
                      tmp_path / "x.csv")
    with pytest.raises(curvbench.UsageError) as e:
        curvbench.estimate(V, F, method="lhf", degree=9)
    assert str(e.value) == want
    with pytest.raises(curvbench.UsageError, match="method lhf-4 names degree 4 but degree is 2"):
        curvbench.estimate(V, F, method="lhf-4", degree=2)
    assert curvbench.estimate(V, F, method="lhf-4").method == "LHF-4"
    # One validation (the option table) for C++, the command line and Python: negative values are
    # errors with the command line's message; 0 is each option's default, as in C++.
    for name, value in (("degree", -1), ("rings", -1.0), ("threads", -1), ("ball_factor", -2.0)):
        method = "normal-cycle" if name == "ball_factor" else "lhf"
        flag = "--" + name.replace("_", "-")
        want = error_line("estimate", torus, "--method", method, flag, str(value), "--output",
                          tmp_path / "x.csv")
        with pytest.raises(curvbench.UsageError) as e:
            curvbench.estimate(V, F, method=method, **{name: value})
        assert str(e.value) == want, name
    default = curvbench.estimate(V, F, method="lhf").H
    for kwargs in ({"degree": 0}, {"rings": 0}, {"threads": 0}, {"degree": None}):
        assert np.array_equal(curvbench.estimate(V, F, method="lhf", **kwargs).H, default,
                              equal_nan=True), kwargs
    with pytest.raises(curvbench.UsageError, match="unknown option 'ring'"):
        curvbench.estimate(V, F, ring=2)
    with pytest.raises(curvbench.UsageError, match="noisy: expected True or False"):
        curvbench.estimate(V, F, noisy=1)
    with pytest.raises(curvbench.UsageError, match="torus-structured"):
        curvbench.mesh("nosuch", 1)
    with pytest.raises(curvbench.UsageError):
        curvbench.mesh("torus-structured", 99)


def test_options_of_single_methods_match_the_command_line(torus, tmp_path):
    V, F = curvbench.read_mesh(torus)
    for method, cli_args, kwargs in (
            ("meyer", ["--vertex-normals", "angle"], {"vertex_normals": "angle"}),
            ("quadric", ["--quadric-constant"], {"quadric_constant": True}),
            ("normal-cycle", ["--ball-factor", "2"], {"ball_factor": 2.0}),
            ("icc", ["--vertex-normals", "lhf-3"], {"vertex_normals": "lhf-3"})):
        out = tmp_path / f"{method}.csv"
        r = cli("estimate", torus, "--method", method, *cli_args, "--output", out)
        assert r.returncode == 0, r.stderr
        want = np.array([float(row["H"]) for row in read_cli_csv(out)])
        got = curvbench.estimate(V, F, method=method, **kwargs).H
        assert np.array_equal(got, want, equal_nan=True), method
        assert not np.array_equal(curvbench.estimate(V, F, method=method).H, got), method
    want = error_line("estimate", torus, "--method", "lhf", "--vertex-normals", "max", "--output",
                      tmp_path / "x.csv")
    with pytest.raises(curvbench.UsageError) as e:
        curvbench.estimate(V, F, method="lhf", vertex_normals="max")
    assert str(e.value) == want
    want = error_line("estimate", torus, "--method", "icc", "--vertex-normals", "meyer",
                      "--output", tmp_path / "y.csv")
    with pytest.raises(curvbench.UsageError) as e:
        curvbench.estimate(V, F, method="icc", vertex_normals="meyer")  # not a fit
    assert str(e.value) == want
    for kwargs in ({"vertex_normals": "cot"}, {"vertex_normals": "lhf-3"},
                   {"quadric_constant": True}, {"ball_factor": 1.0}):
        with pytest.raises(curvbench.UsageError):
            curvbench.estimate(V, F, method="meyer", **kwargs)


def test_read_mesh_errors_and_warnings_match_the_command_line():
    corpus = os.path.join(os.environ["CURVBENCH_SOURCE_DIR"], "tests", "corpus", "off")
    for name in ("broken_nan.off", "broken_index_out_of_range.off", "broken_truncated.off"):
        path = os.path.join(corpus, name)
        want = error_line("info", path)
        with pytest.raises(curvbench.MeshError) as e:
            curvbench.read_mesh(path)
        assert str(e.value) == want, name
    with pytest.raises(curvbench.MeshError, match="nonexistent"):
        curvbench.read_mesh("/nonexistent/mesh.off")
    path = os.path.join(corpus, "defect_repeated_index.off")
    r = cli("info", path)
    want = [l.split("curvbench: warning: ", 1)[1] for l in r.stderr.splitlines()
            if l.startswith("curvbench: warning: ")]
    assert want
    with pytest.warns(UserWarning) as w:
        curvbench.read_mesh(path)
    assert [str(x.message) for x in w] == want


def test_methods_version_and_docstrings():
    assert {"lhf", "lop", "xu", "lscm", "jet"} <= set(curvbench.methods())
    r = cli("--version")
    assert curvbench.__version__ in r.stdout
    for f in (curvbench.estimate, curvbench.read_mesh, curvbench.mesh, curvbench.score,
              curvbench.methods, curvbench.Estimate, curvbench.Exact, curvbench.MeshError,
              curvbench.UsageError, curvbench.Error):
        assert f.__doc__ and len(f.__doc__) > 20, f
    assert "-1/r" in curvbench.estimate.__doc__  # the sign convention


def test_mesh_options():
    # aspect=A and density=D reach the generator; the default given equals the default.
    V4, F4, _ = curvbench.mesh("torus-anisotropic", 1)
    V4b, _, _ = curvbench.mesh("torus-anisotropic", 1, aspect=4)
    V16, _, ex16 = curvbench.mesh("torus-anisotropic", 1, aspect=16)
    assert np.array_equal(V4, V4b)
    assert not (V4.shape == V16.shape and np.array_equal(V4, V16))
    assert "aspect A=16" in ex16.description
    _, _, exd = curvbench.mesh("bump-density", 1, density=2, seed=3)
    assert "density D=2 " in exd.description
    with pytest.raises(curvbench.UsageError, match=r"^aspect 1 out of range: must be > 1$"):
        curvbench.mesh("torus-anisotropic", 1, aspect=1)
    with pytest.raises(curvbench.UsageError, match=r"^density 0.5 out of range: must be >= 1$"):
        curvbench.mesh("bump-density", 1, density=0.5)
    with pytest.raises(curvbench.UsageError, match="aspect 4 does not apply to bump-48"):
        curvbench.mesh("bump-48", 1, aspect=4)
    with pytest.raises(curvbench.UsageError, match="unknown mesh option 'stretch'"):
        curvbench.mesh("bump-anisotropic", 1, stretch=2)
    with pytest.raises(curvbench.UsageError, match="mesh option aspect: expected a number"):
        curvbench.mesh("bump-anisotropic", 1, aspect="wide")


def test_auto_follows_the_recommendation_of_the_command_line(tmp_path):
    # method="auto" runs the estimator and radius `curvbench recommend` names for the mesh, keeps
    # the advice in est.recommendation, and gives what naming them gives.
    import json

    path = tmp_path / "bump.off"
    r = cli("mesh", "--family", "bump-irregular", "--level", "2", "--output", path)
    assert r.returncode == 0, r.stderr
    r = cli("recommend", path, "--format", "json")
    assert r.returncode == 0, r.stderr
    want = json.loads(r.stdout)
    V, F = curvbench.read_mesh(str(path))
    rec = curvbench.recommend(V, F)
    for key in ("quality", "quality_reason", "noise", "noise_level", "swept", "method", "label",
                "quantity", "norm", "error", "table", "provenance"):
        assert rec[key] == want[key], key
    assert rec["sigma_over_h"] == pytest.approx(want["sigma_over_h"], rel=1e-12)
    assert rec["options"] == {k.replace("-", "_"): v for k, v in want["options"].items()}
    assert rec["quality"] == "irregular" and rec["swept"]
    # The advice from mesh features (advice_cases.csv beside the table): the normals' choice,
    # the curvatures' cross-validated range and the features out of range, as the JSON says.
    advice = want["advice"]
    assert rec["normal_label"] == advice["normal"]["label"]
    assert rec["normal_method"] == advice["normal"]["method"]
    assert rec["label"] == advice["H"]["label"]
    assert rec["error_low"] == pytest.approx(advice["H"]["lowest_error"], rel=1e-12)
    assert rec["regret_median"] == pytest.approx(advice["H"]["median_regret"], rel=1e-12)
    assert rec["regret_worst"] == pytest.approx(advice["H"]["worst_regret"], rel=1e-12)
    assert rec["out_of_range"] == [o["feature"] for o in want["out_of_range"]]
    est = curvbench.estimate(V, F, method="auto")
    assert est.recommendation == rec
    named = curvbench.estimate(V, F, method=rec["method"], **rec["options"])
    assert est.method == named.method == rec["label"].split(" ")[0]
    for q in QUANTITIES:
        assert np.array_equal(getattr(est, q), getattr(named, q), equal_nan=True), q
    assert named.recommendation is None
    # Given noise, another table; the run options only; bad tables name the file.
    assert curvbench.recommend(V, F, noise=0.2)["noise_level"] == 0.1
    assert curvbench.recommend(V, F, noise=0.2)["noise"] == "given"
    assert curvbench.estimate(V, F, method="Auto", threads=1).method == est.method
    with pytest.raises(curvbench.UsageError, match="rings cannot be given"):
        curvbench.estimate(V, F, method="auto", rings=2)
    with pytest.raises(curvbench.MeshError, match="recommendations.csv: not found"):
        curvbench.recommend(V, F, results=str(tmp_path))
    (tmp_path / "recommendations.csv").write_text("# x\nquality,sigma_over_h\nwell-shaped,0\n")
    with pytest.raises(curvbench.MeshError, match="recommendations.csv: no column 'status'"):
        curvbench.recommend(V, F, results=str(tmp_path))
    with pytest.raises(curvbench.UsageError, match="sigma/h must be finite"):
        curvbench.recommend(V, F, noise=-1.0)


def test_measured_advice_matches_the_command_line(tmp_path):
    # recommend(measure=True) is `curvbench recommend --measure`: the same choices per quantity,
    # the curvature's predicted error, and what the measurement did on the swept meshes.
    import json

    path = tmp_path / "t.off"
    r = cli("mesh", "--family", "torus-unstructured", "--level", "1", "--noise-order", "2",
            "--output", path)
    assert r.returncode == 0, r.stderr
    r = cli("recommend", path, "--measure", "--format", "json")
    assert r.returncode == 0, r.stderr
    want = json.loads(r.stdout)["measured_advice"]
    V, F = curvbench.read_mesh(str(path))
    rec = curvbench.recommend(V, F, measure=True, threads=1)
    assert rec["measured"] is True
    assert rec["label"] == want["H"]["label"]
    assert rec["error"] == pytest.approx(want["H"]["predicted"], rel=1e-12)
    assert rec["normal_label"] == want["normal"]["label"]
    assert rec["normal_predicted"] == pytest.approx(want["normal"]["predicted"], rel=1e-12)
    assert rec["experiment"] == "measured on the mesh" and rec["family"] == ""
    assert rec["error_low"] is None and rec["error_high"] is None
    assert rec["regret_median"] == pytest.approx(want["H"]["validated"]["median_regret"], rel=1e-12)
    assert rec["regret_worst"] >= rec["regret_median"] >= 1.0
    assert curvbench.recommend(V, F)["measured"] is False
    (tmp_path / "recommendations.csv").write_bytes(
        open(os.path.join(os.environ["CURVBENCH_SOURCE_DIR"], "results",
                          "recommendations.csv"), "rb").read())
    with pytest.raises(curvbench.MeshError, match="measure: no advice_cases.csv beside"):
        curvbench.recommend(V, F, results=str(tmp_path), measure=True)


def test_the_module_includes_only_the_public_api():
    # python/curvbench_module.cpp is a client of include/curvbench/ like any other: besides
    # pybind11 and the standard library it includes only <curvbench/...> headers.
    source = os.path.join(os.environ["CURVBENCH_SOURCE_DIR"], "python", "curvbench_module.cpp")
    quoted = [line.split('"')[1] for line in open(source) if line.startswith('#include "')]
    assert quoted and all(h.startswith("curvbench/") for h in quoted), quoted
    public = os.listdir(os.path.join(os.environ["CURVBENCH_SOURCE_DIR"], "include", "curvbench"))
    assert all(h.split("/", 1)[1] in public for h in quoted)


def test_point_set_without_faces_is_outward_and_matches_the_command_line(tmp_path):
    """estimate(V) without F: a point set (docs/point_sets.md); a sphere's points get
    H = -1/r with outward normals, the same bits as `curvbench estimate` on the .xyz file."""
    rng = np.random.default_rng(5)
    d = rng.normal(size=(3000, 3))
    V = 2.0 * d / np.linalg.norm(d, axis=1)[:, None]
    r = curvbench.estimate(V, method="lhf-3", neighbourhood="knn=20")
    ok = r.status == "ok"
    assert ok.sum() == len(V)
    assert np.all(np.einsum("ij,ij->i", r.normal, V) > 0)
    # O(h^2) for degree 3 on random points, h / r about 0.065 here: within 2% of -1/r.
    assert np.allclose(r.H, -0.5, atol=1e-2)
    default = curvbench.estimate(V, method="lhf-3")  # the default knn=2*10=20
    assert np.array_equal(default.H, r.H)
    path = tmp_path / "sphere.xyz"
    np.savetxt(path, V, fmt="%.17g")
    out = tmp_path / "est.csv"
    c = cli("estimate", "--method", "lhf-3", "--neighbourhood", "knn=20", "--output", out, path)
    assert c.returncode == 0, c.stderr
    with open(out) as f:
        H = np.array([float(row["H"]) for row in csv.DictReader(f)])
    assert np.array_equal(H, r.H)
    with pytest.raises(curvbench.UsageError, match="a point set has no faces"):
        curvbench.estimate(V, method="meyer")


def test_point_normals_option_jet_and_file_without_normals(tmp_path):
    """point_normals="jet": the jet's starting normals, outward on a sphere and the same bits as
    the command line's --point-normals jet; "file" on arrays (no normals given) is refused with
    the command line's one line."""
    rng = np.random.default_rng(7)
    d = rng.normal(size=(2000, 3))
    V = 2.0 * d / np.linalg.norm(d, axis=1)[:, None]
    r = curvbench.estimate(V, method="lhf-2", point_normals="jet")
    assert (r.status == "ok").all()
    assert np.all(np.einsum("ij,ij->i", r.normal, V) > 0)
    assert np.allclose(r.H, -0.5, atol=5e-2)
    path = tmp_path / "sphere.xyz"
    np.savetxt(path, V, fmt="%.17g")
    out = tmp_path / "est.csv"
    c = cli("estimate", "--method", "lhf-2", "--point-normals", "jet", "--output", out, path)
    assert c.returncode == 0, c.stderr
    with open(out) as f:
        H = np.array([float(row["H"]) for row in csv.DictReader(f)])
    assert np.array_equal(H, r.H)
    with pytest.raises(curvbench.MeshError, match="point-normals=file, but the points come "
                       "without normals"):
        curvbench.estimate(V, method="lhf-2", point_normals="file")
