"""Each function against the command line's output for the same input, to the last digit of
the JSON (dict equality of floats parsed from the same shortest-repr text)."""

import re
import subprocess

import numpy as np
import pytest

import stressfield as sf
from conftest import BIN, ROOT, SCENES, cli, cli_error, cli_json

HERTZ_SCENES = [
    "sphere_ball_on_flat",  # point, dimensional, yield strength
    "line_tau1",  # line, normalised
    "gear_pitch_point",  # line, gears
    "ellipse_bearing_groove",  # elliptical, DC-FFT maxima
    "sphere_partial_slip",  # point, numerical
    "thermal_sliding_sphere",  # point with [thermal]
    "rough_worn_on_flat",  # rough: contact --json
    "surface_worn_homework",  # surface: surface --json
    # Issue 50: the coated, heated and wear scenes.
    "coated_roller_babbitt_on_steel",  # coated line, soft on hard (was 172 MPa, not 207)
    "coated_roller_b4c_on_aluminium",  # coated line, hard on soft
    "thermal_ball_on_disc",  # point with a coupled [thermal]
    "wear_series_measured",  # a measured wear series: its first map's contact
    # Issue 52: lubricated scenes (the "lubrication" keys).
    "lubricated_roller_bearing",  # line, Pan & Hamrock
    "lubricated_gear_pitch_point",  # gears: the film along the path of contact
    "lubricated_ball_on_flat",  # point, Hamrock & Dowson
]


@pytest.mark.parametrize("name", HERTZ_SCENES)
def test_scene_hertz_is_hertz_json(name):
    path = SCENES / f"{name}.toml"
    assert sf.load_scene(path).hertz() == cli_json("hertz", path, "--json")


def test_scene_from_toml_is_the_file():
    path = SCENES / "sphere_ball_on_flat.toml"
    scene = sf.Scene.from_toml(path.read_text(), base_dir=SCENES, name="sphere_ball_on_flat")
    assert scene.hertz() == cli_json("hertz", path, "--json")
    # Files named by the scene are read relative to base_dir.
    rough = SCENES / "rough_worn_on_flat.toml"
    scene = sf.Scene.from_toml(rough.read_text(), base_dir=SCENES, name="rough_worn_on_flat")
    assert scene.contact().to_dict() == cli_json("contact", rough, "--json")


def test_scene_contact_is_contact_json_and_the_pressure_file(tmp_path):
    path = SCENES / "rough_worn_on_flat.toml"
    npy = tmp_path / "p.npy"
    expected = cli_json("contact", path, "--json", "--pressure", npy)
    result = sf.load_scene(path).contact()
    assert result.to_dict() == expected
    assert result.keys() == list(expected)
    assert result.contact_fraction == expected["contact_fraction"]
    assert result.von_mises_max_pa == expected["von_mises_max_pa"]
    pressure = np.load(npy)
    assert result.pressure.dtype == np.float64
    assert result.pressure.shape == (expected["rows"], expected["columns"])
    np.testing.assert_array_equal(result.pressure, pressure)


def test_contact_of_heights_is_the_scene_s_contact(tmp_path):
    """The free function on the heights the scene reads, with the scene's settings: the
    heights as given, so the scene keeps them as measured (level = "none")."""
    text = (SCENES / "rough_worn_on_flat.toml").read_text()
    worn = (SCENES / "surfaces" / "worn.asc").resolve().as_posix()
    text = text.replace('file = "surfaces/worn.asc"', f'file = "{worn}"')
    # The scene levels its map (level = "plane"): keep it as measured instead.
    text = re.sub(r'(?m)^level = .*$', 'level = "none"', text)
    assert text.count('level = "none"') == 1
    path = tmp_path / "raw.toml"
    path.write_text(text)
    expected = cli_json("contact", path, "--json")
    assert expected["levelling"] == {"removed": "none", "plane_m": None}
    heights, spacing = sf.read_surface(SCENES / "surfaces" / "worn.asc")
    assert list(spacing) == expected["spacing_m"]
    result = sf.contact(
        heights,
        spacing,
        expected["e_star_pa"],
        mean_pressure=50e6,
        periodic=True,
        hardness=expected["hardness_pa"],
        friction=0.2,
        poisson=expected["poisson"],
    )
    assert result.to_dict() == expected
    # Fortran order gives the same result, bit for bit.
    fortran = sf.contact(
        np.asfortranarray(heights),
        spacing,
        expected["e_star_pa"],
        mean_pressure=50e6,
        periodic=True,
        hardness=expected["hardness_pa"],
        friction=0.2,
        poisson=expected["poisson"],
    )
    assert fortran.to_dict() == expected
    np.testing.assert_array_equal(fortran.pressure, result.pressure)


