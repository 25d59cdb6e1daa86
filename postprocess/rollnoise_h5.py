"""Shared helpers of the plot scripts: open a rollnoise output (or bench CSV) with a one-line error
and exit status 2 on a wrong file, read datasets with their `units` attribute, and label
1/3-octave bands by their nominal centres.

Every plot script ends with `rollnoise_h5.run(main)`: a missing file, a file that is not HDF5, or
one without the datasets the plot needs gives

    plot_x.py: error: FILE: what is wrong

on stderr and exit status 2 (the convention of the rollnoise program), never a traceback.
"""
import math
import os
import re
import sys

import numpy as np


class PlotInputError(Exception):
    """A wrong input file or option: reported in one line, exit status 2."""


def fail(message):
    raise PlotInputError(message)


def run(main):
    """Calls main(); input errors end in one line on stderr and exit status 2."""
    prog = os.path.basename(sys.argv[0])
    try:
        main()
    except PlotInputError as e:
        print(f"{prog}: error: {e}", file=sys.stderr)
        sys.exit(2)
    except (OSError, KeyError, ValueError, IndexError) as e:  # a layout we did not foresee
        print(f"{prog}: error: {type(e).__name__}: {e}", file=sys.stderr)
        sys.exit(2)


def file_and_output(doc, suffix):
    """Parses `SCRIPT FILE [-o OUT.png]` (usage text `doc`); (file, output), the output defaulting
    to FILE without its extension + `suffix`."""
    import argparse

    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("-o", "--output", default=None, help=f"PNG file (default FILE{suffix})")
    args = ap.parse_args()
    return args.file, args.output or args.file.rsplit(".", 1)[0] + suffix


def check_file(path):
    """The path names a readable regular file."""
    if not os.path.exists(path):
        fail(f"{path}: no such file")
    if os.path.isdir(path):
        fail(f"{path}: is a directory, not a file")
    if not os.access(path, os.R_OK):
        fail(f"{path}: not readable")


def open_output(path, *needed, command="rollnoise"):
    """The HDF5 output `path`, open for reading, after checking that it holds every path in
    `needed` (one of them may be a tuple of alternatives). `command` names the rollnoise command
    whose output the plot expects (for the message)."""
    import h5py

    check_file(path)
    if not h5py.is_hdf5(path):
        fail(f"{path}: not an HDF5 file (expected the output of `{command}`)")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        fail(f"{path}: cannot be read as HDF5 ({e})")
    for need in needed:
        alternatives = need if isinstance(need, tuple) else (need,)
        if not any(a in f for a in alternatives):
            f.close()
            fail(f"{path}: no {' or '.join(alternatives)}: not the output of `{command}`")
    return f


def values(f, path):
    """The dataset as a NumPy array; complex compounds {r, i} (older h5py) become complex."""
    a = f[path][()]
    if isinstance(a, np.ndarray) and a.dtype.names and set(a.dtype.names) >= {"r", "i"}:
        a = a["r"] + 1j * a["i"]
    return a


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def units(f, path, default="?"):
    """The dataset's `units` attribute."""
    return text(f[path].attrs.get("units", default))


def component_units(f, path, count):
    """Per-component units of a dataset whose `units` lists them comma-separated, e.g.
    "N, N, N m" -> ["N", "N", "N m"] (one unit for all when there is a single one)."""
    u = [s.strip() for s in units(f, path).split(",")]
    return u if len(u) == count else [u[0]] * count


def attribute(obj, name, default=None):
    v = obj.attrs.get(name, default)
    return text(v) if v is not None else None


def case_value(f, section, key):
    """A value of the case as run (`/case` attribute `toml`), as text, or None."""
    if "/case" not in f:
        return None
    toml = text(f["/case"].attrs.get("toml", ""))
    sec = None
    for line in toml.splitlines():
        line = line.split("#")[0].strip()
        if line.startswith("["):
            sec = line.strip("[]").strip()
        elif "=" in line and sec == section and line.split("=")[0].strip() == key:
            return line.split("=", 1)[1].strip().strip('"')
    return None


# ---- units of the creep coefficients ----

def _times_metre(u):
    """u * m for the units written here ("N" -> "N m", "N m" -> "N m^2")."""
    if u in ("-", ""):
        return "m"
    m = re.fullmatch(r"(.*\S)\s+m(?:\^(\d+))?", u)
    if m:
        return f"{m.group(1)} m^{int(m.group(2) or 1) + 1}"
    return u + " m"


def creep_entry_units(unit_text):
    """Units of f_jk (3 x 3) from the `units` attribute of /creep/f, which names the rows' and the
    columns' units ("rows Fx [N], Fy [N], Mz [N m]; columns xi_x [-], xi_y [-], phi [rad/m]"):
    f_jk = dF_j / dxi_k, so its unit is the row's unit over the column's (rad/m -> times m)."""
    rows = re.search(r"rows\s+([^;]*)", unit_text)
    cols = re.search(r"columns\s+([^:;]*)", unit_text)
    r = re.findall(r"\[([^\]]*)\]", rows.group(1)) if rows else []
    c = re.findall(r"\[([^\]]*)\]", cols.group(1)) if cols else []
    if len(r) != 3 or len(c) != 3:  # older files: the units of the conventions
        r, c = ["N", "N", "N m"], ["-", "-", "rad/m"]
    out = []
    for rj in r:
        row = []
        for ck in c:
            if ck == "-":
                row.append(rj)
            elif ck == "rad/m":
                row.append(_times_metre(rj))
            else:
                row.append(f"{rj}/({ck})")
        out.append(row)
    return out


