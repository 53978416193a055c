"""`cmake --install` puts our plugins where the MeshLab of the build's generation finds them.

Installs the build tree into a temporary DESTDIR, then:
  2020.09: the plugins must land in Debian's MeshLab plugin folder (/usr/lib/x86_64-linux-gnu/meshlab/plugins);
  2025.07: the plugins land in the user's MeshLabExtraPlugins/2025.07 folder; an unmodified MeshLab 2025.07
           (the cached build, whose own plugins/ folder has none of ours) is started under Xvfb with HOME
           pointing there, and Qt's plugin loader must report each of our plugins loaded.
Prints "N passed, N failed".
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "script"))
from meshlab_script import virtual_display  # noqa: E402

OURS = ["libfilter_segment.so", "libfilter_primitive_fit.so", "libfilter_measure_accuracy.so"]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--build", required=True)
    p.add_argument("--generation", required=True, choices=["2020.09", "2025.07"])
    p.add_argument("--meshlab", help="stock MeshLab 2025.07 binary (not the test prefix's copy)")
    p.add_argument("--with-edit", action="store_true", help="the edit tool is built too")
    a = p.parse_args()
    ours = OURS + (["libedit_primitive.so"] if a.with_edit else [])
    passed = failed = 0

    def check(ok, what):
        nonlocal passed, failed
        print(("ok: " if ok else "FAILED: ") + what)
        passed, failed = passed + bool(ok), failed + (not ok)

    work = tempfile.mkdtemp(prefix="pe-install-")
    try:
        dest = os.path.join(work, "dest")
        env = dict(os.environ, DESTDIR=dest)
        r = subprocess.run(["cmake", "--install", a.build], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        check(r.returncode == 0, "cmake --install succeeds")
        installed = {f: os.path.join(d, f) for d, _, files in os.walk(dest) for f in files if f.endswith(".so")}
        for lib in ours:
            check(lib in installed, "%s installed" % lib)
        if a.generation == "2020.09":
            folder = os.path.join(dest, "usr/lib/x86_64-linux-gnu/meshlab/plugins")
            for lib in ours:
                check(os.path.dirname(installed.get(lib, "")) == folder,
                      "%s is in Debian MeshLab's plugin folder" % lib)
        else:
            home = os.path.join(work, "home")
            user_dir = os.path.join(home, ".local/share/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/2025.07")
            os.makedirs(user_dir)
            for lib in ours:
                if lib in installed:
                    check(os.path.dirname(installed[lib]).endswith("MeshLabExtraPlugins/2025.07"),
                          "%s is in the user's MeshLabExtraPlugins/2025.07" % lib)
                    shutil.copy(installed[lib], user_dir)
            stock = os.path.join(os.path.dirname(a.meshlab), "plugins")
            check(not any(os.path.exists(os.path.join(stock, lib)) for lib in ours),
                  "the stock MeshLab's own plugins folder has none of ours")
            with virtual_display() as env:
                env.update(HOME=home, QT_DEBUG_PLUGINS="1")
                try:
                    out = subprocess.run(["timeout", "-s", "TERM", "20", a.meshlab], env=env, stdout=subprocess.PIPE,
                                         stderr=subprocess.STDOUT, timeout=120).stdout
                except subprocess.TimeoutExpired as e:
                    out = e.stdout or b""
            text = out.decode(errors="replace")
            for lib in ours:
                check(('loaded library "%s"' % os.path.join(user_dir, lib)) in text,
                      "MeshLab 2025.07 loaded %s from the user's folder" % lib)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
