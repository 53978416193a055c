#!/usr/bin/env python3
"""Writes the corpus of malformed meshes (ASCII PLY) that every filter must survive: the defects of real
reverse-engineering scans. Made here, never downloaded. Usage: make_malformed_meshes.py OUTDIR
(or import and call make_all(outdir) -> {name: path}).

Each mesh but the trivial ones is built on a welded box (a grid per side, so that segmentation and fits
have work to do) plus a cylinder shell, then damaged in one way.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from meshlab_script import box_mesh, write_ply  # noqa: E402


def cylinder(radius=2.0, height=4.0, around=24, along=6, centre=(20.0, 0.0, 0.0)):
    """An open cylinder shell around the z axis through centre, outward faces."""
    vertices, faces = [], []
    for j in range(along + 1):
        for i in range(around):
            t = 2 * math.pi * i / around
            vertices.append([centre[0] + radius * math.cos(t), centre[1] + radius * math.sin(t),
                             centre[2] + height * j / along])
    for j in range(along):
        for i in range(around):
            a, b = j * around + i, j * around + (i + 1) % around
            c, d = b + around, a + around
            faces += [[a, b, c], [a, c, d]]
    return vertices, faces


def combine(*meshes):
    vertices, faces = [], []
    for v, f in meshes:
        base = len(vertices)
        vertices += [list(p) for p in v]
        faces += [[base + i for i in face] for face in f]
    return vertices, faces


def make_all(outdir):
    os.makedirs(outdir, exist_ok=True)
    meshes = {}
    base_v, base_f = combine(box_mesh(), cylinder())

    meshes["empty"] = ([], [])
    meshes["one_triangle"] = ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    meshes["point_cloud"] = (base_v, [])

    v = [list(p) for p in base_v]
    v[5] = [float("nan")] * 3
    v[40][1] = float("nan")
    meshes["nan_coordinates"] = (v, base_f)

    v = [list(p) for p in base_v]
    v[7][0] = float("inf")
    v[60][2] = float("-inf")
    meshes["inf_coordinates"] = (v, base_f)

    # Zero-area faces: collapsed (repeated vertex) and collinear triangles among the good ones.
    f = [list(x) for x in base_f]
    for k in range(0, len(f), 9):
        f[k] = [f[k][0], f[k][0], f[k][1]]
    v = [list(p) for p in base_v]
    n0 = len(v)
    v += [[0, 0, -5], [1, 0, -5], [2, 0, -5]]
    f += [[n0, n0 + 1, n0 + 2]]
    meshes["zero_area_faces"] = (v, f)

    meshes["duplicate_faces"] = (base_v, base_f + base_f[::3] + [list(reversed(x)) for x in base_f[1::7]])

    # Non-manifold edge: two extra fins on an edge of the box top.
    v = [list(p) for p in base_v]
    e0, e1 = base_f[0][0], base_f[0][1]
    n0 = len(v)
    v += [[5, 3, 9], [5, -3, 9]]
    meshes["nonmanifold_edge"] = (v, base_f + [[e0, e1, n0], [e1, e0, n0 + 1]])

    # Non-manifold vertex: a second box touching the first at one corner (shared vertex).
    bv, bf = box_mesh(n=3, size=(3.0, 3.0, 3.0), offset=(-3.0, -3.0, -3.0))
    v = [list(p) for p in base_v]
    n0 = len(v)
    corner = min(range(len(bv)), key=lambda i: sum((bv[i][k] - 0.0) ** 2 for k in range(3)))
    remap = {}
    for i, p in enumerate(bv):
        if i == corner:
            remap[i] = min(range(len(base_v)), key=lambda j: sum(base_v[j][k] ** 2 for k in range(3)))
        else:
            remap[i] = len(v)
            v.append(list(p))
    meshes["nonmanifold_vertex"] = (v, base_f + [[remap[i] for i in x] for x in bf])

    meshes["inconsistent_orientation"] = (base_v, [list(reversed(x)) if k % 3 == 0 else x
                                                   for k, x in enumerate(base_f)])
    meshes["flipped_normals"] = (base_v, [list(reversed(x)) for x in base_f])

    # Holes, isolated vertices and several shells.
    v = [list(p) for p in base_v] + [[50, 50, 50], [-40, 0, 3], [0, -70, 0]]
    f = [x for k, x in enumerate(base_f) if k % 11 not in (0, 1)]
    sv, sf = box_mesh(n=2, size=(1.0, 1.0, 1.0), offset=(30.0, 30.0, 0.0))
    meshes["holes_isolated_shells"] = combine((v, f), (sv, sf))

    # 10^6-scale coordinates: far from the origin and huge.
    meshes["huge_coordinates"] = ([[1e6 + 1e5 * c for c in p] for p in base_v], base_f)
    meshes["tiny_coordinates"] = ([[1e-7 * c for c in p] for p in base_v], base_f)

    # Every defect at once.
    v = [list(p) for p in base_v]
    f = [list(reversed(x)) if k % 4 == 0 else list(x) for k, x in enumerate(base_f) if k % 13]
    f += f[::10]
    f += [[f[0][0], f[0][0], f[0][1]]]
    v += [[99, 99, 99]]
    meshes["everything"] = (v, f)

    paths = {}
    for name, (v, f) in meshes.items():
        path = os.path.join(outdir, name + ".ply")
        write_ply(path, v, f)
        paths[name] = path
    return paths


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "malformed"
    for name, path in make_all(out).items():
        print(name, path)
