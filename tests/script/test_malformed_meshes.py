"""Every filter of the suite, run through meshlabserver on every malformed mesh of make_malformed_meshes.py,
either does its job or refuses with a clear log line; none may crash.

Per mesh, one script runs all filters in order (with two stock selection helpers); the clean box is loaded
first as the reference layer for the accuracy filter, the malformed mesh last (so it is the current mesh and
the one saved with -o). meshlabserver 2020.09 stops a script at the first filter that returns false, prints
"Problem with filter: X", exits with 255 and saves nothing. So a refusal of X is detected from that line, X
is then dropped and the script rerun without it, until the script completes. Classification:
  done     the script ran the filter and completed;
  refused  exit 255, "Problem with filter: X", plus a log line "X: <reason>" (our filters' own message);
  crash    any other non-zero exit (signal, abort, ASan...) -> the crashing filter is found by rerunning
           growing prefixes of the script; the test fails.
The mesh left by a refusal: meshlabserver discards the document of a failed script, so the mesh "as left by
the refused filter" cannot be saved. What can be checked faithfully is (a) that nothing is saved when X
refuses (the output file does not exist afterwards), and (b) that the script WITHOUT X saves a mesh whose
vertices are all finite wherever the input's are (as baseline, a script with no filter at all saves the input
as meshlabserver loads it; no filter may write a NaN/Inf where the input had a finite coordinate).
Prints a table filter x mesh and writes it as malformed_table.md into the work dir.
"""
import concurrent.futures
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_malformed_meshes import make_all  # noqa: E402
from meshlab_script import (Checker, box_mesh, read_ply, run_meshlabserver, select_faces, step,  # noqa: E402
                            test_args, write_mlx, write_ply)


def ours(name, **values):
    return step(name, **values) + (True,)


def selection(expression):
    return select_faces(expression) + (False,)


# (name, params, ours): every parameter listed by name, as meshlabserver 2020.09 requires.
FILTERS = [
    ours("Segment: Auto by Primitive Fit", SeedPatchFaces=20, NormalSmoothing=2),
    ours("Segment: Auto by Normal Angle", Angle=30, NormalSmoothing=1, MinSegmentFaces=0),
    selection("fq < 2"),
    ours("Segment: Merge Selected"),
    ours("Segment: Split by Plane", PlanePoint=(5, 3, 2)),
    selection("x0 < 2 && x1 < 2 && x2 < 2"),
    ours("Segment: Split by Selection"),
    ours("Segment: Select Segment"),
    ours("Primitive: Fit Segment"),
    ours("Primitive: Snap Segment", Segment=1),
    ours("Primitive: Fit All Segments"),
    # The malformed mesh measured against the clean reference, then as the reference.
    ours("Measure: Accuracy Against Reference", MeasuredMesh=1, ReferenceMesh=0, Samples=20000, Tolerance=0.1,
         Seed=1, DeviationMap=True),
    ours("Measure: Accuracy Against Reference", MeasuredMesh=0, ReferenceMesh=1, Samples=20000, Tolerance=0.1,
         Seed=1),
]
COLUMN = ["auto fit", "auto", "select", "merge", "split plane", "select", "split sel", "select seg", "fit", "snap", "fit all",
          "accuracy (measured)", "accuracy (reference)"]


def finite_vertices(path):
    vertices = read_ply(path)[0]
    return [all(math.isfinite(c) for c in v) for v in vertices]


def run_script(args, name, inputs, steps, tag):
    """Runs the filters `steps` (indices into FILTERS); returns (exit code, log + console, output path)."""
    script = os.path.join(args.workdir, "%s_%s.mlx" % (name, tag))
    write_mlx(script, [(FILTERS[i][0], FILTERS[i][1]) for i in steps])
    out = os.path.join(args.workdir, "%s_%s.ply" % (name, tag))
    if os.path.exists(out):
        os.remove(out)
    code, log, console = run_meshlabserver(args.meshlabserver, args.workdir, inputs, script, out, "fq")
    return code, log + "\n" + console, out


