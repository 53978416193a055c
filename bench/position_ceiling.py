#!/usr/bin/python3
"""The accuracy left when every surface has its true type and direction, and only its position (and sizes) is fitted.

An ideal of the relation methods (issue 10): the segmentation is the truth, each surface's type and direction
(normal or axis) are the CAD's, and so are its sizes (radius, tube radius, half-angle) unless --sizes is given;
its position (a plane's offset, a cylinder's axis across it, the apex or centre of a cone, sphere or torus) and,
with --sizes, its sizes are the least-squares fit of its own scan faces (their centroids, weighed by area). With
--relations the fit is joint, under the CAD's own relations read off the reference B-rep, as a relation method
that found every one of them, and no wrong one, would hold them:
- coaxial: rotational surfaces on one axis line (a sphere: its centre on it) keep their axes together;
  concentric spheres keep one centre, coplanar planes one plane (`coaxial` and `all`);
- equal sizes: with --sizes, surfaces of one type with equal radii, tubes or half-angles keep them equal;
- tangent (`all`): two surfaces that meet smoothly along a B-rep edge (normals within 1 degree at its points)
  move alike along the normal there, so that a fillet goes where the faces it rounds go.
Each relation is a linear condition on the two surfaces' parameter changes, held with a weight a thousand times
the data's. The fit is Gauss-Newton on the signed distances, 8 rounds. Writes the primitives as
`bench_segment_scan --primitives` reads them; snapping the true segments onto them (`--labels TRUE.ply`) and
`measure_scan` give the ceiling of any method that takes positions (and sizes) from the scan, even with perfect
relations. Prints the relations held and each surface's shift from its true position, largest first.

Usage: /usr/bin/python3 bench/position_ceiling.py SCAN.ply TRUTH.txt REFERENCE.json REFERENCE.ply OUT_PRIMS.txt
           [--relations none|coaxial|all] [--sizes]
then   build/bench/bench_segment_scan SCAN.ply --labels TRUE.ply --primitives OUT_PRIMS.txt --snapped OUT.ply
       build/bench/bracket/measure_scan OUT.ply bench/data/bracket_reference.ply
Cost: about 1 s for 150k faces, 5 s for 1M (numpy, 40 surfaces). Needs numpy.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "script"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fit_errors import closest  # noqa: E402
from meshlab_script import read_ply  # noqa: E402
from offset_ceiling import ScanByTrueSurface, outward_normals  # noqa: E402

RELATION_WEIGHT = 1e3
TANGENT_COS = math.cos(math.radians(1.0))


def perpendicular_basis(a):
    """Two unit vectors perpendicular to a and to each other."""
    u = np.cross(a, [1.0, 0, 0] if abs(a[0]) < 0.9 else [0, 1.0, 0])
    u /= np.linalg.norm(u)
    return np.stack([u, np.cross(a, u)], axis=1)


def position_basis(prim):
    """Columns span the translations that move the surface: a plane's normal, a cylinder's cross-section."""
    if prim["type"] == "Plane":
        return prim["axis"][:, None]
    if prim["type"] == "Cylinder":
        return perpendicular_basis(prim["axis"])
    return np.eye(3)


SIZES = {"Plane": (), "Sphere": ("radius",), "Cylinder": ("radius",), "Cone": ("half_angle",),
         "Torus": ("radius", "minor")}


class Surface:
    """One surface's free parameters: its translation (position_basis) and, with sizes, its sizes' changes."""

    def __init__(self, prim, sizes):
        self.prim = prim
        self.basis = position_basis(prim)
        self.sizes = SIZES[prim["type"]] if sizes else ()
        self.count = self.basis.shape[1] + len(self.sizes)

    def at(self, params):
        out = dict(self.prim)
        out["origin"] = self.prim["origin"] + self.basis @ params[:self.basis.shape[1]]
        for name, change in zip(self.sizes, params[self.basis.shape[1]:]):
            out[name] = self.prim[name] + change
        return out

    def jacobian(self, params, x):
        """Signed distances of x to the surface at params, its outward normals there, and the rows of the
        surface's displacement along them per parameter (the distances fall by that much)."""
        prim = self.at(params)
        p, _ = closest(prim, x)
        n = outward_normals(prim, x, p)
        columns = [n @ self.basis]
        for name in self.sizes:
            if name == "half_angle":  # a point L from the apex along its generator moves L d(angle) outward
                columns.append(np.linalg.norm(p - prim["origin"], axis=1)[:, None])
            elif name == "radius" and prim["type"] == "Torus":  # the tube's centre moves along u
                a = prim["axis"]
                d = x - prim["origin"]
                radial = d - np.outer(d @ a, a)
                u = radial / np.maximum(np.linalg.norm(radial, axis=1), 1e-12)[:, None]
                columns.append((u * n).sum(1)[:, None])
            else:
                columns.append(np.ones((len(x), 1)))
        return ((x - p) * n).sum(1), n, np.hstack(columns)


