//! Rough contact solver: the Hertz limit, Westergaard's wavy surface, load against approach
//! control, the plastic cap, grid convergence and bad input.

use std::f64::consts::PI;

use ndarray::Array2;
use stressfield::contact::rough::{
    solve, Control, RoughContactError, RoughContactProblem, RoughSolution, DEFAULT_TOLERANCE,
};
use stressfield::operator::elastic::Periodicity;
use stressfield::solution::dcfft::TractionGrid;
use stressfield::solution::point_numerical::PointTractions;
use stressfield::solution::Solution;
use stressfield::stress::Quantity;
use stressfield::study::assess::{self, grid_maxima};

const E_STAR: f64 = 1e11;
const RADIUS: f64 = 0.01;
const LOAD: f64 = 100.0;

/// Hertz (Johnson 1985, §4.2): contact radius and peak pressure of a sphere on a flat.
fn hertz() -> (f64, f64) {
    let a = (3.0 * LOAD * RADIUS / (4.0 * E_STAR)).cbrt();
    (a, 3.0 * LOAD / (2.0 * PI * a * a))
}

fn problem(
    heights: &Array2<f64>,
    spacing: f64,
    periodicity: Periodicity,
    control: Control,
) -> RoughContactProblem<'_> {
    RoughContactProblem {
        heights_m: heights.view(),
        spacing_m: [spacing, spacing],
        e_star_pa: E_STAR,
        periodicity,
        control,
        hardness_pa: None,
        tolerance: DEFAULT_TOLERANCE,
        max_iterations: 2000,
        memory_limit_bytes: 1 << 30,
    }
}

/// A sampled paraboloid of radius R over ±extent a, `cells` per side (odd: a centre cell).
fn paraboloid(cells: usize, extent_over_a: f64) -> (Array2<f64>, f64) {
    let (a, _) = hertz();
    let spacing = 2.0 * extent_over_a * a / cells as f64;
    let centre = (cells - 1) as f64 / 2.0;
    let heights = Array2::from_shape_fn((cells, cells), |(j, i)| {
        let (x, y) = ((i as f64 - centre) * spacing, (j as f64 - centre) * spacing);
        -(x * x + y * y) / (2.0 * RADIUS)
    });
    (heights, spacing)
}

fn solve_hertz(cells: usize) -> (RoughSolution, f64) {
    let (heights, spacing) = paraboloid(cells, 1.6);
    let solution = solve(
        &problem(
            &heights,
            spacing,
            Periodicity::NonPeriodic,
            Control::Load { newtons: LOAD },
        ),
        &mut |_, _| {},
    )
    .expect("solves");
    (solution, spacing)
}

