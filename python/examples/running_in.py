"""Running-in of a rough ball on a flat at three loads, on a Dask cluster.

A pin-on-disc running-in study: a rough mild-steel ball (its asperities capped at the
ball's hardness, 200 HV) slides on a smooth steel flat and wears by Archard's law. Each load is one
wear scene (TOML text) run by `stressfield.batch(..., command="wear")`, which maps the scenes
over the cluster's workers and returns each scene's `wear --json` dict. The figure shows,
against the sliding distance, the worn scar's area, the real contact area and the plastic
area (the cells at the hardness): the plastic area falls as the asperities are worn flat (the lecture notes'
Figs. 53-55), the scar grows as the ball conforms to the flat.

Here (one machine):        python python/examples/running_in.py
A finer study:             python python/examples/running_in.py --samples 128 --steps 40
"""

import argparse
import time

import stressfield as sf

SCENE = """\
format = 1
title = "running-in at {load_n:g} N"

[contact]
kind = "rough"
load = "{load_n!r} N"
hardness = "200 HV"          # a mild steel pin's asperities flow at its hardness

[contact.body1]               # the ball, whose surface is worn and whose stresses are found
material = "steel"

[contact.body2]
material = "steel"

[surface.generate]
samples = {samples}
spacing = "{spacing_um!r} um"
hurst = 0.8
rolloff = "40 um"
cutoff = "12 um"
rms_height = "0.4 um"
sphere_radius = "10 mm"
seed = 7

[wear]
coefficient = "2e-6 mm^3/(N m)"
distance = "{distance_m!r} m"
steps = {steps}
"""


def tasks(loads_n, samples, steps, distance_m):
    """One wear scene per load: the same ball and map (seed), a map 320 µm wide."""
    return [
        SCENE.format(
            load_n=float(load),
            samples=samples,
            spacing_um=320.0 / samples,
            steps=steps,
            distance_m=distance_m,
        )
        for load in loads_n
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--loads", type=float, nargs="+", default=[0.5, 1.0, 2.0], help="N")
    parser.add_argument("--samples", type=int, default=64, help="grid points per side")
    parser.add_argument("--steps", type=int, default=20)
    parser.add_argument("--distance", type=float, default=1.0, help="sliding distance, m")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster workers")
    parser.add_argument("--figure", default="running_in.png")
    args = parser.parse_args()

    from dask.distributed import Client, LocalCluster

    work = tasks(args.loads, args.samples, args.steps, args.distance)
    # Workers of one thread each: each wear run already uses the cores it is given.
    with LocalCluster(
        n_workers=args.workers, threads_per_worker=1, dashboard_address=None
    ) as cluster, Client(cluster) as client:
        started = time.perf_counter()
        results = sf.batch(work, client=client, command="wear")
        elapsed = time.perf_counter() - started
    print(f"{len(work)} wear runs of {args.steps} steps solved in {elapsed:.1f} s")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (scar, real, plastic) = plt.subplots(1, 3, figsize=(12, 3.8), dpi=120)
    for load, result in zip(args.loads, results):
        steps = result["steps"]
        distance = [s["sliding_distance_m"] for s in steps]
        label = f"{load:g} N"
        scar.plot(distance, [s["scar_area_m2"] * 1e6 for s in steps], "o-", ms=3, label=label)
        real.plot(distance, [s["contact_area_m2"] * 1e12 for s in steps], "o-", ms=3,
                  label=label)
        plastic.plot(distance, [s["plastic_area_m2"] * 1e12 for s in steps], "o-", ms=3,
                     label=label)
        last = steps[-1]
        print(
            f"{load:g} N: scar {last['scar_area_m2'] * 1e6:.4f} mm², real area "
            f"{steps[0]['contact_area_m2'] * 1e12:.0f} -> {last['contact_area_m2'] * 1e12:.0f} µm², "
            f"plastic {steps[0]['plastic_area_m2'] * 1e12:.0f} -> "
            f"{last['plastic_area_m2'] * 1e12:.0f} µm², deepest wear "
            f"{last['max_wear_depth_m'] * 1e6:.3f} µm"
        )
    for axis, what in [
        (scar, "worn scar area (mm²)"),
        (real, "real contact area (µm²)"),
        (plastic, "plastic area, cells at H (µm²)"),
    ]:
        axis.set_xlabel("sliding distance (m)")
        axis.set_ylabel(what)
        axis.legend(fontsize=8)
    fig.suptitle(f"running-in of a rough ball (R = 10 mm, {args.samples}² map, 200 HV)")
    fig.tight_layout()
    fig.savefig(args.figure)
    print(f"figure written to {args.figure}")


if __name__ == "__main__":
    main()