def test_read_surface_and_stats_are_surface_json(tmp_path):
    path = SCENES / "surfaces" / "worn.asc"
    npy = tmp_path / "h.npy"
    expected = cli_json("surface", path, "--json", "--heights", npy)
    heights, spacing = sf.read_surface(path)
    assert heights.dtype == np.float64 and heights.ndim == 2
    np.testing.assert_array_equal(heights, np.load(npy))
    assert sf.surface_stats(heights, spacing) == expected
    # Options as the command line's.
    expected = cli_json(
        "surface", path, "--json", "--form", "quadratic", "--e-star", "115GPa", "--hardness", "3GPa"
    )
    got = sf.surface_stats(heights, spacing, form="quadratic", e_star=115e9, hardness=3e9)
    assert got == expected


def _probe(contact, friction, points):
    """`stressfield probe` at `points` (rows x, y, z in units of a): its six components."""
    text = "x,y,z\n" + "".join(",".join(repr(float(v)) for v in p) + "\n" for p in points)
    done = subprocess.run(
        [str(BIN), "probe", "--contact", contact, "--friction", str(friction), "--points", "-"],
        input=text,
        capture_output=True,
        text=True,
        cwd=ROOT,
        check=True,
    )
    rows = [line.split(",") for line in done.stdout.strip().splitlines()[1:]]
    return np.array([[float(v) for v in row[3:9]] for row in rows])


def test_closed_forms_are_probe_s():
    rng = np.random.default_rng(39)
    points = np.column_stack(
        [rng.uniform(-2, 2, 40), rng.uniform(-1.5, 1.5, 40), rng.uniform(0, 2, 40)]
    )
    x, y, z = points.T
    line = sf.line_stress(x, z, friction=0.3)
    np.testing.assert_array_equal(line, _probe("line", 0.3, np.column_stack([x, 0 * x, z])))
    sphere = sf.sphere_stress(x, y, z, friction=0.2)
    np.testing.assert_array_equal(sphere, _probe("point", 0.2, points))


@pytest.mark.parametrize(
    "name", ["record_sphere_friction_sweep", "record_rough_load_sweep", "record_thermal_speed_sweep"]
)
def test_scene_sweep_is_sweep_json(name):
    path = SCENES / f"{name}.toml"
    expected = cli_json("sweep", path, "--json")
    assert sf.load_scene(path).sweep() == expected
    assert len(expected["steps"]) >= 2
    assert list(expected["steps"][0]) == list(expected["units"])