#[test]
fn hertz_limit_pressure_radius_load_and_subsurface_maximum() {
    let (a, p0) = hertz();
    let (solution, spacing) = solve_hertz(127);
    // The load is the integral of the pressure, to rounding.
    let integral = solution.pressure_pa.sum() * spacing * spacing;
    assert!((integral / LOAD - 1.0).abs() < 1e-9, "{integral}");
    assert!((solution.load_n / LOAD - 1.0).abs() < 1e-9);
    // Peak pressure within 0.5 %, contact radius within one cell.
    let peak_error = solution.max_pressure_pa / p0 - 1.0;
    let cells = solution.pressure_pa.iter().filter(|&&p| p > 0.0).count();
    let radius = (cells as f64 * spacing * spacing / PI).sqrt();
    eprintln!(
        "Hertz 127²: p0 {:.5e} vs {p0:.5e} ({:+.3} %), a {:.5e} vs {a:.5e} ({:+.2} cells), {} iterations, residual {:.1e}",
        solution.max_pressure_pa,
        100.0 * peak_error,
        radius,
        (radius - a) / spacing,
        solution.iterations,
        solution.residual
    );
    assert!(peak_error.abs() < 0.005, "p0 off by {peak_error}");
    assert!((radius - a).abs() < spacing, "a = {radius} vs {a}");
    // Approach δ = a²/R.
    let approach = a * a / RADIUS;
    assert!(
        (solution.approach_m / approach - 1.0).abs() < 0.01,
        "{} vs {approach}",
        solution.approach_m
    );
    // No tension, no penetration.
    assert!(solution.pressure_pa.iter().all(|&p| p >= 0.0));
    let scale = approach;
    assert!(
        solution.gap_m.iter().all(|&g| g >= -1e-8 * scale),
        "penetration"
    );
    assert_eq!(solution.spots, 1);

    // The subsurface von Mises maximum under the solved pressure (DC-FFT layers, ν = 0.3)
    // against the closed form's (Huber: 0.62 p0 near 0.48a).
    let [ny, nx] = [solution.pressure_pa.nrows(), solution.pressure_pa.ncols()];
    let cell = spacing / a;
    let origin = [-(nx as f64) * cell / 2.0, -(ny as f64) * cell / 2.0];
    let grid = TractionGrid::new(
        origin,
        [cell, cell],
        Some(solution.pressure_pa.mapv(|p| p / p0)),
        None,
        None,
    )
    .expect("grid");
    let tractions = PointTractions::new(grid, 0.3).expect("tractions");
    let maxima = grid_maxima(&tractions).expect("layers");
    let exact = assess::maximum(
        &Solution::SphereHertz {
            friction: 0.0,
            poisson: 0.3,
        },
        Quantity::VonMises,
        false,
    );
    eprintln!(
        "von Mises max {:.4} p0 at z = {:.3}a; closed form {:.4} p0 at {:.3}a",
        maxima.von_mises.value_over_p0,
        maxima.von_mises.z_over_a,
        exact.value_over_p0,
        exact.z_over_a
    );
    assert!((maxima.von_mises.value_over_p0 / exact.value_over_p0 - 1.0).abs() < 0.01);
    assert!((maxima.von_mises.z_over_a - exact.z_over_a).abs() < 0.02 + cell);
    assert!((exact.value_over_p0 - 0.62).abs() < 0.005 && (exact.z_over_a - 0.48).abs() < 0.01);
}

#[test]
fn the_pressure_converges_with_the_grid() {
    let (a, p0) = hertz();
    eprintln!("cells  a/dx   p_max/p0 - 1   a_num/a - 1   iterations");
    let mut errors = Vec::new();
    for cells in [31, 63, 127] {
        let (solution, spacing) = solve_hertz(cells);
        let count = solution.pressure_pa.iter().filter(|&&p| p > 0.0).count();
        let radius = (count as f64 * spacing * spacing / PI).sqrt();
        // The mean of |p - p_Hertz| at the cell centres, relative to p0.
        let centre = (cells - 1) as f64 / 2.0;
        let mut sum = 0.0;
        for ((j, i), &p) in solution.pressure_pa.indexed_iter() {
            let r2 =
                ((i as f64 - centre).powi(2) + (j as f64 - centre).powi(2)) * spacing * spacing;
            let exact = p0 * (1.0 - r2 / (a * a)).max(0.0).sqrt();
            sum += (p - exact).abs();
        }
        let l1 = sum / (cells * cells) as f64 / p0;
        eprintln!(
            "{cells:5}  {:5.1}  {:+.2e}      {:+.2e}     {}   mean |p - p_H| {l1:.2e} p0",
            a / spacing,
            solution.max_pressure_pa / p0 - 1.0,
            radius / a - 1.0,
            solution.iterations
        );
        errors.push(l1);
    }
    assert!(errors[1] < errors[0] && errors[2] < errors[1], "{errors:?}");
}

