#!/usr/bin/python3
"""postprocess/contact_files.py on the raw CONTACT runs of tests/data/contact/raw: the printed
totals read back exactly, the integrated ones equal the values documented with the files (2
decimals, tolerance 0.006), and cut or bad files give one line naming the file and line with exit
status 2. Run by CTest (test `postprocess_contact_files`). Prints 'N passed, M failed'."""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "postprocess"))
import contact_files as cf  # noqa: E402

RAW = os.path.join(ROOT, "tests", "data", "contact", "raw")
passed, failed = 0, []


def check(name, ok, detail=""):
    global passed
    if ok:
        passed += 1
    else:
        failed.append(name)
        print(f"FAIL {name}: {detail}")


def near(a, b, tol):
    return abs(a - b) <= tol


s2 = cf.read_out(os.path.join(RAW, "S2", "S2_coarse.out"))[0]["patches"][0]["values"]
check("S2 printed", (s2["FN"], s2["FX"], s2["FY"], s2["MZ"], s2["NSLIP"]) == (98100, -11760, -8965, 22110, 177),
      s2)
t = cf.integrate(cf.read_mat(os.path.join(RAW, "S2", "S2_coarse.0001.mat")))
check("S2 integrated", all(near(t[k], v, 0.006) for k, v in
                           {"Fn": 98100.16, "Fx": -11761.00, "Fy": -8965.09, "Mz": 22110.83}.items()), t)
check("S2 counts", (t["n_exterior"], t["n_adhesion"], t["n_slip"]) == (312, 361, 177), t)
u1 = cf.read_out(os.path.join(RAW, "U1", "U1_coarse_40steps.out"))
check("U1 cases", len(u1) == 41 and u1[1]["patches"][0]["values"]["FX"] == -12520, len(u1))
for n, fx in (("0002", -12520.02), ("0041", -12556.23)):
    t = cf.integrate(cf.read_mat(os.path.join(RAW, "U1", f"U1_coarse_40steps.{n}.mat")))
    check(f"U1 {n} integrated", near(t["Fx"], fx, 0.006) and t["n_slip"] == 142, t)
c1 = cf.read_out(os.path.join(RAW, "C1_u3", "u3_norm_d2.out"))[0]
check("C1 case and patch", c1["module"] == 1 and c1["values"]["FY(TR)"] == -13480
      and c1["patches"][0]["values"]["MN"] == 4560, c1)
inp = cf.read_inp(os.path.join(RAW, "U1", "U1_coarse_40steps.inp"))
check("U1 input", len(inp) == 41 and inp[1]["lines"][-1]["numbers"][1] == 0.00104883229430894, inp[1])
check("3-digit exponent", near(cf.fortran_number("0.228751-310") / 0.228751e-310, 1, 1e-12))

with tempfile.TemporaryDirectory() as d:
    text = open(os.path.join(RAW, "S2", "S2_coarse.0001.mat")).read()
    cut = os.path.join(d, "cut.mat")
    open(cut, "w").write(text[:-40])
    r = subprocess.run([sys.executable, os.path.join(ROOT, "postprocess", "contact_files.py"), cut],
                       capture_output=True, text=True)
    check("cut .mat", r.returncode == 2 and f"{cut}:863:" in r.stderr and "Traceback" not in r.stderr, r.stderr)
    out = os.path.join(d, "cut.out")
    text = open(os.path.join(RAW, "S2", "S2_coarse.out")).read()
    open(out, "w").write(text[:text.find("Performance")])
    r = subprocess.run([sys.executable, os.path.join(ROOT, "postprocess", "contact_files.py"), out],
                       capture_output=True, text=True)
    check("cut .out", r.returncode == 2 and f"{out}:" in r.stderr and "truncated" in r.stderr, r.stderr)

# run_contact.py: without CONTACT_EXE exit 2; with a stand-in executable (copies S2's .out) it runs
# "EXE 2 NAME" in the input's folder and prints the totals
RUN = os.path.join(ROOT, "postprocess", "run_contact.py")
with tempfile.TemporaryDirectory() as d:
    inp = os.path.join(d, "S2_coarse.inp")
    open(inp, "w").write(open(os.path.join(RAW, "S2", "S2_coarse.inp")).read())
    env = {k: v for k, v in os.environ.items() if k != "CONTACT_EXE"}
    r = subprocess.run([sys.executable, RUN, inp], capture_output=True, text=True, env=env)
    check("run_contact without CONTACT_EXE", r.returncode == 2 and "CONTACT_EXE" in r.stderr, r.stderr)
    fake = os.path.join(d, "fake_contact")
    open(fake, "w").write(f"#!/bin/sh\n[ \"$1\" = 2 ] && cp {os.path.join(RAW, 'S2', 'S2_coarse.out')} \"$2.out\"\n")
    os.chmod(fake, 0o755)
    r = subprocess.run([sys.executable, RUN, inp], capture_output=True, text=True, env=dict(env, CONTACT_EXE=fake))
    check("run_contact with CONTACT_EXE", r.returncode == 0 and "FX -1.176e+04 N" in r.stdout, r.stdout + r.stderr)

print(f"{passed} passed, {len(failed)} failed")
sys.exit(1 if failed else 0)
