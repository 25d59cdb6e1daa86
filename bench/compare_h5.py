#!/usr/bin/python3
"""Compares two HDF5 outputs of rollnoise dataset by dataset (docs/performance.md Sec. 7).

    /usr/bin/python3 bench/compare_h5.py before.h5 after.h5 [--all]

For every numeric dataset present in both files: the max relative difference
max |a - b| / max(max |a|, tiny) (relative to the dataset's largest magnitude) and, for datasets whose
path ends in "_level" (band levels in dB), the max absolute difference in dB. Prints the datasets
that differ (all with --all), the largest of each kind, and the datasets present in only one file.
"""
import sys

import h5py
import numpy as np


def numeric_datasets(f):
    out = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and obj.dtype.kind in "fciub":
            out[name] = np.asarray(obj[()])

    f.visititems(visit)
    return out


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    show_all = "--all" in argv
    with h5py.File(argv[1], "r") as fa, h5py.File(argv[2], "r") as fb:
        a, b = numeric_datasets(fa), numeric_datasets(fb)
    worst_rel, worst_db = (0.0, ""), (0.0, "")
    for name in sorted(set(a) & set(b)):
        x, y = a[name], b[name]
        if x.shape != y.shape:
            print(f"{name}: shape {x.shape} vs {y.shape}")
            continue
        if x.size == 0:
            continue
        finite = np.isfinite(x) & np.isfinite(y)
        if not np.array_equal(np.isfinite(x), np.isfinite(y)):
            print(f"{name}: non-finite entries differ")
        d = np.abs(x[finite].astype(complex) - y[finite].astype(complex))
        scale = np.max(np.abs(x[finite])) if finite.any() else 0.0
        rel = float(d.max() / max(scale, 1e-300)) if d.size else 0.0
        line = f"{name}: max rel diff {rel:.3e}"
        if name.endswith("_level") or "/bands/" in name and "level" in name:
            db = float(d.max()) if d.size else 0.0
            line += f", max abs diff {db:.3e} dB"
            if db > worst_db[0]:
                worst_db = (db, name)
        if rel > worst_rel[0]:
            worst_rel = (rel, name)
        if show_all or rel > 0.0:
            print(line)
    for name in sorted(set(a) ^ set(b)):
        print(f"{name}: only in {'first' if name in a else 'second'} file")
    print(f"largest relative difference: {worst_rel[0]:.3e} ({worst_rel[1] or '-'})")
    print(f"largest band-level difference: {worst_db[0]:.3e} dB ({worst_db[1] or '-'})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
