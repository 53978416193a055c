"""Driving MeshLab under Xvfb for the GUI tests: a Session starts Xvfb and MeshLab on a mesh (a home of its own,
software GL), sends keys, clicks and drags with xdotool, takes screenshots (kept as PNG artifacts) and exports
the current mesh through MeshLab's own Export dialog. Also the checks' tally and two screenshot measures (where
the mesh is, where the tool's panel ends)."""
import contextlib
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "script"))
from meshlab_script import start_virtual_display  # noqa: E402

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


def summary():
    """Prints the tally; the exit code of a test."""
    print("%d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


def prepare(workdir):
    """Checks the X tools are there and empties the work directory of an earlier run's shots and meshes."""
    for tool in ("Xvfb", "xdotool", "import", "convert"):
        if shutil.which(tool) is None:
            print("missing %s" % tool)
            check(False, "the X tools are installed")
            summary()
            return False
    os.makedirs(workdir, exist_ok=True)
    for name in os.listdir(workdir):
        if name.endswith((".png", ".ply", ".ppm")):
            os.remove(os.path.join(workdir, name))
    return True


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
        # Xvfb picks a free display itself (start_virtual_display): GUI tests started side by side by ctest -j
        # once both saw :91 free and started two servers on it, one of which had not yet given up a second later,
        # so both tests took :91.
        self.xvfb, self.display = start_virtual_display("1280x1024x24")
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
        self.restore_window(pause=0)
        self.xdo("windowfocus", self.window)
        time.sleep(4)

    @contextlib.contextmanager
    def running(self, what="GUI session"):
        """`with s.running():` around a session's steps: an exception in them fails a check ("<what> ran
        without error"; the screenshots so far are kept), and MeshLab and Xvfb are stopped in any case."""
        try:
            yield self
        except Exception as e:  # report, keep the screenshots, and fail
            check(False, "%s ran without error: %s" % (what, e))
        finally:
            self.stop()

    def zoom_out(self, steps=2):
        """Wheel steps out with the pointer in the view; before the tool starts, as the tool takes the wheel."""
        self.xdo("mousemove", "640", "500")
        self.xdo("click", "--repeat", str(steps), "--delay", "300", "4")
        time.sleep(1.0)

    def restore_window(self, pause=2.0):
        """Puts the window back at the screen's size: without a window manager it shrinks when a panel docks."""
        self.xdo("windowmove", self.window, "0", "0")
        self.xdo("windowsize", self.window, "1280", "1024")
        time.sleep(pause)

    def toggle_tool(self, pause=2.0):
        """Ctrl+Shift+P: turns the Primitive Edit tool on or off, then restores the window."""
        self.key("ctrl+shift+p", pause=2.0)
        self.restore_window(pause)

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
                raise RuntimeError("meshlab exited with code %d on %s; the end of its output:\n%s" %
                                   (self.meshlab.returncode, self.display, self.output_tail()))
            time.sleep(0.5)
        raise RuntimeError("no window named %r after %d s" % (name, timeout))

    def output_tail(self, lines=15):
        """The last lines MeshLab wrote (meshlab.log), so that a failure says why it stopped."""
        self.log.flush()
        with open(os.path.join(self.workdir, "meshlab.log"), errors="replace") as f:
            return "".join(f.readlines()[-lines:])

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


def panel_right(shot, rows=range(940, 986)):
    """The right edge of the tool's panel (docked on the left) near its foot: on each row, walking right from the
    window's left border, the first column whose colour differs from the panel's background; the largest over the
    rows, as the status text at the panel's foot, which grows with the last log line, crosses some of them but
    not the gaps between its lines."""
    w, h, data = shot
    size = len(data) // (w * h * 3)  # bytes per sample: import writes 8 or 16 bit PPM

    def rgb(px, y):
        i = size * 3 * (y * w + px)
        return data[i], data[i + size], data[i + 2 * size]

    def edge(y):
        x = 3
        background = rgb(x, y)
        while x + 1 < w and sum(abs(a - b) for a, b in zip(rgb(x + 1, y), background)) < 30:
            x += 1
        return x

    return max(edge(y) for y in rows)
