"""Helpers for the meshlabserver script tests: PLY reading/writing, .mlx writing, a virtual display, running
meshlabserver, a welded box to run the filters on.

Standard library only. meshlabserver 2020.09 asserts unless a script lists every parameter of a filter,
so scripts are written from complete parameter lists: step() writes them from FILTER_PARAMETERS.
"""
import argparse
import contextlib
import os
import select
import struct
import subprocess
import time
import xml.sax.saxutils as saxutils

PLY_TYPES = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
    "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


def test_args():
    parser = argparse.ArgumentParser()
    parser.add_argument("--meshlabserver", required=True)
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    return args


def box_mesh(n=6, size=(10.0, 6.0, 4.0), offset=(0.0, 0.0, 0.0)):
    """A closed box [0, size] moved by offset, each side an n x n grid, vertices welded, outward faces.
    Returns (vertices, faces)."""
    vertices, index, faces = [], {}, []

    def vid(p):
        key = tuple(round(c, 6) for c in p)
        if key not in index:
            index[key] = len(vertices)
            vertices.append([p[k] + offset[k] for k in range(3)])
        return index[key]

    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for side in (0, 1):
            def point(i, j):
                p = [0.0, 0.0, 0.0]
                p[axis] = size[axis] * side
                p[u] = size[u] * i / n
                p[v] = size[v] * j / n
                return vid(p)
            for i in range(n):
                for j in range(n):
                    a, b, c, d = point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)
                    # (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis.
                    faces += [[a, b, c], [a, c, d]] if side == 1 else [[a, c, b], [a, d, c]]
    return vertices, faces


def write_ply(path, vertices, faces, face_quality=None):
    """ASCII PLY with float vertices and triangle faces (and per-face quality if given)."""
    with open(path, "w") as out:
        out.write("ply\nformat ascii 1.0\n")
        out.write("element vertex %d\nproperty float x\nproperty float y\nproperty float z\n" % len(vertices))
        out.write("element face %d\nproperty list uchar int vertex_indices\n" % len(faces))
        if face_quality is not None:
            out.write("property float quality\n")
        out.write("end_header\n")
        for v in vertices:
            out.write("%.9g %.9g %.9g\n" % tuple(v))
        for i, f in enumerate(faces):
            line = "3 %d %d %d" % tuple(f)
            if face_quality is not None:
                line += " %.9g" % face_quality[i]
            out.write(line + "\n")


