#!/usr/bin/python3
"""results/REAL_MESHES.md from the runs of tools/realmeshes.sh (standard library only).

Per mesh: the `curvbench info` counts and defects; per method: time, vertices by status, and the
agreement of H with the reference method as the median and 99th percentile of
    d_i = |H_i - H_ref,i| / (|H_ref,i| + median_j |H_ref,j|)
(one vertex cannot dominate it, unlike a relative L2 norm, which is also given with the share of
its square that the 10 worst vertices carry); then the worst vertices (largest d over all
methods) with their local mesh quality: smallest and largest angle of the incident faces, valence,
the ratio of the largest to the smallest incident face area, the fold (the largest angle between
the normals of two faces sharing an edge in the vertex's two-ring patch: near 180 degrees the sheet
folds back on itself, and no height function over any plane fits it) and the shortest edge at the
vertex over the mean edge length (near-coincident vertices). Per method also the relative L2
difference without the vertices whose two-ring holds a fold > 90 degrees.
"""
import argparse
import csv
import math
import os
import re
import sys


def read_off(path):
    toks = open(path).read().split()
    assert toks[0].upper().startswith("OFF")
    nv, nf = int(toks[1]), int(toks[2])
    p = 4
    V = [tuple(float(x) for x in toks[p + 3 * i:p + 3 * i + 3]) for i in range(nv)]
    p += 3 * nv
    F = []
    for _ in range(nf):
        k = int(toks[p])
        idx = [int(x) for x in toks[p + 1:p + 1 + k]]
        for j in range(1, k - 1):  # fan, as the reader does
            F.append((idx[0], idx[j], idx[j + 1]))
        p += 1 + k
    return V, F


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a):
    return math.sqrt(dot(a, a))


def vertex_quality(V, F):
    """Per vertex: (smallest angle, largest angle) in degrees over incident faces, valence,
    largest / smallest incident face area (inf if a face has zero area)."""
    n = len(V)
    amin = [180.0] * n
    amax = [0.0] * n
    val = [0] * n
    area_lo = [math.inf] * n
    area_hi = [0.0] * n
    for f in F:
        P = [V[i] for i in f]
        area = 0.5 * norm(cross(sub(P[1], P[0]), sub(P[2], P[0])))
        angles = []
        for k in range(3):
            e1, e2 = sub(P[(k + 1) % 3], P[k]), sub(P[(k + 2) % 3], P[k])
            angles.append(math.degrees(math.atan2(norm(cross(e1, e2)), dot(e1, e2))))
        for k, v in enumerate(f):
            val[v] += 1
            amin[v] = min(amin[v], min(angles))
            amax[v] = max(amax[v], max(angles))
            area_lo[v] = min(area_lo[v], area)
            area_hi[v] = max(area_hi[v], area)
    ratio = [(area_hi[v] / area_lo[v]) if area_lo[v] > 0 else math.inf for v in range(n)]
    return amin, amax, val, ratio


def folds_and_short_edges(V, F):
    """Per vertex: the fold in degrees (largest angle between the normals of two faces sharing an
    edge, over the edges of the faces around the vertex and around its neighbours) and the
    shortest incident edge length; and the mean edge length."""
    n = len(V)
    normal = []
    for f in F:
        P = [V[i] for i in f]
        c = cross(sub(P[1], P[0]), sub(P[2], P[0]))
        ln = norm(c)
        normal.append((c[0] / ln, c[1] / ln, c[2] / ln) if ln > 0 else None)
    edge_faces = {}
    for fi, f in enumerate(F):
        for k in range(3):
            edge_faces.setdefault(tuple(sorted((f[k], f[(k + 1) % 3]))), []).append(fi)
    face_fold = [0.0] * len(F)  # largest angle to an edge-neighbour face
    shortest = [math.inf] * n
    nbrs = [set() for _ in range(n)]
    total = 0.0
    for (a, b), fs in edge_faces.items():
        ln = norm(sub(V[a], V[b]))
        total += ln
        shortest[a] = min(shortest[a], ln)
        shortest[b] = min(shortest[b], ln)
        nbrs[a].add(b)
        nbrs[b].add(a)
        for x in fs:
            for y in fs:
                if x < y and normal[x] and normal[y]:
                    ang = math.degrees(math.acos(max(-1.0, min(1.0, dot(normal[x], normal[y])))))
                    face_fold[x] = max(face_fold[x], ang)
                    face_fold[y] = max(face_fold[y], ang)
    star = [0.0] * n
    for fi, f in enumerate(F):
        for v in f:
            star[v] = max(star[v], face_fold[fi])
    fold = [max([star[v]] + [star[w] for w in nbrs[v]]) for v in range(n)]
    return fold, shortest, total / max(1, len(edge_faces))


