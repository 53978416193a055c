"""GUI test of the Primitive Edit tool across a layer change: MeshLab under Xvfb with our plugins, driven by
xdotool.

A box already segmented into its 6 faces (segment ids in the face quality) is opened and the tool started
(Ctrl+Shift+P); the panel then shows no status and the stored segments are drawn in colour. Normal-angle segmentation is chosen and S pressed. A hexagonal
prism is imported while the tool is active (File > Import Mesh, Ctrl+I, typing its path in the dialog): the
tool must move to the new current layer, visibly: the log says so and names the prism, the panel stays, and S
segments the prism (its 8 faces) with the segments drawn in colour. Ctrl+Shift+P then turns the tool off (S
does nothing more) and the next one starts it again on the prism, with no status left from before in the
panel: its part below the segment count is the same, pixel for pixel, as when the tool first started on the
box. Last, a point cloud is imported while the tool is active: the tool cannot edit it, so it must end,
visibly: the log says why, and MeshLab's button is off (the next Ctrl+Shift+P tries to start the tool again,
which the log shows, instead of ending it). Screenshots of every step are kept in the work directory.

Usage: python3 test_edit_primitive_layers.py --meshlab PATH --workdir DIR [--batch PATH]
(--batch is accepted for the test runner and not used.) Needs Xvfb, xdotool and ImageMagick's import. Prints
"N passed, N failed"; exits non-zero on failure.
"""
import argparse
import math
import os
import sys
import time

import gui_session
from gui_session import Session, check, mesh_box, panel_right

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "script"))
from meshlab_script import write_ply  # noqa: E402

DEADLINE = time.time() + 150
# The panel below its segment count (from the Merge button down: primitive, Undo, status, help); above it the
# method and the count differ between the two shots compared.
PANEL_LOWER_TOP, PANEL_LOWER_BOTTOM = 300, 1000


class Mesh:
    """Vertices merged by position, triangles, and per face the flat side it lies on."""

    def __init__(self):
        self.vertices, self.faces, self.side, self.index = [], [], [], {}

    def vertex(self, p):
        key = tuple(round(c, 6) for c in p)
        if key not in self.index:
            self.index[key] = len(self.vertices)
            self.vertices.append(list(p))
        return self.index[key]

    def quad(self, corners, n, side):
        """A planar quad (corners in order) as n x n cells of two triangles."""
        a, b, c, d = corners

        def at(u, v):
            return self.vertex([a[k] + (b[k] - a[k]) * u + (d[k] - a[k]) * v + (c[k] - b[k] - d[k] + a[k]) * u * v
                                for k in range(3)])
        for i in range(n):
            for j in range(n):
                p = [at(i / n, j / n), at((i + 1) / n, j / n), at((i + 1) / n, (j + 1) / n), at(i / n, (j + 1) / n)]
                self.faces += [[p[0], p[1], p[2]], [p[0], p[2], p[3]]]
                self.side += [side, side]

    def triangle(self, a, b, c, n, side):
        """A triangle as n x n smaller ones."""
        def at(i, j):
            return self.vertex([a[k] + (b[k] - a[k]) * i / n + (c[k] - a[k]) * j / n for k in range(3)])
        for i in range(n):
            for j in range(n - i):
                self.faces.append([at(i, j), at(i + 1, j), at(i, j + 1)])
                self.side.append(side)
                if i + j < n - 1:
                    self.faces.append([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)])
                    self.side.append(side)


def make_box(path, n=4):
    """Cube of side 2 at the origin, each face n x n cells; written with its 6 faces as segments."""
    m = Mesh()
    side = 0
    for axis in range(3):
        for sign in (-1, 1):
            u, v = [a for a in range(3) if a != axis]

            def corner(cu, cv):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = sign, cu, cv
                return p
            corners = [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)]
            outward = sign * (-1 if axis == 1 else 1) > 0  # the corners turn about +x, -y and +z
            m.quad(corners if outward else corners[::-1], n, side)
            side += 1
    write_ply(path, m.vertices, m.faces, face_quality=m.side)
    return len(m.faces)


def make_prism(path, x=3.5, n=4):
    """Hexagonal prism (circumradius 1, height 2) around an axis along z through (x, 0): 8 flat faces, each
    large enough (more than 30 triangles) to be a segment of its own."""
    m = Mesh()
    ring = [[x + math.cos(math.pi * k / 3), math.sin(math.pi * k / 3)] for k in range(6)]
    for k in range(6):
        p, q = ring[k], ring[(k + 1) % 6]
        m.quad([[p[0], p[1], -1], [q[0], q[1], -1], [q[0], q[1], 1], [p[0], p[1], 1]], n, k)
    for z, side in ((-1, 6), (1, 7)):
        for k in range(6):
            p, q = ring[k], ring[(k + 1) % 6]
            a, b = [p[0], p[1], z], [q[0], q[1], z]
            m.triangle([x, 0, z], a, b, n, side) if z > 0 else m.triangle([x, 0, z], b, a, n, side)
    write_ply(path, m.vertices, m.faces)
    return len(m.faces)