@pytest.mark.skipif(not sf._ext.has_rerun(), reason="the package was built without Rerun")
def test_scene_record_writes_the_command_line_s_recording(tmp_path):
    # A recording holds its recording id and wall-clock times, so two recordings of one scene
    # are not byte-equal; the same scene recorded twice by the command line differs in size by
    # a few bytes only. The package's recording must be the command line's: the RRD magic, and
    # its size within 0.1 % of the command line's.
    for name in ["record_sphere_volume", "record_line_friction_sweep"]:
        path = SCENES / f"{name}.toml"
        ours, theirs = tmp_path / f"{name}_py.rrd", tmp_path / f"{name}_cli.rrd"
        sf.load_scene(path).record(ours)
        cli("record", path, "-o", theirs)
        head = ours.read_bytes()[:4]
        assert head == theirs.read_bytes()[:4] == b"RRF2", head
        assert ours.stat().st_size == pytest.approx(theirs.stat().st_size, rel=1e-3), name
    # A heated scene of one state is refused with the command line's message, and nothing is
    # left behind.
    heated = SCENES / "thermal_sliding_sphere.toml"
    target = tmp_path / "heated.rrd"
    with pytest.raises(sf.StressfieldError) as caught:
        sf.load_scene(heated).record(target)
    # (`record` takes several scenes and ends with a summary line of its own.)
    expected = cli_error("record", heated, "-o", target).split("\nerror: ")[0]
    assert str(caught.value) == expected
    assert not target.exists()
    # An unwritable destination names the path, as the command line does.
    missing = tmp_path / "missing" / "x.rrd"
    with pytest.raises(sf.StressfieldError) as caught:
        sf.load_scene(SCENES / "record_sphere_volume.toml").record(missing)
    assert "missing/x.rrd" in str(caught.value), str(caught.value)
    assert not missing.exists()


def _coarse_coated_ball(tmp_path):
    """The coated ball of issue 50 (12.7 mm steel ball on 10 µm of B4C over steel, 5 N) on a
    coarser grid than the shipped scene's (64 cells a side: 0.4 s instead of 5 s), written
    beside the test."""
    text = (SCENES / "coated_ball_on_b4c_10um.toml").read_text()
    text = text.replace("[figure]", "[numerical]\ncells = 64\n\n[figure]", 1)
    path = tmp_path / "coated_ball.toml"
    path.write_text(text)
    return path, text


def test_a_coated_point_scene_is_the_coated_contact(tmp_path):
    """Issue 50: hertz() and batch() of a coated point scene are `hertz --json`'s coated
    contact with its "coating" object, not the Hertz contact of the coating's material
    (828.9 MPa; the coated contact's peak is 693.4 MPa on the shipped grid)."""
    path, text = _coarse_coated_ball(tmp_path)
    expected = cli_json("hertz", path, "--json")
    assert set(expected["coating"]) >= {"thickness_m", "interface_shear_max_pa"}
    assert expected["max_pressure_pa"] == pytest.approx(693.4e6, rel=2e-3)
    assert sf.load_scene(path).hertz() == expected
    assert sf.Scene.from_toml(text, name="coated_ball").hertz() == expected
    assert sf.batch([path, text]) == [expected, expected]


@pytest.mark.parametrize("name", ["coated_roller_babbitt_on_steel", "wear_series_measured"])
def test_batch_of_coated_and_wear_scenes_is_hertz_json(name):
    path = SCENES / f"{name}.toml"
    assert sf.batch([path]) == [cli_json("hertz", path, "--json")]


@pytest.mark.parametrize("name", ["rough_ball_on_b4c_coated_flat", "wear_series_measured"])
def test_scene_contact_of_coated_and_wear_scenes_is_contact_json(name, tmp_path):
    path = SCENES / f"{name}.toml"
    npy = tmp_path / "p.npy"
    expected = cli_json("contact", path, "--json", "--pressure", npy)
    result = sf.load_scene(path).contact()
    assert result.to_dict() == expected
    np.testing.assert_array_equal(result.pressure, np.load(npy))


@pytest.mark.parametrize("name", ["thermal_ball_on_disc", "wear_rough_ball"])
def test_scene_thermal_is_thermal_json_and_the_temperature_file(name, tmp_path):
    """A heated point contact (coupled) and a heated rough wear scene: `thermal --json` and
    its temperature file, to the last digit."""
    path = SCENES / f"{name}.toml"
    npy = tmp_path / "t.npy"
    expected = cli_json("thermal", path, "--json", "--temperature", npy)
    got = sf.load_scene(path).thermal()
    temperature = got.pop("temperature")
    assert got == expected
    np.testing.assert_array_equal(temperature, np.load(npy))


def test_scene_wear_is_wear_json():
    path = SCENES / "wear_series_measured.toml"
    expected = cli_json("wear", path, "--json")
    assert sf.load_scene(path).wear() == expected
    line = SCENES / "line_tau1.toml"
    with pytest.raises(sf.StressfieldError) as caught:
        sf.load_scene(line).wear()
    assert str(caught.value) == cli_error("wear", line)


