#!/usr/bin/python3
"""How far each fitted primitive is from the true surface it stands for, per true surface of a scan.

For every true surface of the bracket (bench/data/bracket_reference.json), the scan faces it owns (the truth
file) are projected onto the TRUE primitive; the distances of those points to the FITTED primitive of the
segment holding most of them (the fits JSON of Fit All or bench_segment_scan --fits, segment ids = the face
quality of the segmented PLY) say how much that fit costs after snapping: a vertex snapped onto the fitted
primitive lies that far from the CAD surface. Printed per surface, largest loss first: area, true and fitted
type, direction error (degrees), size error (radius, half-angle), the mean and 90th percentile distance, and
the share of the surface's area farther than the tolerance ("lost"), then the totals.

Usage: /usr/bin/python3 bench/fit_errors.py SCAN.ply TRUTH.txt REFERENCE.json SEGMENTED.ply FITS.json [--tolerance 0.42]
SEGMENTED.ply may be the true segmentation (bench/true_segmentation.py) or any segmented copy of the scan.
Needs numpy.
"""
import argparse
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "script"))
from meshlab_script import read_ply  # noqa: E402
from score_segmentation import read_truth  # noqa: E402


def unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def reference_primitive(f):
    t = f["type"]
    if t == "plane":
        return {"type": "Plane", "origin": np.array(f["point"], float), "axis": unit(f["normal"])}
    if t == "sphere":
        return {"type": "Sphere", "origin": np.array(f["centre"], float), "radius": f["radius"]}
    if t == "cylinder":
        return {"type": "Cylinder", "origin": np.array(f["point"], float), "axis": unit(f["axis"]), "radius": f["radius"]}
    if t == "cone":
        return {"type": "Cone", "origin": np.array(f["apex"], float), "axis": unit(f["axis"]),
                "half_angle": f["half_angle"]}
    if t == "torus":
        return {"type": "Torus", "origin": np.array(f["centre"], float), "axis": unit(f["axis"]),
                "radius": f["major_radius"], "minor": f["minor_radius"]}
    return None


def fitted_primitive(seg):
    p = seg.get("parameters")
    t = seg.get("type")
    if t == "Plane":
        return {"type": t, "origin": np.array(p["point"], float), "axis": unit(p["normal"])}
    if t == "Sphere":
        return {"type": t, "origin": np.array(p["center"], float), "radius": p["radius"]}
    if t == "Cylinder":
        return {"type": t, "origin": np.array(p["axis_point"], float), "axis": unit(p["axis"]), "radius": p["radius"]}
    if t == "Cone":
        return {"type": t, "origin": np.array(p["apex"], float), "axis": unit(p["axis"]),
                "half_angle": math.radians(p["half_angle_deg"])}
    if t == "Torus":
        return {"type": t, "origin": np.array(p["center"], float), "axis": unit(p["axis"]),
                "radius": p["major_radius"], "minor": p["minor_radius"]}
    return None


def closest(prim, x):
    """Closest points of prim to the rows of x, and the unsigned distances."""
    o = prim["origin"]
    d = x - o
    t = prim["type"]
    if t == "Plane":
        n = prim["axis"]
        h = d @ n
        return x - np.outer(h, n), np.abs(h)
    if t == "Sphere":
        r = np.linalg.norm(d, axis=1)
        u = d / np.maximum(r, 1e-12)[:, None]
        return o + u * prim["radius"], np.abs(r - prim["radius"])
    a = prim["axis"]
    h = d @ a
    radial = d - np.outer(h, a)
    rho = np.linalg.norm(radial, axis=1)
    u = radial / np.maximum(rho, 1e-12)[:, None]
    if t == "Cylinder":
        return o + np.outer(h, a) + u * prim["radius"], np.abs(rho - prim["radius"])
    if t == "Cone":
        s, c = math.sin(prim["half_angle"]), math.cos(prim["half_angle"])
        g = c * a[None, :] + s * u  # generator direction through each point
        along = np.maximum((d * g).sum(1), 0.0)
        p = o + along[:, None] * g
        return p, np.linalg.norm(x - p, axis=1)
    if t == "Torus":
        ring = o + np.outer(h * 0, a) + u * prim["radius"]
        w = x - ring
        dist = np.linalg.norm(w, axis=1)
        p = ring + w / np.maximum(dist, 1e-12)[:, None] * prim["minor"]
        return p, np.abs(dist - prim["minor"])
    raise ValueError(t)


