"""Times Tamaas's `PolonskyKeerRey.solve` alone on given heights: the peer of the
`rough_contact` criterion bench (`benches/rough_contact.rs`), run by it when
`STRESSFIELD_TAMAAS_PYTHON` names a Python with `tamaas` and `numpy` installed.

    python tamaas_solve.py HEIGHTS.npy SPACING_M MEAN_PRESSURE_OVER_E_STAR TOLERANCE REPEATS

The heights (m, float64, `[rows, columns]`, row = y, cells `SPACING_M` square) are pressed
periodically to the given mean pressure with E* = 1 (E = 1, nu = 0: only the ratio matters).
Each repeat builds the model and solver afresh (not timed) and times `solve` alone with
`time.perf_counter`. Prints one line of JSON: the threads, the seconds of each repeat, and the
contact fraction (Tamaas does not expose its iterations), a check that both codes solved the
same problem.

The OpenMP threads are Tamaas's own: set `OMP_NUM_THREADS` before starting this script.
"""

import json
import os
import sys
import time

import numpy as np
import tamaas as tm


def main():
    heights_path, spacing, mean_pressure, tolerance, repeats = sys.argv[1:6]
    heights = np.ascontiguousarray(np.load(heights_path), dtype=np.float64)
    spacing, mean_pressure = float(spacing), float(mean_pressure)
    tolerance, repeats = float(tolerance), int(repeats)
    rows, columns = heights.shape
    tm.set_log_level(tm.LogLevel.error)
    seconds = []
    fraction = None
    for _ in range(repeats):
        model = tm.ModelFactory.createModel(
            tm.model_type.basic_2d, [rows * spacing, columns * spacing], [rows, columns]
        )
        model.E = 1.0
        model.nu = 0.0
        solver = tm.PolonskyKeerRey(model, heights, tolerance)
        solver.max_iter = 100000
        start = time.perf_counter()
        solver.solve(mean_pressure)
        seconds.append(time.perf_counter() - start)
        fraction = float(np.mean(model.traction > 0))
    print(
        json.dumps(
            {
                "threads": os.environ.get("OMP_NUM_THREADS", ""),
                "seconds": seconds,
                "contact_fraction": fraction,
            }
        )
    )


if __name__ == "__main__":
    main()
