#!/usr/bin/python3
"""Run CONTACT (Vollebregt & Kalker) on an input written by `rollnoise contact-input`, when the
environment variable CONTACT_EXE names its stand-alone executable, and print its totals.

  CONTACT_EXE=/path/to/contact_linux64 /usr/bin/python3 postprocess/run_contact.py DIR/NAME.inp

CONTACT runs in the input's folder as the reference runs were made
(`OMP_NUM_THREADS=1 $CONTACT_EXE 2 NAME`: mode 2 = batch run of NAME.inp in the current folder) and
writes NAME.out and the .mat files beside the input; that folder is then what
`rollnoise validate|steady CASE --reference contact DIR` reads. Without CONTACT_EXE, or when CONTACT
fails, one line on stderr and exit status 2 (CONTACT's own status when it fails).
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_files  # noqa: E402


def main(argv):
    if len(argv) != 1 or not argv[0].endswith(".inp"):
        print(__doc__, file=sys.stderr)
        return 2
    exe = os.environ.get("CONTACT_EXE")
    if not exe:
        print("run_contact.py: error: CONTACT_EXE is not set (the path of CONTACT's executable)", file=sys.stderr)
        return 2
    inp = os.path.abspath(argv[0])
    if not os.path.isfile(inp):
        print(f"run_contact.py: error: {inp}: no such input", file=sys.stderr)
        return 2
    folder, name = os.path.dirname(inp), os.path.basename(inp)[:-4]
    env = dict(os.environ, OMP_NUM_THREADS="1")
    try:
        r = subprocess.run([exe, "2", name], cwd=folder, env=env, capture_output=True, text=True)
    except OSError as e:
        print(f"run_contact.py: error: cannot run {exe}: {e.strerror}", file=sys.stderr)
        return 2
    if r.returncode != 0:
        print(f"run_contact.py: error: {exe} 2 {name} (in {folder}) ended with status {r.returncode}:\n"
              f"{r.stderr[-2000:]}", file=sys.stderr)
        return r.returncode if 0 < r.returncode < 128 else 2
    try:
        contact_files.main([os.path.join(folder, name + ".out")])
    except contact_files.ContactFileError as e:
        print(f"run_contact.py: error: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
