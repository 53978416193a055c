"""The fillets that Segment: Auto by Primitive Fit carves on the bundled CT scan stay blends for Fit All after an
edit of another segment (Split by Plane, which renumbers the ids): each blend Fit All lists must be a carved
segment, face for face, and every carved one listed. (A record dropped when its own segments change:
SegmentBlendsAttribute.ReadBackWhileItsSegmentsAreAsTheyWere.)"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from meshlab_script import Checker, read_ply, run_meshlabserver, step, test_args, write_mlx

SCAN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bench", "data", "bracket_scan.ply")
SEGMENT = step("Segment: Auto by Primitive Fit")
FIT_ALL = step("Primitive: Fit All Segments", Snap=False, SharpEdges=False)
CARVED = re.compile(r"segment (\d+) between (\d+) and (\d+)")
FITTED_BLEND = re.compile(r"segment (\d+): (?:fillet|chamfer) of segments (\d+) and (\d+)")


def split_by_plane(segment, point):
    return step("Segment: Split by Plane", Segment=segment, PlanePoint=point)


def faces_of(path):
    """Per segment id the set of its faces, from the face quality of a saved PLY."""
    _, _, props, _ = read_ply(path)
    out = {}
    for f, q in enumerate(props["quality"]):
        out.setdefault(int(round(q)), set()).add(f)
    return out


def run(args, c, name, filters):
    script = os.path.join(args.workdir, name + ".mlx")
    out = os.path.join(args.workdir, name + ".ply")
    if os.path.exists(out):
        os.remove(out)
    write_mlx(script, filters)
    code, log, console = run_meshlabserver(args.meshlabserver, args.workdir, [SCAN], script, out, "fq")
    c.check(code == 0 and os.path.exists(out), "%s ran" % name)
    if not os.path.exists(out):
        print(log, console[-3000:])
        c.finish()
    return log, faces_of(out)


def centroid(path, faces):
    v, f, _, _ = read_ply(path)
    points = [v[i] for face in faces for i in f[face]]
    return tuple(sum(p[k] for p in points) / len(points) for k in range(3))


def main():
    args = test_args()
    c = Checker()
    log, segments = run(args, c, "segmented", [SEGMENT])
    carved = [tuple(int(x) for x in m) for m in CARVED.findall(log.split("carved from the planes")[-1].split("\n")[0])]
    c.check(len(carved) >= 1, "the segmentation carves fillets or chamfers on the scan (%s)" % carved)
    if not carved:
        c.finish()
    carved_faces = [frozenset(segments[s]) for s, _, _ in carved]
    involved = {k for blend in carved for k in blend}
    # The largest segment that is no blend and no blend's plane, cut through its middle.
    other = max((s for s in segments if s not in involved), key=lambda s: len(segments[s]))
    segmented = os.path.join(args.workdir, "segmented.ply")

    log, after = run(args, c, "split_elsewhere",
                     [SEGMENT, split_by_plane(other, centroid(segmented, segments[other])), FIT_ALL])
    c.check("Split by Plane: 1 segment(s) cut" in log, "Split by Plane cut segment %d" % other)
    fitted = [frozenset(after[int(s)]) for s, _, _ in FITTED_BLEND.findall(log)]
    print(log)
    c.check(sorted(map(len, fitted)) == sorted(map(len, carved_faces)) and set(fitted) == set(carved_faces),
            "after a split elsewhere Fit All makes every carved segment, and only those, a blend (%d listed, %d "
            "carved)" % (len(fitted), len(carved_faces)))

    c.finish()


if __name__ == "__main__":
    main()
