#!/usr/bin/python3
"""Smoke test of the plot scripts (postprocess/): each runs on a real, small output of the
program (Agg backend, coarse grids) and writes its PNG files; a wrong input file (missing, not
HDF5, another command's output) gives one line on stderr and exit status 2, no traceback.

  /usr/bin/python3 tests/postprocess/smoke_test.py ROLLNOISE_BINARY WORKDIR

Run by CTest (test `postprocess_plots_smoke`, CMakeLists.txt). Prints 'N passed, M failed'.
"""
import contextlib
import csv
import io
import os
import runpy
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
POST = os.path.join(ROOT, "postprocess")
CASES = os.path.join(ROOT, "cases")
sys.path.insert(0, POST)  # the scripts' shared module, as when they run from postprocess/
COARSE = ["--set", "grid.nx=20", "--set", "grid.ny=15"]

# another command's output, which the script cannot plot
OTHER_OUTPUT = {"plot_patch.py": "sweep.h5", "plot_creep.py": "steady.h5"}
EXTRA_ARGS = {"plot_study.py": ["--x", "curve.radius"]}  # options a script requires

passed, failed = 0, []


def check(name, ok, detail=""):
    global passed
    if ok:
        passed += 1
    else:
        failed.append(name)
        print(f"FAIL {name}: {detail}")