def direction_error(a, b):
    if "axis" not in a or "axis" not in b:
        return float("nan")
    return math.degrees(math.acos(min(1.0, abs(float(a["axis"] @ b["axis"])))))


def size_error(true, fit):
    if true["type"] != fit["type"]:
        return ""
    if true["type"] in ("Sphere", "Cylinder"):
        return "r %+.3f" % (fit["radius"] - true["radius"])
    if true["type"] == "Cone":
        return "a %+.2f deg" % math.degrees(fit["half_angle"] - true["half_angle"])
    if true["type"] == "Torus":
        return "R %+.3f r %+.3f" % (fit["radius"] - true["radius"], fit["minor"] - true["minor"])
    return ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scan"), ap.add_argument("truth"), ap.add_argument("reference"), ap.add_argument("segmented")
    ap.add_argument("fits"), ap.add_argument("--tolerance", type=float, default=0.42)
    a = ap.parse_args()
    ref = json.load(open(a.reference))["faces"]
    surface_of = {f["index"]: f.get("surface", f["index"]) for f in ref}
    true_prim = {f["index"]: reference_primitive(f) for f in ref if f.get("surface", f["index"]) == f["index"]}
    vertices, faces, _, _ = read_ply(a.scan)
    _, _, face_props, _ = read_ply(a.segmented)
    quality = face_props["quality"]
    v = np.array(vertices, float)
    f = np.array(faces, int)
    seg = np.array(quality, float).astype(int)
    truth = np.array([surface_of.get(t, -1) for t in read_truth(a.truth)])
    tri = v[f]
    centroid = tri.mean(1)
    area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    fits = {s["id"]: s for s in json.load(open(a.fits))["segments"]}
    rows, lost_total, dist_total, area_total = [], 0.0, 0.0, 0.0
    for s, prim in sorted(true_prim.items()):
        mask = truth == s
        if not mask.any() or prim is None:
            continue
        owner = np.bincount(seg[mask][seg[mask] >= 0]).argmax() if (seg[mask] >= 0).any() else -1
        fit = fitted_primitive(fits[owner]) if owner in fits else None
        p, _ = closest(prim, centroid[mask])
        w = area[mask]
        if fit is None:
            dist = np.full(len(p), np.nan)
        else:
            _, dist = closest(fit, p)
        ok = np.isfinite(dist)
        lost = float(w[~ok].sum() + w[ok][dist[ok] > a.tolerance].sum())
        mean = float((w[ok] * dist[ok]).sum() / max(w[ok].sum(), 1e-12)) if ok.any() else float("nan")
        p90 = float(np.percentile(dist[ok], 90)) if ok.any() else float("nan")
        rows.append((lost, s, prim["type"], fit["type"] if fit else "free", float(w.sum()),
                     direction_error(prim, fit) if fit else float("nan"), size_error(prim, fit) if fit else "",
                     mean, p90, owner))
        lost_total += lost
        area_total += float(w.sum())
        dist_total += float((w[ok] * np.minimum(dist[ok], 10)).sum())
    print("%-4s %-9s %-9s %8s %7s %-18s %8s %8s %8s %5s" % ("surf", "true", "fitted", "area", "dir deg", "size",
                                                           "mean mm", "p90 mm", "lost %", "seg"))
    for lost, s, tt, ft, w, de, se, mean, p90, owner in sorted(rows, reverse=True):
        print("%-4d %-9s %-9s %8.1f %7.2f %-18s %8.3f %8.3f %8.2f %5d" % (s, tt, ft, w, de, se, mean, p90,
                                                                        100 * lost / area_total, owner))
    typed = sum(r[4] for r in rows if r[2] == r[3])
    print("total: %.1f mm2; area beyond %.2f mm %.2f%%; mean distance %.3f mm; right type %.1f%% of the area" % (
        area_total, a.tolerance, 100 * lost_total / area_total, dist_total / area_total, 100 * typed / area_total))


if __name__ == "__main__":
    main()
