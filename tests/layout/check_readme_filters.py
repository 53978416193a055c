"""The README's filter tables list every filter of ours with the PyMeshLab name the plugins really give it.

Usage: check_readme_filters.py README.md RUNNER    (RUNNER: tools/meshlab_runner, whose -d dump lists the
filters and PyMeshLab names of every loaded plugin). Prints "N passed, N failed".
"""
import os
import re
import subprocess
import sys
import tempfile

OUR_PREFIXES = ("Segment: ", "Primitive: ", "Measure: Accuracy")


def main():
    readme, runner = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        dump = os.path.join(tmp, "filters.txt")
        subprocess.run([runner, "-d", dump], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True,
                       env=dict(os.environ, QT_QPA_PLATFORM="offscreen"))
        text = open(dump).read()
    plugins = dict(re.findall(r"\\section f\d+ (.*)\nPyMeshLab: (\S+)", text))
    ours = {name: py for name, py in plugins.items() if name.startswith(OUR_PREFIXES)}
    rows = dict(re.findall(r"^\| `([^`]+)` \| `([a-z_]+)` \|", open(readme).read(), re.M))
    passed = failed = 0
    for name, py in sorted(ours.items()):
        ok = rows.get(name) == py
        print(("ok: " if ok else "FAILED: ") + "%s is in the README as `%s` (README: %s)" % (name, py, rows.get(name)))
        passed, failed = passed + ok, failed + (not ok)
    for name in sorted(set(rows) - set(ours)):
        print("FAILED: the README lists %s, which no plugin has" % name)
        failed += 1
    if not ours:
        print("FAILED: the runner listed none of our filters")
        failed += 1
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