/// Westergaard (Johnson 1985, §13.2): a periodic wavy surface `Δ cos(2πx/λ)` pressed on a flat
/// touches over `|x| < a` with `p̄ = p* sin²(πa/λ)`, `p* = π E* Δ / λ`, and peak pressure
/// `2 p̄ / sin(πa/λ)`.
#[test]
fn westergaard_wavy_surface() {
    let (nx, ny, wavelength, amplitude) = (256, 4, 1e-3, 1e-6);
    let spacing = wavelength / nx as f64;
    let heights = Array2::from_shape_fn((ny, nx), |(_, i)| {
        amplitude * (2.0 * PI * (i as f64 + 0.5) * spacing / wavelength).cos()
    });
    let p_star = PI * E_STAR * amplitude / wavelength;
    for ratio in [0.1, 0.25, 0.5] {
        let mean = ratio * p_star;
        let solution = solve(
            &problem(
                &heights,
                spacing,
                Periodicity::Periodic,
                Control::MeanPressure { pa: mean },
            ),
            &mut |_, _| {},
        )
        .expect("solves");
        let half_width = ratio.sqrt().asin() * wavelength / PI;
        let fraction = 2.0 * half_width / wavelength;
        let peak = 2.0 * mean / ratio.sqrt();
        eprintln!(
            "Westergaard p/p* = {ratio}: contact {:.4} vs {fraction:.4}, peak {:.4e} vs {peak:.4e}, {} iterations",
            solution.contact_fraction, solution.max_pressure_pa, solution.iterations
        );
        assert!((solution.contact_fraction - fraction).abs() <= 2.0 / nx as f64 + 1e-12);
        assert!((solution.max_pressure_pa / peak - 1.0).abs() < 0.01);
        assert!((solution.mean_pressure_pa / mean - 1.0).abs() < 1e-9);
        assert_eq!(solution.spots, 1, "one band, joined across y");
    }
}

#[test]
fn the_stress_under_a_periodic_contact_repeats_and_tends_to_the_mean_pressure() {
    // Westergaard's wavy surface at p̄ = p*/4: the tractions of one period stand for all of
    // them. At the surface σzz = -p in every cell (exactly: the other cells and the images add
    // no normal stress there); a wavelength down the field is the uniform one of the mean
    // pressure (the wavy parts decay at least as e^(-2π z/λ)).
    let (nx, ny, wavelength, amplitude) = (128, 4, 1e-3, 1e-6);
    let spacing = wavelength / nx as f64;
    let heights = Array2::from_shape_fn((ny, nx), |(_, i)| {
        amplitude * (2.0 * PI * (i as f64 + 0.5) * spacing / wavelength).cos()
    });
    let mean = 0.25 * PI * E_STAR * amplitude / wavelength;
    let solution = solve(
        &problem(
            &heights,
            spacing,
            Periodicity::Periodic,
            Control::MeanPressure { pa: mean },
        ),
        &mut |_, _| {},
    )
    .expect("solves");
    let tractions = stressfield::study::rough::tractions(&solution, 0.0, 0.3).expect("grid");
    assert!(tractions.is_periodic());
    let unit = stressfield::study::rough::REFERENCE_PRESSURE_PA;
    let surface = tractions.dcfft().layer(0.0).expect("layer");
    for ((j, i), &p) in solution.pressure_pa.indexed_iter() {
        let szz = surface[[2, j, i]] * unit;
        assert!((szz + p).abs() < 1e-9 * mean, "[{j}, {i}]: {szz} vs -{p}");
    }
    // Two wavelengths down (in the traction grid's unit, 1 um).
    let depth = 2.0 * wavelength / stressfield::study::rough::REFERENCE_LENGTH_M;
    let deep = tractions.dcfft().layer(depth).expect("layer");
    for ((c, j, i), &value) in deep.indexed_iter() {
        let expected = if c == 2 { -mean } else { 0.0 };
        assert!(
            (value * unit - expected).abs() < 1e-3 * mean,
            "component {c} at [{j}, {i}]: {} vs {expected}",
            value * unit
        );
    }
    // The isolated reading of the same tractions misses the other periods' load.
    let isolated = PointTractions::new(
        stressfield::study::rough::traction_grid(&solution, 0.0).expect("grid"),
        0.3,
    )
    .expect("grid");
    let shallow = isolated.dcfft().layer(depth).expect("layer");
    assert!(shallow[[2, 0, 0]] * unit > -0.5 * mean);
}

#[test]
fn approach_control_reproduces_load_control() {
    let (heights, spacing) = paraboloid(63, 1.6);
    let by_load = solve(
        &problem(
            &heights,
            spacing,
            Periodicity::NonPeriodic,
            Control::Load { newtons: LOAD },
        ),
        &mut |_, _| {},
    )
    .expect("load");
    let by_approach = solve(
        &problem(
            &heights,
            spacing,
            Periodicity::NonPeriodic,
            Control::Approach {
                m: by_load.approach_m,
            },
        ),
        &mut |_, _| {},
    )
    .expect("approach");
    assert!(
        (by_approach.load_n / LOAD - 1.0).abs() < 1e-6,
        "{}",
        by_approach.load_n
    );
    let difference = (&by_load.pressure_pa - &by_approach.pressure_pa)
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(difference < 1e-5 * by_load.max_pressure_pa, "{difference}");
}