def refusal_reason(text, filter_name):
    """The reason our filter logged ("<name>: <reason>"), or None."""
    for line in text.splitlines():
        line = line.strip()
        if line.startswith(filter_name + ":") and len(line) > len(filter_name) + 3:
            return line[len(filter_name) + 1:].strip()
    return None


def run_mesh(args, name, path, reference):
    """Returns (status per step, list of (condition, message) checks)."""
    inputs = [reference, path]
    checks = []
    code, text, baseline = run_script(args, name, inputs, [], "baseline")
    if code != 0 or not os.path.exists(baseline):
        # MeshLab itself cannot open the file: no filter of ours ever sees it.
        return ["not loadable by MeshLab"] * len(FILTERS), checks
    base_finite = finite_vertices(baseline)

    status = [None] * len(FILTERS)
    active = list(range(len(FILTERS)))
    for attempt in range(len(FILTERS) + 1):
        code, text, out = run_script(args, name, inputs, active, "run%d" % attempt)
        if code == 0:
            for i in active:
                status[i] = "done"
            checks.append((os.path.exists(out), "%s: completed script saved its output" % name))
            if os.path.exists(out):
                fin = finite_vertices(out)
                checks.append((len(fin) == len(base_finite), "%s: the filters kept the %d vertices" %
                               (name, len(base_finite))))
                new_bad = sum(1 for b, a in zip(base_finite, fin) if b and not a)
                checks.append((new_bad == 0, "%s: no filter wrote NaN/Inf into a finite vertex (%d did)" %
                               (name, new_bad)))
            break
        failed = re.findall(r"Problem with filter: (.+)", text)
        if code == 255 and failed:
            fname = failed[-1].strip()
            # The failing step: the first active step of that name not logged as completed before it.
            started = text.count("filter: " + fname) - text.count("Problem with filter: " + fname)
            candidates = [i for i in active if FILTERS[i][0] == fname]
            step = candidates[max(0, min(started - 1, len(candidates) - 1))]
            reason = refusal_reason(text.split("Problem with filter")[0].split("filter: " + fname)[-1], fname)
            ours = FILTERS[step][2]
            if ours:
                checks.append((reason is not None, "%s: '%s' refused with a clear log line (%s)" %
                               (name, fname, reason)))
            status[step] = "refused: " + (reason or "no reason logged")
            checks.append((not os.path.exists(out), "%s: nothing saved after '%s' refused" % (name, fname)))
            active.remove(step)
            continue
        # A crash: find the step by rerunning growing prefixes.
        crashed = active[-1]
        for k in range(1, len(active) + 1):
            c, _, _ = run_script(args, name, inputs, active[:k], "prefix%d" % k)
            if c not in (0, 255):
                crashed = active[k - 1]
                break
        status[crashed] = "CRASH (exit %d)" % code
        checks.append((False, "%s: '%s' crashed meshlabserver (exit %d)" % (name, FILTERS[crashed][0], code)))
        active.remove(crashed)
    return status, checks


def main():
    args = test_args()
    c = Checker()
    meshes = make_all(os.path.join(args.workdir, "malformed"))
    reference = os.path.join(args.workdir, "reference_box.ply")
    v, f = box_mesh()
    write_ply(reference, v, f)

    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        futures = {name: pool.submit(run_mesh, args, name, path, reference) for name, path in meshes.items()}
        results = {name: fut.result() for name, fut in futures.items()}

    header = "| mesh | " + " | ".join(COLUMN) + " |"
    lines = [header, "|" + "---|" * (len(COLUMN) + 1)]
    for name in meshes:
        status, checks = results[name]
        lines.append("| %s | %s |" % (name, " | ".join(s or "not run" for s in status)))
        for ok, what in checks:
            c.check(ok, what)
    table = "\n".join(lines)
    print(table)
    with open(os.path.join(args.workdir, "malformed_table.md"), "w") as out:
        out.write("# Filters on malformed meshes (meshlabserver)\n\n" + table + "\n")
    c.finish()


if __name__ == "__main__":
    main()
