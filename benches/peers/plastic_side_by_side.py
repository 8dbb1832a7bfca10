"""stressfield's volume plasticity beside Tamaas's EPICSolver, one after the other in one run
(issue 51's speed target: at most half of EPIC's time at equal grid and tolerance).

The problem of `benches/plastic_point.rs` and `scenes/plastic_rigid_ball_on_flat.toml`: a
rigid ball (R = 10 mm) on an elastic-plastic steel flat (E = 210 GPa, nu = 0.3, Y = 1 GPa,
perfectly plastic) pressed to Hertz's p0 = 2.5 Y in two load steps, tolerance 1e-6, no
unloading; N x N cells over +-2 a_H (stressfield isolated by zero padding, Tamaas periodic
with that period) and N/2 layers down to 2 a_H. For each N given, Tamaas solves first (its
load steps timed inside this process, one thread), then `stressfield plastic` (the whole
process timed, REPEATS runs, the fastest kept). Prints a Markdown table.

    /tmp/venv/bin/python benches/peers/plastic_side_by_side.py [STRESSFIELD] [N ...]

STRESSFIELD defaults to target/release/stressfield; N to 32 64. Tamaas at 128 takes about
three quarters of an hour on this machine kind.
"""

import json
import os
import subprocess
import sys
import tempfile
import time

import tamaas_epic

REPEATS = 3
SCENE = """format = 1
[contact]
kind = "point"
load = "{load} N"
[contact.body1]
radius = "flat"
material = "steel"
[contact.body2]
radius = "10 mm"
material = "rigid"
[plasticity]
yield_strength = "1 GPa"
hardening_modulus = "0 GPa"
unload = false
steps = 2
tolerance = 1e-6
grid_cells = {n}
depth_cells = {nz}
extent_over_a = 2.0
depth_over_a = 2.0
"""


def stressfield(binary, n, nz, load):
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, f"ball{n}.toml")
        with open(path, "w") as scene:
            scene.write(SCENE.format(load=repr(load), n=n, nz=nz))
        best, report = float("inf"), None
        for _ in range(REPEATS):
            started = time.perf_counter()
            out = subprocess.run([binary, "plastic", path, "--json"], check=True,
                                 capture_output=True, text=True).stdout
            best = min(best, time.perf_counter() - started)
            report = json.loads(out)
    return best, report


def main():
    args = sys.argv[1:]
    binary = args.pop(0) if args and not args[0].isdigit() else "target/release/stressfield"
    sizes = [int(a) for a in args] or [32, 64]
    rows = []
    for n in sizes:
        nz = n // 2
        peer = tamaas_epic.solve(2.5, n, nz, 4.0, 2.0, 2, 1e-6, unload=False)
        ours, report = stressfield(binary, n, nz, peer["load_n"])
        loaded = report["loaded"]
        rows.append((n, nz, peer, ours, loaded, report["iterations"]))
    print("| volume | Tamaas EPIC, load steps | stressfield, whole process | ratio |"
          " peak pressure (sf / Tamaas) | contact radius | largest plastic strain |")
    print("|---|---|---|---|---|---|---|")
    for n, nz, peer, ours, loaded, iterations in rows:
        print(f"| {n} x {n} x {nz} | {peer['load_seconds']:.1f} s | {ours:.2f} s "
              f"({iterations} iterations) | {peer['load_seconds'] / ours:.0f} x | "
              f"{loaded['max_pressure_pa'] / 1e6:.1f} / {peer['max_pressure_pa'] / 1e6:.1f} MPa | "
              f"{loaded['contact_radius_m'] * 1e6:.2f} / {peer['contact_radius_m'] * 1e6:.2f} um | "
              f"{loaded['max_plastic_strain']:.4e} / {peer['max_plastic_strain']:.4e} |")


if __name__ == "__main__":
    main()
