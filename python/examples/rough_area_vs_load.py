"""Real contact area against load, with its spread over surface realisations, on a Dask cluster.

A realisations x loads study of rough contact: self-affine steel surfaces (Hurst 0.8, rms
slope 0.1; one seed per realisation) pressed on a rigid flat at a range of mean pressures.
Each task is a scene (TOML text) solved by `stressfield.batch`, which maps the tasks over the
cluster's workers and returns each scene's `contact --json` dict in order. The figure shows
the contact fraction A/A0 against p/E*, the mean over realisations with a band of one
standard deviation, and the line of the asymptotic theories (A/A0 = kappa p / (E* rms slope)).

Here (one machine):        python python/examples/rough_area_vs_load.py
On a Slurm cluster:        python python/examples/rough_area_vs_load.py --slurm 8
On PBS:                    python python/examples/rough_area_vs_load.py --pbs 8
(`--slurm N` starts N single-node jobs with dask-jobqueue; see docs/python.md for the queue,
account and memory options, and for running it inside an allocation.)
"""

import argparse
import time

import numpy as np

import stressfield as sf

SCENE = """\
format = 1
title = "realisation {seed}, p = {pressure_pa:.4e} Pa"

[contact]
kind = "rough"
mean_pressure = "{pressure_pa!r} Pa"
periodic = true

[contact.body1]
material = "steel"

[contact.body2]
material = "rigid"

[surface.generate]
samples = {samples}
spacing = "1 um"
hurst = 0.8
rolloff = "32 um"
cutoff = "4 um"
rms_slope = 0.1
seed = {seed}
"""


def tasks(seeds, pressures_pa, samples):
    """One scene text per (realisation, load), realisations outermost."""
    return [
        SCENE.format(seed=seed, pressure_pa=float(p), samples=samples)
        for seed in seeds
        for p in pressures_pa
    ]


def cluster(args):
    """A LocalCluster here, or jobs on Slurm/PBS through dask-jobqueue (the same code)."""
    if args.slurm or args.pbs:
        import dask_jobqueue

        kind = dask_jobqueue.SLURMCluster if args.slurm else dask_jobqueue.PBSCluster
        # One worker per job, each using every core of its node (stressfield is parallel
        # inside a task); adjust queue/account/walltime to your site.
        jobs = kind(cores=args.cores, processes=1, memory=args.memory, walltime="01:00:00")
        jobs.scale(jobs=args.slurm or args.pbs)
        return jobs
    from dask.distributed import LocalCluster

    # Two workers of one thread each: each solve already uses the cores it is given.
    return LocalCluster(n_workers=args.workers, threads_per_worker=1, dashboard_address=None)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--realisations", type=int, default=4)
    parser.add_argument("--loads", type=int, default=6)
    parser.add_argument("--samples", type=int, default=128, help="grid points per side")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster workers")
    parser.add_argument("--slurm", type=int, metavar="JOBS", help="run on Slurm with N jobs")
    parser.add_argument("--pbs", type=int, metavar="JOBS", help="run on PBS with N jobs")
    parser.add_argument("--cores", type=int, default=8, help="cores per job (Slurm/PBS)")
    parser.add_argument("--memory", default="8GB", help="memory per job (Slurm/PBS)")
    parser.add_argument("--figure", default="area_vs_load.png")
    args = parser.parse_args()

    from dask.distributed import Client

    e_star_pa = 230e9  # steel on a rigid flat: E/(1 - nu^2), the scenes' E*
    pressures_pa = e_star_pa * np.geomspace(1e-4, 4e-3, args.loads)
    seeds = range(1, args.realisations + 1)
    work = tasks(seeds, pressures_pa, args.samples)
    with cluster(args) as c, Client(c) as client:
        started = time.perf_counter()
        results = sf.batch(work, client=client)
        elapsed = time.perf_counter() - started
    print(f"{len(work)} contacts solved in {elapsed:.1f} s")

    shape = (args.realisations, args.loads)
    fraction = np.array([r["contact_fraction"] for r in results]).reshape(shape)
    pressure = np.array([r["mean_pressure_pa"] for r in results]).reshape(shape)
    e_star = results[0]["e_star_pa"]
    load = pressure.mean(axis=0) / e_star
    mean, spread = fraction.mean(axis=0), fraction.std(axis=0, ddof=1)
    for p, m, s in zip(load, mean, spread):
        print(f"p/E* = {p:.2e}: A/A0 = {m:.4f} +- {s:.4f}")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5, 4), dpi=120)
    ax.fill_between(load, mean - spread, mean + spread, alpha=0.3, label="± 1 std")
    ax.plot(load, mean, "o-", label=f"mean of {args.realisations} realisations")
    kappa = 2.0  # Persson's theory gives about 1.6, boundary elements 2 to 2.3
    ax.plot(load, kappa * load / 0.1, "k--", lw=1, label=r"$\kappa\,p/(E^*\,h')$, $\kappa$ = 2")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"mean pressure $p/E^*$")
    ax.set_ylabel(r"real contact area $A/A_0$")
    ax.set_title(f"{args.samples}² self-affine surfaces, H = 0.8")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.figure)
    print(f"figure written to {args.figure}")


if __name__ == "__main__":
    main()