def rollnoise(binary, work, *args):
    r = subprocess.run([binary, *args, "-q"], cwd=work, capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        print(f"rollnoise {' '.join(args)} failed ({r.returncode}):\n{r.stdout}{r.stderr}")
        sys.exit(1)


def plot(script, *args):
    """Runs postprocess/SCRIPT in this process (matplotlib is imported once); (status, stderr)."""
    argv, sys.argv = sys.argv, [os.path.join(POST, script), *args]
    err = io.StringIO()
    status = 0
    try:
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            runpy.run_path(sys.argv[0], run_name="__main__")
    except SystemExit as e:
        status = e.code if isinstance(e.code, int) else 1
    except Exception as e:  # a traceback is a failure of the script
        status, err = -1, io.StringIO(f"{type(e).__name__}: {e}")
    finally:
        sys.argv = argv
    return status, err.getvalue()


def main():
    binary, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    t0 = time.time()
    hertz = os.path.join(CASES, "hertz_paper.toml")
    rollnoise(binary, work, "steady", hertz, "-o", "steady.h5", *COARSE)
    rollnoise(binary, work, "steady", hertz, "-o", "sweep.h5", *COARSE, "--sweep", "creepage.mean[0]=0:0.004:5")
    rollnoise(binary, work, "transient", hertz, "-o", "transient.h5", *COARSE, "--set", "transient.duration=0.002",
              "--set", "transient.snapshots=[0.001, 0.002]", "--set", "excitation.amplitude=[5e-5, 0, 0]")
    rollnoise(binary, work, "creep", hertz, "-o", "creep.h5", *COARSE, "--set", "frequency.count=20")
    rollnoise(binary, work, "statespace", hertz, "-o", "statespace.h5", *COARSE, "--set", "frequency.count=30")
    rollnoise(binary, work, "validate", os.path.join(CASES, "paper_s32_combined.toml"), "-o", "validate.h5",
              *COARSE, "--set", "transient.duration=0.003", "--set", "transient.analysis_start=0.001")
    rollnoise(binary, work, "response", os.path.join(CASES, "paper_s32_combined.toml"), "-o", "response.h5",
              *COARSE, "--set", "transient.duration=0.002")
    rollnoise(binary, work, "noise", os.path.join(CASES, "curve_300m_hertz.toml"), "-o", "noise.h5", *COARSE,
              "--set", "noise.points_per_band=4", "--set", "track.support=\"continuous\"")
    # the bogie: per-wheel groups /noise/wheels/* (the table-wheel profile case, coarse: ~1.5 s)
    rollnoise(binary, work, "noise", os.path.join(CASES, "curve_300m_table.toml"), "-o", "noise_wheels.h5",
              "--set", "grid.nx=12", "--set", "grid.ny=10", "--set", "noise.points_per_band=4",
              "--set", "track.support=\"continuous\"", "--set", "noise.band_max=800")
    # the pass-by of two coaches on a coarse sampling (~2 s)
    rollnoise(binary, work, "passby", os.path.join(CASES, "passby_tangent.toml"), "-o", "passby.h5",
              "--set", "wheel.mesh_size=0.03", "--set", "wheel.n_max=3", "--set", "wheel.f_max=2500",
              "--set", "noise.points_per_band=4", "--set", "noise.band_refinement=0", "--set", "noise.band_min=500",
              "--set", "noise.band_max=2000", "--set", "train.vehicles=2")
    rollnoise(binary, work, "modes", os.path.join(CASES, "curve_300m.toml"), "-o", "modes.h5",
              "--set", 'curve.creepage="estimate"',
              "--set", "wheel.mesh_size=0.03", "--set", "wheel.n_max=3", "--set", "wheel.f_max=2000")
    rollnoise(binary, work, "corrugation", hertz, "-o", "corrugation.h5", *COARSE, "--set", "corrugation.points=20",
              "--set", "corrugation.wavelength_min=0.02")
    rollnoise(binary, work, "bench", hertz, "--nx", "8,10,12", "--csv", os.path.join(work, "bench.csv"))
    rollnoise(binary, work, "receptance", os.path.join(CASES, "curve_300m_hertz.toml"), "-o", "rail_waves.h5",
              *COARSE, "--set", "frequency.count=4", "--set", "track.support=\"continuous\"",
              "--set", "track.model=\"waveguide\"")
    rollnoise(binary, work, "receptance", os.path.join(CASES, "tangent.toml"), "-o", "receptance.h5", *COARSE,
              "--set", "frequency.count=40")
    with open(os.path.join(work, "study.toml"), "w") as f:  # 4 cases of the small study case
        f.write(f'base = "{os.path.join(ROOT, "tests/data/study/curve_small.toml")}"\noutput = "study"\n[axes]\n'
                '"curve.radius" = [300.0, 600.0]\n"roughness.wheel" = ["cast-iron", "disc-braked"]\n')
    rollnoise(binary, work, "study", "study.toml", "-j", "1")
    rollnoise(binary, work, "collect", "study.toml")
    t_runs = time.time() - t0
    j = lambda name: os.path.join(work, name)  # noqa: E731
    runs = [  # script, arguments, files it must write
        ("plot_patch.py", [j("steady.h5"), "-o", j("patch.png")], ["patch.png"]),
        ("plot_patch.py", [j("transient.h5"), "--snapshot", "1", "-o", j("patch_snap.png")], ["patch_snap.png"]),
        ("plot_sweep.py", [j("sweep.h5"), "-o", j("sweep.png")], ["sweep.png"]),
        ("plot_transient.py", [j("transient.h5"), "-o", j("forces.png")], ["forces.png"]),
        ("plot_transient.py", [j("response.h5"), "-o", j("response.png")], ["response.png"]),
        ("plot_creep.py", [j("creep.h5"), "--entries", "11,22,23,33", "-o", j("creep.png")], ["creep.png"]),
        ("plot_statespace.py", [j("statespace.h5"), "-o", j("statespace.png")], ["statespace.png"]),
        ("plot_validate.py", [j("validate.h5"), "--prefix", j("val")], ["val_time.png", "val_spectra.png"]),
        ("plot_noise.py", [j("noise.h5"), "--prefix", j("noise")], ["noise_bands.png", "noise_transfer.png",
                                                                   "noise_velocity.png", "noise_sound.png"]),
        ("plot_noise.py", [j("noise_wheels.h5"), "--wheel", "trailing_inner", "--prefix", j("noise_ti")],
         ["noise_ti_bands.png", "noise_ti_wheels.png", "noise_ti_sound.png"]),
        # two runs overlaid (different band ranges), labelled
        ("plot_noise.py", [j("noise.h5"), j("noise_wheels.h5"), "--label", "Hertz", "--label", "bogie", "--prefix",
                           j("noise_cmp")], ["noise_cmp_bands.png", "noise_cmp_transfer.png", "noise_cmp_velocity.png",
                                             "noise_cmp_wheels.png", "noise_cmp_sound.png"]),
        ("plot_bench.py", [j("bench.csv"), "-o", j("bench.png")], ["bench.png"]),
        # roughness files against the EN ISO 3095 limit (no program output needed)
        ("plot_roughness.py", [os.path.join(ROOT, "models", "roughness", "wheel_cast_iron_block.csv"),
                               os.path.join(ROOT, "models", "roughness", "wheel_disc_braked.csv"), "--label", "cast iron",
                               "--label", "disc", "-o", j("roughness.png")], ["roughness.png"]),
        ("plot_passby.py", [j("passby.h5"), "-o", j("passby.png")], ["passby.png"]),
        ("plot_corrugation.py", [j("corrugation.h5"), "-o", j("corrugation.png")], ["corrugation.png"]),
        ("plot_modes.py", [j("modes.h5"), "--s", "-0.02", "--prefix", j("modes")],
         ["modes_sections.png", "modes_receptance.png"]),
        ("plot_rail_waves.py", [j("rail_waves.h5"), "-o", j("rail_waves.png")], ["rail_waves.png"]),
        ("plot_receptance.py", [j("receptance.h5"), "-o", j("receptance.png")], ["receptance.png"]),
        ("plot_receptance.py", [j("receptance.h5"), j("rail_waves.h5"), "--label", "tangent", "--label", "waveguide",
                                "--entries", "11,33,13", "-o", j("receptance_cmp.png")], ["receptance_cmp.png"]),
        ("plot_study.py", [j("study/study.h5"), "--x", "curve.radius", "--curves", "roughness.wheel", "-o",
                           j("study.png")], ["study.png"]),
        # runs `rollnoise squeal` itself: 2 x 2 runs on a coarse grid (~1 s)
        ("plot_squeal_map.py", ["--binary", binary, "--fast", "--work", j("squeal_map"), "-o", j("squeal_map.png"),
                                "--set", "grid.nx=12", "--set", "grid.ny=10", "--set", "grid.scale=1.3",
                                "--set", "noise.band_max=2000"], ["squeal_map.png", "squeal_map/summary.csv"]),
        # the wheels' panel: one run of the profile case with every wheelset (constant friction, 300-400 Hz, ~1 s);
        # the table-wheel twin of curve_300m (the FE wheel's squeal per wheelset is checked in WheelsetPassivity)
        ("plot_squeal_map.py", ["--binary", binary, "--case", os.path.join(CASES, "curve_300m_table.toml"), "--radii",
                                "300",
                                "--param", "friction.mu", "--values", "0.3", "--wheelsets", "--work",
                                j("squeal_map_wheels"), "-o", j("squeal_map_wheels.png"), "--set", "grid.nx=12",
                                "--set", "grid.ny=10", "--set", "noise.band_max=400", "--set",
                                'track.support="continuous"'],
         ["squeal_map_wheels.png", "squeal_map_wheels/summary.csv"]),
    ]
    for script, args, outputs in runs:
        status, err = plot(script, *args)
        check(f"{script} {os.path.basename(args[0])}", status == 0 and all(os.path.getsize(j(o)) > 0 for o in outputs
                                                                          if os.path.exists(j(o))) and
              all(os.path.exists(j(o)) for o in outputs), f"status {status}: {err}")
    # the wheels' map ran the squeal of the wheelsets (a column per wheel, wheelsets_run = 1)
    summary = j("squeal_map_wheels/summary.csv")
    if os.path.exists(summary):
        with open(summary) as f:
            rows = list(csv.DictReader(f))
        check("plot_squeal_map.py --wheelsets summary", len(rows) == 1 and "leading_inner_unstable_modes" in rows[0] and
              rows[0].get("wheelsets_run") == "1", str(rows))
    # wrong inputs: one line naming the file, exit status 2
    with open(j("not_hdf5.h5"), "w") as f:
        f.write("not HDF5\n")
    wrong = [(s, bad) for s in ["plot_patch.py", "plot_sweep.py", "plot_transient.py", "plot_creep.py",
                                "plot_rail_waves.py", "plot_statespace.py", "plot_validate.py", "plot_noise.py", "plot_receptance.py", "plot_bench.py", "plot_study.py",
                                "plot_modes.py", "plot_roughness.py", "plot_passby.py", "plot_corrugation.py"]
             for bad in [j("missing.h5"), j("not_hdf5.h5"), j(OTHER_OUTPUT.get(s, "creep.h5"))]]
    for script, bad in wrong:
        status, err = plot(script, bad, *EXTRA_ARGS.get(script, []))
        lines = err.strip().splitlines()
        check(f"{script} {os.path.basename(bad)} refused", status == 2 and len(lines) == 1 and bad in lines[0]
              and "Traceback" not in err, f"status {status}, stderr {err!r}")
    # several files: a wrong one among them, or --label not once per file
    for script, args, bad in [("plot_noise.py", [j("noise.h5"), j("not_hdf5.h5")], j("not_hdf5.h5")),
                              ("plot_noise.py", [j("noise.h5"), j("noise_wheels.h5"), "--label", "one"], "--label")]:
        status, err = plot(script, *args)
        lines = err.strip().splitlines()
        check(f"{script} {' '.join(os.path.basename(a) for a in args)} refused", status == 2 and len(lines) == 1
              and bad in lines[0] and "Traceback" not in err, f"status {status}, stderr {err!r}")
    # the same through a real process: the exit status a shell sees
    r = subprocess.run(["/usr/bin/python3", os.path.join(POST, "plot_noise.py"), j("not_hdf5.h5")],
                       capture_output=True, text=True)
    check("plot_noise.py process exit 2", r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr)
    print(f"(program runs {t_runs:.1f} s, plots {time.time() - t0 - t_runs:.1f} s)")
    print(f"{passed} passed, {len(failed)} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