@pytest.mark.parametrize("name", ["coated_roller_babbitt_on_steel", "wear_series_measured"])
def test_scene_render_is_the_command_line_s_figure(name, tmp_path):
    """The figure (a coated section, a wear sheet) byte for byte as `render` writes it."""
    path = SCENES / f"{name}.toml"
    cli("render", path, "--out-dir", tmp_path / "cli")
    sf.load_scene(path).render(tmp_path / "py.png")
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli" / f"{name}.png").read_bytes()


SMALL_WEAR = """format = 1
[contact]
kind = "rough"
load = "0.5 N"
[contact.body1]
material = "steel"
[contact.body2]
material = "steel"
[surface.generate]
samples = 48
spacing = "4 um"
hurst = 0.8
rolloff = "24 um"
cutoff = "8 um"
rms_height = "0.1 um"
sphere_radius = "10 mm"
seed = 2
[wear]
coefficient = "2e-6 mm^3/(N m)"
distance = "1 m"
steps = 3
"""


def test_scene_wear_arrays_are_the_steps_of_wear_json(tmp_path):
    """Issue 54: Scene.wear(arrays=True) is `wear --json` plus each step's worn heights,
    pressure and wear depth; the heights are those `wear --heights-out` writes, bit for bit,
    the pressure carries the load and the wear depth holds the worn volume reported."""
    path = tmp_path / "small_wear.toml"
    path.write_text(SMALL_WEAR)
    expected = cli_json("wear", path, "--json")
    got = sf.load_scene(path).wear(arrays=True)
    heights, pressure, depth = got.pop("heights"), got.pop("pressure"), got.pop("wear_depth")
    assert got == expected
    steps = expected["steps"]
    assert heights.shape == pressure.shape == depth.shape == (len(steps), 48, 48)
    assert heights.dtype == pressure.dtype == depth.dtype == np.float64
    out = tmp_path / "heights"
    out.mkdir()
    cli("wear", path, "--heights-out", out)
    written = sorted(out.glob("*.npy"))
    assert len(written) == len(steps), written
    for k, file in enumerate(written):
        np.testing.assert_array_equal(heights[k], np.load(file))
    dx, dy = 4e-6, 4e-6
    for k, step in enumerate(steps):
        # Equilibrium to the solver's tolerance; the worn volume is the depth's integral.
        assert abs(pressure[k].sum() * dx * dy - 0.5) < 1e-6 * 0.5
        volume = depth[k].sum() * dx * dy
        assert abs(volume - step["worn_volume_m3"]) <= 1e-9 * max(step["worn_volume_m3"], 1e-30)
        assert depth[k].max() == pytest.approx(step["max_wear_depth_m"], rel=1e-12, abs=1e-30)
    assert depth[0].max() == 0.0
    assert sf.load_scene(path).wear() == expected


def test_batch_runs_wear_scenes(tmp_path):
    """Issue 54: batch(command="wear") gives each scene's `wear --json`."""
    path = tmp_path / "small_wear.toml"
    path.write_text(SMALL_WEAR)
    expected = cli_json("wear", path, "--json")
    assert sf.batch([path, SMALL_WEAR], command="wear") == [expected, expected]
    with pytest.raises(sf.StressfieldError) as caught:
        sf.batch([path], command="contact")
    assert "command must be" in str(caught.value)


SMALL_PLASTIC = """format = 1
[contact]
kind = "point"
load = "151.62 N"
[contact.body1]
radius = "flat"
material = "steel"
[contact.body2]
radius = "10 mm"
material = "rigid"
[plasticity]
yield_strength = "1 GPa"
hardening_modulus = "10 GPa"
steps = 2
unload_steps = 1
grid_cells = 32
depth_cells = 16
"""


