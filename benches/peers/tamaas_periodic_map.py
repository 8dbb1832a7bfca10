"""Checks a periodic self-affine map given as a file against Tamaas (issue 50): the kind of
map Tamaas, ContactMechanics and SurfaceTopography generate and exchange, solved by
`stressfield contact` with the default levelling and by Tamaas's `PolonskyKeerRey` on the
same heights; prints the correlation of the two pressure fields and both contact fractions.
Not run by the tests (they never need Python); run it by hand:

    python tamaas_periodic_map.py STRESSFIELD_BINARY N [N ...] [--level plane]

Each N gives an N x N map of 1 um cells (Hurst 0.8, self-affine from the longest wavelength
(q0 = q1 = 1 period over the map) to N/4 periods, rms slope 0.1, Tamaas's own generator,
seed 7), written as .npy and read by a scene
with `[surface] file` and `contact.periodic = true`, pressed on a rigid flat to a mean
pressure of 0.5 % of E* (steel, E* = 230.8 GPa); `--level plane` asks for the plane that
the default removed before issue 50. The two codes' kernels differ (Tamaas's
is spectral, stressfield's uniform cells), so their fields agree to about 1e-4, not to the
solver's tolerance.
"""

import json
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import tamaas as tm

E, NU = 210e9, 0.3
E_STAR = E / (1 - NU**2)
MEAN = 0.005 * E_STAR
SPACING = 1e-6


def heights_of(n):
    spectrum = tm.Isopowerlaw2D()
    spectrum.q0, spectrum.q1, spectrum.q2 = 1, 1, n // 4
    spectrum.hurst = 0.8
    generator = tm.SurfaceGeneratorFilter2D([n, n])
    generator.spectrum = spectrum
    generator.random_seed = 7
    surface = np.array(generator.buildSurface(), dtype=np.float64)
    # rms slope 0.1 in physical units (Tamaas's wavenumbers are periods over the map).
    gy, gx = np.gradient(surface, SPACING)
    surface *= 0.1 / np.sqrt(np.mean(gx**2 + gy**2))
    return surface


def tamaas_pressure(heights):
    n = heights.shape[0]
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [n * SPACING] * 2, [n, n])
    model.E, model.nu = E, NU
    solver = tm.PolonskyKeerRey(model, heights, 1e-10)
    solver.max_iter = 100000
    solver.solve(MEAN)
    return np.array(model.traction, dtype=np.float64).reshape(n, n)


def stressfield_pressure(binary, heights, folder, level):
    np.save(folder / "heights.npy", heights)
    scene = folder / "periodic_map.toml"
    scene.write_text(
        "format = 1\n[contact]\nkind = \"rough\"\n"
        f"mean_pressure = \"{MEAN} Pa\"\nperiodic = true\n"
        "[contact.body1]\nmodulus = \"210 GPa\"\npoisson = 0.3\n"
        "[contact.body2]\nmaterial = \"rigid\"\n"
        "[numerical]\ntolerance = 1e-10\n"
        "[surface]\nfile = \"heights.npy\"\nspacing = \"1 um\"\n"
        + (f"level = \"{level}\"\n" if level else "")
    )
    pressure = folder / "pressure.npy"
    out = subprocess.run(
        [binary, "contact", str(scene), "--json", "--pressure", str(pressure)],
        check=True,
        capture_output=True,
        text=True,
    )
    return json.loads(out.stdout), np.load(pressure)


def main():
    args = sys.argv[1:]
    level = None
    if "--level" in args:
        at = args.index("--level")
        level = args[at + 1]
        del args[at : at + 2]
    binary, sizes = args[0], [int(n) for n in args[1:]]
    tm.set_log_level(tm.LogLevel.error)
    for n in sizes:
        heights = heights_of(n)
        with tempfile.TemporaryDirectory() as folder:
            report, ours = stressfield_pressure(binary, heights, Path(folder), level)
        theirs = tamaas_pressure(heights)
        correlation = float(np.corrcoef(ours.ravel(), theirs.ravel())[0, 1])
        print(
            json.dumps(
                {
                    "n": n,
                    "levelling": report["levelling"]["removed"],
                    "correlation": correlation,
                    "contact_fraction": [report["contact_fraction"], float(np.mean(theirs > 0))],
                }
            )
        )


if __name__ == "__main__":
    main()
