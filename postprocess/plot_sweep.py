#!/usr/bin/python3
"""Force-creepage curves of a steady sweep (`rollnoise steady CASE --sweep SPEC`).

  /usr/bin/python3 postprocess/plot_sweep.py OUT.h5 [-o sweep.png]

Fx, Fy and Mz (units from the datasets) against the swept value: the varying creepage component
for a creepage sweep (`creepage.mean[0]=0:0.01:21`, or a list of creepage vectors when one
component varies), otherwise the value of the swept key (`friction.mu=0.1:0.5:5`) or the point
index (a TOML-array sweep of vectors). The Coulomb bound +-mu N is drawn dotted on the force
panels (mu and N of the case, unless the sweep varies them); the last panel counts adhesion and
slip elements per point.
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollnoise_h5 as rh  # noqa: E402

CREEPAGE_NAMES = ["xi_x [-]", "xi_y [-]", "phi [rad/m]"]


def x_axis(spec, value, creepage):
    """(x values, label) for the sweep `spec`."""
    key, _, values = spec.partition("=")
    key = key.strip()
    varying = [j for j in range(3) if np.ptp(creepage[:, j]) > 0]
    if key.startswith("creepage.mean") and len(varying) == 1:
        j = varying[0]
        return creepage[:, j], f"{['xi_x', 'xi_y', 'phi'][j]} (creepage.mean[{j}]) [{['-', '-', 'rad/m'][j]}]"
    if values.strip().startswith("["):  # a TOML array of values: one point each
        return np.arange(len(value)), f"point of --sweep {spec}"
    return value, key


def main():
    file, out = rh.file_and_output(__doc__, "_sweep.png")
    with rh.open_output(file, "/sweep/force", "/sweep/creepage", "/sweep/value",
                        command="rollnoise steady --sweep") as f:
        force = rh.values(f, "/sweep/force")
        units = rh.component_units(f, "/sweep/force", 3)
        creepage = rh.values(f, "/sweep/creepage")
        value = rh.values(f, "/sweep/value")
        n_adh = rh.values(f, "/sweep/n_adhesion") if "/sweep/n_adhesion" in f else None
        n_slip = rh.values(f, "/sweep/n_slip") if "/sweep/n_slip" in f else None
        spec = rh.attribute(f["/sweep"], "spec", "")
        mu = rh.case_value(f, "friction", "mu")
        normal = float(rh.values(f, "/normal/force")) if "/normal/force" in f else None
    x, xlabel = x_axis(spec, value, creepage)
    order = np.argsort(x, kind="stable")
    fig, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    for j, (ax, name) in enumerate(zip(axes, ["Fx", "Fy", "Mz"])):
        ax.plot(x[order], force[order, j], "o-", ms=3, color="k")
        ax.set_ylabel(f"{name} [{units[j]}]")
        ax.grid(alpha=0.3)
        key = spec.split("=", 1)[0]
        if j < 2 and mu and normal and not key.startswith(("friction.mu", "contact.normal_force")):
            bound = float(mu) * normal
            for s in (-1, 1):
                ax.axhline(s * bound, color="tab:red", ls=":", lw=1,
                           label="Coulomb bound ±mu N" if s > 0 else None)
            ax.legend(fontsize=8)
    if n_adh is not None and n_slip is not None:
        axes[3].plot(x[order], n_adh[order], "o-", ms=3, color="tab:blue", label="adhesion")
        axes[3].plot(x[order], n_slip[order], "o-", ms=3, color="tab:red", label="slip")
        axes[3].legend(fontsize=8)
    axes[3].set_ylabel("elements")
    axes[3].grid(alpha=0.3)
    axes[3].set_xlabel(xlabel)
    axes[0].set_title(f"{file}: --sweep {spec} ({len(value)} points)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    rh.run(main)
