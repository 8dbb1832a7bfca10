"""Issue 50: the command line's limits from Python. Every argument within the bounds the
command line keeps for the same quantity, and named; arrays of text, complex numbers or with
masked points refused; the memory of stress() estimated and refused; Ctrl-C heard between the
iterations of a long contact()."""

import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import stressfield as sf


def _raises(call, *fragments):
    with pytest.raises(sf.StressfieldError) as info:
        call()
    for fragment in fragments:
        assert fragment in str(info.value), str(info.value)
    return str(info.value)


@pytest.fixture
def heights():
    h = np.zeros((8, 8))
    h[4, 4] = 1e-6
    return h


def test_friction_lies_in_0_to_10_everywhere(heights):
    for call in (
        lambda: sf.contact(heights, 1e-6, 1e11, load=1, friction=11),
        lambda: sf.line_stress(0.0, 0.5, friction=11),
        lambda: sf.sphere_stress(0.0, 0.0, 0.5, friction=-0.1),
    ):
        _raises(call, "friction: the coefficient of friction must lie in 0..=10", "hint:")
    # 10 itself is the command line's limit, and allowed.
    assert np.isfinite(sf.line_stress(0.0, 0.5, friction=10)).all()


def test_tolerance_is_numerical_tolerance_s(heights):
    for bad in (0.5, 0.01, 0.0, -1e-8, float("nan")):
        _raises(
            lambda: sf.contact(heights, 1e-6, 1e11, load=1, tolerance=bad),
            "tolerance must lie in (0, 0.01), as a scene's numerical.tolerance",
        )


def test_loads_lie_in_the_scene_s_range(heights):
    _raises(lambda: sf.contact(heights, 1e-6, 1e11, load=1e20), "load must lie between 1e-12 N and 1e12 N")
    _raises(lambda: sf.contact(heights, 1e-6, 1e11, load=1e-15), "load must lie between")
    _raises(
        lambda: sf.contact(heights, 1e-6, 1e11, mean_pressure=1e14),
        "mean_pressure must lie between 1 Pa and 1e13 Pa",
    )
    _raises(lambda: sf.contact(heights, 1e-6, 1e11, approach=0.5), "approach must lie between 1e-12 m and 0.1 m")
    _raises(lambda: sf.contact(heights, 1e-6, 1e11, approach=float("inf")), "approach must lie between")
    # A spacing beyond the map's 1 m, as a scene's [surface] spacing.
    _raises(lambda: sf.contact(heights, 10.0, 1e11, load=1), "spacing:", "1 m")


def test_heights_of_1e294_m_name_the_argument_and_its_limit(heights):
    # It used to run the solver to "did not converge: residual inf".
    tall = heights.copy()
    tall[2, 3] = 1e294
    for call in (
        lambda: sf.contact(tall, 1e-6, 1e11, load=1),
        lambda: sf.surface_stats(tall, 1e-6),
    ):
        message = _raises(call, "heights: the height at row 2, column 3 is 1e294 m")
        assert "more than the 1 m a surface's height may reach" in message


def test_closed_forms_take_finite_points_within_the_probe_s_reach():
    # line_stress(inf, 0.5) returned NaN.
    _raises(lambda: sf.line_stress(np.inf, 0.5), "x must be finite", "inf")
    _raises(lambda: sf.sphere_stress(0.0, [0.0, np.nan], 0.5), "y must be finite", "point 1")
    _raises(lambda: sf.line_stress(0.0, np.inf), "z must be finite")
    _raises(lambda: sf.line_stress(2e9, 0.5), "point 0 (x = 2e9, z = 0.5)", "farther than the 1e9 a")
    # Within the reach, far points are fine.
    assert np.isfinite(sf.sphere_stress(1e9, 0.0, 1.0)).all()


