# SPDX-License-Identifier: MIT
"""Load against friction: the paper's extrusion benchmark for a few values of mu_f.

    PYTHONPATH=build/python python3 examples/friction_sweep.py [output.png]

Solves the benchmark (Q2, 2x2 volumetric rule) on mesh I for mu_f = 0 ... 0.2,
prints the extrusion pressure measured two ways, and plots it against mu_f
(matplotlib, Agg backend: no display needed). Written like a notebook: each
block is a cell. Expected: the ram reaction rises from 2.920 at mu_f = 0 to
2.998 at mu_f = 0.2 (the power balance from 2.799 to 2.884).
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after the backend is chosen)

import formflow  # noqa: E402

# %% One case, changed key by key: every set() is validated like --set.
case = formflow.Case({"mesh.size": 10 / 6})
frictions = [0.0, 0.05, 0.1, 0.15, 0.2]
reaction, power = [], []
for mu in frictions:
    result = formflow.run(case.set("friction.mu", mu))
    if not result.converged:
        sys.exit(f"mu = {mu}: not converged ({result.stop_reason})")
    reaction.append(result.pressure.ram_reaction)
    power.append(result.pressure.power_balance)
    print(f"mu = {mu:4.2f}: ram reaction {reaction[-1]:.4f}, power balance {power[-1]:.4f}, "
          f"{result.iterations} iterations")

# %% The plot.
figure, axes = plt.subplots(figsize=(6, 4))
axes.plot(frictions, reaction, "o-", label="ram reaction / height")
axes.plot(frictions, power, "s--", label="power balance")
axes.set_xlabel("friction coefficient $\\mu_f$")
axes.set_ylabel("extrusion pressure $p / k$")
axes.set_title("Plane-strain extrusion, 50 % reduction (mesh I, Q2)")
axes.grid(True, alpha=0.3)
axes.legend()
figure.tight_layout()
output = sys.argv[1] if len(sys.argv) > 1 else "friction_sweep.png"
figure.savefig(output, dpi=120)
print(f"plot written to {output}")