def read_estimate(path):
    H, status = [], []
    with open(path) as f:
        for row in csv.DictReader(f):
            H.append(float(row["H"]))
            status.append(row["status"])
    return H, status


def median(xs):
    s = sorted(xs)
    if not s:
        return math.nan
    m = len(s) // 2
    return s[m] if len(s) % 2 else 0.5 * (s[m - 1] + s[m])


def percentile(xs, q):
    s = sorted(xs)
    if not s:
        return math.nan
    return s[min(len(s) - 1, int(math.ceil(q / 100.0 * len(s))) - 1)]


def agreement(H, Href, skip=frozenset()):
    """d_i as in the module comment, over vertices where both are finite; relative L2 and the share
    of its square carried by the 10 worst vertices; relative L2 without the vertices in skip."""
    scale = median([abs(h) for h in Href if math.isfinite(h)])
    d = {}
    for i, (h, r) in enumerate(zip(H, Href)):
        if math.isfinite(h) and math.isfinite(r):
            d[i] = abs(h - r) / (abs(r) + scale)
    num = [(H[i] - Href[i]) ** 2 for i in d]
    den = sum(Href[i] ** 2 for i in d)
    l2 = math.sqrt(sum(num) / den) if den > 0 else math.nan
    top10 = sum(sorted(num, reverse=True)[:10]) / sum(num) if sum(num) > 0 else math.nan
    kept = [i for i in d if i not in skip]
    den_kept = sum(Href[i] ** 2 for i in kept)
    l2_kept = (math.sqrt(sum((H[i] - Href[i]) ** 2 for i in kept) / den_kept)
               if den_kept > 0 else math.nan)
    return d, l2, top10, l2_kept


def summary_time(log):
    m = re.search(r" in ([0-9.]+) s ", open(log).read())
    return float(m.group(1)) if m else math.nan


def info_lines(path):
    keep = ("vertices", "faces", "boundary edges", "non-manifold edges", "non-manifold vertices",
            "zero-area faces", "duplicate vertices", "components", "euler characteristic",
            "mean edge length", "orientation")
    out = []
    for line in open(path):
        key = line.split(":")[0].strip()
        if key in keep:
            out.append("%s: %s" % (key, line.split(":", 1)[1].strip()))
    return out


