#!/usr/bin/python3
"""Band levels of two `rollnoise noise` runs side by side: where they differ by more than a margin.

Usage: postprocess/compare_rail_models.py A.h5 B.h5 [--margin 3] [--label-a beam] [--label-b waveguide]

For each wheel of both files (/noise/wheels/<wheel>/bands/force_level [nb][4]: Fz, Fx, Fy, Mz, and
velocity_level [nb][2][4]: wheel and rail, z, x, y, rot z) prints every band and component whose
levels differ by more than the margin (dB), B - A, with both levels, and a count per component.
Written for the beam / waveguide comparison of docs/models.md ("Beam and waveguide: where they
differ and why"), but any two runs with the same bands will do.
"""
import argparse
import sys

import h5py
import numpy as np

FORCES = ["Fz", "Fx", "Fy", "Mz"]
DIRS = ["z", "x", "y", "rot z"]


def wheels(path):
    out = {}
    with h5py.File(path, "r") as f:
        centre = f["noise/bands/centre"][()]
        group = f["noise/wheels"] if "noise/wheels" in f else None
        names = list(group) if group is not None else []
        for w in names:
            if not isinstance(group[w], h5py.Group) or "bands" not in group[w]:
                continue  # e.g. /noise/wheels/sources
            b = group[w]["bands"]
            out[w] = (b["force_level"][()], b["velocity_level"][()])
        if not out:  # a file without the per-wheel group: the reported wheel
            out["reported"] = (f["noise/bands/force_level"][()], f["noise/bands/velocity_level"][()])
    return centre, out


def components(force, velocity):
    for i, name in enumerate(FORCES):
        yield name, force[:, i]
    for s, body in enumerate(["wheel", "rail"]):
        for i, d in enumerate(DIRS):
            yield f"{body} v_{d}", velocity[:, s, i]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--margin", type=float, default=3.0)
    p.add_argument("--label-a", default="A")
    p.add_argument("--label-b", default="B")
    args = p.parse_args()
    ca, wa = wheels(args.a)
    cb, wb = wheels(args.b)
    if len(ca) != len(cb) or not np.allclose(ca, cb):
        print("the two files have different bands", file=sys.stderr)
        return 1
    for w in [w for w in wa if w in wb]:
        print(f"{w}: |{args.label_b} - {args.label_a}| > {args.margin:g} dB")
        print(f"  {'band (Hz)':>9}  {'component':<12} {args.label_a:>9} {args.label_b:>9} {'diff':>7}")
        counts = {}
        for (name, la), (_, lb) in zip(components(*wa[w]), components(*wb[w])):
            for k, c in enumerate(ca):
                d = lb[k] - la[k]
                if np.isfinite(d) and abs(d) > args.margin:
                    counts[name] = counts.get(name, 0) + 1
                    print(f"  {c:9.0f}  {name:<12} {la[k]:9.1f} {lb[k]:9.1f} {d:+7.1f}")
        print("  bands over the margin: " +
              (", ".join(f"{n} {m}" for n, m in counts.items()) if counts else "none"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
