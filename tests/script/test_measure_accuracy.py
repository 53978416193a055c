"""meshlabserver test of "Measure: Accuracy Against Reference" (filter_measure_accuracy).

A reference plate at z = 0 and a measured surface of two plates of equal area at z = 0.3 and z = 0.6:
with tolerance 0.42 half the samples are within (the paper's Eq. 3), the mean distance is 0.45, the
RMS sqrt((0.09 + 0.36) / 2) and the max 0.6. The deviation map writes each vertex's distance into its
quality. Bad parameters and the same layer as both inputs must fail with a clear log line.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import meshlab_script as ms  # noqa: E402

FILTER = "Measure: Accuracy Against Reference"


def plate(x0, y0, x1, y1, z, n, base=0):
    """A rectangle at height z as an n x n grid of quads, two triangles each."""
    verts = [[x0 + (x1 - x0) * j / n, y0 + (y1 - y0) * i / n, z] for i in range(n + 1) for j in range(n + 1)]
    faces = []
    for i in range(n):
        for j in range(n):
            a = base + i * (n + 1) + j
            faces += [[a, a + 1, a + n + 2], [a, a + n + 2, a + n + 1]]
    return verts, faces


def script(path, measured, reference, samples, tolerance, seed=0, deviation_map=False):
    ms.write_mlx(path, [ms.step(FILTER, MeasuredMesh=measured, ReferenceMesh=reference, Samples=samples,
                                Tolerance=tolerance, Seed=seed, DeviationMap=deviation_map)])


def accuracy_line(log):
    m = re.search(r"Accuracy: ([0-9.]+)% of (\d+) samples within ([0-9.]+) \(mean ([0-9.]+), RMS ([0-9.]+), "
                  r"max ([0-9.]+)\)", log)
    if not m:
        return None
    return {"share": float(m.group(1)), "samples": int(m.group(2)), "tolerance": float(m.group(3)),
            "mean": float(m.group(4)), "rms": float(m.group(5)), "max": float(m.group(6))}


def main():
    args = ms.test_args()
    c = ms.Checker()
    work = args.workdir
    # Layer 0: the reference; layer 1 (loaded last, so the current layer that -o saves): the measured mesh.
    reference = os.path.join(work, "reference.ply")
    measured = os.path.join(work, "measured.ply")
    ms.write_ply(reference, *plate(-1, -1, 11, 11, 0.0, 12))
    low_v, low_f = plate(0, 0, 10, 5, 0.3, 20)
    high_v, high_f = plate(0, 5, 10, 10, 0.6, 20, base=len(low_v))
    ms.write_ply(measured, low_v + high_v, low_f + high_f)

    # 1. The figures, and the deviation map in the saved vertex quality.
    mlx = os.path.join(work, "measure.mlx")
    out = os.path.join(work, "measured_out.ply")
    script(mlx, 1, 0, 200000, 0.42, seed=3, deviation_map=True)
    code, log, console = ms.run_meshlabserver(args.meshlabserver, work, [reference, measured], mlx,
                                              output=out, mask="vq vc")
    c.check(code == 0, "meshlabserver succeeds (exit %d)" % code)
    r = accuracy_line(log)
    c.check(r is not None, "the log has the accuracy line:\n" + log + console[-2000:])
    if r:
        # 200000 samples, p = 0.5: sigma of the share is 0.11%.
        c.check(abs(r["share"] - 50.0) < 1.0, "half the samples within 0.42 (%.1f%%)" % r["share"])
        c.check(r["samples"] == 200000, "200000 samples")
        c.check(abs(r["mean"] - 0.45) < 0.005, "mean 0.45 (%.3f)" % r["mean"])
        c.check(abs(r["rms"] - math.sqrt(0.225)) < 0.005, "RMS 0.474 (%.3f)" % r["rms"])
        c.check(abs(r["max"] - 0.6) < 0.001, "max 0.6 (%.3f)" % r["max"])
    c.check(log.count("Accuracy histogram") == 11, "10 histogram bins and an overflow bin are logged")
    bins = [float(share) for share in re.findall(r"Accuracy histogram [^:]*: +([0-9.]+)%", log)]
    if len(bins) == 11:
        # Bins of 2 * 0.42 / 10 = 0.084: 0.3 falls in bin 3, 0.6 in bin 7.
        c.check(abs(bins[3] - 50.0) < 1.0 and abs(bins[7] - 50.0) < 1.0 and
                all(b == 0.0 for i, b in enumerate(bins) if i not in (3, 7)),
                "the histogram puts half the samples in the 0.3 bin and half in the 0.6 bin: %s" % bins)
    if os.path.exists(out):
        verts, _, _, vprops = ms.read_ply(out)
        quality = vprops.get("quality", [])
        c.check(len(quality) == len(verts) and len(verts) == len(low_v) + len(high_v),
                "the measured mesh is saved with a quality per vertex")
        if len(quality) == len(verts):
            ok = all(abs(q - z) < 1e-4 for q, (_, _, z) in zip(quality, verts))
            c.check(ok, "vertex quality is the distance to the reference (= z)")
        c.check("red" in vprops and "blue" in vprops, "the deviation map colours are saved")
        if "red" in vprops:
            # The ramp runs blue (0), green (0.42), red (0.84): z = 0.6 is redder than z = 0.3.
            high = [i for i, (_, _, z) in enumerate(verts) if z > 0.5]
            low = [i for i, (_, _, z) in enumerate(verts) if z < 0.5]
            c.check(all(vprops["red"][i] > vprops["red"][j] for i, j in zip(high, low)),
                    "farther vertices are redder")
    else:
        c.check(False, "meshlabserver saved the measured mesh")

    # 2. Bad input: the filter fails, says why in the log, and meshlabserver stops.
    cases = [
        ("samples0", dict(measured=1, reference=0, samples=0, tolerance=0.42), "Samples must be between 1"),
        ("tolerance0", dict(measured=1, reference=0, samples=1000, tolerance=0.0), "Tolerance must be a positive"),
        ("tolerance_negative", dict(measured=1, reference=0, samples=1000, tolerance=-1.0),
         "Tolerance must be a positive"),
        ("same_layer", dict(measured=1, reference=1, samples=1000, tolerance=0.42), "are the same layer"),
    ]
    for name, kw, message in cases:
        mlx = os.path.join(work, name + ".mlx")
        script(mlx, kw["measured"], kw["reference"], kw["samples"], kw["tolerance"])
        code, log, console = ms.run_meshlabserver(args.meshlabserver, work, [reference, measured], mlx)
        c.check(message in log, "%s: the log says '%s':\n%s" % (name, message, log))
        c.check("Problem with filter: " + FILTER in log, "%s: meshlabserver reports the filter failed" % name)
        c.check(accuracy_line(log) is None, "%s: no accuracy is reported" % name)
    c.finish()


if __name__ == "__main__":
    main()
