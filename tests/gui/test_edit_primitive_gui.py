"""GUI test of the Primitive Edit tool: MeshLab under Xvfb with our plugins, driven by xdotool.

A closed cylinder (axis along x, radius 2) is opened; the tool is started (Ctrl+Shift+P), the mesh is
segmented (S), the side is picked by a click and split by a Ctrl+drag across it, the two halves are picked
(click, Shift+click) and merged (M), a cylinder is fitted (3, F), its radius set to 2.5 (R, typing, Return),
applied (Enter), undone (Ctrl+Z) - the mesh is exported and must be back at radius 2 - and applied again
(Enter) - exported again, at radius 2.5. Then what a user must not be surprised by: the view does not move
sideways across fit and apply (the panel's width is fixed); a Ctrl+drag in empty space cuts nothing; a radius
of 1e4 typed in scientific notation is taken, and Apply then warns and asks instead of throwing the side
10 km away (Escape cancels, nothing moves); S pressed 40 times adds one undo step at most, and undoing to the
end restores the mesh as it was opened (geometry and segments). The exported PLY files are checked: geometry
and segment ids (face quality). Screenshots of every step are kept in the work directory.

Usage: python3 test_edit_primitive_gui.py --meshlab PATH --workdir DIR
Needs Xvfb, xdotool and ImageMagick's import. Prints "N passed, N failed"; exits non-zero on failure.
"""
import argparse
import math
import os
import random
import sys
import time

import gui_session
from gui_session import Session, check, mesh_box, panel_right

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "script"))
from meshlab_script import read_ply, write_ply  # noqa: E402

RADIUS, LENGTH, AROUND, RINGS = 2.0, 6.0, 48, 12
NEW_RADIUS = 2.5
DEADLINE = time.time() + 300


def make_cylinder(path):
    """Closed cylinder around the x axis, x in [-LENGTH/2, LENGTH/2], slightly noisy radius. Returns the
    face ranges (side, left cap, right cap)."""
    rng = random.Random(7)
    vertices = []
    for i in range(RINGS + 1):
        x = -LENGTH / 2 + LENGTH * i / RINGS
        for j in range(AROUND):
            t = 2 * math.pi * j / AROUND
            r = RADIUS + rng.uniform(-0.004, 0.004)
            vertices.append([x, r * math.cos(t), r * math.sin(t)])
    left, right = len(vertices), len(vertices) + 1
    vertices += [[-LENGTH / 2, 0, 0], [LENGTH / 2, 0, 0]]
    faces = []
    v = lambda i, j: i * AROUND + j % AROUND  # noqa: E731
    for i in range(RINGS):
        for j in range(AROUND):
            faces.append([v(i, j), v(i, j + 1), v(i + 1, j + 1)])
            faces.append([v(i, j), v(i + 1, j + 1), v(i + 1, j)])
    side = (0, len(faces))
    for j in range(AROUND):
        faces.append([left, v(0, j + 1), v(0, j)])
    caps_left = (side[1], len(faces))
    for j in range(AROUND):
        faces.append([right, v(RINGS, j), v(RINGS, j + 1)])
    caps_right = (caps_left[1], len(faces))
    write_ply(path, vertices, faces)
    return side, caps_left, caps_right


def check_export(path, ranges, radius, label):
    side, left, right = ranges
    if not check(os.path.exists(path), "%s: exported %s" % (label, os.path.basename(path))):
        return
    vertices, faces, face_props, _ = read_ply(path)
    check(len(faces) == right[1], "%s: %d faces kept" % (label, len(faces)))
    quality = face_props.get("quality")
    if not check(quality is not None and len(quality) == len(faces), "%s: face quality (segment ids) saved" % label):
        return
    side_ids = {int(quality[f]) for f in range(*side)}
    left_ids = {int(quality[f]) for f in range(*left)}
    right_ids = {int(quality[f]) for f in range(*right)}
    check(len(side_ids) == 1 and len(left_ids) == 1 and len(right_ids) == 1,
          "%s: side and each cap are one segment each (%s %s %s)" % (label, side_ids, left_ids, right_ids))
    check(len(side_ids | left_ids | right_ids) == 3, "%s: three distinct segments after split and merge" % label)
    side_vertices = {i for f in range(*side) for i in faces[f]}
    radii = [math.hypot(vertices[i][1], vertices[i][2]) for i in side_vertices]
    worst = max(abs(r - radius) for r in radii)
    check(worst < 0.012, "%s: side vertices at radius %g (worst deviation %.4g)" % (label, radius, worst))
    xs = [vertices[i][0] for i in side_vertices]
    check(abs(min(xs) + LENGTH / 2) < 0.05 and abs(max(xs) - LENGTH / 2) < 0.05,
          "%s: length kept (x from %.3f to %.3f)" % (label, min(xs), max(xs)))


