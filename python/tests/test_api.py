"""Closed forms against Johnson's maxima, DC-FFT stress against the sphere's closed form,
shapes and dtypes, C and Fortran order, the GIL released, and every error path."""

import threading
import time

import numpy as np
import pytest

import stressfield as sf
from conftest import SCENES, cli_error


def test_line_contact_maxima_are_johnson_s():
    # Johnson, Contact Mechanics (1985) §4.2: frictionless line contact, on the axis
    # τ1 = (σ1 − σ3)/2 is largest, 0.300 p0 at z = 0.78a; σzz(0, z) = −p0 / sqrt(1 + z²).
    z = np.linspace(0.0, 2.0, 20001)
    s = sf.line_stress(0.0, z)
    assert s.shape == (z.size, 6) and s.dtype == np.float64
    tresca = 0.5 * np.abs(s[:, 0] - s[:, 2])
    k = np.argmax(tresca)
    assert tresca[k] == pytest.approx(0.3003, abs=1e-4)
    assert z[k] == pytest.approx(0.786, abs=1e-3)
    np.testing.assert_allclose(s[:, 2], -1.0 / np.sqrt(1.0 + z**2), rtol=1e-12, atol=1e-15)
    # Surface: σxx = σzz = −p inside the contact.
    x = np.linspace(-0.99, 0.99, 11)
    surface = sf.line_stress(x, 0.0)
    np.testing.assert_allclose(surface[:, 0], -np.sqrt(1 - x**2), atol=1e-12)
    np.testing.assert_allclose(surface[:, 2], -np.sqrt(1 - x**2), atol=1e-12)


def test_sphere_maxima_are_johnson_s():
    # Johnson §3.4, ν = 0.3: on the axis (σ1 − σ3)/2 is largest, 0.31 p0 at z = 0.48a;
    # at the edge of the contact the radial stress is (1 − 2ν)/3 p0 in tension.
    z = np.linspace(0.0, 1.5, 15001)
    s = sf.sphere_stress(0.0, 0.0, z, poisson=0.3)
    tresca = 0.5 * np.abs(s[:, 0] - s[:, 2])
    k = np.argmax(tresca)
    assert tresca[k] == pytest.approx(0.31, abs=0.005)
    assert z[k] == pytest.approx(0.48, abs=0.01)
    edge = sf.sphere_stress(1.0, 0.0, 0.0, poisson=0.3)
    assert edge.shape == (6,)
    assert edge[0] == pytest.approx((1 - 2 * 0.3) / 3, abs=1e-9)


def test_closed_forms_broadcast():
    x = np.linspace(-1, 1, 5)[:, None]
    z = np.linspace(0, 1, 3)[None, :]
    assert sf.line_stress(x, z).shape == (5, 3, 6)
    assert sf.sphere_stress(x[..., None], 0.0, z[..., None]).shape == (5, 3, 1, 6)
    assert sf.sphere_stress(np.float32(0.5), 0, 0.5).dtype == np.float64


def test_stress_under_hertz_pressure_is_the_sphere_s():
    """DC-FFT under p0 sqrt(1 − r²) on 128² cells over [−1.25a, 1.25a]² against Hamilton's
    closed form at the cell centres, from 0.25a down: within 1.5e-3 p0 (measured 0.8e-3; the
    error is the discretisation of the pressure into uniform cells)."""
    n, half = 128, 1.25
    a, p0 = 1e-4, 1e9  # m, Pa: the function works in SI
    dx = 2 * half * a / n
    centres = (np.arange(n) + 0.5) * dx - half * a
    X, Y = np.meshgrid(centres, centres)
    pressure = p0 * np.sqrt(np.clip(1 - (X**2 + Y**2) / a**2, 0, None))
    depths = np.array([0.25, 0.5, 1.0]) * a
    layers = sf.stress(pressure, dx, depths)
    assert layers.shape == (3, n, n, 6) and layers.dtype == np.float64
    for k, z in enumerate(depths):
        exact = sf.sphere_stress(X / a, Y / a, z / a)
        error = np.max(np.abs(layers[k] / p0 - exact))
        assert error < 1.5e-3, (z / a, error)
    # Fortran order and a pair spacing give the same layers.
    fortran = sf.stress(np.asfortranarray(pressure), (dx, dx), depths)
    np.testing.assert_array_equal(fortran, layers)


def test_stress_with_shear_is_linear():
    rng = np.random.default_rng(1)
    p = rng.uniform(0, 1e8, (16, 24))
    q = rng.uniform(0, 1e7, (16, 24))
    both = sf.stress(p, 1e-6, [0.0, 2e-6], shear_x=q, periodic=True)
    apart = sf.stress(p, 1e-6, [0.0, 2e-6], periodic=True) + sf.stress(
        None, 1e-6, [0.0, 2e-6], shear_x=q, periodic=True
    )
    assert both.shape == (2, 16, 24, 6)
    np.testing.assert_allclose(both, apart, atol=1e-6 * np.abs(both).max())


def test_contact_shapes_and_no_copy_of_the_pressure():
    rng = np.random.default_rng(3)
    heights = rng.normal(0, 1e-7, (32, 48))
    result = sf.contact(heights, (1e-6, 2e-6), 1e11, mean_pressure=1e7)
    assert result.pressure.shape == (32, 48)
    assert result.pressure.dtype == np.float64
    # The pressure is the solver's array handed to NumPy (it owns no Python copy).
    assert result.pressure.flags.c_contiguous and result.pressure.base is not None
    assert result.rows == 32 and result.columns == 48
    assert result.spacing_m == [1e-6, 2e-6]
    assert result.load_n == pytest.approx(1e7 * 48e-6 * 64e-6, rel=1e-12)
    assert result.to_dict()["periodic"] is True


