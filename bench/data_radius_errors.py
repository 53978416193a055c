#!/usr/bin/python3
"""How far the scan itself stands from the CAD's radii: the ideal a fitted radius can reach on it.

For every cylinder and sphere of the bracket (bench/data/bracket_reference.json), the centroids of the scan faces it
owns (the truth file: the reference face nearest to each scan face) are measured from the TRUE axis (a sphere: the
true centre); their median distance is the radius the data holds, whatever a fit does. Printed per surface: the
true radius and the data's error, absolute and relative, then the median relative error over the surfaces, to set
beside the fitted radii's (bench/fit_errors.py). On the simulated CT scans the holes' walls lie 0.2-0.4 mm inside
the CAD's (the scanner's blur and threshold), so a fit that follows the data cannot have a median radius error
under 1%.

Usage: /usr/bin/python3 bench/data_radius_errors.py SCAN.ply TRUTH.txt [REFERENCE.json]
Needs numpy.
"""
import json
import os
import statistics
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "script"))
sys.path.insert(0, HERE)
from meshlab_script import read_ply  # noqa: E402
from score_segmentation import read_truth  # noqa: E402


def main():
    if len(sys.argv) not in (3, 4):
        raise SystemExit(__doc__.strip().splitlines()[-2])
    scan, truth = sys.argv[1], sys.argv[2]
    reference = sys.argv[3] if len(sys.argv) == 4 else os.path.join(HERE, "data", "bracket_reference.json")
    faces_of_reference = json.load(open(reference))["faces"]
    vertices, faces, _, _ = read_ply(scan)
    centroids = np.asarray(vertices, float)[np.asarray(faces, int)].mean(axis=1)
    surface = np.asarray([faces_of_reference[i]["surface"] for i in read_truth(truth)])
    relative = []
    for f in faces_of_reference:
        # One line per surface (a surface split into several B-rep faces is listed under its first).
        if f["index"] != f["surface"] or f["type"] not in ("cylinder", "sphere"):
            continue
        points = centroids[surface == f["surface"]]
        if len(points) < 20:
            continue
        if f["type"] == "cylinder":
            axis = np.asarray(f["axis"], float) / np.linalg.norm(f["axis"])
            d = points - np.asarray(f["point"], float)
            r = np.linalg.norm(d - np.outer(d @ axis, axis), axis=1)
        else:
            r = np.linalg.norm(points - np.asarray(f["centre"], float), axis=1)
        error = float(np.median(r)) - f["radius"]
        relative.append(abs(error) / f["radius"])
        print("%2d %-8s radius %.2f: the data's %+.3f mm (%.1f%%)" % (f["surface"], f["type"], f["radius"], error,
                                                                     100 * relative[-1]))
    if relative:
        print("median relative error of the data's radii: %.1f%% over %d surfaces" %
              (100 * statistics.median(relative), len(relative)))


if __name__ == "__main__":
    main()