def on_line(point, origin, axis):
    d = point - origin
    return np.linalg.norm(d - (d @ axis) * axis) < 1e-6


def padded(rows, surface):
    """Rows over a surface's translation, zero over its sizes."""
    return np.hstack([rows @ surface.basis, np.zeros((len(rows), len(surface.sizes)))])


def size_rows(surface, name):
    out = np.zeros((1, surface.count))
    out[0, surface.basis.shape[1] + surface.sizes.index(name)] = 1.0
    return out


def relation_rows(surfaces):
    """The CAD's coaxial, concentric, coplanar and (with sizes) equal-size relations, as (A, B, J_A, J_B, kind)
    with J_A p_A + J_B p_B = 0."""
    out = []
    keys = sorted(surfaces)
    for i, a in enumerate(keys):
        for b in keys[i + 1:]:
            sa, sb = surfaces[a], surfaces[b]
            pa, pb = sa.prim, sb.prim
            ta, tb = pa["type"], pb["type"]
            rows = None
            if ta == "Plane" and tb == "Plane":
                if abs(pa["axis"] @ pb["axis"]) > 1 - 1e-12 and abs((pb["origin"] - pa["origin"]) @ pa["axis"]) < 1e-6:
                    rows, kind = pa["axis"][None, :], "coplanar"
            elif ta == "Sphere" and tb == "Sphere":
                if np.linalg.norm(pa["origin"] - pb["origin"]) < 1e-6:
                    rows, kind = np.eye(3), "concentric"
            elif "Plane" not in (ta, tb):
                line, other = (pb, pa) if ta == "Sphere" else (pa, pb)
                parallel = other["type"] == "Sphere" or abs(line["axis"] @ other["axis"]) > 1 - 1e-12
                if parallel and on_line(other["origin"], line["origin"], line["axis"]):
                    rows, kind = perpendicular_basis(line["axis"]).T, "coaxial"
            if rows is not None:
                out.append((a, b, padded(rows, sa), -padded(rows, sb), kind))
            if ta == tb:
                for name in set(sa.sizes) & set(sb.sizes):
                    if abs(pa[name] - pb[name]) < 1e-9:
                        out.append((a, b, size_rows(sa, name), -size_rows(sb, name), "equal " + name))
    return out


def tangent_rows(surfaces, ref_vertices, ref_triangles, ref_face, surface_of):
    """Pairs of surfaces that meet smoothly along a B-rep edge, as (A, B, J_A, J_B, "tangent"): one row per
    edge point, so that both surfaces move alike along the normal there."""
    tri = np.asarray(ref_triangles)
    surf = np.array([surface_of.get(int(q), -1) for q in ref_face])
    edges = {}
    for t, (i, j, k) in enumerate(tri):
        for e in ((i, j), (j, k), (k, i)):
            edges.setdefault((min(e), max(e)), []).append(surf[t])
    points = {}
    for (i, j), owners in edges.items():
        if len(owners) == 2 and owners[0] != owners[1] and min(owners) >= 0:
            a, b = sorted(owners)
            points.setdefault((a, b), []).append(0.5 * (ref_vertices[i] + ref_vertices[j]))
    out = []
    for (a, b), pts in sorted(points.items()):
        if a not in surfaces or b not in surfaces:
            continue
        x = np.array(pts)
        _, na, ja = surfaces[a].jacobian(np.zeros(surfaces[a].count), x)
        _, nb, jb = surfaces[b].jacobian(np.zeros(surfaces[b].count), x)
        cos = (na * nb).sum(1)
        smooth = np.abs(cos) > TANGENT_COS
        if smooth.mean() > 0.9:
            scale = 1.0 / math.sqrt(smooth.sum())
            out.append((a, b, ja[smooth] * scale, -(jb[smooth] * np.sign(cos[smooth])[:, None]) * scale, "tangent"))
    return out


