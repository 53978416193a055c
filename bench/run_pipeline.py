#!/usr/bin/env python3
"""The automatic pipeline on simulated CT scans of the bracket, before and after, in one table.

Per scan, one meshlabserver run (reference loaded first: layer 0 = reference, layer 1 = scan):
  Measure: Accuracy Against Reference   the input accuracy (the paper's measure, section 3)
  <segmentation filter>                 default: the best one this meshlabserver has
  Primitive: Fit All Segments           Relations, Snap, SharpEdges, Export JSON
  Measure: Accuracy Against Reference   the output accuracy
then the segmented, snapped scan (saved with its face quality = segment id) is scored against the
scan's ground truth with bench/score_segmentation.py, each face weighed by its area in the scan (the mesh that
was segmented; the snap stretches and collapses triangles). Printed (and written as markdown with --report):
faces, input and output share within the tolerance and mean distance, area labelled correctly, area
with the right primitive type, the hole radius errors, and the time of each stage.

Scans: the bundled sample (bench/data) by default; --scans SCAN.ply ... for others (the ground truth is
read from SCAN_truth.txt next to each, as simulate_ct_scan --truth names it in make_data.sh); --sizes
200k,1M,4M simulates scans of those face counts into a cache directory (simulate_ct_scan, preset paper).

Stage times come from the plugins' log lines (segmentation "in N ms", "Fitting took N ms", "Snapping
took N ms"); the measurement filter logs no time, so its time is taken between meshlabserver's
"filter:" lines, read as they are printed (stdout line-buffered with stdbuf). Standard library only.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(REPO, "tests", "script"))
sys.path.insert(0, HERE)
from meshlab_script import FILTER_PARAMETERS, param, step, virtual_display, write_mlx  # noqa: E402
from score_segmentation import score  # noqa: E402

MEASURE = "Measure: Accuracy Against Reference"
FIT_ALL = "Primitive: Fit All Segments"

# Segmentation filters in order of preference, each with its complete parameter list (meshlabserver
# 2020.09 asserts unless a script lists every parameter) at the filter's defaults: name -> [(parameter,
# default, Rich type)].
PREFERRED = ["Segment: Auto by Primitive Fit", "Segment: Auto by Normal Angle"]
SEGMENTATIONS = {name: FILTER_PARAMETERS[name] for name in PREFERRED}
# The segmentation filters' log line with their time ("Segment: ... in N ms").
SEGMENT_MS = re.compile(r"Segment: .* in (\d+) ms")

# Face count ~ FACES_PER_AREA * area / voxel^2 for the bracket's scans with preset paper (the rough
# surface gives more triangles than a smooth one); see bench/bracket/README.md.
FACES_PER_AREA = 2.9
BRACKET_AREA = 5895.0
RICH_TYPES = {"RichFloat": float, "RichInt": int, "RichBool": lambda v: str(v).lower() in ("1", "true", "yes"),
              "RichString": str}


def available_filters(meshlabserver):
    """Filter names this meshlabserver knows (from its -d documentation dump)."""
    dump = os.path.join(os.environ.get("TMPDIR", "/tmp"), "run_pipeline_filters_%d.txt" % os.getpid())
    try:
        with virtual_display() as env:
            subprocess.run([meshlabserver, "-d", dump], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                           timeout=300, env=env)
        text = open(dump, errors="replace").read() if os.path.exists(dump) else ""
    finally:
        if os.path.exists(dump):
            os.remove(dump)
    return set(re.findall(r"\\section f\d+ (.*?) *$", text, re.M))


def segmentation_step(name, overrides, available):
    """(filter name, [param lines], description). name None: the first of PREFERRED that meshlabserver
    has and SEGMENTATIONS knows. overrides: list of 'Name=Value' or, for a filter the table does not
    know (named with --segment), 'Name:RichType=Value' covering all of its parameters."""
    if name is None:
        for candidate in PREFERRED:
            if candidate in available and candidate in SEGMENTATIONS:
                name = candidate
                break
            if candidate in available:
                print("run_pipeline: %s exists but its parameters are not in SEGMENTATIONS; "
                      "give them with --segment and --segment-param" % candidate, file=sys.stderr)
        if name is None:
            raise SystemExit("run_pipeline: no segmentation filter found in %s" % sorted(available))
    elif available and name not in available:
        raise SystemExit("run_pipeline: meshlabserver has no filter '%s'" % name)
    table = [list(p) for p in SEGMENTATIONS.get(name, [])]
    for item in overrides:
        if "=" not in item:
            raise SystemExit("run_pipeline: --segment-param wants Name=Value or Name:RichType=Value, not %s" % item)
        key, value = item.split("=", 1)
        key, _, kind = key.partition(":")
        row = next((p for p in table if p[0] == key), None)
        if row is None:
            if kind not in RICH_TYPES:
                raise SystemExit("run_pipeline: %s is not a known parameter of '%s': give it as %s:RichType=Value "
                                 "(RichFloat, RichInt, RichBool, RichString)" % (key, name, key))
            row = [key, None, kind]
            table.append(row)
        row[1] = RICH_TYPES[kind or row[2]](value)
    if not table and name not in SEGMENTATIONS:
        raise SystemExit("run_pipeline: give every parameter of '%s' with --segment-param" % name)
    return name, [param(k, v, kind) for k, v, kind in table], ", ".join("%s=%s" % (k, v) for k, v, _ in table)


def run_timed(meshlabserver, inputs, script, output, mask="fq"):
    """Runs meshlabserver on a virtual display of its own with line-buffered output. Returns (exit code,
    [(seconds since start, line)]): the plugins' log lines ("LOG: level text", printed as they are logged) and
    meshlabserver's own ("filter: NAME" as each filter starts)."""
    cmd = ["stdbuf", "-oL", meshlabserver]
    for i in inputs:
        cmd += ["-i", i]
    cmd += ["-s", script, "-o", output, "-m"] + mask.split()
    t0 = time.monotonic()
    lines = []
    with virtual_display() as env, subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                                    env=env) as proc:
        for raw in proc.stdout:
            lines.append((time.monotonic() - t0, raw.decode(errors="replace").rstrip("\n")))
        code = proc.wait()
    lines.append((time.monotonic() - t0, "<exit>"))
    return code, lines


