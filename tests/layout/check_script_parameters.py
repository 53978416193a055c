"""The scripts' table of our filters' parameters (tests/script/meshlab_script.py FILTER_PARAMETERS) is the plugins'
own: every filter of ours is in it, with every parameter in the filter's order, of its type, at its default.

The script tests and bench/run_pipeline.py write meshlabserver scripts from that table (meshlabserver 2020.09
asserts unless a script lists every parameter), and the bench's "default parameters" are the table's.
Usage: check_script_parameters.py RUNNER    (RUNNER: tools/meshlab_runner, whose --list -i MESH prints each
parameter's name, type and default as a script's <Param>). Prints "N passed, N failed".
"""
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "script"))
from meshlab_script import FILTER_PARAMETERS, box_mesh, write_ply  # noqa: E402

OUR_PREFIXES = ("Segment: ", "Primitive: ", "Measure: Accuracy")
# The table names a point as 2020.09's scripts do; 2025.07 has a position and a direction.
SAME_TYPE = {"RichPoint3f": ("RichPosition", "RichDirection")}


def listed_parameters(runner):
    """Per filter of ours [(name, Rich type, <Param> element)] as the plugins declare them on a box."""
    with tempfile.TemporaryDirectory() as tmp:
        box = os.path.join(tmp, "box.ply")
        write_ply(box, *box_mesh())
        text = subprocess.run([runner, "--list", "-i", box], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                              check=True, universal_newlines=True,
                              env=dict(os.environ, QT_QPA_PLATFORM="offscreen")).stdout
    out, current = {}, None
    for line in text.splitlines():
        m = re.match(r"^    (\S+) \((\S+)\) (<.*>)$", line)
        if m and current is not None:
            out[current].append((m.group(1), m.group(2), ET.fromstring(m.group(3))))
        elif not line.startswith(" "):
            name = line.split("\t")[0]
            current = name if name.startswith(OUR_PREFIXES) else None
            if current is not None:
                out[current] = []
    return out


def same_default(default, kind, element):
    if default is None:
        return True
    if kind == "RichPoint3f":
        return all(abs(float(element.get(k)) - float(v)) <= 1e-6 for k, v in zip("xyz", default))
    value = element.get("value")
    if kind == "RichBool":
        return (value.lower() == "true") == default
    if kind == "RichFloat":
        return abs(float(value) - default) <= 1e-6 * max(1.0, abs(default))
    if kind in ("RichInt", "RichEnum"):
        return int(value) == default
    return value == default


def main():
    listed = listed_parameters(sys.argv[1])
    passed = failed = 0

    def check(ok, what):
        nonlocal passed, failed
        print(("ok: " if ok else "FAILED: ") + what)
        passed, failed = passed + ok, failed + (not ok)

    check(bool(listed), "the runner listed our filters with their parameters")
    for name in sorted(set(listed) | set(FILTER_PARAMETERS)):
        table, plugin = FILTER_PARAMETERS.get(name), listed.get(name)
        if table is None or plugin is None:
            check(False, "%s is %s" % (name, "not in FILTER_PARAMETERS" if table is None else "no filter of ours"))
            continue
        names = [p[0] for p in plugin]
        check([p[0] for p in table] == names, "%s: parameters %s (table: %s)" % (name, names, [p[0] for p in table]))
        for (key, default, kind), (_, listed_kind, element) in zip(table, plugin):
            check(listed_kind in SAME_TYPE.get(kind, (kind,)) and same_default(default, kind, element),
                  "%s: %s is %s = %s (plugin: %s %s)" % (name, key, kind, default, listed_kind,
                                                        ET.tostring(element, encoding="unicode")))
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