def fit_parameters(surfaces, data, relations, rounds=8):
    """Parameters per surface minimising the area-weighted squared signed distances of its data, with the
    relations held by heavy weights (Gauss-Newton)."""
    start, n = {}, 0
    for s in sorted(surfaces):
        start[s] = n
        n += surfaces[s].count
    block = {s: slice(start[s], start[s] + surfaces[s].count) for s in surfaces}
    params = np.zeros(n)
    weight = RELATION_WEIGHT * sum(w.sum() for _, w in data.values()) / max(len(relations), 1)
    for _ in range(rounds):
        normal = np.zeros((n, n))
        rhs = np.zeros(n)
        for s, (x, w) in data.items():
            sd, _, j = surfaces[s].jacobian(params[block[s]], x)
            normal[block[s], block[s]] += (j * w[:, None]).T @ j
            rhs[block[s]] += (j * w[:, None]).T @ sd
        for a, b, ja, jb, _ in relations:
            residual = ja @ params[block[a]] + jb @ params[block[b]]
            for si, ji in ((block[a], ja), (block[b], jb)):
                for sk, jk in ((block[a], ja), (block[b], jb)):
                    normal[si, sk] += weight * ji.T @ jk
                rhs[si] -= weight * ji.T @ residual
        params += np.linalg.lstsq(normal, rhs, rcond=None)[0]
    return {s: params[block[s]] for s in surfaces}


def primitive_line(s, prim):
    kind = prim["type"].lower()
    axis = prim.get("axis", np.array([0, 0, 1.0]))
    sizes = {"plane": (0, 0, 0), "sphere": (prim.get("radius", 0), 0, 0), "cylinder": (prim.get("radius", 0), 0, 0),
             "cone": (0, 0, prim.get("half_angle", 0)), "torus": (prim.get("radius", 0), prim.get("minor", 0), 0)}[kind]
    return "%d %s %s\n" % (s, kind, " ".join("%.17g" % v for v in (*prim["origin"], *axis, *sizes)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    for name in ("scan", "truth", "reference", "reference_ply", "out"):
        ap.add_argument(name)
    ap.add_argument("--relations", choices=("none", "coaxial", "all"), default="none")
    ap.add_argument("--sizes", action="store_true", help="fit the sizes too (radii, half-angles)")
    a = ap.parse_args()
    scan = ScanByTrueSurface(a.scan, a.truth, a.reference)
    prims, surface_of = scan.prims, scan.surface_of
    surfaces = {s: Surface(p, a.sizes) for s, p in prims.items() if p is not None and (scan.face_surface == s).any()}
    data = {s: (scan.centroid[scan.face_surface == s], scan.area[scan.face_surface == s]) for s in surfaces}

    relations = []
    if a.relations != "none":
        relations = relation_rows(surfaces)
    if a.relations == "all":
        rv, rf, rprops, _ = read_ply(a.reference_ply)
        relations += tangent_rows(surfaces, np.array(rv, float), rf, rprops["quality"], surface_of)
    kinds = {}
    for r in relations:
        kinds[r[4]] = kinds.get(r[4], 0) + 1
    print("relations held: %s" % (", ".join("%d %s" % (c, k) for k, c in sorted(kinds.items())) or "none"))

    params = fit_parameters(surfaces, data, relations)
    fitted = {s: surfaces[s].at(params[s]) for s in surfaces}
    with open(a.out, "w") as out:
        out.write("# true types and directions; positions%s fitted (relations: %s)\n"
                  % (" and sizes" if a.sizes else "", a.relations))
        for s in sorted(fitted):
            out.write(primitive_line(s, fitted[s]))
    print("surf type        area mm2  shift mm  size changes")
    shift = {s: np.linalg.norm(fitted[s]["origin"] - prims[s]["origin"]) for s in fitted}
    for s in sorted(shift, key=lambda k: -shift[k]):
        changes = " ".join("%s %+.3f" % (k, fitted[s][k] - prims[s][k]) for k in surfaces[s].sizes)
        print("%-4d %-9s %10.1f %9.3f  %s" % (s, prims[s]["type"], data[s][1].sum(), shift[s], changes))


if __name__ == "__main__":
    main()