def test_complex_text_and_masked_arrays_are_refused(heights):
    _raises(lambda: sf.contact(heights + 0j, 1e-6, 1e11, load=1), "heights must be real numbers, got complex")
    _raises(lambda: sf.line_stress(np.array([0.5 + 1j]), 0.5), "x must be real numbers, got complex")
    _raises(lambda: sf.line_stress(["0.5"], [1.0]), "x must be real numbers, got text")
    _raises(lambda: sf.stress(heights, 1e-6, ["1e-6"]), "depths must be real numbers, got text")
    _raises(lambda: sf.contact(heights > 0, 1e-6, 1e11, load=1), "heights must be real numbers, got booleans")
    _raises(lambda: sf.contact(heights, "1e-6", 1e11, load=1), "spacing must be a number, got text '1e-6'")
    _raises(lambda: sf.contact(heights, 1e-6, "115e9", load=1), "e_star must be a number, got text")
    _raises(lambda: sf.contact(heights, 1e-6, 1e11, load=np.complex128(1 + 1j)), "load must be real numbers, got complex")
    _raises(lambda: sf.contact(heights, 1e-6, 1e11, load=np.array([1.0, 2.0])), "load must be one number")
    _raises(lambda: sf.line_stress(0.0, 0.5, friction="0.2"), "friction must be a number, got text")
    masked = np.ma.masked_array(heights, mask=np.zeros_like(heights, dtype=bool))
    masked[1, 1] = np.ma.masked
    _raises(lambda: sf.contact(masked, 1e-6, 1e11, load=1), "masked array with 1 masked point", "fill")
    _raises(lambda: sf.surface_stats(masked, 1e-6), "heights is a masked array")
    # A masked array that masks nothing is its data.
    unmasked = np.ma.masked_array(heights, mask=False)
    assert sf.contact(unmasked, 1e-6, 1e11, load=1e-3).to_dict() == sf.contact(
        heights, 1e-6, 1e11, load=1e-3
    ).to_dict()


def test_stress_tractions_and_depths_are_bounded(heights):
    big = heights * 1e26
    _raises(lambda: sf.stress(big, 1e-6, [1e-6]), "pressure[4, 4] is 1e20 Pa", "at most 1e13 Pa")
    _raises(lambda: sf.stress(heights, 1e-6, [1e-6], shear_x=np.full((8, 8), np.nan)), "shear_x[0, 0]")
    _raises(lambda: sf.stress(heights, 1e-6, [[1e-6]]), "depths must be a number or a 1-D array")


def _python(script, timeout):
    """Runs `script` in a fresh interpreter (an abort or a signal there is not this test
    run's); returns the completed process."""
    return subprocess.run(
        [sys.executable, "-c", textwrap.dedent(script)],
        capture_output=True,
        text=True,
        timeout=timeout,
        env={**os.environ, "PYTHONFAULTHANDLER": "1"},
    )


def test_stress_of_a_grid_too_large_is_refused_not_an_abort():
    """A 4096² grid at 50 depths asked for 40 GB and aborted the interpreter (SIGABRT): the
    memory is estimated and the call refused with StressfieldError before anything is
    allocated (the tractions are a broadcast view: no 128 MB array either)."""
    done = _python(
        """
        import numpy as np, stressfield as sf
        pressure = np.broadcast_to(np.float64(1e6), (4096, 4096))
        try:
            sf.stress(pressure, 1e-6, np.linspace(0.0, 5e-5, 50))
        except sf.StressfieldError as error:
            print("refused:", error)
        """,
        timeout=120,
    )
    assert done.returncode == 0, (done.returncode, done.stderr[-2000:])
    assert done.stdout.startswith("refused: stress: 50 depths of a 4096 x 4096 grid need about"), done.stdout
    assert "hint: ask for fewer depths at a time" in done.stdout


def test_ctrl_c_stops_a_long_contact_between_iterations():
    """A 512² capped contact that takes 155 iterations (8.6 s here) gets SIGINT after 1 s:
    KeyboardInterrupt arrives within the next iteration, not when the solve ends."""
    done = _python(
        """
        import os, signal, threading, time
        import numpy as np, stressfield as sf
        rng = np.random.default_rng(7)
        n = 512
        k = np.fft.fftfreq(n)
        q = np.sqrt(k[:, None] ** 2 + k[None, :] ** 2)
        q[0, 0] = 1.0
        spectrum = (rng.normal(size=(n, n)) + 1j * rng.normal(size=(n, n))) * q ** -1.8
        spectrum[0, 0] = 0.0
        heights = np.real(np.fft.ifft2(spectrum))
        heights *= 1e-6 / heights.std()
        threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT)).start()
        started = time.perf_counter()
        try:
            sf.contact(heights, 1e-6, 1e11, mean_pressure=1e7, hardness=5e8)
            print("finished", time.perf_counter() - started)
        except KeyboardInterrupt:
            print("interrupted", time.perf_counter() - started)
        """,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    what, seconds = done.stdout.split()
    assert what == "interrupted", done.stdout
    assert float(seconds) < 3.0, done.stdout