STATUSES = ["ok", "degree_reduced", "disk_cut", "sign_undetermined", "partial", "reprojected",
            "failed", "excluded"]


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("work")
    ap.add_argument("output")
    ap.add_argument("--meshes", nargs="+", required=True)
    ap.add_argument("--methods", nargs="+", required=True)
    ap.add_argument("--reference", default="lhf-4")
    ap.add_argument("--worst", type=int, default=5)
    a = ap.parse_args()
    out = []
    out.append("# Real meshes\n")
    out.append("Generated by `make realmeshes` (tools/realmeshes.sh, tools/realmeshes_report.py) "
               "on the sample meshes of Debian's `libcgal-demo`; every method at degrees 2-4 with "
               "2 threads. Agreement: d = |H - H_ref| / (|H_ref| + median |H_ref|) against "
               "**%s** (the most accurate method of the convergence studies at this degree); "
               "rel. L2 = ||H - H_ref||_2 / ||H_ref||_2, with the share of its square carried by "
               "the 10 worst vertices, and without the vertices next to a fold (an angle > 90 deg "
               "between the normals of two adjacent faces in the two-ring). Timings are wall times on the machine that ran it.\n"
               % a.reference.upper())
    for m in a.meshes:
        w = a.work
        V, F = read_off(os.path.join(w, "data", "meshes", m + ".off"))
        amin, amax, val, ratio = vertex_quality(V, F)
        fold, shortest, mean_edge = folds_and_short_edges(V, F)
        folded = frozenset(i for i in range(len(V)) if fold[i] > 90.0)
        ref_path = os.path.join(w, "%s.%s.csv" % (m, a.reference))
        Href, _ = read_estimate(ref_path)
        out.append("\n## %s\n" % m)
        out.append("`info`: " + "; ".join(info_lines(os.path.join(w, m + ".info"))) + "\n")
        picture = os.path.join("realmeshes", m + ".H.png")  # tools/render_ply.py, if drawn
        if os.path.exists(os.path.join(os.path.dirname(os.path.abspath(a.output)), picture)):
            out.append("![H of %s by %s](%s)\n" % (m, a.reference.upper(), picture))
        out.append("| method | time (s) | " + " | ".join(STATUSES) +
                   " | median d | p99 d | max d | rel. L2 | top-10 share | rel. L2 off folds |")
        out.append("|---|---:|" + "---:|" * len(STATUSES) + "---:|---:|---:|---:|---:|---:|")
        worst = {}
        for method in a.methods:
            H, status = read_estimate(os.path.join(w, "%s.%s.csv" % (m, method)))
            t = summary_time(os.path.join(w, "%s.%s.log" % (m, method)))
            counts = [sum(1 for s in status if s == k) for k in STATUSES]
            d, l2, top10, l2_kept = agreement(H, Href, folded)
            ds = list(d.values())
            out.append("| %s | %.2f | %s | %.3g | %.3g | %.3g | %.3g | %.0f%% | %.3g |" % (
                method.upper(), t, " | ".join(str(c) for c in counts), median(ds),
                percentile(ds, 99), max(ds) if ds else math.nan, l2, 100 * top10, l2_kept))
            if method != a.reference:
                for i, x in d.items():
                    if x > worst.get(i, (0, ""))[0]:
                        worst[i] = (x, method, H[i])
        out.append("\nWorst vertices (largest d over all methods):\n")
        out.append("| vertex | d | method | H | H_ref | smallest angle | largest angle | valence | "
                   "area ratio | fold (deg) | shortest edge / mean |")
        out.append("|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
        ranked = [i for i, _ in sorted(worst.items(), key=lambda kv: -kv[1][0])]
        for i in ranked[:a.worst]:
            x, method, h = worst[i]
            out.append("| %d | %.3g | %s | %.4g | %.4g | %.2f | %.2f | %d | %.3g | %.1f | %.3g |"
                       % (
                i, x, method.upper(), h, Href[i], amin[i], amax[i], val[i], ratio[i], fold[i],
                shortest[i] / mean_edge))
        top = ranked[:50]
        out.append("\nOf the %d worst vertices, %d have a fold > 90 deg in their two-ring and %d "
                   "an "
                   "edge shorter than 0.1 mean edge length." % (
                       len(top), sum(1 for i in top if i in folded),
                       sum(1 for i in top if shortest[i] < 0.1 * mean_edge)))
        if top and 2 * sum(1 for i in top if i in folded) > len(top):
            out.append("Most of them sit where the surface folds over: two faces sharing an edge "
                       "nearby have normals more than 90 deg apart, so no height function over "
                       "any plane fits the patch (compare rel. L2 with rel. L2 off folds).")
        # Mesh quality overall, for comparison with the worst vertices.
        out.append("Whole mesh: median smallest angle %.1f deg, vertices with an angle < 1 deg: "
                   "%d, with an angle > 170 deg: %d; median fold %.1f deg, vertices with a fold "
                   "> 90 deg in their two-ring: %d (%.1f%%), with an edge < 0.1 mean edge length: "
                   "%d.\n" % (
                       median(amin), sum(1 for x in amin if x < 1.0),
                       sum(1 for x in amax if x > 170.0), median(fold), len(folded),
                       100.0 * len(folded) / len(V),
                       sum(1 for x in shortest if x < 0.1 * mean_edge)))
    open(a.output, "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    sys.exit(main())