def read_ply(path):
    """Reads an ASCII or binary little-endian PLY. Returns (vertices, faces, face_props, vertex_props):
    vertices as [x, y, z] lists, faces as index lists, and dicts from property name to list of values."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii").splitlines()
    fmt = None
    elements = []
    for line in header:
        words = line.split()
        if not words:
            continue
        if words[0] == "format":
            fmt = words[1]
        elif words[0] == "element":
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property":
            if words[1] == "list":
                elements[-1][2].append((words[4], "list", words[2], words[3]))
            else:
                elements[-1][2].append((words[2], words[1], None, None))
    body = data[end:]
    values = {}
    if fmt == "ascii":
        tokens = body.split()
        pos = 0
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = {}
                for pname, ptype, ctype, itype in props:
                    if ptype == "list":
                        n = int(tokens[pos]); pos += 1
                        row[pname] = [int(t) for t in tokens[pos:pos + n]]; pos += n
                    else:
                        t = tokens[pos]; pos += 1
                        row[pname] = float(t) if PLY_TYPES[ptype] in "fd" else int(t)
                rows.append(row)
            values[name] = rows
    elif fmt == "binary_little_endian":
        pos = 0
        for name, count, props in elements:
            rows = []
            for _ in range(count):
                row = {}
                for pname, ptype, ctype, itype in props:
                    if ptype == "list":
                        c = PLY_TYPES[ctype]
                        (n,) = struct.unpack_from("<" + c, body, pos); pos += struct.calcsize(c)
                        i = PLY_TYPES[itype]
                        row[pname] = list(struct.unpack_from("<%d%s" % (n, i), body, pos))
                        pos += n * struct.calcsize(i)
                    else:
                        c = PLY_TYPES[ptype]
                        (row[pname],) = struct.unpack_from("<" + c, body, pos); pos += struct.calcsize(c)
                rows.append(row)
            values[name] = rows
    else:
        raise ValueError("unsupported PLY format %s" % fmt)
    verts = values.get("vertex", [])
    faces = values.get("face", [])
    vertices = [[v["x"], v["y"], v["z"]] for v in verts]
    index_key = "vertex_indices" if faces and "vertex_indices" in faces[0] else "vertex_index"
    face_list = [f[index_key] for f in faces]
    face_props = {}
    for f in faces:
        for k, v in f.items():
            if k != index_key:
                face_props.setdefault(k, []).append(v)
    vertex_props = {}
    for v in verts:
        for k, val in v.items():
            if k not in ("x", "y", "z"):
                vertex_props.setdefault(k, []).append(val)
    return vertices, face_list, face_props, vertex_props


def param(name, value, kind, enum_values=None):
    """One <Param> line. kind: RichInt, RichFloat, RichBool, RichString, RichEnum (give enum_values, as
    meshlabserver reads an enum only with its list of values), RichMesh, RichPoint3f."""
    q = saxutils.quoteattr
    if kind == "RichEnum":
        values = "".join(' enum_val%d=%s' % (i, q(v)) for i, v in enumerate(enum_values))
        return '  <Param type="RichEnum" name=%s value="%d" enum_cardinality="%d"%s/>\n' % (
            q(name), value, len(enum_values), values)
    if kind == "RichPoint3f":
        x, y, z = value
        return '  <Param type="RichPoint3f" name=%s x="%.9g" y="%.9g" z="%.9g"/>\n' % (q(name), x, y, z)
    if kind == "RichBool":
        value = "true" if value else "false"
    return '  <Param type=%s name=%s value=%s/>\n' % (q(kind), q(name), q(str(value)))


TYPES = ["Auto", "Plane", "Sphere", "Cylinder", "Cone", "Torus"]
METHODS = ["Refined starts", "Direct (paper)", "Direct, refined"]
ENUM_VALUES = {"Type": TYPES, "Method": METHODS}

# Every parameter of our filters, in the filter's order, with its default (filter_segment.cpp,
# filter_primitive_fit.cpp, filter_measure_accuracy.cpp): (name, default, Rich type). None: the default depends on
# the document (a point of the mesh's box, a layer), so a script must give it. tests/layout/
# check_script_parameters.py checks the table against the plugins' own lists.
FILTER_PARAMETERS = {
    "Segment: Auto by Normal Angle": [("Angle", 20.0, "RichFloat"), ("NormalSmoothing", -1, "RichInt"),
                                      ("MinSegmentFaces", -1, "RichInt")],
    "Segment: Auto by Primitive Fit": [("Tolerance", 0.0, "RichFloat"), ("NormalAngle", 30.0, "RichFloat"),
                                       ("SeedPatchFaces", 60, "RichInt"), ("NormalSmoothing", 10, "RichInt"),
                                       ("CarveBlends", True, "RichBool")],
    "Segment: Merge Selected": [],
    "Segment: Split by Plane": [("Segment", -1, "RichInt"), ("PlanePoint", None, "RichPoint3f"),
                                ("PlaneNormal", (1.0, 0.0, 0.0), "RichPoint3f")],
    "Segment: Split by Selection": [],
    "Segment: Select Segment": [("Segment", 0, "RichInt")],
    "Primitive: Fit Segment": [("Segment", -1, "RichInt"), ("Type", 0, "RichEnum"), ("Method", 0, "RichEnum")],
    "Primitive: Snap Segment": [("Segment", -1, "RichInt"), ("Type", 0, "RichEnum"), ("Method", 0, "RichEnum"),
                                ("Radius", 0.0, "RichFloat"), ("Angle", 0.0, "RichFloat"),
                                ("MajorRadius", 0.0, "RichFloat"), ("MinorRadius", 0.0, "RichFloat"),
                                ("SharpEdges", True, "RichBool")],
    "Primitive: Fit All Segments": [("Tolerance", 0.0, "RichFloat"), ("Relations", True, "RichBool"),
                                    ("RelationAngle", 10.0, "RichFloat"), ("RelationDistance", 0.0, "RichFloat"),
                                    ("RelationCost", 1.0, "RichFloat"), ("Snap", True, "RichBool"),
                                    ("Export", "", "RichString"), ("SharpEdges", True, "RichBool")],
    "Measure: Accuracy Against Reference": [("MeasuredMesh", None, "RichMesh"), ("ReferenceMesh", None, "RichMesh"),
                                            ("Samples", 1000000, "RichInt"), ("Tolerance", 0.42, "RichFloat"),
                                            ("Seed", 0, "RichInt"), ("DeviationMap", False, "RichBool")],
}


def step(name, **values):
    """(name, [param lines]) for write_mlx: every parameter of our filter `name`, at its default unless given by
    keyword. A parameter without a fixed default must be given; one the filter does not have raises."""
    table = FILTER_PARAMETERS[name]
    unknown = set(values) - {p for p, _, _ in table}
    if unknown:
        raise KeyError("%s has no parameter %s" % (name, ", ".join(sorted(unknown))))
    lines = []
    for p, default, kind in table:
        value = values.get(p, default)
        if value is None:
            raise KeyError("%s needs %s in a script" % (name, p))
        lines.append(param(p, value, kind, ENUM_VALUES.get(p)))
    return name, lines


def select_faces(expression):
    """MeshLab's Conditional Face Selection of the faces where `expression` holds (e.g. "fq < 2")."""
    return "Conditional Face Selection", [param("condSelect", expression, "RichString")]