def parse_run(lines):
    """Accuracy figures and stage times from a timed run."""
    out = {"accuracy": [], "stage_s": {}}
    # meshlabserver prints the first "filter:" right after "Starting Script of N actions", on its line.
    starts = [(t, m.group(1).strip()) for t, m in ((t, re.search(r"(?:^|actions)filter: (.+)$", line))
                                                  for t, line in lines) if m]
    end = lines[-1][0]
    for k, (t, name) in enumerate(starts):
        nxt = starts[k + 1][0] if k + 1 < len(starts) else end
        out["stage_s"].setdefault(name, []).append(nxt - t)
    out["load_s"] = starts[0][0] if starts else None
    out["filters_run"] = [name for _, name in starts]
    for _, line in lines:
        if not line.startswith("LOG: "):
            continue
        text = line.split(" ", 2)[2] if line.count(" ") >= 2 else ""
        m = re.match(r"Accuracy: ([\d.]+)% of (\d+) samples within \S+ \(mean ([\d.]+), RMS ([\d.]+), max ([\d.]+)\)",
                     text)
        if m:
            out["accuracy"].append({"within": float(m.group(1)), "mean": float(m.group(3)),
                                    "rms": float(m.group(4)), "max": float(m.group(5))})
        m = SEGMENT_MS.match(text)
        if m:
            out["segment_ms"] = int(m.group(1))
        m = re.match(r"Segment: .*?split into (\d+) segments", text)
        if m:
            out["segments"] = int(m.group(1))
        m = re.search(r"Fitting took (\d+) ms", text)
        if m:
            out["fit_ms"] = int(m.group(1))
        m = re.search(r"Snapping took (\d+) ms", text)
        if m:
            out["snap_ms"] = int(m.group(1))
    return out


def simulate(args, size_label):
    """A cached scan of about the given face count (e.g. 200k, 1M, 4M) with the paper preset."""
    m = re.fullmatch(r"([\d.]+)([kKmM]?)", size_label)
    if not m:
        raise SystemExit("run_pipeline: --sizes wants counts like 200k,1M,4M, not %s" % size_label)
    faces = float(m.group(1)) * {"": 1, "k": 1e3, "m": 1e6}[m.group(2).lower()]
    voxel = float("%.2g" % (FACES_PER_AREA * BRACKET_AREA / faces) ** 0.5)
    os.makedirs(args.cache, exist_ok=True)
    stem = os.path.join(args.cache, "bracket_%s_%s_v%g_s%d" % (size_label, args.preset, voxel, args.seed))
    scan, truth = stem + ".ply", stem + "_truth.txt"
    if not (os.path.exists(scan) and os.path.exists(truth)):
        print("run_pipeline: simulating %s (voxel %g mm) into %s" % (size_label, voxel, scan), flush=True)
        subprocess.run([args.simulate, "--in", args.reference, "--out", scan, "--truth", truth, "--preset",
                        args.preset, "--voxel", str(voxel), "--seed", str(args.seed)], check=True)
    return size_label, scan, truth