def check_start(path, ranges):
    """After undoing everything: the mesh as opened, radius 2 and no segmentation (one value in face quality)."""
    side = ranges[0]
    if not check(os.path.exists(path), "undone to the end: exported %s" % os.path.basename(path)):
        return
    vertices, faces, face_props, _ = read_ply(path)
    quality = face_props.get("quality") or []
    check(len(set(int(q) for q in quality)) == 1, "undone to the end: no segments, as opened (%d ids)"
          % len(set(int(q) for q in quality)))
    side_vertices = {i for f in range(*side) for i in faces[f]}
    worst = max(abs(math.hypot(vertices[i][1], vertices[i][2]) - RADIUS) for i in side_vertices)
    check(worst < 0.005, "undone to the end: side back at radius %g as opened (worst %.4g)" % (RADIUS, worst))


def check_log(path):
    """MeshLab echoes its log on stdout ("LOG: <level> <text>"): every step must have been done, in order."""
    with open(path, errors="replace") as f:
        lines = [l.strip() for l in f if "Primitive Edit:" in l]
    steps = [("segmented", "automatic segmentation: 3 segments"),
             ("side picked", "picked segment "),
             ("split by the drag", "split: 1 segment(s) cut into 2 pieces; 4 segments"),
             ("two halves picked", "picked segments "),
             ("merged", "merge: 2 segments merged"),
             ("cylinder fitted", "fit Cylinder to segment"),
             ("radius edited", "edited primitive: Cylinder"),
             ("applied", "snapped onto Cylinder"),
             ("undone", "undo: apply"),
             ("applied again", "snapped onto Cylinder")]
    at = 0
    for name, text in steps:
        found = next((i for i in range(at, len(lines)) if text in lines[i]), None)
        if check(found is not None, "log: %s (%r)" % (name, text)):
            at = found + 1
    edited = [l for l in lines if "edited primitive: Cylinder" in l]
    check(any("radius %g" % NEW_RADIUS in l for l in edited), "log: radius set to %g" % NEW_RADIUS)
    check(not any(l.startswith("LOG: 1 ") for l in lines[:at]), "log: no warnings from the tool up to here")
    check(sum(1 for l in lines if "edited primitive: Cylinder" in l and "radius %g" % NEW_RADIUS in l) == 1,
          "log: one line per edit (Return and the focus leaving the field do not both log)")
    surprises = [("stroke in empty space cuts nothing", "split: the line does not cut"),
                 ("1e4 typed is taken", "edited primitive: Cylinder"),
                 ("apply warns before moving vertices 1e4 away", "confirm to apply"),
                 ("the warning's Cancel leaves the mesh", "cancelled; the mesh is unchanged"),
                 ("segmented again", "automatic segmentation"),
                 ("repeated segmentation adds no step", "no undo step added"),
                 ("undone to the end", "undo: nothing to undo")]
    for name, text in surprises:
        found = next((i for i in range(at, len(lines)) if text in lines[i]), None)
        if check(found is not None, "log: %s (%r)" % (name, text)):
            at = found + 1
    check(any("radius 10000" in l for l in lines if "edited primitive: Cylinder" in l), "log: radius 1e4 taken")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--meshlab", required=True)
    parser.add_argument("--batch")
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    if not gui_session.prepare(args.workdir):
        return 1
    mesh = os.path.join(args.workdir, "cylinder.ply")
    ranges = make_cylinder(mesh)

    s = Session(args.meshlab, args.workdir)
    with s.running():
        s.start(mesh)
        s.shot("opened")
        # Zoom out two wheel steps (before the tool, which takes the wheel) so that the whole cylinder is in
        # the view beside the docks.
        s.zoom_out()
        s.toggle_tool()
        before = s.shot("tool_started")
        # This clean cylinder is the normal-angle method's case (the default, primitive fit, is for scans):
        # Alt+M focuses the method, Down picks "Normal angle", and the keys go back to the view.
        s.key("alt+m", "Down", pause=1.0)
        s.shot("normal_angle_chosen")
        s.key("s", pause=2.0)
        after = s.shot("segmented")
        box = mesh_box(before, after)
        if not check(box is not None and box[2] - box[0] > 100 and box[3] - box[1] > 50,
                     "segmentation coloured the mesh (box %s)" % (box,)):
            return 1
        x0, y0, x1, y1 = box
        cx, cy = (x0 + x1) // 2, (y0 + y1) // 2
        s.click(cx, cy)
        s.shot("side_picked")
        s.drag(cx, y0 - 40, cx + 3, y1 + 40, "ctrl")
        s.shot("split")
        s.click(x0 + (cx - x0) // 2, cy)
        s.click(cx + (x1 - cx) // 2, cy, modifier="shift")
        s.shot("halves_picked")
        s.key("m", pause=1.5)
        s.shot("merged")
        s.key("3", "f", pause=3.0)
        s.shot("cylinder_fitted")
        s.key("r", pause=0.5)
        s.xdo("type", "--delay", "60", str(NEW_RADIUS))
        time.sleep(0.3)
        s.key("Return", pause=1.0)
        s.shot("radius_edited")
        s.key("Return", pause=3.0)
        applied_shot = s.shot("applied")
        edge = panel_right(before)
        check(100 < edge < 600 and panel_right(applied_shot) == edge,
              "the panel's edge stays at x = %d (now %d) across fit and apply: the view does not move"
              % (edge, panel_right(applied_shot)))
        s.key("ctrl+z", pause=3.0)
        s.shot("undone")
        # Undo keeps the edited cylinder: Enter applies it again.
        s.key("Return", pause=3.0)
        s.shot("applied_again")
        applied = os.path.join(args.workdir, "applied.ply")
        check(s.export(applied), "export after applying again")
        # With the side picked, a stroke in empty space below the mesh, on the line of the split that cut the
        # side in two before: the plane through it crosses the side, the stroke does not.
        s.click(cx, cy)
        s.drag(cx, y1 + 40, cx + 1, y1 + 120, "ctrl")
        s.shot("stroke_in_empty_space")
        # Radius 1e4 on the side: taken, then Apply warns and asks; Escape cancels.
        s.key("3", "f", pause=3.0)
        s.key("r", pause=0.5)
        s.xdo("type", "--delay", "60", "1e4")
        time.sleep(0.3)
        s.key("Return", pause=1.0)
        s.key("Return", pause=2.0)
        s.shot("apply_warning")
        s.key("Escape", pause=1.5, focus=False)
        s.shot("apply_cancelled")
        # S 40 times, then undo to the end.
        s.key(*(["s"] * 40), pause=3.0)
        s.key(*(["ctrl+z"] * 45), pause=4.0)
        s.shot("undone_to_the_end")
        start = os.path.join(args.workdir, "start.ply")
        check(s.export(start), "export after undoing to the end")
        s.shot("final")
        if time.time() > DEADLINE:
            check(False, "finished within the time limit")

    check_log(os.path.join(args.workdir, "meshlab.log"))
    check_export(os.path.join(args.workdir, "applied.ply"), ranges, NEW_RADIUS, "after apply, undo, apply")
    check_start(os.path.join(args.workdir, "start.ply"), ranges)
    return gui_session.summary()


if __name__ == "__main__":
    sys.exit(main())
