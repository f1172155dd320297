#!/usr/bin/python3
"""The corpus section of results/REAL_MESHES.md from the runs of `CORPUS=all tools/realmeshes.sh`
(standard library only).

RUNS holds, for every file DATA/F that curvbench reads (.off .obj .ply .xyz .pts .pwn), a folder
RUNS/F with `info.txt` / `info.log` / `info.rc` (`curvbench info F`) and METHOD.log / METHOD.rc
(`curvbench estimate F --method METHOD`): stderr, and "exit-code seconds". A point set (a .xyz,
.pts or .pwn file, or a file `info` reports 0 faces of: is_point_set) is run with the point-set
methods (--point-methods), every other file with --methods. The summary counts the files, lists
the refusals (exit code 2) with their message, the crashes (another exit code, or a signal) and
the time-outs, sums the failed vertices per method on clean meshes and on the rest, and by cause,
and gives a table of the point sets (file, points, method, vertices by status, seconds). Clean:
`curvbench info` reports no boundary edge, non-manifold edge or vertex, zero-area face, duplicate
vertex or face, or isolated vertex, and at least 50 vertices.

The section is written between the lines `<!-- corpus: begin -->` and `<!-- corpus: end -->` of
REPORT: replaced if present, else appended; the rest of REPORT is left as it is. It has no wall
times (the run time goes to stderr only), and its order is fixed: files by name, methods in the
order given; the point-set table's seconds are the only wall times. The logs of an older curvbench (no `partial` status, no "by cause" lines) are read
too: failed vertices without a reported cause are counted as "cause not reported".
"""
import argparse
import collections
import os
import re
import signal
import sys

BEGIN = "<!-- corpus: begin -->"
END = "<!-- corpus: end -->"
POINT_EXT = (".xyz", ".pts", ".pwn")  # point files: always point sets
READ_EXT = (".off", ".obj", ".ply") + POINT_EXT  # the formats curvbench reads
# `curvbench info` lines whose count must be 0 for a clean mesh
CLEAN_ZERO = ("boundary edges", "non-manifold edges", "non-manifold vertices", "zero-area faces",
              "duplicate vertices", "duplicate faces", "isolated vertices")
CLEAN_MIN_VERTICES = 50
STATUSES = ("ok", "degree_reduced", "failed", "excluded", "disk_cut", "sign_undetermined",
            "partial", "reprojected", "normal_fallback")
# Causes in the order of `curvbench info`'s "hard for estimators" line, then the methods' own
# failures (Estimator::failure_without_defect: a fit's, ICC's).
CAUSE_ORDER = ("isolated vertex", "component of fewer than 7 vertices",
               "non-manifold neighbourhood", "zero-area faces only", "boundary vertex",
               "no mesh defect (a singular fit)",
               "no mesh defect (a corrected area measure that is not positive)")
NOT_REPORTED = "cause not reported"

SUMMARY_RE = re.compile(r"^curvbench estimate: (\S+) on .*: (\d+) vertices \(([^()]*)\)")
CAUSE_RE = re.compile(r"^curvbench estimate: (failed|excluded) vertices by cause: (.*)$")
PAIR_RE = re.compile(r"\s*([^,]+?)\s+(\d+)\s*(?:,|$)")


def read_rc(path):
    """(exit code, seconds) from a .rc file, or None if the run did not happen."""
    try:
        parts = open(path).read().split()
    except OSError:
        return None
    return int(parts[0]), (float(parts[1]) if len(parts) > 1 else 0.0)


def read_text(path):
    try:
        with open(path, errors="replace") as f:
            return f.read()
    except OSError:
        return ""


def parse_info(text):
    """The `key: integer` lines of `curvbench info`."""
    out = {}
    for line in text.splitlines():
        key, sep, val = line.partition(":")
        if sep:
            m = re.match(r"\s*(-?\d+)\s*$", val)
            if m:
                out[key.strip()] = int(m.group(1))
    return out