def panel_lower(shot):
    """The panel's pixels below its segment count (the panel is docked on the left), one bytes object per row."""
    w, h, data = shot
    pixel = 3 * (len(data) // (w * h * 3))  # import writes 8 or 16 bit samples
    right = min(panel_right(shot), w)
    return [data[pixel * y * w:pixel * (y * w + right)] for y in range(PANEL_LOWER_TOP, min(PANEL_LOWER_BOTTOM, h))]


def colourful_fraction(shot, x0, y0, x1, y1):
    """The fraction of pixels (every 4th row and column) in a box whose channels differ by more than 60: segment
    colours, not the grey shading of an uncoloured mesh."""
    w, h, data = shot
    size = len(data) // (w * h * 3)
    samples = [(x, y) for y in range(y0, y1, 4) for x in range(x0, x1, 4)]
    colourful = 0
    for x, y in samples:
        i = size * 3 * (y * w + x)
        rgb = (data[i], data[i + size], data[i + 2 * size])
        colourful += max(rgb) - min(rgb) > 60
    return colourful / max(1, len(samples))


def differing_rows(a, b):
    """How many rows of two crops differ (rows one has and the other lacks count too)."""
    return sum(1 for x, y in zip(a, b) if x != y) + abs(len(a) - len(b))


def tool_lines(path):
    with open(path, errors="replace") as f:
        return [l.rstrip("\n") for l in f if l.startswith("LOG:")]


def find(lines, text, start=0):
    return next((i for i in range(start, len(lines)) if text in lines[i]), None)



def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--meshlab", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--batch", help="not used")
    args = parser.parse_args()
    if not gui_session.prepare(args.workdir):
        return 1
    box = os.path.join(args.workdir, "box.ply")
    prism = os.path.join(args.workdir, "prism.ply")
    box_faces = make_box(box)
    prism_faces = make_prism(prism)
    points = os.path.join(args.workdir, "points.ply")
    write_ply(points, [[0.3 * i, 0.2 * (i % 7), 0.1 * (i % 5)] for i in range(50)], [])
    log = os.path.join(args.workdir, "meshlab.log")

    s = Session(args.meshlab, args.workdir)
    shots = {}
    with s.running():
        s.start(box)
        s.toggle_tool(pause=1.5)
        shots["fresh"] = s.shot("tool_on_box")
        s.key("alt+m", "Down", pause=1.0)
        s.key("s", pause=2.0)
        s.shot("box_segmented")
        s.key("ctrl+i", pause=2.0)
        s.shot("import_dialog")
        s.xdo("type", "--delay", "30", prism)
        time.sleep(0.5)
        s.key("Return", pause=4.0, focus=False)
        s.restore_window(pause=1.5)
        shots["imported"] = s.shot("prism_imported")
        s.key("s", pause=2.0)
        shots["segmented"] = s.shot("prism_segmented")
        s.key("ctrl+shift+p", pause=2.0)
        s.shot("tool_off")
        s.key("s", pause=2.0)
        s.toggle_tool(pause=1.5)
        shots["reopened"] = s.shot("tool_reopened")
        s.key("ctrl+i", pause=2.0)
        s.xdo("type", "--delay", "30", points)
        time.sleep(0.5)
        s.key("Return", pause=4.0, focus=False)
        s.shot("points_imported")
        s.key("s", pause=1.0)
        s.key("ctrl+shift+p", pause=2.0)
        s.shot("points_tool_pressed")
        if time.time() > DEADLINE:
            check(False, "finished within the time limit")

    lines = tool_lines(log)
    # Before the import: the box, with its stored segments, then segmented again by normal angle.
    at = find(lines, "Primitive Edit: editing box.ply (%d faces): 6 segments" % box_faces)
    check(at is not None, "log: the tool starts on the box with its 6 stored segments")
    at = find(lines, "automatic segmentation: 6 segments at", at or 0)
    check(at is not None, "log: S segments the box into 6")
    opened = find(lines, "Opened mesh %s" % prism, at or 0)
    check(opened is not None, "log: MeshLab opened the prism")
    to_points = find(lines, "the current layer is now points.ply")
    after_import = lines[(at or 0) + 1:to_points]
    check(not any(l.startswith("LOG: 1 ") and "Primitive Edit" in l for l in after_import),
          "log: no warning from the tool after importing the prism (%s)"
          % [l for l in after_import if l.startswith("LOG: 1 ")])
    moved = find(lines, "Primitive Edit: the current layer is now prism.ply; the tool moves to it.", at or 0)
    check(moved is not None, "log: the tool says it moves to the imported layer")
    editing = find(lines, "Primitive Edit: editing prism.ply (%d faces): no segments yet." % prism_faces,
                   moved or 0)
    started = [i for i, l in enumerate(lines) if "Started Mode Primitive Edit" in l]
    # A start by Ctrl+Shift+P logs its line just before MeshLab's "Started Mode"; the move to the layer does not.
    check(editing is not None and editing + 1 not in started,
          "log: the tool edits the imported prism (%d faces) with no Ctrl+Shift+P" % prism_faces)
    segmented = find(lines, "automatic segmentation: 8 segments at", editing or 0)
    check(segmented is not None and (len(started) < 2 or segmented < started[1]),
          "log: S after the import segments the prism into its 8 faces")
    check(len(started) == 2, "log: MeshLab started the tool twice, at first and on the last Ctrl+Shift+P (%d)"
          % len(started))
    if segmented is not None and len(started) == 2:
        check(find(lines, "Primitive Edit: closed; its 1 undo step(s) are gone", segmented) is not None and
              find(lines, "Primitive Edit: closed;", segmented) < started[1],
              "log: the first Ctrl+Shift+P after the import closes the tool (its undo step on the prism is gone)")
        check(sum(1 for l in lines[segmented + 1:started[1]] if "automatic segmentation" in l) == 0,
              "log: S after Ctrl+Shift+P does nothing: the first Ctrl+Shift+P after the import turned the tool off")
        check(find(lines, "Primitive Edit: editing prism.ply (%d faces): 8 segments." % prism_faces, started[1] - 1)
              is not None, "log: the next Ctrl+Shift+P starts the tool on the prism again, its 8 segments kept")

    # The point cloud: the tool ends, and says why; MeshLab's button is off, so the next Ctrl+Shift+P starts
    # the tool, which refuses the point cloud again.
    moved = find(lines, "Primitive Edit: the current layer is now points.ply; the tool moves to it.")
    closed = find(lines, "Primitive Edit: closed, the current layer cannot be edited.", moved or 0)
    check(moved is not None and find(lines, "cannot edit points.ply", moved) is not None and closed is not None,
          "log: importing a point cloud ends the tool, saying why")
    refused = [i for i, l in enumerate(lines) if "cannot edit points.ply" in l]
    check(closed is not None and len(refused) == 2 and refused[1] > closed,
          "log: the next Ctrl+Shift+P starts the tool again (it refuses the point cloud again): its button was off")
    check(moved is not None and not any("automatic segmentation" in l for l in lines[moved:]),
          "log: S does nothing once the tool has ended")

    if "fresh" in shots:
        # The box fills the view's middle: its stored segments must be drawn as soon as the tool starts.
        fraction = colourful_fraction(shots["fresh"], 400, 300, 800, 700)
        check(fraction > 0.5, "the box's stored segments are drawn in colour when the tool starts (%.0f%% of the "
              "view's middle)" % (100 * fraction))
    if all(k in shots for k in ("fresh", "imported", "segmented", "reopened")):
        edge = panel_right(shots["fresh"])
        check(100 < edge < 600 and panel_right(shots["imported"]) == edge,
              "the panel stays shown after the import (edge at x = %d, then %d)"
              % (edge, panel_right(shots["imported"])))
        coloured = mesh_box(shots["imported"], shots["segmented"])
        check(coloured is not None and coloured[0] > edge and coloured[2] - coloured[0] > 40
              and coloured[3] - coloured[1] > 40,
              "the prism's segments are drawn in colour (changed box %s)" % (coloured,))
        fresh, reopened = panel_lower(shots["fresh"]), panel_lower(shots["reopened"])
        check(panel_right(shots["reopened"]) == edge, "the panel is shown again on reopening")
        shown = differing_rows(panel_lower(shots["segmented"]), fresh)
        check(shown > 5, "the panel's lower part shows the status (%d rows differ from the fresh panel)" % shown)
        left = differing_rows(fresh, reopened)
        check(left == 0, "on reopening, the panel below the count is as fresh: no status left from before "
              "(%d rows differ)" % left)
    return gui_session.summary()


if __name__ == "__main__":
    sys.exit(main())
