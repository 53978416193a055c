"""meshlabserver runs an .mlx that segments, merges, splits and saves a box; the saved PLY's face quality
(the segment ids) is checked, and a filter given a bad segment id must fail with a clear log line."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from meshlab_script import (Checker, box_mesh, read_ply, run_meshlabserver, select_faces, step, test_args,
                            write_mlx, write_ply)

def normal(vertices, f):
    a, b, c = (vertices[i] for i in f)
    e1 = [b[k] - a[k] for k in range(3)]
    e2 = [c[k] - a[k] for k in range(3)]
    n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
    length = sum(x * x for x in n) ** 0.5
    return tuple(round(x / length) for x in n)


def centroid(vertices, f):
    return [sum(vertices[i][k] for i in f) / 3.0 for k in range(3)]


def main():
    args = test_args()
    c = Checker()
    box = os.path.join(args.workdir, "box.ply")
    vertices, faces = box_mesh(12)
    write_ply(box, vertices, faces)

    auto = step("Segment: Auto by Normal Angle", Angle=30, NormalSmoothing=0, MinSegmentFaces=0)

    script = os.path.join(args.workdir, "segment.mlx")
    write_mlx(script, [
        auto,
        select_faces("fq < 2"),
        step("Segment: Merge Selected"),
        select_faces("z0 > 3.99 && z1 > 3.99 && z2 > 3.99"),
        step("Segment: Split by Plane", PlanePoint=(5, 3, 2)),
        select_faces("z0 < 0.01 && z1 < 0.01 && z2 < 0.01 && x0 < 2.01 && x1 < 2.01 && x2 < 2.01"),
        step("Segment: Split by Selection"),
    ])
    out = os.path.join(args.workdir, "segmented.ply")
    code, log, console = run_meshlabserver(args.meshlabserver, args.workdir, [box], script, out, "fq")
    c.check(code == 0 and os.path.exists(out), "meshlabserver ran the segmentation script (exit %d)" % code)
    if not os.path.exists(out):
        print(console[-3000:])
        c.finish()
    print(log)
    c.check("split into 6 segments" in log, "auto segmentation logged 6 segments")
    c.check("2 segments merged into one" in log, "merge logged")

    v, f, fprops, _ = read_ply(out)
    c.check(len(f) == len(faces), "saved mesh keeps all %d faces" % len(faces))
    ids = [int(round(q)) for q in fprops.get("quality", [])]
    c.check(len(ids) == len(f) and all(abs(q - round(q)) < 1e-6 for q in fprops.get("quality", [])),
            "every face has an integer segment id in face quality")
    distinct = sorted(set(ids))
    # 6 sides -> merge 2 -> 5 -> top cut in two -> 6 -> a patch of the bottom leaves -> 7.
    c.check(distinct == list(range(7)), "ids are dense 0..6 (got %s)" % distinct)

    normals_of = {}
    for face, s in zip(f, ids):
        normals_of.setdefault(s, set()).add(normal(v, face))
    spans = sorted(len(n) for n in normals_of.values())
    c.check(spans == [1, 1, 1, 1, 1, 1, 2], "one segment is two merged sides, the others one side each (%s)" % spans)

    top = {}
    for face, s in zip(f, ids):
        cen = centroid(v, face)
        if normal(v, face) == (0, 0, 1):
            top.setdefault(s, []).append(cen[0])
    c.check(len(top) == 2 and all(max(xs) < 5 or min(xs) > 5 for xs in top.values()),
            "the top side is cut by the plane x = 5 into two segments")

    bottom = {}
    for face, s in zip(f, ids):
        if normal(v, face) == (0, 0, -1):
            bottom.setdefault(s, []).append(centroid(v, face)[0])
    patch = [s for s, xs in bottom.items() if max(xs) < 2.01]
    c.check(len(bottom) == 2 and len(patch) == 1 and len(bottom[patch[0]]) == 2 * 12 * 2,
            "the selected patch of the bottom is a segment of its own (%s)" % {k: len(x) for k, x in bottom.items()})

    # Reopened from the PLY, the mesh has its segments back: Select Segment works on it.
    script2 = os.path.join(args.workdir, "reselect.mlx")
    write_mlx(script2, [step("Segment: Select Segment", Segment=6)])
    code, log, console = run_meshlabserver(args.meshlabserver, args.workdir, [out], script2)
    c.check(code == 0 and "segment 6 selected" in log, "a reopened PLY has its segments back")

    # A plane that grazes the top's corner would cut off one face: a sliver is no segment, it stays in its own.
    script4 = os.path.join(args.workdir, "graze.mlx")
    write_mlx(script4, [
        select_faces("z0 > 3.99 && z1 > 3.99 && z2 > 3.99 && x0 < 4.99 && x1 < 4.99 && x2 < 4.99"),
        step("Segment: Split by Plane", PlanePoint=(0.35, 0.35, 4), PlaneNormal=(1, 1, 0)),
    ])
    out4 = os.path.join(args.workdir, "grazed.ply")
    code, log, console = run_meshlabserver(args.meshlabserver, args.workdir, [out], script4, out4, "fq")
    c.check(code == 0 and "cut into 1 pieces; 7 segments before, 7 after" in log,
            "a cut grazing a corner leaves no one-face segment")

    # A bad segment id: the filter fails and says why in the log.
    script3 = os.path.join(args.workdir, "bad.mlx")
    write_mlx(script3, [step("Segment: Select Segment", Segment=99)])
    out3 = os.path.join(args.workdir, "bad.ply")
    code, log, console = run_meshlabserver(args.meshlabserver, args.workdir, [out], script3, out3)
    c.check("there is no segment 99" in log + console, "a bad id is refused with a clear message")
    c.finish()


if __name__ == "__main__":
    main()
