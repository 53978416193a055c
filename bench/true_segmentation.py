"""Writes a scan segmented by its ground truth: face quality = the true analytic surface of each face.

Inputs: the scan PLY (simulate_ct_scan), its truth file (one B-rep face index per scan face, in face order)
and the reference JSON (make_bracket). Each face's segment id is the `surface` of its B-rep face in the
reference JSON (faces on one analytic surface share it); -1 where the truth has no face.
Output: a binary PLY of the same vertices and faces (vertex coordinates copied bit for bit) with a double
face quality, as `bench_segment_scan SCAN.ply --labels OUT.ply` reads it: fitting and snapping the true
segments gives the ceiling of any segment-fit-snap pipeline on that scan (bench/bracket/README.md).
With --types TYPES.txt it also writes "SEGMENT_ID TYPE" per true surface (`bench_segment_scan --types`:
fit each with its true type); with --primitives PRIMS.txt, "SEGMENT_ID TYPE ORIGIN(3) AXIS(3) RADIUS MINOR_RADIUS
HALF_ANGLE" per true surface, in common/base/primitive.h's conventions (`bench_segment_scan --primitives`: snap
onto the true primitives, the ideal that the fits are measured against).
Standard library only.
Usage: true_segmentation.py SCAN.ply TRUTH.txt REFERENCE.json OUT.ply [--types TYPES.txt] [--primitives PRIMS.txt]
"""
import json
import os
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "script"))
from meshlab_script import read_ply  # noqa: E402
from score_segmentation import read_truth  # noqa: E402


def true_surfaces(truth_face, reference):
    """Segment id per face: the reference `surface` of its B-rep face, -1 for an unknown face."""
    surface_of = {f["index"]: f.get("surface", f["index"]) for f in reference}
    return [surface_of.get(t, -1) for t in truth_face]


def write_labelled_ply(path, vertices, faces, quality):
    """Binary little-endian PLY: double vertices, triangle faces, a double face quality."""
    header = ("ply\nformat binary_little_endian 1.0\ncomment true segmentation (face quality = true surface)\n"
              "element vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
              "element face %d\nproperty list uchar int vertex_indices\nproperty double quality\nend_header\n"
              % (len(vertices), len(faces)))
    with open(path, "wb") as out:
        out.write(header.encode("ascii"))
        out.write(b"".join(struct.pack("<3d", *v) for v in vertices))
        face = struct.Struct("<B3id")
        out.write(b"".join(face.pack(3, f[0], f[1], f[2], float(q)) for f, q in zip(faces, quality)))


def primitive_line(face):
    """The reference face's exact primitive as a --primitives line, or None for a free-form face."""
    t = face["type"]
    if t == "plane":
        origin, axis, sizes = face["point"], face["normal"], (0, 0, 0)
    elif t == "sphere":
        origin, axis, sizes = face["centre"], (0, 0, 1), (face["radius"], 0, 0)
    elif t == "cylinder":
        origin, axis, sizes = face["point"], face["axis"], (face["radius"], 0, 0)
    elif t == "cone":
        origin, axis, sizes = face["apex"], face["axis"], (0, 0, face["half_angle"])
    elif t == "torus":
        origin, axis, sizes = face["centre"], face["axis"], (face["major_radius"], face["minor_radius"], 0)
    else:
        return None
    return "%d %s %s\n" % (face["index"], t, " ".join("%.17g" % x for x in (*origin, *axis, *sizes)))


def main():
    args = sys.argv[1:]
    options = {"--types": None, "--primitives": None}
    while len(args) > 4 and len(args) % 2 == 0 and args[-2] in options:
        options[args[-2]] = args[-1]
        args = args[:-2]
    if len(args) != 4:
        raise SystemExit(__doc__)
    types_txt, primitives_txt = options["--types"], options["--primitives"]
    scan_ply, truth_txt, reference_json, out_ply = args
    with open(reference_json) as f:
        reference = json.load(f)["faces"]
    vertices, faces, _, _ = read_ply(scan_ply)
    if any(len(f) != 3 for f in faces):
        raise SystemExit("%s: not a triangle mesh" % scan_ply)
    truth_face = read_truth(truth_txt)
    if len(truth_face) != len(faces):
        raise SystemExit("truth has %d faces, scan %d" % (len(truth_face), len(faces)))
    quality = true_surfaces(truth_face, reference)
    write_labelled_ply(out_ply, vertices, faces, quality)
    if types_txt:
        with open(types_txt, "w") as out:
            out.write("# true primitive type of each segment of %s\n" % os.path.basename(out_ply))
            for f in reference:
                if f["index"] == f.get("surface", f["index"]):
                    out.write("%d %s\n" % (f["index"], f["type"]))
    if primitives_txt:
        with open(primitives_txt, "w") as out:
            out.write("# true primitive of each segment of %s: id type origin axis radius minor half_angle\n"
                      % os.path.basename(out_ply))
            for f in reference:
                line = primitive_line(f) if f["index"] == f.get("surface", f["index"]) else None
                if line:
                    out.write(line)
    print("%s: %d faces, %d true surfaces, %d faces without one" % (
        out_ply, len(faces), len(set(q for q in quality if q >= 0)), quality.count(-1)))


if __name__ == "__main__":
    main()