#[test]
fn the_plastic_cap_limits_the_pressure_and_keeps_the_load() {
    let (_, p0) = hertz();
    let (heights, spacing) = paraboloid(63, 1.6);
    let mut capped = problem(
        &heights,
        spacing,
        Periodicity::NonPeriodic,
        Control::Load { newtons: LOAD },
    );
    capped.hardness_pa = Some(0.8 * p0);
    let solution = solve(&capped, &mut |_, _| {}).expect("solves");
    assert!(solution.max_pressure_pa <= 0.8 * p0 * (1.0 + 1e-12));
    assert!(solution.plastic_cells > 0);
    // Capped, the load is met by the approach to the tolerance (1e-8), and the reported load
    // is the integral of the pressure.
    eprintln!(
        "capped at 0.8 p0: {} plastic cells, load {:+.2e}, {} iterations",
        solution.plastic_cells,
        solution.load_n / LOAD - 1.0,
        solution.iterations
    );
    assert!((solution.load_n / LOAD - 1.0).abs() < 1e-8);
    let integral = solution.pressure_pa.sum() * spacing * spacing;
    assert!((integral / solution.load_n - 1.0).abs() < 1e-12);
    // Capped, the same load spreads wider than in the elastic solution.
    let elastic = solve(
        &problem(
            &heights,
            spacing,
            Periodicity::NonPeriodic,
            Control::Load { newtons: LOAD },
        ),
        &mut |_, _| {},
    )
    .expect("elastic");
    assert!(solution.contact_fraction > elastic.contact_fraction);
}

#[test]
fn bad_input_is_refused_with_the_reason() {
    let (heights, spacing) = paraboloid(31, 1.6);
    let run = |control| {
        solve(
            &problem(&heights, spacing, Periodicity::NonPeriodic, control),
            &mut |_, _| {},
        )
    };
    assert!(matches!(
        run(Control::Load { newtons: 0.0 }),
        Err(RoughContactError::Parameter { .. })
    ));
    assert!(matches!(
        run(Control::Load { newtons: -1.0 }),
        Err(RoughContactError::Parameter { .. })
    ));
    assert!(matches!(
        run(Control::Approach { m: -1e-6 }),
        Err(RoughContactError::NoContact { .. })
    ));
    // A domain too small: ±0.8a cannot hold the contact.
    let (small, small_spacing) = paraboloid(31, 0.8);
    let error = solve(
        &problem(
            &small,
            small_spacing,
            Periodicity::NonPeriodic,
            Control::Load { newtons: LOAD },
        ),
        &mut |_, _| {},
    )
    .expect_err("edge");
    assert!(
        matches!(error, RoughContactError::PressureAtEdge { .. }),
        "{error}"
    );
    assert!(error.to_string().contains("enlarge the domain"));
    // Full contact: a wavy surface pressed beyond p*.
    let wavy = Array2::from_shape_fn((4, 32), |(_, i)| 1e-6 * (2.0 * PI * i as f64 / 32.0).cos());
    let error = solve(
        &problem(
            &wavy,
            1e-5,
            Periodicity::Periodic,
            Control::MeanPressure {
                pa: 2.0 * PI * E_STAR * 1e-6 / 3.2e-4,
            },
        ),
        &mut |_, _| {},
    )
    .expect_err("full");
    assert!(error.to_string().contains("full contact"), "{error}");
    // Non-finite heights, named by row and column.
    let mut broken = heights.clone();
    broken[[3, 4]] = f64::NAN;
    let error = solve(
        &problem(
            &broken,
            spacing,
            Periodicity::NonPeriodic,
            Control::Load { newtons: LOAD },
        ),
        &mut |_, _| {},
    )
    .expect_err("nan");
    assert!(matches!(
        error,
        RoughContactError::NotFinite {
            row: 3,
            column: 4,
            ..
        }
    ));
    assert!(error.to_string().contains("row 3, column 4"), "{error}");
    // Too large for the memory allowed: an estimate, before allocating.
    let mut limited = problem(
        &heights,
        spacing,
        Periodicity::NonPeriodic,
        Control::Load { newtons: LOAD },
    );
    limited.memory_limit_bytes = 1000;
    assert!(matches!(
        solve(&limited, &mut |_, _| {}),
        Err(RoughContactError::TooLarge { .. })
    ));
    // Too few iterations: an error with the residual, never a result.
    let mut hurried = problem(
        &heights,
        spacing,
        Periodicity::NonPeriodic,
        Control::Load { newtons: LOAD },
    );
    hurried.max_iterations = 2;
    let error = solve(&hurried, &mut |_, _| {}).expect_err("not converged");
    assert!(
        matches!(error, RoughContactError::NotConverged { iterations: 2, .. }),
        "{error}"
    );
}