def run_scan(args, label, scan, truth, segmentation):
    work = os.path.join(args.workdir, re.sub(r"[^\w.-]", "_", label))
    os.makedirs(work, exist_ok=True)
    fit_json = os.path.join(work, "fit.json")
    out_ply = os.path.join(work, "segmented.ply")
    for stale in (fit_json, out_ply):
        if os.path.exists(stale):
            os.remove(stale)
    measure = step(MEASURE, MeasuredMesh=1, ReferenceMesh=0, Samples=args.samples, Tolerance=args.tolerance, Seed=1)
    seg_name, seg_params, _ = segmentation
    filters = [measure, (seg_name, seg_params),
               step(FIT_ALL, Tolerance=args.fit_tolerance, Relations=bool(args.relations), Export=fit_json),
               measure]
    script = os.path.join(work, "pipeline.mlx")
    write_mlx(script, filters)
    t0 = time.monotonic()
    code, lines = run_timed(args.meshlabserver, [args.reference, scan], script, out_ply)
    with open(os.path.join(work, "meshlabserver.log"), "w") as log:
        log.writelines("%9.3f %s\n" % (t, line) for t, line in lines)
    r = parse_run(lines)
    r.update(label=label, scan=scan, work=work)
    if code != 0 or len(r["accuracy"]) != 2 or not os.path.exists(out_ply):
        tail = "\n".join(line for _, line in lines[-15:])
        raise SystemExit("run_pipeline: meshlabserver failed on %s (exit %d); log in %s:\n%s" % (
            scan, code, os.path.join(work, "meshlabserver.log"), tail))
    if truth and os.path.exists(truth):
        t1 = time.monotonic()
        r["score"] = score(out_ply, truth, args.reference_json, fit_json if os.path.exists(fit_json) else None,
                           area_ply=scan)
        r["score_s"] = time.monotonic() - t1
    r["wall_s"] = time.monotonic() - t0
    return r


def hole_summary(r, reference):
    """(max |radius error| of the holes found, found, total): holes are the reference's cylinders whose
    outward normal points at the axis."""
    holes = {f["index"] for f in reference if f["type"] == "cylinder" and f.get("outward") == -1}
    rows = [c for c in r.get("score", {}).get("cylinders", []) if c[0] in holes]
    errors = [abs(fitted - true_r) for _, true_r, fitted in rows if fitted is not None]
    return (max(errors) if errors else None), len(errors), len(rows)


