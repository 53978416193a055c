#!/usr/bin/python3
"""The automatic pipeline on copies of a scan whose coordinates are moved by a few nanometres: how far its
figures move when nothing physical changes.

The segmentation is greedy (seeds in order of flatness, regions grown and merged at thresholds), so a decision
that lies near a threshold can go either way under a perturbation far below the scan's noise, and with it a
few segments. Copy 0 is the scan itself; copy k moves every vertex coordinate by a uniform random amount in
[-A, A] (seed k). Per copy: with --truth, `bench_segment_parts --runs 1 --threads 1` segments it and scores the
share of the area labelled right; `bench_segment_scan --runs 1 --threads 1` segments it (the same way; the
segment count is read from it) and fits and snaps the segments as Fit All does after it (with the blends the
segmentation found), and `measure_scan` measures the snapped copy against the reference (share within 0.42 mm, mean).
Printed per copy, then the median, lowest and highest of each figure over the copies. With --keep DIR each copy's
segmentation and snapped scan stay in DIR as copyK.segmented.ply and copyK.snapped.ply, to look at a copy that
scores apart.

Usage: /usr/bin/python3 bench/perturbed_runs.py SCAN.ply [--truth TRUTH.ply] [--copies 6] [--amplitude 1e-6]
       [--build build] [--reference bench/data/bracket_reference.ply] [--keep DIR]
SCAN.ply must be a binary little-endian PLY (as simulate_ct_scan and MeshLab write); TRUTH.ply is
bench/true_segmentation.py's. Needs numpy and a build with -DPRIMITIVE_EDIT_BUILD_BENCH=ON.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

import numpy as np

REPO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
TYPES = {"float": "<f4", "double": "<f8", "uchar": "u1", "char": "i1", "ushort": "<u2", "short": "<i2",
         "uint": "<u4", "int": "<i4"}


def perturb(src, dst, seed, amplitude):
    """Writes src with every vertex's x, y and z moved by a uniform random in [-amplitude, amplitude]."""
    with open(src, "rb") as f:
        data = f.read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in header:
        raise SystemExit("perturbed_runs: %s is not a binary little-endian PLY" % src)
    elements, fields = [], []
    for line in header:
        words = line.split()
        if words[:1] == ["element"]:
            elements.append((words[1], int(words[2])))
        elif words[:1] == ["property"] and elements[-1:] and elements[-1][0] == "vertex":
            if words[1] == "list" or words[1] not in TYPES:
                raise SystemExit("perturbed_runs: %s has a vertex property this script cannot read" % src)
            fields.append((words[2], TYPES[words[1]]))
    # The vertices are read where the body starts.
    if not elements or elements[0][0] != "vertex" or not {"x", "y", "z"} <= {name for name, _ in fields}:
        raise SystemExit("perturbed_runs: %s does not start with vertices that have x, y and z" % src)
    count = elements[0][1]
    dtype = np.dtype(fields)
    vertices = np.frombuffer(data, dtype=dtype, count=count, offset=end).copy()
    rng = np.random.default_rng(seed)
    for axis in "xyz":
        vertices[axis] += rng.uniform(-amplitude, amplitude, count).astype(vertices[axis].dtype)
    with open(dst, "wb") as f:
        f.write(data[:end] + vertices.tobytes() + data[end + count * dtype.itemsize:])


def run(cmd):
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    text = done.stdout.decode(errors="replace")
    if done.returncode != 0:
        raise SystemExit("perturbed_runs: %s failed (exit %d):\n%s" % (os.path.basename(cmd[0]), done.returncode,
                                                                      text[-2000:]))
    return text


def number(pattern, text, what):
    m = re.search(pattern, text)
    if not m:
        raise SystemExit("perturbed_runs: no %s in:\n%s" % (what, text[-2000:]))
    return float(m.group(1))


def one_copy(args, scan, work, k):
    """(segments, labelled % or None, within %, mean mm) of the pipeline on copy k."""
    bench = os.path.join(args.build, "bench")
    out = args.keep or work
    snapped = os.path.join(out, "copy%d.snapped.ply" % k)
    segmented = os.path.join(out, "copy%d.segmented.ply" % k)
    for path in (snapped, segmented):  # so that a step that writes nothing cannot pass on an earlier run's file
        if os.path.exists(path):
            os.remove(path)
    segments = labelled = None
    if args.truth:  # bench_segment_parts scores only against a truth
        text = run([os.path.join(bench, "bench_segment_parts"), scan, "--runs", "1", "--threads", "1", "--truth",
                    args.truth])
        segments = number(r"segments (\d+)\n", text, "segment count")
        labelled = number(r"labelled ([\d.]+)%", text, "labelled share")
    # Segmented again in the same process as Fit All (the same segmentation: it is deterministic), as the filters
    # run in one MeshLab: Fit All gets the segmentation's blends from the mesh (segment_blends_attribute.h).
    text = run([os.path.join(bench, "bench_segment_scan"), scan, "--runs", "1", "--threads", "1", "--snapped",
                snapped] + (["--segmented", segmented] if args.keep else []))
    if segments is None:
        segments = number(r"faces, (\d+) segments", text, "segment count")
    text = run([os.path.join(bench, "bracket", "measure_scan"), snapped, args.reference])
    within = number(r"([\d.]+)% within", text, "accuracy")
    mean = number(r"mean ([\d.]+) mm", text, "mean distance")
    return segments, labelled, within, mean


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scan")
    p.add_argument("--truth", help="the scan with face quality = true surface (bench/true_segmentation.py)")
    p.add_argument("--copies", type=int, default=6, help="perturbed copies besides the scan itself (default 6)")
    p.add_argument("--amplitude", type=float, default=1e-6, help="largest move of a coordinate (default 1e-6)")
    p.add_argument("--build", default=os.path.join(REPO, "build"))
    p.add_argument("--reference", default=os.path.join(REPO, "bench", "data", "bracket_reference.ply"))
    p.add_argument("--keep", help="folder that keeps each copy's copyK.segmented.ply and copyK.snapped.ply")
    args = p.parse_args()
    if args.copies < 0 or not args.amplitude > 0:
        raise SystemExit("perturbed_runs: --copies must be at least 0 and --amplitude positive")
    if args.keep and not os.path.isdir(args.keep):
        raise SystemExit("perturbed_runs: --keep %s is not a folder" % args.keep)
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for k in range(args.copies + 1):
            scan = args.scan
            if k > 0:
                scan = os.path.join(work, "copy.ply")
                perturb(args.scan, scan, k, args.amplitude)
            segments, labelled, within, mean = one_copy(args, scan, work, k)
            rows.append((segments, labelled, within, mean))
            print("copy %d%s: %d segments%s, %.1f%% within 0.42 mm, mean %.3f mm" % (
                k, " (the scan)" if k == 0 else "", segments,
                ", labelled %.1f%%" % labelled if labelled is not None else "", within, mean), flush=True)
    for i, name, form in ((0, "segments", "%g"), (1, "labelled", "%.1f%%"), (2, "within 0.42 mm", "%.1f%%"),
                          (3, "mean", "%.3f mm")):
        values = [r[i] for r in rows if r[i] is not None]
        if values:
            print(("%s: median " + form + ", lowest " + form + ", highest " + form + " over %d copies") % (
                name, statistics.median(values), min(values), max(values), len(values)))


if __name__ == "__main__":
    sys.exit(main())
