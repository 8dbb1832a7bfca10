"""Tamaas's EPICSolver on the problem of scenes/plastic_rigid_ball_on_flat.toml: a rigid
sphere (R = 10 mm) pressed into an elastic-plastic half-space (E = 210 GPa, nu = 0.3,
Y = 1 GPa, perfectly plastic) to Hertz's p0 = P0_OVER_Y * Y, then unloaded.

Tamaas is periodic: the period is PERIOD_OVER_A Hertz radii (a large period isolates the
contact), with N x N points and NZ layers down to DEPTH_OVER_A radii.

Run in a throw-away venv (`python3 -m venv /tmp/venv && /tmp/venv/bin/pip install tamaas
numpy`):
    /tmp/venv/bin/python benches/peers/tamaas_epic.py P0_OVER_Y N NZ PERIOD_OVER_A DEPTH_OVER_A STEPS
Prints one JSON line with the quantities of `stressfield plastic --json` that Tamaas gives
and the wall time of the solve.

Reference: L. Frérot, M. Bonnet, J.-F. Molinari, G. Anciaux, A Fourier-accelerated volume
integral method for elastoplastic contact, CMAME 351 (2019) 951-976.
"""

import json
import sys
import time
import warnings

import numpy as np
import tamaas as tm
from tamaas.nonlinear_solvers import DFSANECXXSolver

E, NU, Y, R = 210e9, 0.3, 1e9, 10e-3


def solve(p0_over_y, n, nz, period_over_a, depth_over_a, steps, tolerance=1e-6, unload=True):
    """The problem solved by EPIC; returns the dict printed by `main`."""
    tm.set_log_level(tm.LogLevel.error)
    e_star = E / (1 - NU**2)
    load = (np.pi * p0_over_y * Y) ** 3 * R**2 / (6 * e_star**2)
    a = (3 * load * R / (4 * e_star)) ** (1 / 3)
    period, depth = period_over_a * a, depth_over_a * a
    model = tm.ModelFactory.createModel(tm.model_type.volume_2d, [depth, period, period], [nz, n, n])
    model.E, model.nu = E, NU
    dx = period / n
    x = np.arange(n) * dx - period / 2
    xx, yy = np.meshgrid(x, x, indexing="ij")
    surface = -(xx**2 + yy**2) / (2 * R)
    initial = surface.copy()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        residual = tm.ModelFactory.createResidual(model, sigma_y=Y, hardening=0.0)
    epsolver = DFSANECXXSolver(residual)
    csolver = tm.PolonskyKeerRey(model, surface, 1e-12)
    tm.ModelFactory.registerVolumeOperators(model)
    epic = tm.EPICSolver(csolver, epsolver, tolerance, relaxation=0.3)
    started = time.perf_counter()
    for k in range(1, steps + 1):
        epic.solve(load * k / steps / period**2)
    loaded_time = time.perf_counter() - started
    pressure = np.array(model.traction)[..., 2].copy()
    kappa = np.array(model["cumulated_plastic_strain"]).reshape(nz, n, n).copy()
    z = np.linspace(0, depth, nz)
    contact_area = np.count_nonzero(pressure > 0) * dx * dx
    where = np.unravel_index(np.argmax(kappa), kappa.shape)
    plastic = kappa > 1e-5
    zone_depth = float(z[np.nonzero(plastic.any(axis=(1, 2)))[0].max()]) if plastic.any() else 0.0
    # Unloading: a vanishing load (the contact solver needs one) in steps.
    started = time.perf_counter()
    for k in range(1, (steps // 2 + 1) if unload else 1):
        epic.solve(max(load * (1 - k / (steps // 2)), 1e-9 * load) / period**2)
    unload_time = time.perf_counter() - started
    # The surface displacement of the plastic strain (the dent at zero load): EPIC offsets the
    # contact solver's surface (this array, held by reference) by the residual displacement of
    # the plastic strain, surface = initial - u_plastic (u_plastic > 0 into the body). Tamaas is
    # periodic (the displacement's mean over the period is free), so the dent is read relative to
    # the point half a period away on the diagonal (the corner of the cell).
    u_plastic = initial - surface
    dent = float(u_plastic[n // 2, n // 2] - u_plastic[0, 0])
    return {
        "p0_over_y": p0_over_y, "grid": [n, n, nz], "period_over_a": period_over_a,
        "depth_over_a": depth_over_a, "steps": steps, "tolerance": tolerance,
        "load_n": load, "hertz_radius_m": a,
        "max_pressure_pa": float(pressure.max()),
        "contact_radius_m": float(np.sqrt(contact_area / np.pi)),
        "max_plastic_strain": float(kappa.max()),
        "max_plastic_strain_depth_m": float(z[where[0]]),
        "plastic_zone_depth_m": zone_depth,
        "residual_depth_m": dent,
        "residual_displacement_x_m": [float(u) for u in u_plastic[:, n // 2] - u_plastic[0, 0]],
        "x_m": [float(v) for v in x],
        "load_seconds": loaded_time, "unload_seconds": unload_time,
    }


def main():
    p0_over_y, n, nz = float(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
    period_over_a, depth_over_a, steps = float(sys.argv[4]), float(sys.argv[5]), int(sys.argv[6])
    tolerance = float(sys.argv[7]) if len(sys.argv) > 7 else 1e-6
    print(json.dumps(solve(p0_over_y, n, nz, period_over_a, depth_over_a, steps, tolerance)))


if __name__ == "__main__":
    main()
