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
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "script"))
from meshlab_script import read_ply, write_ply  # noqa: E402

RADIUS, LENGTH, AROUND, RINGS = 2.0, 6.0, 48, 12
NEW_RADIUS = 2.5
DEADLINE = time.time() + 300

passed = 0
failed = 0


def check(condition, what):
    global passed, failed
    if condition:
        passed += 1
        print("PASS", what)
    else:
        failed += 1
        print("FAIL", what)
    return condition


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


class Session:
    def __init__(self, meshlab, workdir):
        self.workdir = workdir
        self.env = dict(os.environ)
        self.display = None
        self.xvfb = None
        self.meshlab = None
        self.meshlab_path = os.path.abspath(meshlab)
        self.window = None
        self.shot_index = 0

    def start(self, mesh):
        for n in range(91, 120):
            if os.path.exists("/tmp/.X11-unix/X%d" % n) or os.path.exists("/tmp/.X%d-lock" % n):
                continue
            self.xvfb = subprocess.Popen(["Xvfb", ":%d" % n, "-screen", "0", "1280x1024x24", "-nolisten", "tcp"],
                                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            time.sleep(1.0)
            if self.xvfb.poll() is None:
                self.display = ":%d" % n
                break
        if self.display is None:
            raise RuntimeError("could not start Xvfb")
        self.env["DISPLAY"] = self.display
        self.env.pop("WAYLAND_DISPLAY", None)
        # A home of the test's own: no settings of earlier runs, and MeshLab 2025.07's first-start question
        # about anonymous statistics already answered (2020.09 reads the same file and ignores the key).
        home = os.path.join(self.workdir, "home")
        shutil.rmtree(home, ignore_errors=True)
        os.makedirs(os.path.join(home, ".config", "VCG"))
        with open(os.path.join(home, ".config", "VCG", "MeshLab_64bit_fp.conf"), "w") as conf:
            conf.write("[General]\ninformativeShown=true\n")
        self.env["HOME"] = home
        self.env["LIBGL_ALWAYS_SOFTWARE"] = "1"
        self.log = open(os.path.join(self.workdir, "meshlab.log"), "w")
        self.meshlab = subprocess.Popen([self.meshlab_path, mesh], env=self.env, stdout=self.log,
                                        stderr=subprocess.STDOUT, cwd=self.workdir)
        self.window = self.wait_for_window("MeshLab", 60)
        self.xdo("windowmove", self.window, "0", "0")
        self.xdo("windowsize", self.window, "1280", "1024")
        self.xdo("windowfocus", self.window)
        time.sleep(4)

    def stop(self):
        for p in (self.meshlab, self.xvfb):
            if p is not None and p.poll() is None:
                p.terminate()
                try:
                    p.wait(10)
                except subprocess.TimeoutExpired:
                    p.kill()

    def xdo(self, *args, check=True):
        r = subprocess.run(["xdotool"] + list(args), env=self.env, capture_output=True, text=True, timeout=20)
        if check and r.returncode != 0:
            raise RuntimeError("xdotool %s failed: %s" % (" ".join(args), r.stderr))
        return r.stdout.strip()

    def wait_for_window(self, name, timeout):
        end = time.time() + timeout
        while time.time() < end:
            out = self.xdo("search", "--onlyvisible", "--name", name, check=False)
            ids = [w for w in out.split() if w]
            if ids:
                return ids[-1]
            if self.meshlab is not None and self.meshlab.poll() is not None:
                raise RuntimeError("meshlab exited with code %d" % self.meshlab.returncode)
            time.sleep(0.5)
        raise RuntimeError("no window named %r after %d s" % (name, timeout))

    def key(self, *keys, pause=0.8, focus=True):
        # Keys for the main window (and the view inside it); dialogs keep their own focus.
        if focus:
            self.xdo("windowfocus", self.window, check=False)
        self.xdo("key", "--delay", "80", *keys)
        time.sleep(pause)

    def click(self, x, y, modifier=None, pause=1.0):
        self.xdo("mousemove", str(x), str(y))
        time.sleep(0.2)
        if modifier:
            self.xdo("keydown", modifier)
        self.xdo("click", "1")
        if modifier:
            self.xdo("keyup", modifier)
        time.sleep(pause)

    def drag(self, x0, y0, x1, y1, modifier):
        self.xdo("mousemove", str(x0), str(y0))
        time.sleep(0.2)
        self.xdo("keydown", modifier)
        self.xdo("mousedown", "1")
        for k in range(1, 11):
            self.xdo("mousemove", str(int(x0 + (x1 - x0) * k / 10)), str(int(y0 + (y1 - y0) * k / 10)))
            time.sleep(0.05)
        self.shot("split_line_drawn")
        self.xdo("mouseup", "1")
        self.xdo("keyup", modifier)
        time.sleep(1.0)

    def shot(self, name):
        """Screenshot as PNG (artifact) and returns the pixels as (width, height, rgb bytes)."""
        self.shot_index += 1
        ppm = os.path.join(self.workdir, "shot.ppm")
        subprocess.run(["import", "-window", "root", "-depth", "8", ppm], env=self.env, check=True, timeout=30)
        subprocess.run(["convert", ppm, os.path.join(self.workdir, "%02d_%s.png" % (self.shot_index, name))],
                       check=True, timeout=30)
        with open(ppm, "rb") as f:
            data = f.read()
        # Binary PPM: "P6 <w> <h> <max>" then RGB bytes.
        fields = []
        pos = 0
        while len(fields) < 4:
            while data[pos:pos + 1].isspace():
                pos += 1
            start = pos
            while not data[pos:pos + 1].isspace():
                pos += 1
            fields.append(data[start:pos])
        return int(fields[1]), int(fields[2]), data[pos + 1:]

    def export(self, path):
        if os.path.exists(path):
            os.remove(path)
        self.key("ctrl+shift+e", pause=2.0)
        self.shot("export_dialog")
        self.key("ctrl+a", pause=0.3, focus=False)
        self.xdo("type", "--delay", "30", path)
        time.sleep(0.5)
        self.key("Return", pause=2.0, focus=False)
        self.shot("export_options")
        self.key("Return", pause=2.0, focus=False)
        end = time.time() + 20
        while time.time() < end and not os.path.exists(path):
            time.sleep(0.5)
        time.sleep(1.0)
        return os.path.exists(path)


def mesh_box(before, after):
    """Box of the mesh on screen: the pixels that changed between two screenshots (the mesh getting its
    segment colours), taken over the columns and then the rows where most of them are (text changing
    elsewhere, e.g. in the log, is sparse)."""
    w, h, a = before
    _, _, b = after
    step = 4
    cols = [0] * (w // step)
    changed = []
    for gy in range(h // step):
        for gx in range(w // step):
            i = 3 * ((gy * step) * w + gx * step)
            if abs(a[i] - b[i]) + abs(a[i + 1] - b[i + 1]) + abs(a[i + 2] - b[i + 2]) > 60:
                cols[gx] += 1
                changed.append((gx, gy))
    if not changed:
        return None

    def longest_run(counts):
        limit = 0.5 * max(counts)
        best, start = (0, -1), None
        for k, c in enumerate(counts + [0]):
            if c >= limit and c > 0:
                start = k if start is None else start
            elif start is not None:
                if k - start > best[1] - best[0] + 1:
                    best = (start, k - 1)
                start = None
        return best

    c0, c1 = longest_run(cols)
    rows = [0] * (h // step)
    for gx, gy in changed:
        if c0 <= gx <= c1:
            rows[gy] += 1
    r0, r1 = longest_run(rows)
    return c0 * step, r0 * step, c1 * step, r1 * step


def panel_right(shot, y=975):
    """The right edge of the tool's panel (docked on the left) on row y, below its widgets: walking right from
    the window's left border, the first column whose colour differs from the panel's background."""
    w, h, data = shot
    size = len(data) // (w * h * 3)  # bytes per sample: import writes 8 or 16 bit PPM

    def rgb(px):
        i = size * 3 * (y * w + px)
        return data[i], data[i + size], data[i + 2 * size]

    x = 3
    background = rgb(x)
    while x + 1 < w and sum(abs(a - b) for a, b in zip(rgb(x + 1), background)) < 30:
        x += 1
    return x


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
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    for tool in ("Xvfb", "xdotool", "import", "convert"):
        if shutil.which(tool) is None:
            print("missing %s" % tool)
            print("0 passed, 1 failed")
            return 1
    os.makedirs(args.workdir, exist_ok=True)
    for name in os.listdir(args.workdir):
        if name.endswith((".png", ".ply", ".ppm")):
            os.remove(os.path.join(args.workdir, name))
    mesh = os.path.join(args.workdir, "cylinder.ply")
    ranges = make_cylinder(mesh)

    s = Session(args.meshlab, args.workdir)
    try:
        s.start(mesh)
        s.shot("opened")
        # Zoom out two wheel steps (before the tool, which takes the wheel) so that the whole cylinder is in
        # the view beside the docks.
        s.xdo("mousemove", "640", "500")
        s.xdo("click", "--repeat", "2", "--delay", "300", "4")
        time.sleep(1.0)
        s.key("ctrl+shift+p", pause=2.0)
        # Without a window manager the window shrinks when the tool's panel docks: restore its size.
        s.xdo("windowmove", s.window, "0", "0")
        s.xdo("windowsize", s.window, "1280", "1024")
        time.sleep(2.0)
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
    except Exception as e:  # report, keep the screenshots, and fail
        check(False, "GUI session ran without error: %s" % e)
    finally:
        s.stop()

    check_log(os.path.join(args.workdir, "meshlab.log"))
    check_export(os.path.join(args.workdir, "applied.ply"), ranges, NEW_RADIUS, "after apply, undo, apply")
    check_start(os.path.join(args.workdir, "start.ply"), ranges)
    print("%d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
