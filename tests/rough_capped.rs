//! Issue 22, rough contact on measured maps: load control under a hardness cap on spiky and
//! non-Gaussian maps (where the search on the approach used to break down), the overloaded
//! case, the warnings of a contact resolved by few cells, and the area curve under a cap.

use ndarray::Array2;
use stressfield::contact::rough::{
    solve, Control, RoughContactError, RoughContactProblem, RoughSolution, DEFAULT_TOLERANCE,
};
use stressfield::operator::elastic::Periodicity;
use stressfield::scene::Scene;
use stressfield::surface::generate::{generate, Amplitude, Form, Generator, Spectrum};

/// Steel on a rigid flat: E / (1 − ν²) with E = 210 GPa, ν = 0.3.
const E_STAR: f64 = 210e9 / (1.0 - 0.09);
/// An AFM-like sampling: 10 µm over 256 samples.
const SPACING: f64 = 10e-6 / 256.0;
/// The mean pressure of every case, Pa.
const MEAN: f64 = 20e6;

/// A periodic self-affine map (H = 0.7, roll-off at a fifth of the map, cutoff 4 samples,
/// rms 4 nm), `n`² samples.
fn self_affine(n: usize, seed: u64) -> Array2<f64> {
    generate(&Generator {
        shape: [n, n],
        spacing_m: [SPACING, SPACING],
        spectrum: Spectrum::SelfAffine {
            hurst: 0.7,
            rolloff_wavelength_m: n as f64 * SPACING / 5.0,
            cutoff_wavelength_m: 4.0 * SPACING,
        },
        amplitude: Amplitude::RmsHeight(4e-9),
        form: Form::None,
        seed,
    })
    .expect("surface")
    .heights_m()
    .to_owned()
}

/// [`self_affine`] with `spikes` single-cell spikes 15 to 60 nm tall (an AFM's tip
/// artefacts; far above the 4 nm roughness), placed by a fixed linear congruential sequence.
fn spiky(n: usize, spikes: usize) -> Array2<f64> {
    let mut heights = self_affine(n, 5);
    let mut state: u64 = 12345;
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..spikes {
        let (j, i) = ((next() * n as f64) as usize, (next() * n as f64) as usize);
        heights[[j, i]] += 15e-9 + 45e-9 * next();
    }
    heights
}

/// [`self_affine`]'s heights replaced, rank for rank, by the quantiles of an exponential
/// distribution of scale 4 nm: the same map's shape with a long upper tail (tall, sharp peaks;
/// skewness 2, kurtosis 9).
fn exponential(n: usize) -> Array2<f64> {
    let heights = self_affine(n, 9);
    let mut order: Vec<usize> = (0..heights.len()).collect();
    let flat: Vec<f64> = heights.iter().copied().collect();
    order.sort_by(|&a, &b| flat[a].total_cmp(&flat[b]));
    let count = flat.len() as f64;
    let mut out = vec![0.0; flat.len()];
    for (rank, &at) in order.iter().enumerate() {
        out[at] = -4e-9 * (1.0 - (rank as f64 + 0.5) / count).ln();
    }
    Array2::from_shape_vec(heights.dim(), out).expect("shape")
}

fn capped(heights: &Array2<f64>, control: Control, hardness_pa: f64) -> RoughContactProblem<'_> {
    RoughContactProblem {
        heights_m: heights.view(),
        spacing_m: [SPACING, SPACING],
        e_star_pa: E_STAR,
        periodicity: Periodicity::Periodic,
        control,
        hardness_pa: Some(hardness_pa),
        tolerance: DEFAULT_TOLERANCE,
        max_iterations: 5000,
        memory_limit_bytes: 1 << 30,
    }
}

