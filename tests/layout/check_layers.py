"""Checks the core's architecture: common/ is split into rooms by layer, and a room may include only
itself and the rooms below it (headers and sources alike); every source X.cpp has its header X.h; the
core includes no Qt or MeshLab header; and no file of ours shadows a file of MeshLab's own common/ (both
are included as "common/..."), for every MeshLab source given.

Usage: check_layers.py REPO_ROOT [MESHLAB_SRC_DIR ...]     (prints "N passed, N failed")
"""
import os
import re
import sys

# Lowest first. A room knows only the rooms before it in this list.
ROOMS = ["base", "geometry", "mesh", "fit", "relate", "segment", "snap", "measure", "pipeline"]
# relate, segment, snap and measure are siblings: none of them may include another.
SIBLINGS = {"relate", "segment", "snap", "measure"}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


def main():
    root = sys.argv[1]
    meshlab_srcs = sys.argv[2:]
    common = os.path.join(root, "common")
    failures = []
    checked = 0
    for dirpath, _, files in os.walk(common):
        for name in sorted(files):
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, root)
            parts = rel.split(os.sep)
            if not name.endswith((".h", ".cpp")):
                continue
            checked += 1
            if len(parts) != 3 or parts[1] not in ROOMS:
                failures.append("%s: a core file must sit in one of the rooms %s" % (rel, ROOMS))
                continue
            if name.endswith(".cpp") and not os.path.exists(path[:-len(".cpp")] + ".h"):
                failures.append("%s: a core source defines what the header of its name declares" % rel)
            room = parts[1]
            with open(path, encoding="utf-8") as f:
                text = f.read()
            for inc in INCLUDE.findall(text):
                if inc.startswith("common/"):
                    target = inc.split("/")
                    if len(target) != 3 or target[1] not in ROOMS:
                        failures.append("%s includes %s, which is not a core room's header" % (rel, inc))
                        continue
                    other = target[1]
                    upward = ROOMS.index(other) > ROOMS.index(room)
                    sideways = other != room and room in SIBLINGS and other in SIBLINGS
                    if upward or sideways:
                        failures.append("%s (room %s) includes %s: room %s is not below it" % (rel, room, inc, other))
                elif inc.startswith("Q") or "meshlab" in inc.lower() or inc.startswith("wrap/qt"):
                    failures.append("%s includes %s: the core must not depend on Qt or MeshLab" % (rel, inc))
            for src in meshlab_srcs:
                if os.path.exists(os.path.join(src, rel)):
                    failures.append("%s shadows MeshLab's %s" % (rel, os.path.join(src, rel)))
    for f in failures:
        print("FAIL " + f)
    print("%d passed, %d failed" % (checked - len({f.split(':')[0] for f in failures}), len(failures)))
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
