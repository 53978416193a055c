#!/usr/bin/env python3
"""The segmentation filter's time as a user sees it in meshlabserver, measured as issue 11 defines it.

Per round and per CPU set (taskset), two meshlabserver runs on the same display, one after the other:
  load + save                 meshlabserver -i MESH -o OUT -m fq
  load + segment + save       the same with a script of the segmentation filter at its defaults
and the filter's own "in N ms" log line. Printed per CPU set: the medians of both runs' wall times, the
median of the rounds' differences (the filter's time, with what it costs to save its ids), and the median
of the logged times. One Xvfb serves every run, so that the server's start is not in the figures.

Usage: bench/time_segment_filter.py MESH.ply [--runs N] [--cpus 0 0,1] [--filter NAME]
       [--meshlabserver PATH]
Standard library only.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(REPO, "tests", "script"))
sys.path.insert(0, HERE)
from meshlab_script import step, virtual_display, write_mlx  # noqa: E402
from run_pipeline import SEGMENT_MS, SEGMENTATIONS  # noqa: E402


def run(meshlabserver, cpus, mesh, out, script, env):
    """Wall seconds of one meshlabserver run and the filter's logged ms (None without a script)."""
    if os.path.exists(out):
        os.remove(out)  # so that a run that saves nothing cannot pass on the last round's file
    cmd = ["taskset", "-c", cpus, meshlabserver, "-i", mesh, "-o", out, "-m", "fq"]
    if script:
        cmd += ["-s", script]
    t0 = time.monotonic()
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env)
    seconds = time.monotonic() - t0
    text = done.stdout.decode(errors="replace")
    if done.returncode != 0 or not os.path.isfile(out):
        raise SystemExit("time_segment_filter: meshlabserver failed (exit %d):\n%s" % (done.returncode, text[-2000:]))
    logged = SEGMENT_MS.search(text)
    if script and not logged:
        raise SystemExit("time_segment_filter: the filter logged no time:\n%s" % text[-2000:])
    return seconds, int(logged.group(1)) if logged else None


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("mesh")
    p.add_argument("--runs", type=int, default=3, help="rounds per CPU set (default 3)")
    p.add_argument("--cpus", nargs="+", default=["0", "0,1"], help="taskset CPU lists (default: 0 and 0,1)")
    p.add_argument("--filter", default="Segment: Auto by Primitive Fit", choices=sorted(SEGMENTATIONS))
    p.add_argument("--meshlabserver", default=os.path.join(REPO, "build", "meshlab-prefix", "bin", "meshlabserver"))
    args = p.parse_args()
    if args.runs < 1:
        raise SystemExit("time_segment_filter: --runs must be at least 1, not %d" % args.runs)
    if not os.path.isfile(args.mesh):
        raise SystemExit("time_segment_filter: no mesh at %s" % args.mesh)
    with tempfile.TemporaryDirectory() as work:
        script = os.path.join(work, "segment.mlx")
        write_mlx(script, [step(args.filter)])
        with virtual_display() as env:
            print("%s, %s at its defaults, %d round(s); seconds, medians" % (args.mesh, args.filter, args.runs))
            for cpus in args.cpus:
                plain, segmented, logged = [], [], []
                for _ in range(args.runs):
                    plain.append(run(args.meshlabserver, cpus, args.mesh, os.path.join(work, "a.ply"), None, env)[0])
                    s, ms = run(args.meshlabserver, cpus, args.mesh, os.path.join(work, "b.ply"), script, env)
                    segmented.append(s)
                    logged.append(ms / 1000.0)
                difference = statistics.median(s - a for s, a in zip(segmented, plain))
                print("CPUs %-5s load+save %.3f  load+segment+save %.3f  difference %.3f  filter's log %.3f" % (
                    cpus, statistics.median(plain), statistics.median(segmented), difference,
                    statistics.median(logged)))


if __name__ == "__main__":
    main()