def test_scene_plastic_is_plastic_json_and_its_fields(tmp_path):
    """Issue 51: Scene.plastic() is `plastic --json` to the last digit; with fields=True the
    arrays of `plastic --fields`, bit for bit."""
    path = tmp_path / "plastic.toml"
    path.write_text(SMALL_PLASTIC)
    npz = tmp_path / "fields.npz"
    expected = cli_json("plastic", path, "--json", "--fields", npz)
    scene = sf.load_scene(path)
    assert scene.plastic() == expected
    got = scene.plastic(fields=True)
    archive = np.load(npz)
    names = ["plastic_strain", "stress", "residual_stress", "pressure", "surface_displacement",
             "x", "y", "z"]
    assert sorted(archive.files) == sorted(names)
    for name in names:
        np.testing.assert_array_equal(got.pop(name), archive[name], err_msg=name)
    assert got == expected
    assert archive["plastic_strain"].shape == (16, 32, 32)
    assert archive["residual_stress"].shape == (16, 32, 32, 6)
    line = SCENES / "line_tau1.toml"
    with pytest.raises(sf.StressfieldError) as caught:
        sf.load_scene(line).plastic()
    assert str(caught.value) == cli_error("plastic", line)


SMALL_PLASTIC_LINE = """format = 1
[contact]
kind = "line"
load = "660 kN/m"
friction = 0.3
[contact.body1]
radius = "flat"
material = "steel"
[contact.body2]
radius = "10 mm"
material = "rigid"
[plasticity]
yield_strength = "1 GPa"
hardening_modulus = "0 GPa"
steps = 2
unload_steps = 1
grid_cells = 48
depth_cells = 12
extent_over_a = 3.0
depth_over_a = 2.0
tolerance = 1e-4
"""


def test_scene_plastic_of_a_line_is_plastic_json_and_its_one_row_fields(tmp_path):
    """Issue 51: a line contact (plane strain) through Scene.plastic() is `plastic --json` to
    the last digit, with the line's keys; fields=True gives the arrays of `plastic --fields`
    bit for bit, one row in y (nz, 1, nx)."""
    path = tmp_path / "plastic_line.toml"
    path.write_text(SMALL_PLASTIC_LINE)
    npz = tmp_path / "fields.npz"
    expected = cli_json("plastic", path, "--json", "--fields", npz)
    assert "load_n_per_m" in expected and "load_n" not in expected
    assert "half_width_m" in expected["loaded"] and "plastic_area_m2" in expected["loaded"]
    scene = sf.load_scene(path)
    assert scene.plastic() == expected
    got = scene.plastic(fields=True)
    archive = np.load(npz)
    names = ["plastic_strain", "stress", "residual_stress", "pressure", "surface_displacement",
             "x", "y", "z"]
    assert sorted(archive.files) == sorted(names)
    for name in names:
        np.testing.assert_array_equal(got.pop(name), archive[name], err_msg=name)
    assert got == expected
    assert archive["plastic_strain"].shape == (12, 1, 48)
    assert archive["residual_stress"].shape == (12, 1, 48, 6)
    assert archive["pressure"].shape == (1, 48)
    np.testing.assert_array_equal(archive["y"], [0.0])
def test_scene_ehl_is_ehl_json_and_the_pressure_file(tmp_path):
    path = SCENES / "lubricated_roller_bearing.toml"
    npy = tmp_path / "ehl.npy"
    expected = cli_json("ehl", path, "--json", "--pressure", npy)
    result = sf.load_scene(path).ehl()
    solution = result.pop("solution")
    assert result == expected
    assert set(sf.load_scene(path).hertz()["lubrication"]) >= {
        "entrainment_speed_m_per_s",
        "central_film_m",
        "minimum_film_m",
        "film_formula",
        "composite_roughness_m",
        "lambda",
        "regime",
    }
    assert solution.dtype == np.float64 and solution.shape[1] == 3
    np.testing.assert_array_equal(solution, np.load(npy))


def test_scene_ehl_of_a_point_contact_is_the_cli_error():
    path = SCENES / "lubricated_ball_on_flat.toml"
    with pytest.raises(sf.StressfieldError) as raised:
        sf.load_scene(path).ehl()
    assert str(raised.value) == cli_error("ehl", path)
