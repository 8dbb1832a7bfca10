//! A rough scene's sheet agrees with its `contact` report (issue 23, items 10 and 11): the xz
//! section passes through the report's maximum and marks its value at its depth, the xy map
//! lies at that depth, the section is sized for reading, and `[figure] z` sets its depth range.

use std::path::Path;

use stressfield::contact::rough::RoughSolution;
use stressfield::render::chart::{Cell, Sheet};
use stressfield::render::{Figure, Panel};
use stressfield::scene::Scene;
use stressfield::study::rough::{self as rough_study, ContactFindings};

/// A small periodic map (64² samples, 10 µm wide) with a contact of a few spots.
const SMALL: &str = r#"
format = 1

[contact]
kind = "rough"
mean_pressure = "20 MPa"
periodic = true
friction = 0.2

[contact.body1]
material = "steel"

[contact.body2]
material = "steel"

[surface.generate]
samples = 64
spacing = "0.15625 um"
correlation_length = "1 um"
rms_height = "0.02 um"
seed = 5
"#;

fn shipped(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(format!("{name}.toml"));
    Scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

fn small(extra: &str) -> Result<Scene, String> {
    Scene::parse(&format!("{SMALL}\n{extra}"), "small", "small.toml").map_err(|e| e.to_string())
}

/// The scene's solved contact, its report's findings and its sheet.
fn solved_sheet(scene: &Scene) -> (RoughSolution, ContactFindings, Sheet) {
    let solution = rough_study::solve(scene, &mut |_, _| {}).expect("solves");
    let findings = rough_study::findings(scene, &solution).expect("findings");
    let sheet = stressfield::figure::rough::rough_sheet(scene, &solution, &findings.maxima, &|| {})
        .expect("sheet");
    (solution, findings, sheet)
}

/// The map of the sheet whose title starts with `start`.
fn map<'s>(sheet: &'s Sheet, start: &str) -> &'s Figure {
    sheet
        .rows
        .iter()
        .flatten()
        .find_map(|cell| match cell {
            Cell::Map(figure) if figure.title.starts_with(start) => Some(figure),
            _ => None,
        })
        .unwrap_or_else(|| panic!("no map titled {start}…"))
}

/// The largest sample of a panel and where it is (display units).
fn largest(panel: &Panel) -> (f64, f64, f64) {
    let mut best = (f64::NEG_INFINITY, 0.0, 0.0);
    for ((iz, ix), &v) in panel.values.indexed_iter() {
        if v > best.0 {
            best = (v, panel.x.value(ix), panel.z.value(iz));
        }
    }
    best
}

/// The section's and the depth map's marked maxima are the report's: value (MPa, to 1e-9)
/// and place (x modulo the period of a periodic map, z, y).
fn assert_marks_the_report(scene: &Scene) {
    let (solution, findings, sheet) = solved_sheet(scene);
    let reported = findings.maxima.von_mises;
    let section = map(&sheet, "von Mises stress σvM in the xz section");
    assert!(
        section.title.ends_with("through the report's largest σvM"),
        "{}",
        section.title
    );
    let panel = &section.panels[0];
    let (value, x, z) = largest(panel);
    let value_mpa = reported.value_over_p0;
    assert!(
        (value - value_mpa).abs() <= 1e-9 * value_mpa,
        "{}: section max {value} MPa, report {value_mpa} MPa",
        scene.name
    );
    let period = solution.pressure_pa.ncols() as f64 * solution.spacing_m[0] * 1e6;
    let dx = (x - reported.x_over_a).rem_euclid(period);
    assert!(
        dx.min(period - dx) < 1e-9,
        "x {x} against {}",
        reported.x_over_a
    );
    assert!(
        (z - reported.z_over_a).abs() < 1e-9,
        "z {z} against {}",
        reported.z_over_a
    );
    assert!(
        panel.subtitle.contains("max = the report's σvM"),
        "{}",
        panel.subtitle
    );
    let y = (reported.y_over_a * 1e3).round() / 1e3;
    assert!(
        panel.subtitle.starts_with(&format!("y = {y} µm")),
        "{} (y = {y})",
        panel.subtitle
    );
    // Colours to the 99.5 % quantile of the section when its maximum is a spike above it:
    // the marked maximum keeps its true value.
    if let Some(range) = panel.scale.as_ref().and_then(|s| s.range) {
        assert!(range.0 == 0.0 && range.1 < value_mpa, "{range:?}");
        let mut sorted: Vec<f64> = panel.values.iter().copied().filter(|v| *v > 0.0).collect();
        sorted.sort_by(f64::total_cmp);
        let at = ((sorted.len() - 1) as f64 * 0.995).round() as usize;
        assert_eq!(range.1, sorted[at]);
    }
    let depth = map(&sheet, "von Mises stress σvM at the depth of the report's");
    let (value, x, y) = largest(&depth.panels[0]);
    assert!(
        (value - value_mpa).abs() <= 1e-9 * value_mpa,
        "{value} {value_mpa}"
    );
    assert!((x - reported.x_over_a).abs() < 1e-9 && (y - reported.y_over_a).abs() < 1e-9);
}

