#!/usr/bin/python3
"""Readers of the files of CONTACT (Vollebregt & Kalker), the Python twin of src/io/contact_results:

  read_out(path)   the text output .out: a list of cases, each {"number", "module", "values",
                   "patches": [{"number", "values"}]}; values by CONTACT's header names
                   (FN FX FY MZ ELAST.EN. FRIC.POWER, FN/G ... APPROACH PMAX, NPOT NCON NADH NSLIP,
                   CHI DQ VELOC CKSI CETA CPHI; module 1 also FX(TR) ..., S_WS ..., XCP(TR) ...
                   and FN FX FS MN per patch)
  read_mat(path)   a traction file .mat (format 2410): {"header": {name: value}, "columns":
                   {name: numpy array}}; element centres by element_centres()
  integrate(mat)   Fn, Fx, Fy (N), Mz (N mm) = DX DY sums over the rows, element counts
  read_inp(path)   the numbers of an input .inp, case by case

CONTACT's units (mm, N, N/mm^2, N mm, rad/mm) and signs (tractions on body 1) are kept;
docs/contact_interop.md maps them to rollnoise's. A file that is not what a reader expects raises
ContactFileError "PATH:LINE: what"; as a script, that is one line on stderr and exit status 2.

  /usr/bin/python3 postprocess/contact_files.py FILE.out|FILE.mat ...   print the totals
"""
import os
import re
import sys

import numpy as np

END_LINE = "The CONTACT program ended succesfully."  # CONTACT's spelling
REQUIRED_HEADERS = {"FN", "FN/G", "NPOT", "CHI", "FX(TR)", "S_WS", "VX_WS", "XCP(TR)", "XCP(W)"}
_EXP_NO_E = re.compile(r"(?<=[0-9.])([+-])(?=\d+$)")


class ContactFileError(Exception):
    """A CONTACT file that cannot be read: the message names the file and line."""


def _fail(path, line, what):
    raise ContactFileError(f"{path}:{line}: {what}")


def fortran_number(s):
    """A Fortran-formatted number ('-8965.', '9.810E+04', g14.6's '0.228751-310'), or None."""
    s = s.strip().replace("D", "E").replace("d", "E")
    if not s or not (s[0].isdigit() or s[0] in "+-."):
        return None
    if "E" not in s.upper():
        s = _EXP_NO_E.sub(r"E\1", s)
    try:
        v = float(s)
    except ValueError:
        return None
    return v if np.isfinite(v) else None


def _numbers(words):
    vals = [fortran_number(w) for w in words]
    return vals if words and all(v is not None for v in vals) else None


def _read_lines(path, what):
    try:
        with open(path) as f:
            return f.read().splitlines()
    except OSError as e:
        raise ContactFileError(f"{path}: cannot open CONTACT {what}: {e.strerror}")


def read_out(path):
    lines = _read_lines(path, "output")
    cases, case, ended, i = [], None, False, 0
    while i < len(lines):
        line = lines[i]
        w = line.split()
        i += 1
        if not w:
            continue
        if line.strip() == END_LINE:
            ended = True
            break
        if len(w) == 2 and w[0] == "Case":
            case = {"number": int(w[1]), "module": 3, "line": i, "values": {}, "patches": []}
            cases.append(case)
            continue
        if case is None:
            continue
        if "WHEEL-RAIL CONTACT" in line:
            case["module"] = 1
        if len(w) >= 6 and w[:2] == ["-----", "DATA"] and w[4] == "PATCH":
            case["patches"].append({"number": int(w[5]), "values": {}})
            continue
        if len(w) < 2 or any(fortran_number(x) is not None for x in w):
            continue
        vals = _numbers(lines[i].split()) if i < len(lines) else None
        if vals is None or len(vals) != len(w):
            if w[0] in REQUIRED_HEADERS:
                _fail(path, i + 1, f"expected the {len(w)} numbers of '{line.strip()}' (truncated?)")
            continue
        per_patch = case["module"] == 3 or case["patches"]
        if per_patch and not case["patches"]:
            case["patches"].append({"number": 1, "values": {}})
        target = case["patches"][-1]["values"] if per_patch else case["values"]
        target.update(zip(w, vals))
        i += 1
    if not cases:
        _fail(path, len(lines), "no ' Case n' block: not a CONTACT .out file")
    if not ended:
        _fail(path, len(lines), f"the file ends without '{END_LINE}' (truncated?)")
    for c in cases:
        if not c["patches"] or "FN" not in c["patches"][0]["values"]:
            _fail(path, c["line"], f"case {c['number']} prints no total forces")
    return cases


