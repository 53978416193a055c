#!/usr/bin/python3
"""How far a segmented mesh's borders lie from the CAD edges they stand for (issue 10, clean borders).

A border edge is a mesh edge between faces of two segments. Each segment stands for the true surface most of
its faces belong to (truth file -> reference JSON `surface`); a border between segments of surfaces a and b
stands for the CAD edge where a meets b: the edges of the reference mesh (make_bracket, 0.005 mm chordal
deviation) between a face of a and a face of b. For every vertex on such a border this prints its distance to
that polyline, and for every CAD edge the share of its length with a border edge of the same two surfaces
within 0.1 and 0.42 mm (an edge the segmentation missed, e.g. a fillet merged into a plane, has none). Borders
between segments of surfaces that do not meet in the CAD are counted apart (a segmentation error, not a
placement one). CAD edges are split into sharp ones (the faces' normals turn by more than 10 degrees across
them, the edges a user sees) and tangent ones (a fillet meeting its faces, where the border's position along
the surface hardly changes the shape).

MESH.ply gives the vertex positions measured (the scan as segmented, or the snapped mesh); the segment of each
face is MESH.ply's face quality, or SEGMENTS.ply's with --segments (the same faces in the same order, e.g.
bench_segment_scan --segmented, whose --snapped output has no face quality).

With --fits FITS.json (the fitted primitives the mesh was snapped onto: Fit All's export or bench_segment_scan
--fits) the border vertices are split into those on their edge (within 1e-4 mm of both segments' primitives,
where snap_segments put them) and the rest (held back, out of reach, or where the primitives do not meet):
the first group's distance to the CAD edge is what the fits lose, the second's what the placement loses.

Usage: /usr/bin/python3 bench/border_deviation.py MESH.ply TRUTH.txt REFERENCE.ply REFERENCE.json
           [--segments SEGMENTS.ply] [--fits FITS.json] [--per-edge]
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
from fit_errors import closest, fitted_primitive  # noqa: E402
from meshlab_script import read_ply  # noqa: E402
from offset_ceiling import majority  # noqa: E402
from score_segmentation import read_truth  # noqa: E402

SHARP_DEGREES = 10.0
NEAR_MM = (0.1, 0.42)
ON_EDGE_MM = 1e-4


def load(path, need_quality):
    vertices, faces, face_props, _ = read_ply(path)
    if any(len(f) != 3 for f in faces):
        raise SystemExit("%s: not a triangle mesh" % path)
    if need_quality and "quality" not in face_props:
        raise SystemExit("%s: no face quality (segment ids); give --segments" % path)
    quality = np.rint(np.array(face_props["quality"], float)).astype(int) if "quality" in face_props else None
    return np.array(vertices, float), np.array(faces, int), quality


def interior_edges(faces):
    """(vertex a, vertex b, face 0, face 1) for every edge with exactly two faces, a < b."""
    corners = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    owner = np.tile(np.arange(len(faces)), 3)
    corners.sort(axis=1)
    order = np.lexsort((corners[:, 1], corners[:, 0]))
    corners, owner = corners[order], owner[order]
    same = np.all(corners[1:] == corners[:-1], axis=1)
    first = np.flatnonzero(same)
    # An edge with three or more faces repeats its key more than twice: not a two-face edge.
    lone = np.ones(len(first), bool)
    lone[1:] &= first[1:] != first[:-1] + 1
    lone[:-1] &= first[:-1] + 1 != first[1:]
    first = first[lone]
    return corners[first, 0], corners[first, 1], owner[first], owner[first + 1]


def face_normals(v, f):
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    return n / np.maximum(np.linalg.norm(n, axis=1), 1e-300)[:, None]


def cad_edges(ref_v, ref_f, ref_surface):
    """{(a, b): (segment starts, segment ends, sharp?)} for each pair of surfaces a < b that meet."""
    va, vb, f0, f1 = interior_edges(ref_f)
    sa, sb = ref_surface[f0], ref_surface[f1]
    meet = (sa != sb) & (sa >= 0) & (sb >= 0)
    n = face_normals(ref_v, ref_f)
    turn = np.degrees(np.arccos(np.clip(np.sum(n[f0] * n[f1], axis=1), -1.0, 1.0)))
    out = {}
    keys = np.stack([np.minimum(sa, sb), np.maximum(sa, sb)], axis=1)
    for key in np.unique(keys[meet], axis=0):
        k = meet & (keys[:, 0] == key[0]) & (keys[:, 1] == key[1])
        out[(int(key[0]), int(key[1]))] = (ref_v[va[k]], ref_v[vb[k]], float(np.median(turn[k])) > SHARP_DEGREES)
    return out


def distance_to_segments(p, a, b):
    """Distance of each point p to the nearest of the segments a[i]-b[i]."""
    ab = b - a
    ab2 = np.maximum(np.sum(ab * ab, axis=1), 1e-300)
    out = np.empty(len(p))
    step = max(1, 2000000 // max(1, len(a)))
    for i in range(0, len(p), step):
        q = p[i:i + step, None, :] - a[None, :, :]
        t = np.clip(np.einsum("ijk,jk->ij", q, ab) / ab2[None, :], 0.0, 1.0)
        d = q - t[:, :, None] * ab[None, :, :]
        out[i:i + step] = np.sqrt(np.min(np.einsum("ijk,ijk->ij", d, d), axis=1))
    return out


def sample_polyline(a, b, step=0.05):
    """Midpoints of the polyline's segments cut into pieces of at most `step` mm, and the pieces' lengths (a
    plane-plane edge is one segment of the reference mesh: its share within a distance needs it cut)."""
    length = np.linalg.norm(b - a, axis=1)
    pieces = np.maximum(1, np.ceil(length / step).astype(int))
    which = np.repeat(np.arange(len(a)), pieces)
    t = (np.arange(len(which)) - np.repeat(np.cumsum(pieces) - pieces, pieces) + 0.5) / pieces[which]
    return a[which] + t[:, None] * (b - a)[which], (length / pieces)[which]


def on_fitted_edge(v, va, vb, g0, g1, fits_json):
    """Per vertex of the mesh, whether it lies on both fitted primitives of a border edge it ends (all False
    without fits)."""
    out = np.zeros(len(v), bool)
    if not fits_json:
        return out
    prims = {s["id"]: fitted_primitive(s) for s in json.load(open(fits_json))["segments"]}
    for pair in np.unique(np.stack([g0, g1], axis=1), axis=0):
        pa, pb = prims.get(int(pair[0])), prims.get(int(pair[1]))
        if pa is None or pb is None:
            continue
        edges = (g0 == pair[0]) & (g1 == pair[1])
        k = np.unique(np.concatenate([va[edges], vb[edges]]))
        out[k] |= np.maximum(closest(pa, v[k])[1], closest(pb, v[k])[1]) < ON_EDGE_MM
    return out


def describe(d):
    if len(d) == 0:
        return "none"
    return "median %.3f, mean %.3f, 95th percentile %.3f, max %.3f mm; within %s" % (
        np.median(d), np.mean(d), np.percentile(d, 95), np.max(d),
        ", ".join("%g mm %.1f%%" % (r, 100.0 * np.mean(d <= r)) for r in NEAR_MM))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("mesh"), ap.add_argument("truth"), ap.add_argument("reference_ply"), ap.add_argument("reference")
    ap.add_argument("--segments")
    ap.add_argument("--fits")
    ap.add_argument("--per-edge", action="store_true")
    a = ap.parse_args()

    ref = json.load(open(a.reference))["faces"]
    surface_of = {f["index"]: f.get("surface", f["index"]) for f in ref}
    ref_v, ref_f, ref_q = load(a.reference_ply, True)
    cad = cad_edges(ref_v, ref_f, np.array([surface_of.get(q, -1) for q in ref_q.tolist()]))

    v, f, segment = load(a.mesh, a.segments is None)
    if a.segments:
        _, sf, segment = load(a.segments, True)
        if not np.array_equal(sf, f):
            raise SystemExit("%s and %s: not the same faces" % (a.segments, a.mesh))
    truth = read_truth(a.truth)
    if len(truth) != len(f):
        raise SystemExit("truth has %d faces, mesh %d" % (len(truth), len(f)))
    face_surface = np.array([surface_of.get(t, -1) for t in truth])
    known = (segment >= 0) & (face_surface >= 0)
    stands_for = dict(zip(*(x.tolist() for x in majority(segment[known], face_surface[known]))))

    va, vb, f0, f1 = interior_edges(f)
    border = (segment[f0] != segment[f1]) & (segment[f0] >= 0) & (segment[f1] >= 0)
    va, vb, g0, g1 = va[border], vb[border], segment[f0[border]], segment[f1[border]]
    s0 = np.array([stands_for.get(s, -1) for s in g0.tolist()], int)
    s1 = np.array([stands_for.get(s, -1) for s in g1.tolist()], int)
    on_edge = on_fitted_edge(v, va, vb, g0, g1, a.fits)
    between = (s0 != s1) & (s0 >= 0) & (s1 >= 0)
    keys = np.stack([np.minimum(s0, s1), np.maximum(s0, s1)], axis=1)

    rows, measured, on, unmatched = [], {True: [], False: []}, {True: [], False: []}, 0
    covered = {True: np.zeros(len(NEAR_MM)), False: np.zeros(len(NEAR_MM))}
    length = {True: 0.0, False: 0.0}
    pairs = {(int(k[0]), int(k[1])) for k in keys[between]}
    for key in sorted(pairs | set(cad)):
        k = between & (keys[:, 0] == key[0]) & (keys[:, 1] == key[1])
        verts = np.unique(np.concatenate([va[k], vb[k]]))
        if key not in cad:
            unmatched += len(verts)
            rows.append((key, "no CAD edge", len(verts), None, None))
            continue
        ea, eb, sharp = cad[key]
        d = distance_to_segments(v[verts], ea, eb)
        measured[sharp].append(d)
        on[sharp].append(on_edge[verts])
        samples, seg_len = sample_polyline(ea, eb)
        near = distance_to_segments(samples, v[va[k]], v[vb[k]]) if k.any() else np.full(len(seg_len), np.inf)
        share = np.array([np.sum(seg_len[near <= r]) for r in NEAR_MM])
        covered[sharp] += share
        length[sharp] += float(seg_len.sum())
        rows.append((key, "sharp" if sharp else "tangent", len(verts), d, share / max(seg_len.sum(), 1e-300)))

    if a.per_edge:
        print("surfaces | CAD edge | border vertices | median / max mm | CAD length within %s" %
              " / ".join("%g mm" % r for r in NEAR_MM))
        for key, kind, n, d, share in rows:
            print("%3d-%-3d | %-11s | %6d | %s | %s" % (
                key[0], key[1], kind, n,
                "%.3f / %.3f" % (np.median(d), np.max(d)) if d is not None and len(d) else "-",
                " / ".join("%.0f%%" % (100 * s) for s in share) if share is not None else "-"))
    total = sum(len(np.concatenate(m)) if m else 0 for m in measured.values()) + unmatched
    for sharp in (True, False):
        d = np.concatenate(measured[sharp]) if measured[sharp] else np.array([])
        print("%s edges: %d border vertices, distance to their CAD edge %s" % (
            "sharp" if sharp else "tangent", len(d), describe(d)))
        if a.fits:
            o = np.concatenate(on[sharp]) if on[sharp] else np.array([], bool)
            print("  on their fitted edge: %d (%.1f%%), %s" % (
                o.sum(), 100.0 * o.mean() if len(o) else 0, describe(d[o])))
            print("  off it: %d, %s" % ((~o).sum(), describe(d[~o])))
        print("  CAD length %.1f mm, with a border edge within %s" % (length[sharp], ", ".join(
            "%g mm %.1f%%" % (r, 100.0 * c / max(length[sharp], 1e-300)) for r, c in zip(NEAR_MM, covered[sharp]))))
    print("border vertices between surfaces that do not meet in the CAD: %d of %d (%.1f%%)" % (
        unmatched, total, 100.0 * unmatched / max(total, 1)))


if __name__ == "__main__":
    main()