def test_the_gil_is_released():
    """A computation in one thread leaves the interpreter to another: the main thread keeps
    counting while the contact is solved (with the GIL held it could not count at all)."""
    rng = np.random.default_rng(5)
    heights = rng.normal(0, 1e-7, (256, 256))
    started = threading.Event()

    def work():
        started.set()
        sf.contact(heights, 1e-6, 1e11, mean_pressure=1e7)

    thread = threading.Thread(target=work)
    t0 = time.perf_counter()
    thread.start()
    started.wait()
    count = 0
    while thread.is_alive():
        count += 1
    elapsed = time.perf_counter() - t0
    thread.join()
    assert elapsed > 0.05, "the solve was too short to tell"
    assert count > 10000, count


def _raises(call, *fragments):
    with pytest.raises(sf.StressfieldError) as info:
        call()
    assert isinstance(info.value, ValueError)
    for fragment in fragments:
        assert fragment in str(info.value), str(info.value)
    return str(info.value)


def test_errors_carry_the_command_line_s_message(tmp_path):
    missing = tmp_path / "missing.toml"
    message = _raises(lambda: sf.load_scene(missing), "cannot read the scene")
    assert message == cli_error("hertz", missing)
    bad = tmp_path / "bad.toml"
    bad.write_text((SCENES / "sphere_ball_on_flat.toml").read_text().replace("friction", "fricton"))
    assert _raises(lambda: sf.load_scene(bad), "fricton") == cli_error("hertz", bad)
    assert _raises(lambda: sf.Scene.from_toml("[contact]\nkind = 3\n"), "contact.kind")
    hertz = sf.load_scene(SCENES / "sphere_ball_on_flat.toml")
    line = SCENES / "line_tau1.toml"
    assert _raises(lambda: hertz.contact(), "not a rough contact scene")
    assert _raises(lambda: sf.load_scene(line).thermal(), "has no [thermal]") == cli_error(
        "thermal", line
    )
    assert _raises(lambda: hertz.render(tmp_path / "x.gif"), ".png or .svg")
    if not sf._ext.has_rerun():
        _raises(lambda: hertz.record(tmp_path / "x.rrd"), "without Rerun", "hint:")


def test_argument_errors_name_the_argument():
    h = np.zeros((8, 8))
    h[4, 4] = 1e-6
    _raises(lambda: sf.contact(h, 1e-6, 1e11), "exactly one of load")
    _raises(lambda: sf.contact(h, 1e-6, 1e11, load=1, approach=1e-7), "load, approach")
    _raises(lambda: sf.contact(h[0], 1e-6, 1e11, load=1), "heights must be a 2-D array")
    _raises(lambda: sf.contact(h, -1e-6, 1e11, load=1), "spacing", "dx")
    _raises(lambda: sf.contact(h, 1e-6, 1e11, load=1, poisson=0.7), "poisson must lie in (-1, 0.5]")
    _raises(lambda: sf.contact(h, 1e-6, -5, load=1), "e_star")
    _raises(lambda: sf.contact(h, (1e-6, 1e-6, 1e-6), 1e11, load=1), "pair (dx, dy)")
    nan = h.copy()
    nan[1, 1] = np.nan
    _raises(lambda: sf.contact(nan, 1e-6, 1e11, load=1), "row 1, column 1", "not finite")
    _raises(lambda: sf.contact(h, 1e-6, 1e11, approach=-1e-9), "approach")
    _raises(lambda: sf.stress(h, 1e-6, [-1e-6]), "depths must be non-negative")
    _raises(lambda: sf.stress(None, 1e-6, [1e-6]), "at least one of pressure")
    _raises(lambda: sf.stress(h, 1e-6, [1e-6], shear_x=np.zeros((4, 4))), "shear_x")
    _raises(lambda: sf.line_stress(0.0, -1.0), "z must be non-negative")
    _raises(lambda: sf.sphere_stress(0.0, 0.0, 0.5, poisson=1.0), "poisson")
    _raises(lambda: sf.line_stress([0, 1, 2], [0, 1]), "broadcast")
    _raises(lambda: sf.read_surface(SCENES / "surfaces" / "worn.asc", fill="guess"), "fill guess")
    _raises(lambda: sf.read_surface(SCENES / "nowhere.asc"), "cannot read")
    _raises(lambda: sf.read_surface(SCENES / "surfaces" / "worn.asc", height_unit="furlong"), "height_unit furlong")
    _raises(lambda: sf.surface_stats(h, 1e-6, form="cubic"), "form cubic")
    _raises(lambda: sf.surface_stats(h, 1e-6, band=(1e-5, 1e-6)), "shorter wavelength first")
    _raises(lambda: sf.batch([42]), "batch task")


def test_nothing_is_printed(capfd):
    sf.load_scene(SCENES / "rough_worn_on_flat.toml").contact()
    sf.load_scene(SCENES / "sphere_ball_on_flat.toml").hertz()
    out, err = capfd.readouterr()
    assert out == "" and err == ""


def test_render_writes_the_figure(tmp_path):
    scene = sf.load_scene(SCENES / "sphere_max_shear.toml")
    scene.render(tmp_path / "f.png")
    scene.render(tmp_path / "f.svg")
    assert (tmp_path / "f.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert b"<svg" in (tmp_path / "f.svg").read_bytes()[:400]
    thermal = sf.load_scene(SCENES / "thermal_sliding_sphere.toml").thermal()
    assert thermal["temperature"].ndim == 2
    assert thermal["temperature"].shape == (thermal["rows"], thermal["columns"])