#[test]
fn the_worn_sheet_marks_the_reports_maximum() {
    // Before: the section through the highest pressure marked 1582 MPa at 1.0 µm, the report
    // 1659 MPa at 0.375 µm.
    let scene = shipped("rough_worn_on_flat");
    assert_marks_the_report(&scene);
    // Its hardness (300 HV: Y = 981 MPa) is exceeded at the maximum: the yield line is drawn.
    let (_, _, sheet) = solved_sheet(&scene);
    let section = &map(&sheet, "von Mises stress σvM in the xz section").panels[0];
    assert!(
        section
            .subtitle
            .ends_with("dashed: σvM = Y = 981 MPa, yielding inside"),
        "{}",
        section.subtitle
    );
    assert!(!section.outlines.is_empty());
    let range = section
        .scale
        .as_ref()
        .and_then(|s| s.range)
        .expect("robust colours");
    assert!(range.1 < 981.0, "{range:?}");
}

#[test]
fn an_isolated_and_a_small_periodic_sheet_mark_the_reports_maximum() {
    let ball = small("").expect("valid");
    assert_marks_the_report(&ball);
    // A rough ball, isolated: one spot of 25 cells.
    let isolated = SMALL
        .replace("periodic = true\n", "")
        .replace("mean_pressure = \"20 MPa\"", "load = \"0.002 N\"")
        .replace("seed = 5", "seed = 5\nsphere_radius = \"50 um\"");
    let isolated = Scene::parse(&isolated, "isolated", "isolated.toml").expect("valid");
    assert_marks_the_report(&isolated);
}

#[test]
fn a_small_maps_section_is_at_least_a_quarter_as_deep_as_wide() {
    let scene = small("").expect("valid");
    let (solution, findings, sheet) = solved_sheet(&scene);
    let panel = &map(&sheet, "von Mises stress σvM in the xz section").panels[0];
    let cell = solution.spacing_m[0] * 1e6;
    let width = panel.x.max - panel.x.min + cell;
    let depth = panel.z.max - panel.z.min;
    assert!(
        depth >= 0.25 * width - 1e-12,
        "{depth} µm deep, {width} µm wide"
    );
    // The default depth: twice the report's search depth (1.08 µm here), within a cell.
    let search = findings.search_depth_m * 1e6;
    assert!(
        depth >= 2.0 * search - 1e-12 && depth <= 2.0 * search + cell,
        "{depth}"
    );
    // Drawn, the map is at least 200 px tall (840 px wide at equal scale).
    let png = stressfield::render::render_png(map(&sheet, "von Mises stress σvM in the xz"))
        .expect("draws");
    assert!(png.height() >= 200 + 150, "{}", png.height());
    // Depth samples no farther apart than a cell.
    assert!(panel.z.step() <= cell * (1.0 + 1e-12));
}

#[test]
fn figure_z_sets_the_depth_range_and_narrows_the_section() {
    let scene = small("[figure]\nz = [0, 0.6]").expect("valid");
    let (solution, findings, sheet) = solved_sheet(&scene);
    let panel = &map(&sheet, "von Mises stress σvM in the xz section").panels[0];
    let cell = solution.spacing_m[0] * 1e6;
    assert_eq!(panel.z.min, 0.0);
    assert!(
        panel.z.max >= 0.6 && panel.z.max < 0.6 + cell,
        "{:?}",
        panel.z
    );
    // A window four times as wide as deep, centred on the maximum.
    let width = panel.x.max - panel.x.min + cell;
    assert!((width - 2.4).abs() <= cell, "{width}");
    let centre = 0.5 * (panel.x.min + panel.x.max);
    assert!((centre - findings.maxima.von_mises.x_over_a).abs() <= cell);
    assert!(panel.subtitle.contains("max = the report's σvM"));

    // A range that leaves the report's depth out says so.
    let scene = small("[figure]\nz = [0.5, 1.5]").expect("valid");
    let (_, findings, sheet) = solved_sheet(&scene);
    let panel = &map(&sheet, "von Mises stress σvM in the xz section").panels[0];
    assert_eq!(panel.z.min, 0.5);
    assert!(findings.maxima.von_mises.z_over_a < 0.5);
    assert!(
        panel.subtitle.contains("outside the depths drawn"),
        "{}",
        panel.subtitle
    );

    // Another quantity: the section still passes through the report's σvM maximum, named.
    let scene = small("[figure]\nquantity = \"sxx\"").expect("valid");
    let (_, findings, sheet) = solved_sheet(&scene);
    let section = map(&sheet, "normal stress σxx in the xz section");
    assert!(section.title.ends_with("the report's largest σvM"));
    let reported = findings.maxima.von_mises.value_over_p0;
    let text = format!(
        "the report's largest σvM, {} MPa",
        stressfield::io::text::approx(reported)
    );
    assert!(
        section.panels[0].subtitle.contains(&text),
        "{}",
        section.panels[0].subtitle
    );
}

