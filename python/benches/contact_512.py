"""stressfield.contact on a 512² map against `stressfield contact` on the same map, side by
side: the scene's generated heights (written by `stressfield surface SCENE --heights`) solved
by both, the results checked equal, wall time best of N.

    python python/benches/contact_512.py [path/to/stressfield] [N]

Measured numbers: docs/python.md.
"""

import json
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

import stressfield as sf

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "target" / "release" / "stressfield")
N = int(sys.argv[2]) if len(sys.argv) > 2 else 3

work = pathlib.Path(tempfile.mkdtemp())
scene = work / "rough512.toml"
scene.write_text(
    (ROOT / "scenes" / "rough_self_affine.toml")
    .read_text()
    .replace("samples = 256", "samples = 512")
    .replace('rolloff = "64 um"', 'rolloff = "128 um"')
)
subprocess.run([BIN, "surface", scene, "--json", "--heights", work / "h.npy"], check=True, capture_output=True)
heights = np.load(work / "h.npy")


def command_line():
    done = subprocess.run([BIN, "contact", scene, "--json"], capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


expected = command_line()


def python():
    return sf.contact(
        heights, 1e-6, expected["e_star_pa"], mean_pressure=1.15e9, periodic=True,
        poisson=expected["poisson"],
    )


assert python().to_dict() == expected, "not the command line's result"
cli_times, py_times = [], []
for _ in range(N):
    t = time.perf_counter()
    command_line()
    cli_times.append(time.perf_counter() - t)
    t = time.perf_counter()
    python()
    py_times.append(time.perf_counter() - t)
print(f"stressfield contact (512², {expected['iterations']} iterations): best {min(cli_times):.3f} s")
print(f"stressfield.contact (same map):         best {min(py_times):.3f} s")
print(f"ratio Python / command line: {min(py_times) / min(cli_times):.3f}")