def write_mlx(path, filters):
    """filters: list of (filter name, [param(...) strings])."""
    with open(path, "w") as out:
        out.write("<!DOCTYPE FilterScript>\n<FilterScript>\n")
        for name, params in filters:
            out.write(" <filter name=%s>\n" % saxutils.quoteattr(name))
            for p in params:
                out.write(" " + p)
            out.write(" </filter>\n")
        out.write("</FilterScript>\n")


def start_virtual_display(screen="1024x768x24", timeout=60):
    """An Xvfb server on a display number it picks itself; returns (process, ':N') once it accepts clients.

    Xvfb -displayfd writes the number when it is ready, and a server of our own needs no authorization file.
    xvfb-run -a, used here before, took one file per process (named by the pid): the malformed-mesh test runs
    meshes on two threads, and when two xvfb-run calls used that file at once a meshlabserver could abort (exit 134)
    before writing its log. That failed a CI run; four loops of xvfb-run sharing one file aborted 2 runs of 80. It
    could also pick a number another server was about to take."""
    read_end, write_end = os.pipe()
    proc = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0", screen, "-nolisten", "tcp"],
                            pass_fds=(write_end,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_end)
    number = b""
    deadline = time.monotonic() + timeout
    while not number.endswith(b"\n") and time.monotonic() < deadline and proc.poll() is None:
        if select.select([read_end], [], [], 1.0)[0]:
            chunk = os.read(read_end, 16)
            if not chunk:
                break
            number += chunk
    os.close(read_end)
    if not number.strip().isdigit():
        stop_virtual_display(proc)
        raise RuntimeError("could not start Xvfb")
    return proc, ":" + number.strip().decode()


def stop_virtual_display(proc):
    proc.terminate()
    try:
        proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


@contextlib.contextmanager
def virtual_display(screen="1024x768x24"):
    """The environment of a process that runs on an Xvfb of its own (start_virtual_display), for a with block."""
    proc, display = start_virtual_display(screen)
    try:
        env = dict(os.environ, DISPLAY=display)
        env.pop("WAYLAND_DISPLAY", None)
        yield env
    finally:
        stop_virtual_display(proc)


def run_meshlabserver(meshlabserver, workdir, inputs, script, output=None, mask="fq", extra=None):
    """Runs meshlabserver on a virtual display of its own. Returns (exit code, log text, console text)."""
    log = os.path.join(workdir, os.path.basename(script) + ".log")
    if os.path.exists(log):
        os.remove(log)
    cmd = [meshlabserver, "-l", log]
    for i in inputs:
        cmd += ["-i", i]
    cmd += ["-s", script]
    if output:
        cmd += ["-o", output]
        if mask:
            cmd += ["-m"] + mask.split()
    cmd += extra or []
    with virtual_display() as env:
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=900, env=env)
    text = open(log, errors="replace").read() if os.path.exists(log) else ""
    return proc.returncode, text, proc.stdout.decode(errors="replace")


class Checker:
    """Counts checks and prints the 'N passed, N failed' closing line."""

    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, condition, what):
        if condition:
            self.passed += 1
            print("ok:", what)
        else:
            self.failed += 1
            print("FAILED:", what)

    def finish(self):
        print("%d passed, %d failed" % (self.passed, self.failed))
        raise SystemExit(1 if self.failed else 0)