#[test]
fn bad_depth_ranges_are_refused_naming_figure_z() {
    for (extra, expected) in [
        ("z = [0, 0.2]", "less than a quarter of the 8 cells"),
        (
            "z = [0, 200]",
            "more than 10 times as deep as the map is wide",
        ),
        ("z = [-1, 2]", "depth must be >= 0"),
        ("x = [0, 2]", "figure.x"),
    ] {
        let error = small(&format!("[figure]\n{extra}")).expect_err(extra);
        assert!(error.contains("figure."), "{extra}: {error}");
        assert!(error.contains(expected), "{extra}: {error}");
    }
    let surface = "format = 1\n[contact]\nkind = \"surface\"\n[surface.generate]\nsamples = 64\nspacing = \"1 um\"\ncorrelation_length = \"5 um\"\nrms_height = \"0.1 um\"\n[figure]\nz = [0, 5]\n";
    let error = Scene::parse(surface, "s", "s.toml")
        .expect_err("refused")
        .to_string();
    assert!(error.contains("figure.z"), "{error}");
}

/// The spectrum chart of a surface sheet states a slope that gives no Hurst exponent (issue
/// 23, item 12: H = 1.753 was drawn for a Gaussian-correlated surface without a word), and
/// keeps its log axis to the rings with power.
#[test]
fn a_hurst_slope_outside_its_meaning_is_drawn_with_the_caveat() {
    let sheet_of = |spectrum: &str| {
        let text = format!(
            "format = 1\n[contact]\nkind = \"surface\"\n[surface.generate]\nsamples = 128\nspacing = \"0.5 um\"\n{spectrum}\nrms_height = \"0.1 um\"\nseed = 2\n"
        );
        let scene = Scene::parse(&text, "s", "s.toml").expect("valid");
        let c = stressfield::study::surface::characterise(&scene).expect("characterised");
        let sheet = stressfield::figure::surface::surface_sheet(&scene, &c).expect("sheet");
        let psd = sheet
            .rows
            .iter()
            .flatten()
            .find_map(|cell| match cell {
                Cell::Chart(chart) if chart.title == "Power spectral density" => {
                    Some(chart.clone())
                }
                _ => None,
            })
            .expect("a spectrum chart");
        (c, psd)
    };
    let (c, psd) = sheet_of("correlation_length = \"4 um\"");
    assert!(c.spectra.hurst.is_none());
    let labels: Vec<&str> = psd.series.iter().map(|s| s.label.as_str()).collect();
    let fitted = -c.spectra.fit_slope / 2.0 - 1.0;
    assert!(fitted > 1.0, "{fitted}");
    let caveat = format!(
        "slope: H = {} outside (0, 1]: not self-affine",
        stressfield::io::text::approx((fitted * 1e3).round() / 1e3)
    );
    assert!(labels.contains(&caveat.as_str()), "{labels:?}");
    assert!(!labels.iter().any(|l| l.starts_with("fit C")), "{labels:?}");
    // No ring of numerically zero power on the log axis.
    let smallest = psd.series[0]
        .points
        .iter()
        .map(|p| p.1)
        .fold(f64::INFINITY, f64::min);
    let largest = psd.series[0].points.iter().map(|p| p.1).fold(0.0, f64::max);
    assert!(smallest > 1e-12 * largest, "{smallest} {largest}");

    let (c, psd) = sheet_of("hurst = 0.8");
    let hurst = c.spectra.hurst.expect("self-affine");
    let labels: Vec<&str> = psd.series.iter().map(|s| s.label.as_str()).collect();
    assert!(labels.contains(&format!("fit C ∝ q^(−2(1+H)), H = {hurst:.3}").as_str()));
    assert!(
        !labels.iter().any(|l| l.contains("not self-affine")),
        "{labels:?}"
    );
}
