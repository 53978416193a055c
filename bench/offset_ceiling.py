#!/usr/bin/python3
"""The accuracy left when every true surface is placed exactly but for the offset its own scan data has.

A fit of a segment's points follows those points: where the scan's roughness shifts a whole face, the fitted
primitive shifts with it, whatever the segmentation, type choice or fitting method. This writes the scan with
every vertex projected onto the true primitive of the surface most of its faces belong to (truth file ->
reference JSON), moved along its normal by that surface's mean offset: the area-weighted mean signed distance
of the surface's scan faces (their centroids) to it, which is what a least-squares fit of the offset alone
(plane position, radius, tube radius) returns. Measuring the output with measure_scan gives the ceiling of any
pipeline that places each surface from its own data, with the segmentation, types, directions and axes all
perfect. --no-offset drops the offsets (every vertex onto its true surface: the 99% row of issue 10's table),
which checks the projection. Prints the offsets, largest first.

Usage: /usr/bin/python3 bench/offset_ceiling.py SCAN.ply TRUTH.txt REFERENCE.json OUT.ply [--no-offset]
then   build/bench/bracket/measure_scan OUT.ply bench/data/bracket_reference.ply
Needs numpy.
"""
import argparse
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "script"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fit_errors import closest, reference_primitive  # noqa: E402
from meshlab_script import read_ply, write_ply  # noqa: E402
from score_segmentation import read_truth  # noqa: E402


def outward_normals(prim, x, p):
    """Unit normals of prim at its closest points p to x, pointing away from the axis, centre or tube centre
    (planes: their own normal), so that (x - p) . n is a signed distance and p + d n the offset surface."""
    t = prim["type"]
    if t == "Plane":
        return np.tile(prim["axis"], (len(x), 1))
    d = x - prim["origin"]
    if t == "Sphere":
        return d / np.maximum(np.linalg.norm(d, axis=1), 1e-12)[:, None]
    a = prim["axis"]
    radial = d - np.outer(d @ a, a)
    u = radial / np.maximum(np.linalg.norm(radial, axis=1), 1e-12)[:, None]
    if t == "Cylinder":
        return u
    if t == "Cone":
        s, c = math.sin(prim["half_angle"]), math.cos(prim["half_angle"])
        return c * u - s * a[None, :]
    if t == "Torus":
        w = p - (prim["origin"] + u * prim["radius"])
        return w / np.maximum(np.linalg.norm(w, axis=1), 1e-12)[:, None]
    raise ValueError(t)


def majority(keys, values):
    """The distinct keys and, for each, its most frequent value (ties: the largest value)."""
    pairs, counts = np.unique(np.stack([keys, values], axis=1), axis=0, return_counts=True)
    pairs = pairs[np.lexsort((counts, pairs[:, 0]))]  # by key, most frequent last
    last = np.ones(len(pairs), bool)
    last[:-1] = pairs[1:, 0] != pairs[:-1, 0]
    return pairs[last, 0], pairs[last, 1]


def majority_surface(faces, face_surface, vertex_count):
    """Per vertex, the surface most of its faces belong to (-1: none known)."""
    corner_vertex = faces.reshape(-1)
    corner_surface = np.repeat(face_surface, 3)
    known = corner_surface >= 0
    vertex, surface = majority(corner_vertex[known], corner_surface[known])
    out = np.full(vertex_count, -1)
    out[vertex] = surface
    return out


class ScanByTrueSurface:
    """A scan and its truth: the reference's surfaces (surface_of: B-rep face -> surface; prims: the true
    primitive of each surface, None for a free-form one), the scan's vertices and faces as arrays, and per face
    its true surface (-1: none), centroid and area."""

    def __init__(self, scan, truth, reference):
        ref = json.load(open(reference))["faces"]
        self.surface_of = {f["index"]: f.get("surface", f["index"]) for f in ref}
        self.prims = {f["index"]: reference_primitive(f) for f in ref if self.surface_of[f["index"]] == f["index"]}
        vertices, faces, _, _ = read_ply(scan)
        self.vertices = np.array(vertices, float)
        self.faces = np.array(faces, int)
        self.face_surface = np.array([self.surface_of.get(t, -1) for t in read_truth(truth)])
        tri = self.vertices[self.faces]
        self.centroid = tri.mean(1)
        self.area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scan"), ap.add_argument("truth"), ap.add_argument("reference"), ap.add_argument("out")
    ap.add_argument("--no-offset", action="store_true")
    a = ap.parse_args()
    scan = ScanByTrueSurface(a.scan, a.truth, a.reference)
    prims, v, f, face_surface = scan.prims, scan.vertices, scan.faces, scan.face_surface
    centroid, area = scan.centroid, scan.area

    offset = {}
    for s, prim in prims.items():
        mask = face_surface == s
        if prim is None or not mask.any():
            continue
        p, _ = closest(prim, centroid[mask])
        signed = ((centroid[mask] - p) * outward_normals(prim, centroid[mask], p)).sum(1)
        offset[s] = 0.0 if a.no_offset else float((area[mask] * signed).sum() / area[mask].sum())

    owner = majority_surface(f, face_surface, len(v))
    out = v.copy()
    for s, prim in prims.items():
        mask = owner == s
        if s not in offset or not mask.any():
            continue
        p, _ = closest(prim, v[mask])
        out[mask] = p + offset[s] * outward_normals(prim, v[mask], p)
    write_ply(a.out, out.tolist(), f.tolist())

    surface_area = {s: float(area[face_surface == s].sum()) for s in offset}
    print("surf type       area mm2  offset mm")
    for s in sorted(offset, key=lambda k: -abs(offset[k])):
        print("%-4d %-9s %9.1f %+10.3f" % (s, prims[s]["type"], surface_area[s], offset[s]))
    total = sum(surface_area.values())
    print("area-weighted mean |offset| %.3f mm; vertices on no known surface (left as scanned): %d"
          % (sum(surface_area[s] * abs(offset[s]) for s in offset) / total, int((owner < 0).sum())))


if __name__ == "__main__":
    main()