def read_mat(path):
    lines = _read_lines(path, "traction file")
    header, names, i = {}, None, 0
    while i < len(lines):
        t = lines[i].strip()
        i += 1
        if not t:
            continue
        if not t.startswith("%"):
            _fail(path, i, "expected a '%' header line of names")
        w = t[1:].split()
        if w[:2] == ["I", "IGS"]:
            names = w
            break
        vals = _numbers(lines[i].split()) if i < len(lines) else None
        if vals is None:
            _fail(path, i + 1, f"expected the numbers of header '{t}'")
        header.update((n, v) for n, v in zip(w, vals) if n != "-")
        i += 1
    if names is None:
        _fail(path, len(lines), "no column line '% I IGS ...'")
    if header.get("FMT") != 2410:
        _fail(path, 2, f"format FMT = {header.get('FMT')}; this reader knows 2410")
    for k in ("MX", "MY", "XL", "YL", "DX", "DY"):
        if k not in header:
            _fail(path, 1, f"the header holds no {k}")
    n_el = int(header["MX"]) * int(header["MY"])
    rows = []
    for j in range(i, len(lines)):
        w = lines[j].split()
        if not w:
            continue
        vals = _numbers(w)
        if vals is None or len(vals) != len(names):
            _fail(path, j + 1, f"an element row needs {len(names)} numbers ({len(w)} words; truncated?)")
        if not (1 <= vals[0] <= n_el) or vals[0] != int(vals[0]):
            _fail(path, j + 1, f"element number I = {w[0]} outside 1..{n_el}")
        rows.append(vals)
    if not rows:
        _fail(path, len(lines), "no element rows")
    table = np.array(rows)
    return {"path": path, "header": header, "columns": {n: table[:, k] for k, n in enumerate(names)}}


def element_centres(mat):
    """x, y (mm) of each row: XL + (ix - 1/2) DX, YL + (iy - 1/2) DY, I = ix + MX (iy - 1)."""
    h = mat["header"]
    i = mat["columns"]["I"].astype(int) - 1
    mx = int(h["MX"])
    return h["XL"] + (i % mx + 0.5) * h["DX"], h["YL"] + (i // mx + 0.5) * h["DY"]


def integrate(mat):
    """Totals over the rows (CONTACT's units, on body 1); Mz about the grid origin (N mm)."""
    c, h = mat["columns"], mat["header"]
    area = h["DX"] * h["DY"]
    x, y = element_centres(mat)
    igs = c["IGS"].astype(int)
    return {"Fn": area * c["PN"].sum(), "Fx": area * c["PX"].sum(), "Fy": area * c["PY"].sum(),
            "Mz": area * (c["PY"] * x - c["PX"] * y).sum(), "max_pn": c["PN"].max(),
            "n_exterior": int((igs == 0).sum()), "n_adhesion": int((igs == 1).sum()),
            "n_slip": int((igs == 2).sum())}


def read_inp(path):
    """Cases of a .inp: [{"module", "lines": [{"line", "numbers", "strings", "label"}]}]."""
    lines = _read_lines(path, "input")
    cases = []
    for n, raw in enumerate(lines, 1):
        t = raw.strip()
        if not t or t.startswith("%"):
            continue
        nums, strs, rest = [], [], t
        while rest:
            rest = rest.lstrip()
            if rest.startswith("'"):
                q = rest.find("'", 1)
                if q < 0:
                    _fail(path, n, "unclosed quote")
                strs.append(rest[1:q])
                rest = rest[q + 1:]
                continue
            word = rest.split()[0] if rest.split() else ""
            v = fortran_number(word)
            if v is None:
                break
            nums.append(v)
            rest = rest[len(word):]
        label = rest.strip()
        if label.startswith("MODULE") and len(nums) == 1:
            if nums[0] == 0:
                return cases
            cases.append({"module": int(nums[0]), "lines": []})
            continue
        if not cases:
            _fail(path, n, "data before the first 'n MODULE' line")
        cases[-1]["lines"].append({"line": n, "numbers": nums, "strings": strs, "label": label})
    _fail(path, len(lines), "no ' 0 MODULE' line ends the input (truncated?)")


def main(argv):
    for path in argv:
        if path.endswith(".mat"):
            t = integrate(read_mat(path))
            print(f"{path}: Fn {t['Fn']:.2f} N, Fx {t['Fx']:.2f} N, Fy {t['Fy']:.2f} N, "
                  f"Mz {t['Mz']:.2f} N mm; adhesion {t['n_adhesion']}, slip {t['n_slip']} elements")
        else:
            for c in read_out(path):
                for p in c["patches"]:
                    v = p["values"]
                    fy, mz = ("FS", "MN") if c["module"] == 1 else ("FY", "MZ")
                    print(f"{path}: case {c['number']} patch {p['number']}: FN {v['FN']:.4g} N, "
                          f"FX {v['FX']:.4g} N, {fy} {v[fy]:.4g} N, {mz} {v[mz]:.4g} N mm")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        print(__doc__)
        sys.exit(2)
    try:
        main(sys.argv[1:])
    except ContactFileError as e:
        print(f"{os.path.basename(sys.argv[0])}: error: {e}", file=sys.stderr)
        sys.exit(2)
