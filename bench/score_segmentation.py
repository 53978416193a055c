"""Scores a segmented scan against the bracket's ground truth.

Inputs: the segmented scan PLY (face quality = segment id, as `meshlabserver -m fq` saves it), the scan's
truth file (one B-rep face index per scan face, `simulate_ct_scan --truth`), the reference JSON
(`make_bracket`), and optionally the JSON that `Primitive: Fit All Segments` exported.

With AREA.ply (a mesh with the same faces, e.g. the scan before a snap moved its vertices) the areas that weigh
the scores are that mesh's.

Each segment is matched to the B-rep face it overlaps most (by area); faces on the same analytic surface
(`surface` in the reference JSON) count as one. Reported:
- labelled: share of the area whose segment is matched to the face's true surface;
- typed: share of the area whose segment's fitted type equals the true surface type;
- the radius error of every cylinder of the reference that a fitted cylinder segment matches;
- with --surfaces, where the unlabelled area lies: per true surface that loses at least 0.2% of the area, its
  type, its share of the area, the share lost (its area in segments matched to another surface) and the
  segments holding most of it (segment -> the surface it is matched to: share of this surface).
Usage: score_segmentation.py [--surfaces] SCAN.ply TRUTH.txt REFERENCE.json [FIT_EXPORT.json [AREA.ply]]
"""
import json
import math
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "script"))
from meshlab_script import read_ply  # noqa: E402


def triangle_area(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    return 0.5 * math.sqrt(sum(x * x for x in n))


def read_truth(path):
    with open(path) as f:
        return [int(line) for line in f if line.strip() and not line.startswith("#")]


def score(scan_ply, truth_txt, reference_json, fit_json=None, area_ply=None):
    vertices, faces, face_props, _ = read_ply(scan_ply)
    segment = [int(round(q)) for q in face_props["quality"]]
    if area_ply:
        # The areas of the mesh that was segmented: a snapped output's triangles are stretched or collapsed
        # by the fits, which would weigh the segmentation by the fits' geometry.
        area_vertices, area_faces, _, _ = read_ply(area_ply)
        if len(area_faces) != len(faces) or any(tuple(a) != tuple(b) for a, b in zip(area_faces, faces)):
            raise SystemExit("%s and %s do not have the same faces" % (area_ply, scan_ply))
        vertices = area_vertices
    truth_face = read_truth(truth_txt)
    if len(truth_face) != len(faces):
        raise SystemExit("truth has %d faces, scan %d" % (len(truth_face), len(faces)))
    reference = json.load(open(reference_json))["faces"]
    surface_of = {f["index"]: f.get("surface", f["index"]) for f in reference}
    type_of = {f["index"]: f["type"] for f in reference}
    area = [triangle_area(*(vertices[i] for i in f)) for f in faces]
    total = sum(area)

    overlap = defaultdict(float)
    for s, t, a in zip(segment, truth_face, area):
        overlap[(s, surface_of[t])] += a
    best = {}
    for (s, surf), a in overlap.items():
        if s not in best or a > best[s][1]:
            best[s] = (surf, a)
    labelled = sum(a for s, t, a in zip(segment, truth_face, area) if best[s][0] == surface_of[t]) / total

    result = {"faces": len(faces), "segments": len(best), "labelled": labelled}
    area_of_surface = defaultdict(float)
    for (s, surf), a in overlap.items():
        area_of_surface[surf] += a
    result["surfaces"] = [
        {"surface": surf, "type": type_of[surf], "share": a / total,
         "lost": (a - sum(o for (s, u), o in overlap.items() if u == surf and best[s][0] == surf)) / total,
         "segments": sorted(((s, best[s][0], o / a) for (s, u), o in overlap.items() if u == surf),
                            key=lambda row: -row[2])}
        for surf, a in area_of_surface.items()]
    result["surfaces"].sort(key=lambda row: -row["lost"])
    if fit_json:
        fits = {s["id"]: s for s in json.load(open(fit_json))["segments"]}
        fitted_type = {s: fits[s]["type"].lower() if s in fits else "freeform" for s in best}
        result["typed"] = sum(a for s, t, a in zip(segment, truth_face, area)
                              if fitted_type[s] == type_of[t]) / total
        radius_errors = []
        for f in reference:
            if f["type"] != "cylinder" or f["index"] != f.get("surface", f["index"]):
                continue
            candidates = [s for s in best if best[s][0] == f["index"] and fitted_type[s] == "cylinder"]
            if candidates:
                s = max(candidates, key=lambda k: overlap[(k, f["index"])])
                radius_errors.append((f["index"], f["radius"], fits[s]["parameters"]["radius"]))
            else:
                radius_errors.append((f["index"], f["radius"], None))
        result["cylinders"] = radius_errors
    return result


def main():
    args = [a for a in sys.argv[1:] if a != "--surfaces"]
    if len(args) < 3 or len(args) > 5 or any(a.startswith("--") for a in args):
        raise SystemExit(__doc__)
    r = score(*args)
    print("faces %d, segments %d, area labelled correctly %.1f%%" % (r["faces"], r["segments"], 100 * r["labelled"]))
    if "--surfaces" in sys.argv[1:]:
        for row in r["surfaces"]:
            if row["lost"] < 0.002:
                break
            print("  surface %2d %-8s %4.1f%% of the area, %4.1f%% lost; in segments %s" % (
                row["surface"], row["type"], 100 * row["share"], 100 * row["lost"],
                ", ".join("%d->%d %.0f%%" % (s, matched, 100 * share) for s, matched, share in row["segments"][:3])))
    if "typed" in r:
        print("area with the right primitive type %.1f%%" % (100 * r["typed"]))
        for index, true_r, fitted in r["cylinders"]:
            print("  cylinder face %d: radius %.3f, fitted %s" % (
                index, true_r, "%.3f (error %+.3f)" % (fitted, fitted - true_r) if fitted else "not found"))


if __name__ == "__main__":
    main()
