//! A rough scene's sheet agrees with its `contact` report (issue 23, items 10 and 11): the xz
//! section passes through the report's maximum and marks its value at its depth, the xy map
//! lies at that depth, the section is sized for reading, and `[figure] z` sets its depth range;
//! a periodic contact's maps are centred on that maximum, a contact on the seam drawn whole.

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
    let fields =
        stressfield::study::rough_sheet::sheet_fields(scene, &solution, &findings.maxima, &|| {})
            .expect("fields");
    let sheet = stressfield::figure::rough::rough_sheet(scene, &solution, &fields).expect("sheet");
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
    // the marked maximum keeps its true value. Where the section reaches the yield strength,
    // the top rises to a quarter beyond it (issue 38: the range must not hide the yield line).
    if let Some(range) = panel.scale.as_ref().and_then(|s| s.range) {
        assert!(range.0 == 0.0 && range.1 < value_mpa, "{range:?}");
        let mut sorted: Vec<f64> = panel.values.iter().copied().filter(|v| *v > 0.0).collect();
        sorted.sort_by(f64::total_cmp);
        let at = ((sorted.len() - 1) as f64 * 0.995).round() as usize;
        let largest = sorted[sorted.len() - 1];
        let expected = match scene.contact.yield_strength {
            Some(y) if largest >= y.pa * 1e-6 => sorted[at].max(largest.min(1.25 * y.pa * 1e-6)),
            _ => sorted[at],
        };
        assert_eq!(range.1, expected);
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
    // The yield line lies inside the colours, the region beyond it shown (a quarter above Y,
    // below the section's peak); the 99.5 % quantile alone (about 900 MPa) hid it.
    assert!(
        range.1 > 981.0 && range.1 <= 1.25 * 981.0 + 1.0,
        "{range:?}"
    );
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

/// The worn surface rolled so that the report's maximum lies under the corner cell (0, 0) and
/// its contact straddles the periodic seam (`tests/data/worn_on_seam.asc`).
fn on_the_seam() -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/rough_worn_on_seam.toml");
    Scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// The three maps of a rough sheet.
const MAPS: [&str; 3] = [
    "Topography and contact spots",
    "Contact pressure",
    "von Mises stress σvM at the depth",
];

/// Issue 23, item 10: a periodic contact on the seam was drawn split into the maps' corners.
/// Its maps are now rolled by whole cells to centre the report's maximum, their axes running on
/// past the period, the marks and the section where they were.
#[test]
fn a_contact_on_the_periodic_seam_is_drawn_centred_on_the_maximum() {
    let scene = on_the_seam();
    let (solution, findings, sheet) = solved_sheet(&scene);
    let reported = findings.maxima.von_mises;
    // The scene does put the maximum on the seam: under the corner cell.
    assert!(
        (reported.x_over_a - 0.5).abs() < 1e-9 && (reported.y_over_a - 0.5).abs() < 1e-9,
        "{reported:?}"
    );
    let (ny, nx) = solution.pressure_pa.dim();
    let [dx, dy] = solution.spacing_m.map(|d| d * 1e6);
    let roll = stressfield::study::rough_sheet::display_roll(&solution, &reported);
    assert_eq!((roll.columns, roll.rows), (-64, -64));
    let stored_mpa = solution.pressure_pa.mapv(|p| p * 1e-6);
    for title in MAPS {
        let panel = &map(&sheet, title).panels[0];
        // Axes of cell centres, one piece from half a period left of the maximum's cell to
        // half a period right, each the stored cell's centre modulo the period.
        assert_eq!((panel.x.count, panel.z.count), (nx, ny));
        assert!((panel.x.min - (-63.5)).abs() < 1e-12 && (panel.x.max - 63.5).abs() < 1e-12);
        assert!((panel.z.min - (-63.5)).abs() < 1e-12 && (panel.z.max - 63.5).abs() < 1e-12);
        for (axis, n, d, shift) in [
            (&panel.x, nx, dx, roll.columns),
            (&panel.z, ny, dy, roll.rows),
        ] {
            let values: Vec<f64> = axis.values().collect();
            assert!(
                values.windows(2).all(|w| w[1] > w[0]),
                "{title}: {values:?}"
            );
            for (k, &u) in values.iter().enumerate() {
                let stored = (k as isize + shift).rem_euclid(n as isize) as f64;
                let periods = (u - (stored + 0.5) * d) / (n as f64 * d);
                assert!(
                    (periods - periods.round()).abs() < 1e-12,
                    "{title}: {k} {u}"
                );
            }
        }
    }
    // The pressure map shows every stored value once, each at its rolled cell.
    let pressure = &map(&sheet, "Contact pressure").panels[0];
    let mut shown: Vec<f64> = pressure.values.iter().copied().collect();
    let mut stored: Vec<f64> = stored_mpa.iter().copied().collect();
    shown.sort_by(f64::total_cmp);
    stored.sort_by(f64::total_cmp);
    assert!(shown
        .iter()
        .zip(&stored)
        .all(|(a, b)| (a - b).abs() <= 1e-12 * b.abs()));
    for ((j, i), &p) in pressure.values.indexed_iter() {
        let at = [(j + ny / 2) % ny, (i + nx / 2) % nx];
        assert!((p - stored_mpa[at]).abs() <= 1e-12 * p.abs(), "{j} {i}");
    }
    // The maximum at the centre cell, marked with the report's value at the report's place.
    let depth = &map(&sheet, "von Mises stress σvM at the depth").panels[0];
    let ((j, i), _) =
        depth
            .values
            .indexed_iter()
            .fold(((0, 0), f64::NEG_INFINITY), |best, (at, &v)| {
                if v > best.1 {
                    (at, v)
                } else {
                    best
                }
            });
    assert!(
        j.abs_diff(ny / 2) <= 1 && i.abs_diff(nx / 2) <= 1,
        "{j} {i}"
    );
    assert_marks_the_report(&scene);
    // The section lies within the maps' x range, on their cell centres, at the maximum's y.
    let section = &map(&sheet, "von Mises stress σvM in the xz section").panels[0];
    assert!(section.x.min >= pressure.x.min - 1e-9 && section.x.max <= pressure.x.max + 1e-9);
    let offset = (section.x.min - pressure.x.min) / dx;
    assert!((offset - offset.round()).abs() < 1e-9, "{offset}");
    assert!(section
        .subtitle
        .starts_with("y = 0.5 µm, centred on the maximum"));
    let topography = &map(&sheet, "Topography and contact spots").panels[0];
    assert!(
        topography
            .subtitle
            .ends_with("; periodic, centred on the maximum"),
        "{}",
        topography.subtitle
    );
    // The spots are outlined on the rolled map, within its axes.
    assert!(!topography.outlines.is_empty());
    assert!(topography
        .outlines
        .iter()
        .flatten()
        .all(|&(x, y)| { (panel_range(&topography.x, x)) && (panel_range(&topography.z, y)) }));

    // The same surface unmoved (the shipped scene, its heights as measured as the rolled
    // map's) looks the same: centred on the same cell, its maps are these, their axes shifted
    // by the whole cells the surface was moved.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/rough_worn_on_flat.toml");
    let text = std::fs::read_to_string(&path)
        .expect("shipped scene")
        .replace("level = \"plane\"", "level = \"none\"");
    assert!(
        text.contains("level = \"none\""),
        "the shipped scene's level"
    );
    let raw = Scene::parse(&text, "rough_worn_on_flat", &path.display().to_string())
        .unwrap_or_else(|e| panic!("{e}"));
    let (_, _, unmoved) = solved_sheet(&raw);
    for title in MAPS {
        let (here, there) = (
            &map(&sheet, title).panels[0],
            &map(&unmoved, title).panels[0],
        );
        assert!(
            (there.x.min - here.x.min - 109.0 * dx).abs() < 1e-9,
            "{title}"
        );
        assert!(
            (there.z.min - here.z.min - 78.0 * dy).abs() < 1e-9,
            "{title}"
        );
        let top = here.values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let differs = here
            .values
            .iter()
            .zip(&there.values)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        // Measured: 0 (topography), 2.9e-11 of 2929 MPa (pressure), 1.5e-11 of 1660 MPa.
        assert!(differs <= 1e-9 * top, "{title}: {differs} of {top}");
    }
}

/// Whether `u` lies on `axis` (within a millionth of its span).
fn panel_range(axis: &stressfield::field::Axis, u: f64) -> bool {
    let slack = 1e-6 * (axis.max - axis.min);
    u >= axis.min - slack && u <= axis.max + slack
}

/// An isolated contact's maps are drawn as stored: nothing lies beyond them.
#[test]
fn an_isolated_contacts_maps_are_not_rolled() {
    let isolated = SMALL
        .replace("periodic = true\n", "")
        .replace("mean_pressure = \"20 MPa\"", "load = \"0.002 N\"")
        .replace("seed = 5", "seed = 5\nsphere_radius = \"50 um\"");
    let scene = Scene::parse(&isolated, "isolated", "isolated.toml").expect("valid");
    let (solution, findings, sheet) = solved_sheet(&scene);
    let roll = stressfield::study::rough_sheet::display_roll(&solution, &findings.maxima.von_mises);
    assert!(roll.is_none(), "{roll:?}");
    let (ny, nx) = solution.pressure_pa.dim();
    let dx = solution.spacing_m[0] * 1e6;
    let pressure = &map(&sheet, "Contact pressure").panels[0];
    assert!((pressure.x.min - 0.5 * dx).abs() < 1e-12);
    assert!((pressure.x.max - (nx as f64 - 0.5) * dx).abs() < 1e-12);
    assert_eq!(pressure.values.dim(), (ny, nx));
    for ((j, i), &p) in pressure.values.indexed_iter() {
        let stored = solution.pressure_pa[[j, i]] * 1e-6;
        assert!((p - stored).abs() <= 1e-12 * stored.abs(), "{j} {i}");
    }
    let topography = &map(&sheet, "Topography and contact spots").panels[0];
    assert!(
        !topography.subtitle.contains("centred"),
        "{}",
        topography.subtitle
    );
    // The rough ball's maximum is not at the map's centre cell: a roll would have moved it.
    let reported = findings.maxima.von_mises;
    let cell = [
        (reported.y_over_a / (solution.spacing_m[1] * 1e6)).floor() as usize,
        (reported.x_over_a / dx).floor() as usize,
    ];
    assert_ne!(cell, [ny / 2, nx / 2]);
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