def matrix_entries(text, rows=3, cols=3):
    """`--entries` of a matrix plot: "11,22,23" -> [(0, 0), (1, 1), (1, 2)] (1-based row and
    column digits within rows x cols); a wrong entry is an input error."""
    entries = []
    for e in text.split(","):
        e = e.strip()
        if len(e) != 2 or not ("1" <= e[0] <= str(rows)) or not ("1" <= e[1] <= str(cols)):
            fail(f"--entries: '{e}' is not an entry ij with i in 1..{rows}, j in 1..{cols} (e.g. 11,22)")
        entries.append((int(e[0]) - 1, int(e[1]) - 1))
    return entries


def pretty(u):
    """A unit for an axis label: "N m^2" -> "N m²", "1 um" -> "1 µm"."""
    return re.sub(r"\bum\b", "\u00b5m", u.replace("^2", "\u00b2").replace("^3", "\u00b3"))


# ---- 1/3-octave bands ----

_NOMINAL = [1000, 1250, 1600, 2000, 2500, 3150, 4000, 5000, 6300, 8000]


def nominal_centre(fc):
    """The nominal centre (IEC 61260-1: ..., 400, 500, 630, ..., 5000 Hz) of the base-10
    1/3-octave band whose exact centre is fc (1000 * 10^(n/10) Hz)."""
    n = int(math.floor(10.0 * math.log10(fc / 1000.0) + 0.5))
    decade, r = divmod(n, 10)
    return _NOMINAL[r] * 10.0 ** decade


def band_label(fc):
    return f"{nominal_centre(fc):g}"


def set_band_axis(ax, centres, every=1, label=True):
    """x ticks 0 .. n-1 labelled with the bands' nominal centres."""
    x = np.arange(len(centres))
    ax.set_xticks(x[::every])
    ax.set_xticklabels([band_label(c) for c in centres[::every]], rotation=45)
    if label:
        ax.set_xlabel("1/3-octave band, nominal centre [Hz]")
    return x


# ---- several files on the same axes ----

def file_labels(files, labels):
    """The legend label of each file: the `--label` options in order (as many as files), else each
    file's stem (its name without directory and last extension)."""
    if labels:
        if len(labels) != len(files):
            fail(f"--label given {len(labels)} times for {len(files)} files (give it once per file or not at all)")
        return list(labels)
    return [os.path.splitext(os.path.basename(p))[0] for p in files]


FILE_STYLES = ["-", "--", ":", "-."]
FILE_COLOURS = ["k", "tab:blue", "tab:red", "tab:green", "tab:purple", "tab:orange", "tab:brown", "tab:olive"]


def file_style(i):
    """Line style of the i-th file where colour means something else (a wheel, a source)."""
    return FILE_STYLES[i % len(FILE_STYLES)]


def file_colour(i):
    """Colour of the i-th file where it is the only distinction."""
    return FILE_COLOURS[i % len(FILE_COLOURS)]


def band_union(centre_lists):
    """The sorted nominal centres of all the files' bands, and for each file the x positions of its
    bands on that common axis (files with different band ranges share one band axis)."""
    nominal = sorted({nominal_centre(c) for cs in centre_lists for c in cs})
    index = {n: i for i, n in enumerate(nominal)}
    return np.array(nominal), [np.array([index[nominal_centre(c)] for c in cs]) for cs in centre_lists]


# ---- which wheel and which loop a noise output's levels belong to ----

WHEELS = ["leading_outer", "leading_inner", "trailing_outer", "trailing_inner"]


def wheel_words(name):
    """"leading_outer" -> "leading outer"."""
    return name.replace("_", " ")


def noise_group(f, wheel=None):
    """The group of a `rollnoise noise` output holding the band levels to plot, and a description of
    it for a title: the wheel's own group /noise/wheels/WHEEL when the file has per-wheel groups
    (WHEEL defaults to leading_outer), else the top-level /noise. The description names the wheel and
    the loop from the attributes the file carries (`loop` of /noise/wheels), e.g. "leading outer
    wheel, bogie loop (4 contacts coupled)"."""
    if "/noise/wheels" in f and any(f"/noise/wheels/{w}/bands/force_level" in f for w in WHEELS):
        w = wheel or "leading_outer"
        group = f"/noise/wheels/{w}"
        if group + "/bands/force_level" not in f:
            present = [x for x in WHEELS if f"/noise/wheels/{x}/bands/force_level" in f]
            fail(f"{f.filename}: no wheel {w} (the file has {', '.join(present)})")
        loop = attribute(f["/noise/wheels"], "loop", "") or ""
        if loop.startswith("coupled"):
            contacts = sum(f"/noise/wheels/{x}/bands/force_level" in f for x in WHEELS)
            contacts += sum(f"/noise/wheels/{x}/patches/1/bands/force_level" in f for x in WHEELS)
            where = f"bogie loop ({contacts} contacts coupled)" if contacts > 1 else "a loop of one contact"
        elif loop.startswith("one contact"):
            where = "a loop of one contact"
        else:
            where = "its single-contact loop alone (wheels not coupled)"
        return group, f"{wheel_words(w)} wheel, {where}", loop.startswith("coupled")
    if wheel:
        fail(f"{f.filename}: no per-wheel groups /noise/wheels/* (a run with one wheel); leave out --wheel")
    return "/noise", "the case's single contact, single-contact loop", False


def top_level_words(f):
    """What the top-level /noise of a file with per-wheel groups is, as its `loop` attribute says
    ("the leading outer wheel's single-contact loop"), or "top-level /noise"."""
    loop = attribute(f["/noise/wheels"], "loop", "") if "/noise/wheels" in f else ""
    m = re.search(r"top-level /noise is (the [^;.]*)", loop or "")
    if m:
        return m.group(1)
    m = re.search(r"(\w+) is the top-level /noise run", loop or "")
    if m:
        return f"the {wheel_words(m.group(1))} wheel's loop"
    return "top-level /noise"