def is_point_set(relpath, info):
    """A point file (.xyz .pts .pwn), or a file `curvbench info` reads with 0 faces (OFF with 0
    faces, PLY without a face element): tools/realmeshes.sh runs the point-set methods on it."""
    return os.path.splitext(relpath)[1].lower() in POINT_EXT or info.get("faces") == 0


def is_clean(info):
    if any(info.get(k) != 0 for k in CLEAN_ZERO):
        return False
    return info.get("vertices", 0) >= CLEAN_MIN_VERTICES


def pairs(text):
    """'a 1, b c 2' -> [('a', 1), ('b c', 2)]"""
    return [(m.group(1), int(m.group(2))) for m in PAIR_RE.finditer(text)]


def parse_estimate(log):
    """The summary line (label, vertices, statuses) and the failed/excluded causes; None if the log
    has no summary line."""
    res = None
    causes = {"failed": {}, "excluded": {}}
    for line in log.splitlines():
        m = SUMMARY_RE.match(line)
        if m:
            res = {"label": m.group(1), "vertices": int(m.group(2)),
                   "status": dict(pairs(m.group(3)))}
            continue
        m = CAUSE_RE.match(line)
        if m:
            for cause, n in pairs(m.group(2)):
                causes[m.group(1)][cause] = causes[m.group(1)].get(cause, 0) + n
    if res is not None:
        res["causes"] = causes
    return res


def error_message(log, relpath):
    """The one-line message of a refusal: the last `curvbench: error:` line without its prefix
    and the file name, else the last line."""
    lines = [l.strip() for l in log.splitlines() if l.strip()]
    errs = [l for l in lines if l.startswith("curvbench: error:")]
    msg = errs[-1] if errs else (lines[-1] if lines else "(no message)")
    msg = re.sub(r"^curvbench: error:\s*", "", msg)
    if msg.startswith(relpath + ":"):
        msg = msg[len(relpath) + 1:].strip()
    return msg


def exit_text(rc):
    if rc > 128:
        try:
            return "signal %s (exit %d)" % (signal.Signals(rc - 128).name, rc)
        except ValueError:
            return "exit %d" % rc
    return "exit %d" % rc


def cause_key(c):
    return (CAUSE_ORDER.index(c) if c in CAUSE_ORDER else len(CAUSE_ORDER) + (c == NOT_REPORTED),
            c)


def plural(n, one, many):
    return "%d %s" % (n, one if n == 1 else many)


def join_names(names, total, everything):
    return everything if len(names) == total else ", ".join(names)