/// Compute once (issue 20): every command solves a rough scene's own contact once, whatever it
/// draws, reports or records (`render --rrd` draws the sheet and records from one solve; the
/// area-against-load curve solves other loads, not counted). The binary prints its count when
/// `STRESSFIELD_COUNT_SOLVES` is set.
#[test]
fn each_command_solves_a_rough_scene_once() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let scene = "scenes/rough_ball_on_flat.toml";
    let out = dir.path().join("out");
    let rrd = dir.path().join("ball.rrd");
    let out_dir = out.to_str().expect("utf-8");
    let mut commands: Vec<Vec<&str>> = vec![
        vec!["contact", scene, "--json"],
        vec!["hertz", scene],
        vec!["render", scene, "--out-dir", out_dir],
    ];
    // Recording needs the Rerun build.
    if cfg!(feature = "rerun") {
        commands.push(vec![
            "render",
            scene,
            "--out-dir",
            out_dir,
            "--rrd",
            rrd.to_str().expect("utf-8"),
        ]);
        commands.push(vec!["record", scene, "--out-dir", out_dir]);
    }
    for args in commands {
        let output = std::process::Command::new(env!("CARGO_BIN_EXE_stressfield"))
            .args(&args)
            .env("STRESSFIELD_COUNT_SOLVES", "1")
            .output()
            .expect("the binary runs");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(output.status.success(), "{args:?}: {stderr}");
        assert!(
            stderr.contains("rough contact solves: 1\n"),
            "{args:?}: {stderr}"
        );
    }
}