/// Solves [`MEAN`] on `heights` capped at `hardness_pa` and checks the answer: the load to
/// 1e-9, no pressure above H(1 + 1e-12), the residual below the tolerance, no cell out of
/// contact penetrating, and an approach-controlled run at the approach found carrying the same
/// load (to 1e-6: there the tolerance 1e-8 of the pressure change is all that fixes the load).
fn check_capped(name: &str, heights: &Array2<f64>, hardness_pa: f64) -> RoughSolution {
    let started = std::time::Instant::now();
    let solution = solve(
        &capped(heights, Control::MeanPressure { pa: MEAN }, hardness_pa),
        &mut |_, _| {},
    )
    .unwrap_or_else(|e| panic!("{name}, H = {hardness_pa:.3e} Pa: {e}"));
    let elapsed = started.elapsed().as_secs_f64();
    let [ny, nx] = [heights.nrows(), heights.ncols()];
    let load = MEAN * (nx * ny) as f64 * SPACING * SPACING;
    let load_error = solution.load_n / load - 1.0;
    let integral_error = solution.pressure_pa.sum() * SPACING * SPACING / load - 1.0;
    let roughness = heights.std(0.0);
    let penetration = solution.gap_m.iter().fold(0.0f64, |m, &g| m.min(g)) / roughness;
    let by_approach = solve(
        &capped(
            heights,
            Control::Approach {
                m: solution.approach_m,
            },
            hardness_pa,
        ),
        &mut |_, _| {},
    )
    .unwrap_or_else(|e| panic!("{name}: approach control at the approach found: {e}"));
    let approach_load_error = by_approach.load_n / load - 1.0;
    eprintln!(
        "{name}, H/p̄ = {:.0}: {} iterations, {elapsed:.2} s, residual {:.1e}, load {load_error:+.1e} (Σp {integral_error:+.1e}), max p / H − 1 {:+.1e}, contact {:.2} %, plastic {:.2} % of the area, min gap {penetration:.1e} Sq, approach control at its approach: load {approach_load_error:+.1e}",
        hardness_pa / MEAN,
        solution.iterations,
        solution.residual,
        solution.max_pressure_pa / hardness_pa - 1.0,
        100.0 * solution.contact_fraction,
        100.0 * solution.plastic_cells as f64 / (nx * ny) as f64,
    );
    assert!(load_error.abs() < 1e-9, "{name}: load {load_error:e}");
    assert!(
        integral_error.abs() < 1e-9,
        "{name}: Σ p {integral_error:e}"
    );
    assert!(
        solution.max_pressure_pa <= hardness_pa * (1.0 + 1e-12),
        "{name}: {} > H",
        solution.max_pressure_pa
    );
    assert!(solution.residual < DEFAULT_TOLERANCE);
    assert!(solution.plastic_cells > 0, "{name}: the cap is reached");
    assert!(
        penetration > -1e-6,
        "{name}: penetration {penetration:e} Sq"
    );
    assert!(
        approach_load_error.abs() < 1e-6,
        "{name}: approach control carries {approach_load_error:e} more"
    );
    solution
}

/// The hardnesses at which 1 %, 10 % and 50 % of the nominal area would be plastic if the
/// cap carried the whole load (p̄ / H); the elastic cells carry part of it, so fewer are.
const HARDNESS_OVER_MEAN: [f64; 3] = [100.0, 10.0, 2.0];

/// A self-affine map with twelve tall single-cell spikes: at the elastic solution's approach
/// only the spikes carry load, all of them at the cap (the case that broke the search: the
/// runs there loaded no other cell, and the approach was doubled without end).
#[test]
fn capped_load_control_converges_on_a_spiky_map() {
    let heights = spiky(128, 12);
    for ratio in HARDNESS_OVER_MEAN {
        check_capped("spiky 128²", &heights, ratio * MEAN);
    }
}

/// An exponential height distribution (long upper tail), at the same hardnesses.
#[test]
fn capped_load_control_converges_on_an_exponential_map() {
    let heights = exponential(128);
    for ratio in HARDNESS_OVER_MEAN {
        check_capped("exponential 128²", &heights, ratio * MEAN);
    }
}

/// A load the fully plastic surface cannot carry (W > H × A) is refused, saying so.
#[test]
fn a_load_beyond_the_fully_plastic_surface_is_refused() {
    let heights = spiky(32, 2);
    let error = solve(
        &capped(&heights, Control::MeanPressure { pa: MEAN }, 0.9 * MEAN),
        &mut |_, _| {},
    )
    .expect_err("overloaded");
    assert!(
        matches!(error, RoughContactError::HardnessTooLow { .. }),
        "{error}"
    );
    let message = error.to_string();
    for needle in [
        "exceeds what the fully plastic surface can carry",
        "contact.load",
        "contact.hardness",
    ] {
        assert!(message.contains(needle), "{message}");
    }
}

