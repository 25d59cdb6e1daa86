#!/usr/bin/python3
"""Compare rollnoise HDF5 outputs dataset by dataset: two files, or every *.h5 of two folders.

Usage: scripts/compare_outputs.py BEFORE AFTER [--relative [--all]]

Default (exact): values, NaNs, the sign of zero, shape, dtype and each dataset's `units` must be
equal; attributes other than `units` (provenance: time, command line, version) are not compared.
Exit 1 on any difference (docs/architecture.md, the refactoring checks).

--relative: for every numeric dataset in both files the max relative difference
max |a - b| / max |a| (relative to the dataset's largest magnitude) and, for band levels (names
ending in "_level"), the max absolute difference in dB; prints the datasets that differ (all with
--all) and the largest of each kind (docs/record/performance.md Sec. 7). Exit 0.
"""
import os
import sys

import h5py
import numpy as np


def datasets(f):
    out = {}
    f.visititems(lambda name, obj: out.__setitem__(name, obj) if isinstance(obj, h5py.Dataset) else None)
    return out


def equal(a, b):
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    x, y = a[()], b[()]
    if isinstance(x, np.ndarray) and x.dtype.kind in "fc":
        return np.array_equal(x, y, equal_nan=True) and np.array_equal(np.signbit(x.real), np.signbit(y.real))
    if isinstance(x, np.ndarray):
        return np.array_equal(x, y)
    if isinstance(x, float):
        return (x == y) or (np.isnan(x) and np.isnan(y))
    return x == y


def exact(label, da, db):
    """Number of datasets and of differences between two files' datasets."""
    bad = 0
    for key in sorted(set(da) | set(db)):
        if key not in da or key not in db:
            print(f"{label}{key}: only {'before' if key in da else 'after'}")
            bad += 1
        elif not equal(da[key], db[key]) or da[key].attrs.get("units") != db[key].attrs.get("units"):
            print(f"{label}{key}: differs")
            bad += 1
    return len(set(da) | set(db)), bad


class Relative:
    """The largest relative and band-level differences over every file compared."""

    def __init__(self, show_all):
        self.show_all = show_all
        self.rel, self.db = (0.0, "-"), (0.0, "-")

    def __call__(self, label, da, db):
        for key in sorted(set(da) | set(db)):
            if key not in da or key not in db:
                print(f"{label}{key}: only {'before' if key in da else 'after'}")
                continue
            if da[key].dtype.kind not in "fciub":
                continue
            x, y = np.asarray(da[key][()]), np.asarray(db[key][()])
            if x.shape != y.shape:
                print(f"{label}{key}: shape {x.shape} vs {y.shape}")
                continue
            finite = np.isfinite(x) & np.isfinite(y)
            if not np.array_equal(np.isfinite(x), np.isfinite(y)):
                print(f"{label}{key}: non-finite entries differ")
            d = np.abs(x[finite].astype(complex) - y[finite].astype(complex))
            if d.size == 0:
                continue
            rel = float(d.max() / max(float(np.max(np.abs(x[finite]))), 1e-300))
            line = f"{label}{key}: max rel diff {rel:.3e}"
            if key.endswith("_level"):
                line += f", max abs diff {float(d.max()):.3e} dB"
                self.db = max(self.db, (float(d.max()), label + key))
            self.rel = max(self.rel, (rel, label + key))
            if self.show_all or rel > 0.0:
                print(line)
        return len(set(da) | set(db)), 0


def pairs(before, after):
    """(label, before file, after file) for two files or for every *.h5 of two folders."""
    if not os.path.isdir(before):
        return [("", before, after)]
    return [(name + ":", os.path.join(before, name), os.path.join(after, name))
            for name in sorted(f for f in os.listdir(before) if f.endswith(".h5"))]


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    if len(args) != 2:
        print(__doc__)
        return 2
    relative = Relative("--all" in argv) if "--relative" in argv else None
    compare = relative or exact
    files, total, bad = 0, 0, 0
    for label, fa_path, fb_path in pairs(*args):
        files += 1
        if not os.path.exists(fb_path):
            print(f"{label} missing after")
            bad += 1
            continue
        with h5py.File(fa_path, "r") as fa, h5py.File(fb_path, "r") as fb:
            n, b = compare(label, datasets(fa), datasets(fb))
        total, bad = total + n, bad + b
    if relative:
        print(f"largest relative difference: {relative.rel[0]:.3e} ({relative.rel[1]})")
        print(f"largest band-level difference: {relative.db[0]:.3e} dB ({relative.db[1]})")
        return 0
    print(f"{files} files, {total} datasets, {bad} differences")
    return 1 if bad or not files else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