/// `contact --json` of a rough scene around the height file `map` (a 64² matrix in µm, 2 µm
/// spacing), with `extra` keys in `[surface]` and `periodic`.
fn contact_of_map(
    dir: &std::path::Path,
    name: &str,
    map: &Array2<f64>,
    extra: &str,
    periodic: bool,
) -> serde_json::Value {
    let rows: Vec<String> = map
        .rows()
        .into_iter()
        .map(|row| {
            row.iter()
                .map(|v| format!("{v:.12e}"))
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect();
    std::fs::write(dir.join(format!("{name}.asc")), rows.join("\n") + "\n").expect("map");
    let scene = dir.join(format!("{name}.toml"));
    std::fs::write(
        &scene,
        format!(
            "format = 1\ntitle = \"{name}\"\n[contact]\nkind = \"rough\"\nload = \"0.05 N\"\nperiodic = {periodic}\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n[surface]\nfile = \"{name}.asc\"\nspacing = \"2 um\"\nheight_unit = \"um\"\n{extra}\n"
        ),
    )
    .expect("scene");
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_stressfield"))
        .args(["contact", scene.to_str().expect("utf-8"), "--json"])
        .output()
        .expect("the binary runs");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("json")
}

/// Measured maps are solved as measured (issue 38): a map tilted as an instrument leaves it
/// is levelled before its isolated contact is solved, so that it gives the untilted map's
/// contact (the least-squares plane is linear in the heights: the same to round-off, 1e-9
/// relative here), and the JSON says what was removed and the plane's slopes (to 1e-9 of the
/// tilt given); `level = "none"` keeps the tilt deliberately and its contact moves to the high
/// side. A periodic map is one period of a surface that repeats, and a plane is not periodic
/// (issue 50): a periodic solve removes only the mean by default (the contact of the map as
/// given, `level = "none"`'s to the solver's tolerance), and a plane only when asked, with a
/// warning that it steps the seam. A periodic solve of a map whose opposite edges do not meet
/// is warned about; one that tiles (whole periods) is not.
#[test]
fn a_tilted_measured_map_is_levelled_before_solving_and_a_seam_is_warned_about() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let n = 64;
    // Whole periods of two waves on a central bump (a map that tiles, its contact inside it),
    // heights in µm; and the same tilted by
    // slopes 4e-3 along x and -2e-3 along y (0.5 µm and 0.25 µm across the map, the order of
    // its roughness), as a mounted specimen leaves it.
    let (sx, sy) = (4e-3, -2e-3);
    // Isolated: on the bump; periodic: the waves alone, so that the raw tilt's high corner
    // carries the contact onto the seam.
    for periodic in [false, true] {
        let bump = if periodic { 0.0 } else { 1.5 };
        let wavy = Array2::from_shape_fn((n, n), |(j, i)| {
            let (x, y) = (i as f64 / n as f64, j as f64 / n as f64);
            let r2 = (x - 0.5).powi(2) + (y - 0.5).powi(2);
            0.1 * (2.0 * PI * (2.0 * x)).cos() * (2.0 * PI * (3.0 * y)).cos()
                + 0.05 * (2.0 * PI * (5.0 * x + 1.0 * y) + 0.4).sin()
                + bump * (-r2 / (2.0 * 0.12f64.powi(2))).exp()
        });
        let tilted = Array2::from_shape_fn((n, n), |(j, i)| {
            wavy[[j, i]] + (sx * (i as f64 * 2.0) + sy * (j as f64 * 2.0)) + 7.0
        });
        let plane = if periodic { "level = \"plane\"" } else { "" };
        let flat = contact_of_map(dir.path(), "wavy", &wavy, plane, periodic);
        let levelled = contact_of_map(dir.path(), "tilted", &tilted, plane, periodic);
        let raw = contact_of_map(dir.path(), "raw", &tilted, "level = \"none\"", periodic);
        let f = |v: &serde_json::Value, key: &str| v[key].as_f64().expect(key);
        assert_eq!(levelled["levelling"]["removed"], "plane");
        // The plane removed is the tilt plus the untilted map's own (least squares is linear).
        let plane = &levelled["levelling"]["plane_m"];
        let own = &flat["levelling"]["plane_m"];
        let slope = |k: usize| plane[k].as_f64().expect("slope") - own[k].as_f64().expect("own");
        assert!(
            (slope(1) - sx).abs() < 1e-9 * sx.abs(),
            "{plane} less {own}"
        );
        assert!(
            (slope(2) - sy).abs() < 1e-9 * sy.abs(),
            "{plane} less {own}"
        );
        assert_eq!(raw["levelling"]["removed"], "none");
        assert!(raw["levelling"]["plane_m"].is_null());
        assert_eq!(levelled["spots"], flat["spots"], "periodic {periodic}");
        for key in ["contact_fraction", "max_pressure_pa", "von_mises_max_pa"] {
            let (a, b) = (f(&levelled, key), f(&flat, key));
            assert!((a - b).abs() <= 1e-9 * b.abs(), "{key}: {a} against {b}");
        }
        // The raw tilt moves the contact: it is no longer the wavy map's.
        assert!(
            (f(&raw, "max_pressure_pa") - f(&flat, "max_pressure_pa")).abs()
                > 1e-3 * f(&flat, "max_pressure_pa")
                || raw["spots"] != flat["spots"],
            "the tilt changed nothing"
        );
        let warned = |v: &serde_json::Value, text: &str| {
            v["warnings"]
                .as_array()
                .expect("warnings")
                .iter()
                .any(|w| w.as_str().expect("text").contains(text))
        };
        let seam = |v: &serde_json::Value| warned(v, "opposite edges do not meet");
        // Whole periods tile, levelled or not (the plane is removed, the waves kept); the raw
        // tilt steps at both seams.
        assert!(!seam(&flat) && !seam(&levelled), "periodic {periodic}");
        assert_eq!(seam(&raw), periodic, "periodic {periodic}: {raw}");
        // A plane asked of a periodic map is warned about where it steps the seam: the tilt's
        // does (0.5 µm across x), the waves' own least-squares plane does not.
        let stepped = "on a periodic map: the removed form is not periodic";
        assert_eq!(warned(&levelled, stepped), periodic, "{levelled}");
        assert!(!warned(&flat, stepped), "{flat}");
        if periodic {
            // The default of a periodic map: only the mean removed, the map as given.
            let default = contact_of_map(dir.path(), "default", &tilted, "", periodic);
            assert_eq!(default["levelling"]["removed"], "mean");
            assert_eq!(
                default["levelling"]["plane_m"],
                levelled["levelling"]["plane_m"]
            );
            assert_eq!(default["spots"], raw["spots"]);
            for key in ["contact_fraction", "max_pressure_pa", "von_mises_max_pa"] {
                let (a, b) = (f(&default, key), f(&raw, key));
                assert!((a - b).abs() <= 1e-6 * b.abs(), "{key}: {a} against {b}");
            }
            assert!(seam(&default) && !warned(&default, stepped), "{default}");
        }
    }
}

/// A periodic self-affine map given as a file (the kind Tamaas, ContactMechanics and
/// SurfaceTopography generate and exchange) is solved as the surface it is (issue 50): with
/// the default levelling its periodic contact is the generated map's own, which nothing
/// levels (pressure fields equal to 1e-9 of the peak, correlation 1 - 1e-12). Removing a
/// plane, as the default did, tilted the map and stepped its seam: the pressures' correlation
/// with Tamaas's solution of the same heights fell to 0.992 at 256².
#[test]
fn a_periodic_map_from_a_file_is_solved_as_given() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let generate = "[surface.generate]\nsamples = 64\nspacing = \"1 um\"\nhurst = 0.8\nrolloff = \"16 um\"\ncutoff = \"2 um\"\nrms_slope = 0.1\nseed = 3\n";
    let head = "format = 1\n[contact]\nkind = \"rough\"\nmean_pressure = \"0.5 GPa\"\nperiodic = true\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"rigid\"\n";
    let generated = dir.path().join("generated.toml");
    std::fs::write(&generated, format!("{head}{generate}")).expect("scene");
    let heights = dir.path().join("heights.npy");
    let written = std::process::Command::new(env!("CARGO_BIN_EXE_stressfield"))
        .args(["surface", generated.to_str().expect("utf-8"), "--heights"])
        .arg(&heights)
        .output()
        .expect("the binary runs");
    assert!(
        written.status.success(),
        "{}",
        String::from_utf8_lossy(&written.stderr)
    );
    let file = dir.path().join("file.toml");
    std::fs::write(
        &file,
        format!("{head}[surface]\nfile = \"heights.npy\"\nspacing = \"1 um\"\n"),
    )
    .expect("scene");
    let run = |scene: &std::path::Path| -> (serde_json::Value, Vec<f64>) {
        let fields = dir.path().join("pressure.npy");
        let output = std::process::Command::new(env!("CARGO_BIN_EXE_stressfield"))
            .args([
                "contact",
                scene.to_str().expect("utf-8"),
                "--json",
                "--pressure",
            ])
            .arg(&fields)
            .output()
            .expect("the binary runs");
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        let json: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json");
        let file = std::fs::File::open(&fields).expect("pressure file");
        let pressure: ndarray::Array2<f64> =
            ndarray_npy::ReadNpyExt::read_npy(file).expect("pressure .npy");
        (json, pressure.iter().copied().collect())
    };
    let (reference, p_reference) = run(&generated);
    let (given, p_given) = run(&file);
    assert_eq!(given["levelling"]["removed"], "mean", "{given}");
    let peak = p_reference.iter().fold(0.0f64, |m, &p| m.max(p));
    let worst = p_reference
        .iter()
        .zip(&p_given)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(
        worst <= 1e-9 * peak,
        "pressures differ by {worst} of a peak {peak} Pa"
    );
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (ma, mb) = (mean(&p_reference), mean(&p_given));
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for (a, b) in p_reference.iter().zip(&p_given) {
        sab += (a - ma) * (b - mb);
        saa += (a - ma).powi(2);
        sbb += (b - mb).powi(2);
    }
    let correlation = sab / (saa * sbb).sqrt();
    assert!(correlation > 1.0 - 1e-12, "correlation {correlation}");
    assert_eq!(reference["spots"], given["spots"]);
}