/// `heights` as a Gwyddion ASCII export (nm) in `dir`, and a scene pressing it on a rigid
/// flat at `mean_pressure` with `extra` lines in `[contact]`.
fn afm_scene(
    dir: &std::path::Path,
    heights: &Array2<f64>,
    mean_pressure: &str,
    extra: &str,
) -> Scene {
    let [ny, nx] = [heights.nrows(), heights.ncols()];
    let mut text = format!(
        "# Channel: Height\n# Width: {} um\n# Height: {} um\n# Value units: nm\n",
        nx as f64 * SPACING * 1e6,
        ny as f64 * SPACING * 1e6
    );
    for row in heights.rows() {
        let values: Vec<String> = row.iter().map(|h| format!("{:.9e}", h * 1e9)).collect();
        text.push_str(&values.join("\t"));
        text.push('\n');
    }
    std::fs::write(dir.join("afm.txt"), text).expect("write the map");
    let scene = format!(
        "format = 1\n[contact]\nkind = \"rough\"\nmean_pressure = \"{mean_pressure}\"\nperiodic = true\n{extra}\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"rigid\"\n[surface]\nfile = \"afm.txt\"\n"
    );
    let path = dir.join("afm.toml");
    std::fs::write(&path, scene).expect("write the scene");
    Scene::load(&path).expect("scene")
}

/// The warnings: a contact on a few spikes (no hardness) is resolved by fewer than ten cells
/// at a peak pressure no material carries, and both are said in the report (text and JSON)
/// and on the sheet; a well-resolved capped contact gives none.
#[test]
fn few_cells_and_an_impossible_peak_are_warned_about() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let heights = spiky(64, 3);
    let scene = afm_scene(dir.path(), &heights, "10 MPa", "");
    let solution = stressfield::study::rough::solve(&scene, &mut |_, _| {}).expect("solves");
    let cells = solution.pressure_pa.iter().filter(|&&p| p > 0.0).count();
    assert!(
        cells < 10,
        "{cells} cells: the case needs a few-cell contact"
    );
    let findings = stressfield::study::rough::findings(&scene, &solution).expect("findings");
    assert_eq!(findings.warnings.len(), 2, "{:?}", findings.warnings);
    assert!(findings.warnings[0].contains(&format!("resolved by only {cells} cell")));
    assert!(findings.warnings[0].contains("refine the grid"));
    assert!(findings.warnings[1].contains("beyond any material"));
    assert!(findings.warnings[1].contains("contact.hardness"));
    let report = stressfield::report::rough::ContactReport::new(&scene, &solution, &findings);
    let json: serde_json::Value = serde_json::from_str(&report.json()).expect("json");
    assert_eq!(json["warnings"].as_array().map(Vec::len), Some(2));
    assert!(report
        .text(&scene)
        .contains("warning: the contact is resolved by only"));
    let findings = stressfield::study::rough::findings(&scene, &solution).expect("findings");
    let sheet = stressfield::figure::rough::rough_sheet(
        &scene,
        &solution,
        &stressfield::study::rough_sheet::sheet_fields(&scene, &solution, &findings.maxima, &|| {})
            .expect("fields"),
    )
    .expect("sheet");
    assert_eq!(sheet.notes.len(), 2);

    // Pressed harder, capped at 300 HV: hundreds of cells, no peak beyond the cap.
    let scene = afm_scene(dir.path(), &heights, "50 MPa", "hardness = \"300 HV\"");
    let solution = stressfield::study::rough::solve(&scene, &mut |_, _| {}).expect("solves");
    assert!(solution.pressure_pa.iter().filter(|&&p| p > 0.0).count() >= 10);
    let warnings = stressfield::study::rough::warnings(&scene, &solution);
    assert!(warnings.is_empty(), "{warnings:?}");
}

/// The real area against load under a cap: the solves at other loads converge too (on the
/// spiky map they failed, and `render` with them), and the area grows with the load.
#[test]
fn the_area_curve_solves_under_a_cap() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let heights = spiky(64, 6);
    let scene = afm_scene(dir.path(), &heights, "20 MPa", "hardness = \"600 HV\"");
    let solution = stressfield::study::rough::solve(&scene, &mut |_, _| {}).expect("solves");
    assert!(solution.plastic_cells > 0);
    let curve = stressfield::study::rough::area_curve(&scene, &solution).expect("area curve");
    assert_eq!(
        curve.len(),
        stressfield::study::rough::AREA_CURVE_FACTORS.len() + 1,
        "{curve:?}"
    );
    assert!(
        curve.windows(2).all(|w| w[1].0 > w[0].0 && w[1].1 > w[0].1),
        "{curve:?}"
    );
}
