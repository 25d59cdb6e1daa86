#!/usr/bin/python3
"""Compare two sets of HDF5 outputs dataset by dataset, exactly (values, shapes, dtypes, `units`).

Usage: scripts/compare_outputs.py BEFORE_DIR AFTER_DIR
Every *.h5 of BEFORE_DIR must exist in AFTER_DIR with the same datasets; attributes other than a
dataset's `units` (provenance: time, command line, version) are not compared. Exit 1 on any difference.
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


def main(before, after):
    files = sorted(f for f in os.listdir(before) if f.endswith(".h5"))
    total, bad = 0, 0
    for name in files:
        other = os.path.join(after, name)
        if not os.path.exists(other):
            print(f"{name}: missing after")
            bad += 1
            continue
        with h5py.File(os.path.join(before, name), "r") as fa, h5py.File(other, "r") as fb:
            da, db = datasets(fa), datasets(fb)
            for key in sorted(set(da) | set(db)):
                total += 1
                if key not in da or key not in db:
                    print(f"{name}:{key}: only {'before' if key in da else 'after'}")
                    bad += 1
                elif not equal(da[key], db[key]) or da[key].attrs.get("units") != db[key].attrs.get("units"):
                    print(f"{name}:{key}: differs")
                    bad += 1
    print(f"{len(files)} files, {total} datasets, {bad} differences")
    return 1 if bad or not files else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
