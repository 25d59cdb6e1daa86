#!/usr/bin/python3
"""Force histories of a `rollnoise transient` run (the unsteady solver) or of a `rollnoise response`
run (the linear model), with the creepage and normal-load histories that drive them.

  /usr/bin/python3 postprocess/plot_transient.py OUT.h5 [-o transient.png]

Left: Fx, Fy, Mz and the normal force N against time (units from the datasets; a response file
also shows the harmonic synthesis, paper Eqs. 33-34, when it has one). Right: the creepages
xi_x, xi_y, phi and, for a transient run, the adhesion and slip element counts.
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402


def main():
    file, out = rh.file_and_output(__doc__, "_forces.png")
    with rh.open_output(file, ("/transient/force", "/response/force"),
                        command="rollnoise transient` or `rollnoise response") as f:
        g = "/transient" if "/transient/force" in f else "/response"
        for name in ("time", "creepage"):
            if f"{g}/{name}" not in f:
                rh.fail(f"{file}: no {g}/{name}")
        t = rh.values(f, g + "/time")
        force = rh.values(f, g + "/force")
        units = rh.component_units(f, g + "/force", 3)
        creepage = rh.values(f, g + "/creepage")
        creep_units = rh.component_units(f, g + "/creepage", 3)
        normal = rh.values(f, g + "/normal_force") if g + "/normal_force" in f else None
        synthesis = rh.values(f, g + "/force_synthesis") if g + "/force_synthesis" in f else None
        n_adh = rh.values(f, g + "/n_adhesion") if g + "/n_adhesion" in f else None
        n_slip = rh.values(f, g + "/n_slip") if g + "/n_slip" in f else None
    ms = t * 1e3
    fig, axes = plt.subplots(4, 2, figsize=(12, 9), sharex=True)
    label = "unsteady solver" if g == "/transient" else "linear model, recursion"
    for j, name in enumerate(["Fx", "Fy", "Mz"]):
        ax = axes[j, 0]
        ax.plot(ms, force[:, j], "k-", lw=1.0, label=label)
        if synthesis is not None:
            ax.plot(ms, synthesis[:, j], "b:", lw=1.0, label="harmonic synthesis (Eqs. 33-34)")
        ax.set_ylabel(f"{name} [{units[j]}]")
        axes[j, 1].plot(ms, creepage[:, j], "-", color="tab:green", lw=1.0)
        axes[j, 1].set_ylabel(f"{['xi_x', 'xi_y', 'phi'][j]} [{creep_units[j]}]")
    axes[0, 0].legend(fontsize=8)
    if normal is not None:
        axes[3, 0].plot(ms, normal, "k-", lw=1.0)
    axes[3, 0].set_ylabel("N [N]")
    if n_adh is not None and n_slip is not None:
        axes[3, 1].plot(ms, n_adh, "-", color="tab:blue", label="adhesion")
        axes[3, 1].plot(ms, n_slip, "-", color="tab:red", label="slip")
        axes[3, 1].legend(fontsize=8)
        axes[3, 1].set_ylabel("elements")
    else:
        axes[3, 1].axis("off")
    for ax in axes.flat:
        ax.grid(alpha=0.3)
    for ax in axes[3]:
        ax.set_xlabel("t [ms]")
    fig.suptitle(f"{file}: {g[1:]} ({len(t)} steps)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    rh.run(main)