def main():
    ap = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0] + " Writes the section between the marker lines "
        "%s and %s of REPORT." % (BEGIN, END))
    ap.add_argument("data", help="the extracted data/ folder of libcgal-demo's data.tar.gz")
    ap.add_argument("runs", help="the per-file run folders (tools/realmeshes.sh: $CORPUS_RUNS/runs)")
    ap.add_argument("report", help="the markdown file to write the section into (created if missing)")
    ap.add_argument("--methods", nargs="+", required=True,
                    help="the methods run on a mesh, in the order of `curvbench methods`")
    ap.add_argument("--point-methods", nargs="+", default=[],
                    help="the methods run on a point set (`curvbench methods --point-sets`)")
    ap.add_argument("--timeout", type=int, default=300, help="the time limit of a run in seconds")
    ap.add_argument("--binary", default="", help="the `curvbench --version` line to print")
    a = ap.parse_args()

    everything = []
    for dirpath, dirnames, filenames in os.walk(a.data):
        dirnames[:] = [d for d in dirnames if not d.startswith(".")]
        for fn in filenames:
            if not fn.startswith("."):
                everything.append(os.path.relpath(os.path.join(dirpath, fn), a.data))
    everything.sort()
    files = [f for f in everything if os.path.splitext(f)[1].lower() in READ_EXT]
    others = [f for f in everything if os.path.splitext(f)[1].lower() not in READ_EXT]
    methods = a.methods
    point_methods = a.point_methods

    refusals = collections.OrderedDict()  # file -> [(run, message)]
    crashes = []  # (file, run, text)
    timeouts = []  # (file, run)
    not_run = []  # (file, run)
    clean_files, other_files, point_files = [], [], []
    point_rows = []  # (file, points, method label, {status: count} or the outcome, seconds)
    labels = {m: collections.Counter() for m in methods}
    failed = {m: {"clean": 0, "other": 0} for m in methods}
    failed_files = {m: {"clean": 0, "other": 0} for m in methods}
    by_cause = {m: collections.Counter() for m in methods}
    status = {m: collections.Counter() for m in methods}
    seen_status = set()
    vertices = {m: 0 for m in methods}
    clean_fail = []  # (file, vertices, method, failed, causes)
    folders = collections.Counter(f.split(os.sep)[0] for f in everything)
    runs_total = runs_ok = 0

    def classify(f, run, rc, log):
        """Records a refusal, crash or time-out; True if the run exited 0."""
        if rc is None:
            not_run.append((f, run))
            return False
        code, secs = rc
        if code == 0:
            return True
        if code == 124 or (code == 137 and secs >= a.timeout):
            timeouts.append((f, run))
        elif code == 2:
            refusals.setdefault(f, []).append((run, error_message(log, f)))
        else:
            last = [l.strip() for l in log.splitlines() if l.strip()]
            crashes.append((f, run, exit_text(code) + (": " + last[-1] if last else "")))
        return False

    for f in files:
        d = os.path.join(a.runs, f)
        info_rc = read_rc(os.path.join(d, "info.rc"))
        info_ok = classify(f, "info", info_rc, read_text(os.path.join(d, "info.log")))
        info = parse_info(read_text(os.path.join(d, "info.txt"))) if info_ok else {}
        if is_point_set(f, info):
            point_files.append(f)
            for m in point_methods:
                runs_total += 1
                log = read_text(os.path.join(d, m + ".log"))
                rc = read_rc(os.path.join(d, m + ".rc"))
                secs = rc[1] if rc else 0.0
                if not classify(f, m, rc, log):
                    outcome = ("not run" if rc is None else "refused" if rc[0] == 2 else
                               "timed out" if rc[0] == 124 else "crashed")
                    point_rows.append((f, info.get("vertices"), m, outcome, secs))
                    continue
                est = parse_estimate(log)
                if est is None:
                    crashes.append((f, m, "exit 0 without the summary line"))
                    point_rows.append((f, info.get("vertices"), m, "crashed", secs))
                    continue
                runs_ok += 1
                point_rows.append((f, est["vertices"], est["label"], est["status"], secs))
            continue
        clean = bool(info) and is_clean(info)
        (clean_files if clean else other_files).append(f)
        kind = "clean" if clean else "other"
        for m in methods:
            runs_total += 1
            log = read_text(os.path.join(d, m + ".log"))
            if not classify(f, m, read_rc(os.path.join(d, m + ".rc")), log):
                continue
            est = parse_estimate(log)
            if est is None:
                crashes.append((f, m, "exit 0 without the summary line"))
                continue
            runs_ok += 1
            labels[m][est["label"]] += 1
            vertices[m] += est["vertices"]
            for s, n in est["status"].items():
                status[m][s] += n
                seen_status.add(s)
            nf = est["status"].get("failed", 0)
            failed[m][kind] += nf
            failed_files[m][kind] += nf > 0
            causes = dict(est["causes"]["failed"])
            if nf > sum(causes.values()):
                causes[NOT_REPORTED] = nf - sum(causes.values())
            by_cause[m].update(causes)
            if clean and nf > 0:
                clean_fail.append((f, est["vertices"], m, nf, causes))

    def label(m):
        lab = labels[m].most_common(1)[0][0] if labels[m] else ""
        return "%s (%s)" % (m, lab) if lab and lab.lower() != m.lower() else m

    nm = len(methods)
    out = [BEGIN, "## Full corpus (`make realmeshes CORPUS=all`)", ""]
    out.append(
        "Generated by `make realmeshes CORPUS=all` (tools/realmeshes.sh, "
        "tools/realmeshes_corpus.py): `curvbench info` and every method at its default (the "
        "names of `curvbench methods`, the fits at their default degree; on a point set the "
        "methods of `curvbench methods --point-sets`) with `--threads 2` and "
        "a time limit of %d s per run, on every file of `libcgal-demo`'s data.tar.gz that "
        "curvbench reads%s. A point set: a .xyz, .pts or .pwn file, or a file `info` reads "
        "without faces. Clean: `info` reports no boundary edge, non-manifold edge or vertex, "
        "zero-area face, duplicate vertex or face, or isolated vertex, and at least %d vertices."
        % (a.timeout, " (%s)" % a.binary if a.binary else "", CLEAN_MIN_VERTICES))
    out.append("")
    out.append("- Files: %d in data/ (%s); %d in a format curvbench reads (.off .obj .ply .xyz "
               ".pts .pwn), each run with `info` (%d estimate runs in all): %s with %d "
               "methods, %d clean and %d other; %s with %d methods."
               % (len(everything), ", ".join("%s/ %d" % (k, folders[k]) for k in sorted(folders)),
                  len(files), runs_total,
                  plural(len(clean_files) + len(other_files), "mesh", "meshes"), nm,
                  len(clean_files), len(other_files),
                  plural(len(point_files), "point set", "point sets"), len(point_methods)))
    by_ext = collections.OrderedDict()
    for f in others:
        by_ext.setdefault(os.path.splitext(f)[1].lower() or "(no extension)", []).append(f)
    out.append("- Not a mesh format curvbench reads (%d files, not run): %s."
               % (len(others), "; ".join("%s: %s" % (e, ", ".join(fs))
                                          for e, fs in sorted(by_ext.items()))
                  if others else "none"))
    out.append("- Estimate runs that exited 0: %d of %d; refusals (exit 2): %d runs on %d file(s); "
               "crashes: %d; time-outs: %d%s."
               % (runs_ok, runs_total, sum(len(v) for v in refusals.values()), len(refusals),
                  len(crashes), len(timeouts),
                  "; not run (missing logs): %d" % len(not_run) if not_run else ""))
    out.append("")

    out.append("### Refusals (exit code 2)")
    out.append("")
    if not refusals:
        out.append("None.")
    for f, rs in refusals.items():
        msgs = collections.OrderedDict()
        for run, msg in rs:
            msgs.setdefault(msg, []).append(run)
        for msg, runs in msgs.items():
            ms = [r for r in runs if r != "info"]
            who = ["info"] if "info" in runs else []
            if ms:
                total = len(point_methods) if f in point_files else nm
                who.append("all %d methods" % total if len(ms) == total else ", ".join(ms))
            out.append("- `%s`: %s (%s)" % (f, msg, " and ".join(who)))
    out.append("")
    out.append("### Crashes (another exit code, or a signal)")
    out.append("")
    out.extend(["- `%s` %s: %s" % c for c in crashes] or ["None."])
    out.append("")
    out.append("### Time-outs (%d s)" % a.timeout)
    out.append("")
    out.extend(["- `%s` %s" % t for t in timeouts] or ["None."])
    if not_run:
        out.append("")
        out.append("Not run (no exit code recorded): "
                   + ", ".join("`%s` %s" % t for t in not_run) + ".")
    out.append("")

    out.append("### Failed vertices by method")
    out.append("")
    out.append("Summed over the files whose run exited 0; in parentheses the number of files with "
               "a failed vertex.")
    out.append("")
    out.append("| method | clean meshes (%d files) | other meshes (%d files) |"
               % (len(clean_files), len(other_files)))
    out.append("|---|---:|---:|")
    for m in methods:
        out.append("| %s | %d (%d) | %d (%d) |"
                   % (label(m), failed[m]["clean"], failed_files[m]["clean"], failed[m]["other"],
                      failed_files[m]["other"]))
    out.append("")

    out.append("### Failed vertices by cause")
    out.append("")
    causes = sorted(set(c for m in methods for c in by_cause[m]), key=cause_key)
    if not causes:
        out.append("No failed vertex.")
    else:
        out.append("Summed over all files (clean and other), per method; the cause is the mesh "
                   "defect at the vertex that `curvbench estimate` reports%s."
                   % ("; \"%s\": failed vertices the log gives no cause for (an older curvbench)"
                      % NOT_REPORTED if NOT_REPORTED in causes else ""))
        out.append("")
        out.append("| method | " + " | ".join(causes) + " |")
        out.append("|---|" + "---:|" * len(causes))
        for m in methods:
            out.append("| %s | " % label(m) + " | ".join(str(by_cause[m][c]) for c in causes)
                       + " |")
    out.append("")

    out.append("### Vertices by status")
    out.append("")
    cols = [s for s in STATUSES if s in seen_status] + sorted(seen_status - set(STATUSES))
    out.append("Summed over all files whose run exited 0.")
    out.append("")
    out.append("| method | vertices | " + " | ".join(cols) + " |")
    out.append("|---|---:|" + "---:|" * len(cols))
    for m in methods:
        out.append("| %s | %d | " % (label(m), vertices[m])
                   + " | ".join(str(status[m][s]) for s in cols) + " |")
    out.append("")

    out.append("### Clean meshes where a method leaves failed vertices")
    out.append("")
    if not clean_fail:
        out.append("None.")
    else:
        out.append("| file | vertices | method | failed | causes |")
        out.append("|---|---:|---|---:|---|")
        for f, nv, m, nf, cs in clean_fail:
            out.append("| `%s` | %d | %s | %d | %s |"
                       % (f, nv, label(m), nf,
                          ", ".join("%s %d" % (c, cs[c]) for c in sorted(cs, key=cause_key))))
    out.append("")

    out.append("### Point sets")
    out.append("")
    if not point_files:
        out.append("None.")
    else:
        pcols = [s for s in STATUSES
                 if any(isinstance(r[3], dict) and r[3].get(s) for r in point_rows)]
        out.append("Each point set with each point-set method at its defaults: the points "
                   "estimated by status, or the run's outcome (a refusal's line is listed above); "
                   "seconds of wall time for the whole run (reading included, 2 threads).")
        out.append("")
        out.append("| file | points | method | " + " | ".join(pcols) + " | seconds |")
        out.append("|---|---:|---|" + "---:|" * len(pcols) + "---:|")
        for f, n, m, st, secs in point_rows:
            cells = ([str(st.get(c, 0)) for c in pcols] if isinstance(st, dict)
                     else [st] + [""] * (len(pcols) - 1) if pcols else [])
            out.append("| `%s` | %s | %s | %s | %.2f |"
                       % (f, "" if n is None else n, m, " | ".join(cells), secs))
    out.append(END)
    section = "\n".join(out) + "\n"

    old = open(a.report).read() if os.path.exists(a.report) else ""
    lines = old.splitlines(keepends=True)
    b = next((i for i, l in enumerate(lines) if l.rstrip("\n") == BEGIN), None)
    e = next((i for i, l in enumerate(lines) if b is not None and i > b and l.rstrip("\n") == END),
             None)
    if b is not None and e is not None:
        new = "".join(lines[:b]) + section + "".join(lines[e + 1:])
    else:
        sep = ("" if not old or old.endswith("\n\n") else
               "\n" if old.endswith("\n") else "\n\n")
        new = old + sep + section
    with open(a.report, "w") as f:
        f.write(new)
    print("realmeshes_corpus: %d files, %d estimate runs (%d exited 0, %d refused, %d crashed, "
          "%d timed out) -> %s" % (len(files), runs_total, runs_ok,
                                   sum(len(v) for v in refusals.values()), len(crashes),
                                   len(timeouts), a.report), file=sys.stderr)


if __name__ == "__main__":
    main()
