#!/usr/bin/env python3
"""Writes the seed corpus of fuzz_common into fuzz/corpus/ (deterministic: same files on every run).

Each seed follows the byte layout decoded by fuzz_common.cpp (LLVMFuzzerTestOneInput, decode_params) and
fuzz_input.h (build_mesh, fuzz_primitive): mesh kind, shape and its primitive, scale, grid size, then a pseudo-random
tail for perturbations, extra faces, parameters, selection and overrides. Seeds cover both mesh types, every
shape (raw cloud, plane, sphere, cylinder, cone, torus), tiny and huge scales and narrow arcs; the fuzzer
mutates from there.
Usage: python3 fuzz/make_seeds.py [output dir]
"""
import os
import random
import struct
import sys


def u16(x):
    return struct.pack("<H", max(0, min(65535, int(x))))


def unit(x):
    """Inverse of Decoder::unit(): x in [0, 1]."""
    return u16(round(x * 65535))


def signed_unit(x):
    return unit((x + 1) / 2)


def seed(rng, mesh_kind, quality, shape, ptype, scale_exp, rows, cols, u_span, v_span, tail, radius=0.5,
         minor=0.3, half=0.4):
    b = bytearray([mesh_kind])
    if mesh_kind & 1:
        b.append(quality)
    b.append(shape)
    # fuzz_primitive: type, wild (non-zero = tame), origin, axis, radius, minor radius, half angle
    b += bytes([ptype, 1])
    for _ in range(3):
        b += signed_unit(rng.uniform(-0.3, 0.3))
    for c in (rng.uniform(-1, 1), rng.uniform(-1, 1), 1.0):
        b += signed_unit(c)
    b += unit((radius - 0.05) / 3.0) + unit((minor - 0.02) / (radius * 1.2)) + unit((half - 0.001) / 1.5687)
    b.append(scale_exp + 6)
    b += unit(rng.random() * 0.3)           # noise
    b += bytes([rows - 2, cols - 2])
    b += unit(u_span - 0.02) + unit(v_span - 0.02)
    b += bytes(rng.randrange(256) for _ in range(tail))
    return bytes(b)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
    os.makedirs(out, exist_ok=True)
    rng = random.Random(20200901)
    seeds = []
    shapes = {1: "plane", 2: "sphere", 3: "cylinder", 4: "cone", 5: "torus"}
    for mesh_kind in (0, 1):
        for shape, name in shapes.items():
            for variant, (rows, cols, us, vs, exp) in enumerate(
                    [(12, 12, 1.0, 1.0, 0), (20, 6, 0.012, 1.0, 0), (8, 30, 1.0, 0.5, 6), (5, 5, 0.3, 0.3, -6)]):
                seeds.append(("%s_%s_%d" % ("cmesho" if mesh_kind else "own", name, variant),
                              seed(rng, mesh_kind, variant % 2, shape, shape - 1, exp, rows, cols, us, vs,
                                   rng.choice([64, 256, 1024]))))
        # Raw clouds of fuzzed coordinates with arbitrary faces.
        for i in range(3):
            b = bytearray([mesh_kind] + ([1] if mesh_kind else []) + [0])
            b += bytes(rng.randrange(256) for _ in range(rng.choice([32, 300, 3000])))
            seeds.append(("%s_raw_%d" % ("cmesho" if mesh_kind else "own", i), bytes(b)))
    seeds.append(("empty", b""))
    seeds.append(("one_byte", b"\x01"))
    for name, data in seeds:
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)
    print("%d seeds written to %s" % (len(seeds), out))


if __name__ == "__main__":
    main()