def table(results, reference, args, segmentation):
    head = ["scan", "faces", "input within / mean", "output within / mean", "labelled", "typed",
            "hole radius max abs. error (found)", "segment", "fit", "snap", "measure x2", "total"]
    rows = []
    for r in results:
        a_in, a_out = r["accuracy"]
        s = r.get("score", {})
        err, found, total = hole_summary(r, reference)
        pct = lambda v: "%.1f%%" % (100 * v) if v is not None else "-"  # noqa: E731
        ms = lambda v: "%.2f s" % (v / 1000.0) if v is not None else "-"  # noqa: E731
        measure_s = sum(r["stage_s"].get(MEASURE, []))
        rows.append([r["label"], "{:,}".format(s["faces"]) if s else "-",
                     "%.1f%% / %.3f mm" % (a_in["within"], a_in["mean"]),
                     "%.1f%% / %.3f mm" % (a_out["within"], a_out["mean"]),
                     pct(s.get("labelled")), pct(s.get("typed")),
                     ("%.3f mm (%d/%d)" % (err, found, total)) if err is not None else "- (%d/%d)" % (found, total),
                     ms(r.get("segment_ms")), ms(r.get("fit_ms")), ms(r.get("snap_ms")),
                     "%.1f s" % measure_s, "%.1f s" % r["wall_s"]])
    widths = [max(len(h), *(len(row[i]) for row in rows)) for i, h in enumerate(head)]
    text = ["  ".join(h.ljust(w) for h, w in zip(head, widths))]
    text += ["  ".join(c.ljust(w) for c, w in zip(row, widths)) for row in rows]
    md = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    md += ["| " + " | ".join(row) + " |" for row in rows]
    notes = ["Within %g mm of the reference, mean distance; %d samples (the paper's measure). Segmentation: %s "
             "(%s). labelled: share of the scan's area whose segment matches its true surface; typed: share with "
             "the right primitive type (areas of the scan as segmented, not as snapped). Times: segment, fit and "
             "snap from the plugins' logs; measure: both accuracy filters; total: wall time of meshlabserver "
             "(loading, all filters, saving) and scoring."
             % (args.tolerance, args.samples, segmentation[0], segmentation[2])]
    return "\n".join(text), "\n".join(md + [""] + notes)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--meshlabserver", default=os.path.join(REPO, "build", "meshlab-prefix", "bin", "meshlabserver"))
    p.add_argument("--scans", nargs="+", help="scan PLYs (default: bench/data/bracket_scan.ply); the truth is "
                   "read from SCAN_truth.txt beside each")
    p.add_argument("--sizes", help="simulate scans of these face counts instead, e.g. 200k,1M,4M")
    p.add_argument("--reference", default=os.path.join(HERE, "data", "bracket_reference.ply"))
    p.add_argument("--reference-json", default=os.path.join(HERE, "data", "bracket_reference.json"))
    p.add_argument("--samples", type=int, default=1000000)
    p.add_argument("--tolerance", type=float, default=0.42)
    p.add_argument("--fit-tolerance", type=float, default=0.0,
                   help="Fit All Segments' RMS limit in mm (0: automatic, the larger of 1%% of each segment's size "
                   "and 3x the scan's roughness)")
    p.add_argument("--segment", help="segmentation filter (default: the best available: %s)" % " or ".join(PREFERRED))
    p.add_argument("--relations", type=int, choices=(0, 1), default=1,
                   help="Fit All Segments' Relations: 1 (default) refits the primitives together under the "
                        "relations found, 0 fits each segment alone")
    p.add_argument("--segment-param", action="append", default=[], metavar="NAME=VALUE",
                   help="a parameter of the segmentation filter (repeatable); Name:RichType=Value for a "
                   "filter whose parameters the driver does not know")
    p.add_argument("--simulate", default=os.path.join(REPO, "build", "bench", "bracket", "simulate_ct_scan"))
    p.add_argument("--preset", default="paper")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--cache", default=os.path.join(REPO, "build", "bench-cache"))
    p.add_argument("--workdir", help="where scripts, logs and outputs go (default: CACHE/runs)")
    p.add_argument("--report", help="also write the table as markdown to this file")
    args = p.parse_args()
    args.workdir = args.workdir or os.path.join(args.cache, "runs")
    if not (os.path.isfile(args.meshlabserver) and os.access(args.meshlabserver, os.X_OK)):
        raise SystemExit("run_pipeline: no meshlabserver at %s (build the project, or give --meshlabserver)"
                         % args.meshlabserver)
    for tool in ("Xvfb", "stdbuf"):
        if shutil.which(tool) is None:
            raise SystemExit("run_pipeline: %s not found (Debian: xvfb, coreutils)" % tool)
    if args.samples < 1 or not args.tolerance > 0:
        raise SystemExit("run_pipeline: --samples must be positive and --tolerance above 0")

    if args.sizes:
        scans = [simulate(args, s.strip()) for s in args.sizes.split(",") if s.strip()]
    else:
        paths = args.scans or [os.path.join(HERE, "data", "bracket_scan.ply")]
        scans = [(os.path.splitext(os.path.basename(s))[0], s, os.path.splitext(s)[0] + "_truth.txt") for s in paths]
    for _, scan, _ in scans:
        if not os.path.isfile(scan):
            raise SystemExit("run_pipeline: no scan %s" % scan)

    segmentation = segmentation_step(args.segment, args.segment_param, available_filters(args.meshlabserver))
    reference = json.load(open(args.reference_json))["faces"]
    results = []
    for label, scan, truth in scans:
        print("run_pipeline: %s: %s ..." % (label, segmentation[0]), flush=True)
        results.append(run_scan(args, label, scan, truth, segmentation))
    text, md = table(results, reference, args, segmentation)
    print(text)
    if args.report:
        with open(args.report, "w") as out:
            out.write(md + "\n")
        print("run_pipeline: report written to %s" % args.report)


if __name__ == "__main__":
    main()
