//! Every scene in scenes/ renders, and the shipped figures show what their captions promise
//! (assertions on the computed maps rather than on pixels).

use std::path::Path;

use stressfield::scene::Scene;
use stressfield::{figure, render};

/// The shipped scene files, sorted by name.
pub(crate) fn shipped_scenes() -> Vec<std::path::PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .expect("scenes/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    paths
}

/// Largest value of a panel and where it is (display units).
fn panel_max(panel: &render::Panel) -> (f64, f64, f64) {
    let mut best = (f64::NEG_INFINITY, 0.0, 0.0);
    for ((iz, ix), &v) in panel.values.indexed_iter() {
        if v > best.0 {
            best = (v, panel.x.value(ix), panel.z.value(iz));
        }
    }
    best
}

#[test]
fn every_shipped_scene_renders() {
    let paths = shipped_scenes();
    assert!(paths.len() >= 5, "{paths:?}");
    for path in paths {
        let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        if scene.wear.is_some() {
            // A wear scene draws its sheet from its study (the shipped ball's is shared).
            let owned;
            let study = if scene.name == "wear_rough_ball" {
                &crate::wear::shipped_ball().1
            } else {
                owned = stressfield::study::wear::study(&scene, &mut |_| {})
                    .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                &owned
            };
            let sheet = figure::wear::wear_sheet(&scene, study);
            let image = render::chart::sheet_png(&sheet)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assert!(image.width() > 800 && image.height() > 1000);
            continue;
        }
        let rough = (scene.contact.kind == stressfield::scene::ContactKind::Rough).then(|| {
            stressfield::study::rough::solve(&scene, &mut |_, _| {})
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        });
        let drawing = figure::compute_and_draw(&scene, rough.as_ref(), &|| {})
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let image = drawing
            .png()
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(image.width() >= scene.figure.width_px * scene.panels.len() as u32);
        assert!(drawing.svg().expect("svg").len() > 1000);
    }
}

fn load(name: &str) -> (Scene, render::Figure) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(format!("{name}.toml"));
    let scene = Scene::load(&path).expect("valid");
    let built = figure::build(
        &scene,
        &stressfield::study::panel_fields(&scene, &|| {}).expect("evaluates"),
    );
    (scene, built)
}

#[test]
fn tau1_figure_peaks_at_0_300_p0_below_the_axis() {
    let (_, built) = load("line_tau1");
    let (max, x, z) = panel_max(&built.panels[0]);
    // Grid spacing 4a/800: the sampled maximum lies within one cell of (0, 0.786a).
    assert!((max - 0.300).abs() < 1e-3, "{max}");
    assert!(x.abs() <= 0.005 && (z - 0.786).abs() <= 0.006, "({x}, {z})");
    assert_eq!(built.value_label, "τ1 / p0");
    assert_eq!(
        (built.x_label.as_str(), built.z_label.as_str()),
        ("x/a", "z/a")
    );
}

#[test]
fn trailing_edge_tension_is_the_sxx_maximum() {
    let (scene, built) = load("line_sxx_trailing_edge");
    let (max, x, z) = panel_max(&built.panels[0]);
    let mu = scene.contact.friction;
    assert!((max - 2.0 * mu).abs() < 1e-9, "{max}");
    assert!((x + 1.0).abs() < 1e-9 && z == 0.0, "({x}, {z})");
}

#[test]
fn friction_panels_raise_the_von_mises_maximum_towards_the_surface() {
    let (_, built) = load("line_von_mises_friction");
    let depths: Vec<f64> = built.panels.iter().map(|p| panel_max(p).2).collect();
    assert_eq!(depths.len(), 3);
    assert!(
        depths[0] > 0.6 && depths[1] < depths[0] && depths[2] == 0.0,
        "{depths:?}"
    );
}

#[test]
fn gear_figure_is_in_mm_and_mpa() {
    let (scene, built) = load("gear_pitch_point");
    assert_eq!(built.value_label, "σvM (MPa)");
    assert_eq!(built.x_label, "x (mm)");
    let (max, _, z) = panel_max(&built.panels[0]);
    let p0_mpa = scene.contact.p0_pa() * 1e-6;
    // Von Mises maximum 0.5568 p0 at z = 0.70a (a = 0.0709 mm), sampled on a 0.0004 mm grid.
    assert!(
        (max / p0_mpa - 0.5568).abs() < 1e-3,
        "{max} MPa of p0 = {p0_mpa}"
    );
    assert!((z - 0.70 * 0.070_938).abs() < 1e-3, "{z} mm");
    let half_width_mm = built.panels[0].half_width;
    assert!((half_width_mm - 0.070_938).abs() < 1e-5, "{half_width_mm}");
}

/// Smallest value of a panel and where it is (display units).
fn panel_min(panel: &render::Panel) -> (f64, f64, f64) {
    let mut best = (f64::INFINITY, 0.0, 0.0);
    for ((iz, ix), &v) in panel.values.indexed_iter() {
        if v < best.0 {
            best = (v, panel.x.value(ix), panel.z.value(iz));
        }
    }
    best
}

#[test]
fn sphere_max_shear_peaks_at_0_31_p0_near_0_48a() {
    let (_, built) = load("sphere_max_shear");
    let (max, x, z) = panel_max(&built.panels[0]);
    // Johnson (1985) §3.4(b), nu = 0.3: 0.31 p0 at z = 0.48a on the axis (two figures); the
    // exact maximum of the closed form is 0.3103 p0 at 0.4803a (tests/point_contact.rs).
    assert!((max - 0.31).abs() < 2e-3, "{max}");
    assert!(x.abs() <= 0.01 && (z - 0.48).abs() <= 0.01, "({x}, {z})");
    assert!(built.vertical_is_depth);
    assert_eq!(
        built.panels[0].subtitle,
        "xz plane, y = 0,  μ = 0,  ν = 0.3"
    );
}

#[test]
fn sliding_sphere_panels_raise_the_von_mises_maximum_to_the_surface() {
    let (_, built) = load("sphere_von_mises_friction");
    let maxima: Vec<(f64, f64, f64)> = built.panels.iter().map(panel_max).collect();
    assert_eq!(maxima.len(), 3);
    // mu = 0: on the axis at 0.48a; mu = 0.25: still below the surface but higher; mu = 0.5:
    // at the trailing edge x = -a of the surface.
    assert!(
        (maxima[0].2 - 0.48).abs() < 0.01 && maxima[0].1.abs() < 0.01,
        "{maxima:?}"
    );
    assert!(maxima[1].2 > 0.0 && maxima[1].2 < maxima[0].2, "{maxima:?}");
    assert!(
        maxima[2].2 == 0.0 && (maxima[2].1 + 1.0).abs() < 0.01,
        "{maxima:?}"
    );
    assert!(
        maxima[0].0 < maxima[1].0 && maxima[1].0 < maxima[2].0,
        "{maxima:?}"
    );
}

#[test]
fn surface_map_shows_the_ring_tension_and_the_trailing_edge_peak() {
    let (scene, built) = load("sphere_surface_s1");
    assert!(!built.vertical_is_depth);
    assert_eq!(
        (built.x_label.as_str(), built.z_label.as_str()),
        ("x/a", "y/a")
    );
    assert!(built.panels.iter().all(|p| p.traction.is_empty()));
    assert!(built.panels.iter().all(|p| p.outlines.len() == 1));
    assert_eq!(built.panels[0].subtitle, "surface z = 0,  μ = 0,  ν = 0.3");
    let nu = scene.panels[0].poisson;
    // Frictionless: the largest tension is the radial stress (1 - 2 nu)/3 p0 at r = a
    // (Johnson 1985 §3.4(b)), and the centre carries s1 = s_r = -(1 + 2 nu)/2 p0.
    let (max, x, y) = panel_max(&built.panels[0]);
    assert!((max - (1.0 - 2.0 * nu) / 3.0).abs() < 1e-3, "{max}");
    assert!(((x * x + y * y).sqrt() - 1.0).abs() < 0.01, "({x}, {y})");
    let (min, x, y) = panel_min(&built.panels[0]);
    assert!((min + (1.0 + 2.0 * nu) / 2.0).abs() < 1e-9 && x.abs() < 1e-9 && y.abs() < 1e-9);
    // Sliding: the peak tension sits at the trailing edge (-a, 0) and exceeds the ring's.
    let (max_sliding, x, y) = panel_max(&built.panels[1]);
    assert!((x + 1.0).abs() < 0.01 && y.abs() < 0.01, "({x}, {y})");
    assert!(max_sliding > 3.0 * max, "{max_sliding}");
}

#[test]
fn ball_on_flat_is_drawn_across_the_sliding_direction_in_mm() {
    let (scene, built) = load("sphere_ball_on_flat");
    assert_eq!(
        (built.x_label.as_str(), built.z_label.as_str()),
        ("y (mm)", "z (mm)")
    );
    let a_mm = scene.contact.half_width_m() * 1e3;
    // The traction strip spans the contact chord at x = 0, which is the diameter.
    assert!((built.panels[0].half_width - a_mm).abs() < 1e-12);
    let p0_mpa = scene.contact.p0_pa() * 1e-6;
    let peak = built.panels[0]
        .traction
        .iter()
        .map(|s| s.p)
        .fold(0.0, f64::max);
    assert!((peak / p0_mpa - 1.0).abs() < 1e-6, "{peak} of {p0_mpa}");
}

#[test]
fn sphere_cross_check_difference_is_small_below_the_surface() {
    let (_, built) = load("sphere_cross_check");
    assert_eq!(built.panels.len(), 3);
    let (exact_max, ..) = panel_max(&built.panels[0]);
    let (numerical_max, ..) = panel_max(&built.panels[1]);
    // 127 cells over [-2a, 2a]: von Mises maxima agree to 0.5 % of p0.
    assert!(
        (exact_max - numerical_max).abs() < 5e-3,
        "{exact_max} vs {numerical_max}"
    );
    // The difference panel is numerical - closed form on the grid's cell centres; below
    // z = 0.05a it stays under 1 % of p0, while the surface rows carry the largest error.
    let difference = &built.panels[2];
    let mut below = 0.0f64;
    let mut surface = 0.0f64;
    for ((iz, _), &v) in difference.values.indexed_iter() {
        if difference.z.value(iz) >= 0.05 {
            below = below.max(v.abs());
        } else {
            surface = surface.max(v.abs());
        }
    }
    assert!(below < 1e-2, "{below}");
    assert!(surface > below, "{surface} vs {below}");
}

#[test]
fn line_cross_check_agrees_below_the_surface() {
    let (_, built) = load("line_cross_check");
    let difference = &built.panels[2];
    let below = difference
        .values
        .indexed_iter()
        .filter(|((iz, _), _)| difference.z.value(*iz) >= 0.1)
        .fold(0.0f64, |m, (_, v)| m.max(v.abs()));
    // 100 strips: about 1e-3 p0 at z >= 0.1a (the probe test measures the convergence).
    assert!(below < 3e-3, "{below}");
}

#[test]
fn elongated_ellipse_lies_between_line_and_sphere() {
    let (scene, built) = load("ellipse_bearing_groove");
    assert!(scene.contact.aspect > 8.0, "{}", scene.contact.aspect);
    let p0_mpa = scene.contact.p0_pa() * 1e-6;
    let a_mm = scene.contact.half_width_m() * 1e3;
    let (max, _, z) = panel_max(&built.panels[0]);
    // A long ellipse approaches plane strain: von Mises max 0.557 p0 at 0.70a for the line
    // contact, 0.620 p0 at 0.48a for the sphere (Johnson 1985 §6.2, nu = 0.3).
    let ratio = max / p0_mpa;
    assert!(ratio > 0.557 && ratio < 0.62, "{ratio}");
    assert!(z / a_mm > 0.48 && z / a_mm < 0.79, "{}", z / a_mm);
}

#[test]
fn partial_slip_tension_lies_between_no_traction_and_sliding() {
    let (scene, built) = load("sphere_partial_slip");
    let (max, x, _) = panel_max(&built.panels[0]);
    let mu = scene.contact.friction;
    let nu = scene.contact.poisson;
    // Closed-form surface tension at the trailing edge of the sliding sphere, computed here
    // from the crate's Hamilton solution, and the frictionless ring (1 - 2 nu)/3.
    let sliding = stressfield::solution::sphere_hertz::stress_over_p0(-1.0, 0.0, 0.0, mu, nu).xx;
    assert!(
        max < sliding && max > (1.0 - 2.0 * nu) / 3.0,
        "{max} vs {sliding}"
    );
    assert!(x < -0.9, "the tension peak is behind the contact: x = {x}");
    // The contact circle and the stick circle c = a (1 - 0.6)^(1/3) are drawn.
    let outlines = &built.panels[0].outlines;
    assert_eq!(outlines.len(), 2);
    let c = outlines[1][0].0;
    assert!((c - 0.4f64.cbrt()).abs() < 1e-12, "{c}");
}

#[test]
fn a_section_across_a_long_ellipse_has_depth_rows_as_fine_as_the_x_cells() {
    // The groove ellipse (b/a = 9.3) cut across the rolling direction: the y cells are 9.3
    // times the x cells; the depth rows follow the finer x cells, so the subsurface maximum is
    // resolved as in the xz section (0.5746 p0 at z = 0.724a, the `hertz` grid maxima).
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/ellipse_bearing_groove.toml");
    let text = std::fs::read_to_string(path)
        .expect("the scene")
        .replace("section = \"xz\"", "section = \"yz\"")
        .replace("x = [-0.33, 0.33]", "y = [-2.0, 2.0]");
    let scene = Scene::parse(&text, "yz", "yz.toml").expect("valid");
    let plane = stressfield::study::plane(&scene, &scene.panels[0]);
    let a_mm = scene.contact.half_width_m() * 1e3;
    let cells = scene.numerical.cells as f64;
    let x_cell = 2.0 * scene.numerical.extent_over_a / cells;
    assert!(
        (plane.v.step() - x_cell).abs() < 1e-9,
        "{} vs {x_cell}",
        plane.v.step()
    );
    assert!(plane.u.step() > 9.0 * plane.v.step());
    let built = figure::build(
        &scene,
        &stressfield::study::panel_fields(&scene, &|| {}).expect("evaluates"),
    );
    let (max, y, z) = panel_max(&built.panels[0]);
    let p0_mpa = scene.contact.p0_pa() * 1e-6;
    assert!((max / p0_mpa - 0.5746).abs() < 2e-3, "{}", max / p0_mpa);
    assert!((z / a_mm - 0.724).abs() < 0.02, "{}", z / a_mm);
    assert!(y.abs() < plane.u.step() * a_mm);
}

/// A numerical panel ends where its traction grid ends: a range or section beyond it is
/// refused naming the grid's extent and the fix (issue 23, item 12: an elliptical scene asked
/// for y = ±4a drew ±0.6a), and a range within a cell of the grid's edge is drawn.
#[test]
fn numerical_ranges_beyond_the_grid_are_refused_with_the_limit() {
    let scene = |contact: &str, figure: &str| {
        Scene::parse(
            &format!("format = 1\n[contact]\n{contact}\n[figure]\n{figure}\n"),
            "range",
            "range.toml",
        )
        .map_err(|e| e.to_string())
    };
    let ellipse = "kind = \"elliptical\"\naspect = 0.3\nmethod = \"numerical\"";
    let error = scene(ellipse, "section = \"yz\"\ny = [-4.0, 4.0]").expect_err("cut");
    for expected in [
        "figure.y",
        "covers y = ±0.6 a",
        "raise numerical.extent to 14",
        "give figure.y within [-0.6, 0.6]",
    ] {
        assert!(error.contains(expected), "{expected}: {error}");
    }
    // Within the grid (its edge, and half a cell beyond) it is drawn, over the whole range.
    for y in ["0.6", "0.602"] {
        let valid = scene(ellipse, &format!("section = \"yz\"\ny = [-{y}, {y}]")).expect(y);
        let plane = stressfield::study::plane(&valid, &valid.panels[0]);
        assert!(plane.u.max > 0.59 && plane.u.min < -0.59, "{:?}", plane.u);
    }
    // A section beyond the grid, and the xy plane's vertical range.
    let point = "kind = \"point\"\nmethod = \"numerical\"";
    let error = scene(point, "at = 3.0").expect_err("beyond");
    assert!(
        error.contains("figure.at") && error.contains("covers y = ±2 a"),
        "{error}"
    );
    let error = scene(point, "section = \"xy\"\ny = [-1.0, 2.5]").expect_err("beyond");
    assert!(
        error.contains("figure.y") && error.contains("extent to 3"),
        "{error}"
    );
    // Closed-form panels have no grid.
    scene(
        "kind = \"point\"",
        "at = 3.0\nx = [-6.0, 6.0]\nz = [0.0, 3.0]",
    )
    .expect("closed form");
}

/// With a yield strength, a von Mises (or Tresca) figure draws where the stress reaches it,
/// or says the section stays below it (issue 23, item 13: a report said σvM/Y = 1.09, the
/// figure showed nothing).
#[test]
fn the_yield_line_is_drawn_where_the_section_reaches_y() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/sphere_ball_on_flat.toml");
    let text = std::fs::read_to_string(&path).expect("scene");
    let figure_of = |text: &str| {
        let scene = Scene::parse(text, "ball", path.to_str().expect("path")).expect("valid");
        let fields = stressfield::study::panel_fields(&scene, &|| {}).expect("evaluates");
        figure::build(&scene, &fields)
    };
    // Y = 1800 MPa: σvM/Y = 0.928 in the report; the yz section through the centre peaks at
    // 1665 MPa, below Y.
    let below = figure_of(&text);
    let panel = &below.panels[0];
    assert!(panel.outlines.is_empty());
    let (max, _, _) = panel_max(panel);
    let ratio = (max / 1800.0 * 1e3).round() / 1e3;
    assert!(
        panel
            .subtitle
            .ends_with(&format!("σvM < Y = 1800 MPa here (max {ratio} of it)")),
        "{}",
        panel.subtitle
    );
    // Y = 1500 MPa: the dashed line σvM = Y around the subsurface maximum (z = 0.11 mm).
    let lower = text.replace(
        "yield_strength = \"1.8 GPa\"",
        "yield_strength = \"1500 MPa\"",
    );
    assert_ne!(
        lower, text,
        "the scene's yield strength is written as 1.8 GPa"
    );
    let above = figure_of(&lower);
    let panel = &above.panels[0];
    assert!(
        panel
            .subtitle
            .ends_with("dashed: σvM = Y = 1500 MPa, yielding inside"),
        "{}",
        panel.subtitle
    );
    assert!(!panel.outlines.is_empty());
    let depths: Vec<f64> = panel.outlines.iter().flatten().map(|p| p.1).collect();
    let (top, bottom) = depths
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &z| (a.min(z), b.max(z)));
    assert!(top > 0.0 && top < 0.11 && bottom > 0.11, "{top}..{bottom}");
    // On the line the field is Y (interpolated between samples: within 1 %).
    for &(y, z) in panel.outlines.iter().flatten() {
        let iy = ((y - panel.x.min) / panel.x.step()).round() as usize;
        let iz = ((z - panel.z.min) / panel.z.step()).round() as usize;
        let v = panel.values[[iz, iy]];
        assert!((v - 1500.0).abs() < 0.01 * 1500.0, "{v} at ({y}, {z})");
    }
}

/// A difference map's colours are clipped to the bulk of it: its subtitle gives the range and
/// its colour bar ends in triangles (the marked extremes lie beyond).
#[test]
fn a_difference_maps_colour_range_is_stated() {
    let (_, built) = load("line_cross_check");
    let difference = &built.panels[2];
    let range = difference
        .scale
        .as_ref()
        .and_then(|s| s.range)
        .expect("clipped");
    assert!(
        difference.subtitle.ends_with(" p0 (98 %)") && difference.subtitle.contains("colours ±"),
        "{}",
        difference.subtitle
    );
    let (max, _, _) = panel_max(difference);
    assert!(max > 100.0 * range.1, "{max} against ±{}", range.1);
}

/// Issue 23, item 11: a section through the `hertz` report's maximum marks the report's value
/// at the report's position (located on the closed form between the samples), and a section
/// that misses it says where the body's maximum is.
#[test]
fn a_section_marks_the_reports_maximum_or_says_where_it_is() {
    use stressfield::study::assess::scene_maxima;
    // Through the maximum: the sliding sphere's xz section at y = 0 (μ = 0.3), the line
    // contact's τ1.
    for (name, tau1) in [("record_sphere_volume", false), ("line_tau1", true)] {
        let (scene, built) = load(name);
        let maxima = scene_maxima(&scene);
        let report = if tau1 {
            maxima.tau1.expect("a line contact's τ1")
        } else {
            maxima.maxima.expect("closed form").von_mises
        };
        let panel = &built.panels[0];
        let peak = panel.peak.expect("a located peak");
        let per_a = scene.length_unit_over_a();
        assert!(
            (peak.value - report.value_over_p0).abs() <= 1e-9,
            "{name}: {peak:?} against {report:?}"
        );
        assert!(
            (peak.x * per_a - report.x_over_a).abs() <= 1e-6
                && (peak.z * per_a - report.z_over_a).abs() <= 1e-6,
            "{name}: {peak:?} against {report:?}"
        );
        // The largest sample is up to half a grid step off, and lower.
        let (sampled, ..) = panel_max(panel);
        assert!(sampled <= peak.value, "{name}: {sampled} > {}", peak.value);
        assert!(!panel.subtitle.contains("body's max"), "{}", panel.subtitle);
    }
    // Missing it: the ball on a flat, across the sliding direction at x = 0, while friction
    // (μ = 0.1) moves the maximum to x = 0.026 mm.
    let (scene, built) = load("sphere_ball_on_flat");
    let report = scene_maxima(&scene).maxima.expect("closed form").von_mises;
    let mpa_per_p0 = scene.contact.p0_pa() * 1e-6;
    let panel = &built.panels[0];
    let peak = panel.peak.expect("a located peak");
    assert!(
        peak.value < report.value_over_p0 * mpa_per_p0 - 1.0,
        "{peak:?}"
    );
    let note = format!(
        "body's max {:.0} MPa at x = 0.026, z = 0.110 mm",
        report.value_over_p0 * mpa_per_p0
    );
    assert!(
        panel.subtitle.contains(&note),
        "{} lacks {note}",
        panel.subtitle
    );
}

/// Panels cut in different planes share one figure and one colour scale (issue 23, item 13):
/// the shipped groove scene's xz and yz sections through the `hertz` report's maximum
/// (0.6350 p0 at x = 0.392a, y = 0, z = 0.582a), and a sliding sphere's xz, yz and xy
/// sections.
#[test]
fn panels_in_different_planes_share_one_colour_range_with_their_own_axes() {
    let (scene, built) = load("ellipse_xz_yz");
    let [xz, yz] = [&built.panels[0], &built.panels[1]];
    assert_eq!(
        built.colour_ranges(),
        vec![(0..2, (0.0, panel_max(xz).0.max(panel_max(yz).0)))]
    );
    assert_eq!(
        (built.x_label.as_str(), built.z_label.as_str()),
        ("x (mm)", "z (mm)")
    );
    assert_eq!(xz.axes, None);
    assert_eq!(
        yz.axes,
        Some(render::PanelAxes {
            x_label: "y (mm)".into(),
            z_label: "z (mm)".into(),
            vertical_is_depth: true,
        })
    );
    // Each panel over its own plane's range, both through the report's maximum.
    let (a_mm, p0_mpa) = (
        scene.contact.half_width_m() * 1e3,
        scene.contact.p0_pa() * 1e-6,
    );
    assert!(xz.x.max < 0.3 && yz.x.max > 0.49, "{:?} {:?}", xz.x, yz.x);
    for (panel, along) in [(xz, 0.392 * a_mm), (yz, 0.0)] {
        let (max, u, z) = panel_max(panel);
        assert!((max / p0_mpa - 0.6350).abs() < 5e-4, "{}", max / p0_mpa);
        assert!((u - along).abs() < 0.01 * a_mm, "{u} vs {along}");
        assert!((z / a_mm - 0.582).abs() < 0.02, "{}", z / a_mm);
    }
    // The yz panel's tractions run along y over the contact's chord at its x.
    let chord = scene.contact.aspect * (1.0 - 0.392f64.powi(2)).sqrt() * a_mm;
    assert!(
        (yz.half_width - chord).abs() < 0.01 * chord,
        "{} vs {chord}",
        yz.half_width
    );

    // A depth section beside a plane parallel to the surface: one scale, each its own axes.
    let text = "format = 1\n[contact]\nkind = \"point\"\nfriction = 0.2\n[figure]\nz = [0.0, 1.5]\nresolution = 81\n[[panel]]\nsection = \"xy\"\nat = 0.46\n[[panel]]\n[[panel]]\nsection = \"yz\"\n";
    let scene = Scene::parse(text, "mixed", "mixed.toml").expect("valid");
    let built = figure::build(
        &scene,
        &stressfield::study::panel_fields(&scene, &|| {}).expect("evaluates"),
    );
    let maxima: Vec<f64> = built.panels.iter().map(|p| panel_max(p).0).collect();
    let largest = maxima.iter().copied().fold(0.0, f64::max);
    // The sliding sphere's maximum lies off the yz plane: its panel alone would have a lower top.
    assert!(maxima[2] < largest - 0.005, "{maxima:?}");
    assert_eq!(built.colour_ranges(), vec![(0..3, (0.0, largest))]);
    assert_eq!(
        (built.x_label.as_str(), built.z_label.as_str()),
        ("x/a", "y/a")
    );
    assert!(!built.vertical_is_depth && built.panels[0].traction.is_empty());
    for (panel, x_label) in [(&built.panels[1], "x/a"), (&built.panels[2], "y/a")] {
        let axes = built.axes_of(panel);
        assert_eq!(
            (axes.x_label, axes.z_label, axes.vertical_is_depth),
            (x_label, "z/a", true)
        );
        assert!(!panel.traction.is_empty());
    }
    assert!(
        built.panels[1].subtitle.starts_with("xz plane, y = 0"),
        "{}",
        built.panels[1].subtitle
    );
    assert!(
        built.panels[2].subtitle.starts_with("yz plane, x = 0"),
        "{}",
        built.panels[2].subtitle
    );
    render::render_png(&built).expect("renders");
}

/// The yz section of a frictionless sphere is its xz section turned about the axis: σxx in the
/// yz plane at x = 0.3a is σyy in the xz plane at y = 0.3a (the closed form, to rounding),
/// where the figure's own xz panel differs.
#[test]
fn a_yz_panel_of_a_sphere_is_its_xz_section_turned() {
    let figure_of = |quantity: &str, panels: &str| {
        let text = format!("format = 1\n[contact]\nkind = \"point\"\n[figure]\nquantity = \"{quantity}\"\nz = [0.0, 1.5]\nresolution = 81\n{panels}");
        let scene = Scene::parse(&text, "turned", "turned.toml").expect("valid");
        figure::build(
            &scene,
            &stressfield::study::panel_fields(&scene, &|| {}).expect("evaluates"),
        )
    };
    let mixed = figure_of(
        "sxx",
        "[[panel]]\nat = 0.3\n[[panel]]\nsection = \"yz\"\nat = 0.3\n",
    );
    let turned = figure_of("syy", "[[panel]]\nat = 0.3\n");
    let (yz, xz) = (&mixed.panels[1], &turned.panels[0]);
    assert_eq!((yz.x, yz.z), (xz.x, xz.z));
    let largest = yz
        .values
        .iter()
        .zip(&xz.values)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(largest < 1e-12, "{largest}");
    let apart = yz
        .values
        .iter()
        .zip(&mixed.panels[0].values)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(apart > 0.05, "{apart}");
}

/// Stresses on the axis of a frictionless elliptical Hertz contact (semi-axes `a` along x, `b`
/// along y, peak pressure 1) at depth `z > 0`: `(σx, σy, σz)`, the principal stresses there.
///
/// Love's potentials of a normal pressure p (Johnson, *Contact Mechanics*, 1985, ch. 3): with
/// `ψ = ∫∫ p/ρ dA` and `∂χ/∂z = ψ`,
/// `σx = (2ν ∂ψ/∂z − z ∂²ψ/∂x² − (1 − 2ν) ∂²χ/∂x²)/2π` and `σz = (∂ψ/∂z − z ∂²ψ/∂z²)/2π`.
/// For the Hertz pressure the potential is an integral over the ellipsoidal coordinate:
/// `ψ = (π a b/2) ∫_λ^∞ (1 − x²/(a² + w) − y²/(b² + w) − z²/w) dw/Δ(w)`,
/// `Δ = √((a² + w)(b² + w) w)`, `λ = z²` on the axis. So on the axis
/// `σz = −a b/√((a² + z²)(b² + z²))` and `σx = (a b/2)(−2ν z I + z J_a − (1 − 2ν) L_a)`, with
/// `I = ∫ dw/(wΔ)`, `J_a = ∫ dw/((a² + w)Δ)`, `L_a = ∫ (√w − z) dw/((a² + w)Δ)` over `w > z²`
/// (`σy` with b for a): the stresses on the axis that Thomas & Hoersch (1930) gave with
/// elliptic integrals, here as single integrals. For a = b they are the sphere's closed form
/// (checked below), and for b = 2a they agree with Boussinesq's point force integrated over
/// the contact to 1e-13 (checked when written, with mpmath).
fn ellipse_axis_stresses(a: f64, b: f64, z: f64, nu: f64) -> (f64, f64, f64) {
    let delta = |w: f64| ((a * a + w) * (b * b + w) * w).sqrt();
    // ∫_{z²}^∞ f(w) dw with w = z²/t², smooth on t in (0, 1].
    let integral = |f: &dyn Fn(f64) -> f64| {
        stressfield::thermal::special::integrate(
            |t: f64| {
                if t <= 0.0 {
                    return 0.0;
                }
                let w = z * z / (t * t);
                f(w) * 2.0 * z * z / (t * t * t)
            },
            0.0,
            1.0,
            1e-15,
        )
    };
    let i = integral(&|w| 1.0 / (w * delta(w)));
    let horizontal = |c: f64| {
        let j = integral(&|w| 1.0 / ((c * c + w) * delta(w)));
        let l = integral(&|w| (w.sqrt() - z) / ((c * c + w) * delta(w)));
        0.5 * a * b * (-2.0 * nu * z * i + z * j - (1.0 - 2.0 * nu) * l)
    };
    let sz = -a * b / ((a * a + z * z) * (b * b + z * z)).sqrt();
    (horizontal(a), horizontal(b), sz)
}

fn von_mises((sx, sy, sz): (f64, f64, f64)) -> f64 {
    (0.5 * ((sx - sy).powi(2) + (sy - sz).powi(2) + (sz - sx).powi(2))).sqrt()
}

/// An ellipse's yz section (numerical) peaks on the contact's axis at the closed-form maximum
/// there, and equals the xz section of the ellipse turned a quarter (semi-axes swapped, the
/// same grid turned with it).
#[test]
fn an_ellipse_yz_panel_peaks_at_the_closed_form_on_its_axis() {
    // The reference against the sphere's closed form (Hamilton), where a = b.
    for z in [0.1, 0.48, 1.3] {
        let (sx, sy, sz) = ellipse_axis_stresses(1.0, 1.0, z, 0.3);
        let s = stressfield::solution::sphere_hertz::stress_over_p0(0.0, 0.0, z, 0.0, 0.3);
        for (ours, theirs) in [(sx, s.xx), (sy, s.yy), (sz, s.zz)] {
            assert!((ours - theirs).abs() < 1e-12, "z = {z}: {ours} vs {theirs}");
        }
    }
    let scene_of = |aspect: f64, panels: &str| {
        let text = format!("format = 1\n[contact]\nkind = \"elliptical\"\naspect = {aspect}\nmethod = \"numerical\"\n[numerical]\ncells = 127\n{panels}");
        let scene = Scene::parse(&text, "ellipse", "ellipse.toml").expect("valid");
        let built = figure::build(
            &scene,
            &stressfield::study::panel_fields(&scene, &|| {}).expect("evaluates"),
        );
        (scene, built)
    };
    let (scene, built) = scene_of(2.0, "[[panel]]\n[[panel]]\nsection = \"yz\"\n");
    let yz = &built.panels[1];
    // The closed form's maximum on the axis, by golden-section search.
    let on_axis = |z: f64| von_mises(ellipse_axis_stresses(1.0, 2.0, z, 0.3));
    let (mut lo, mut hi) = (0.2, 1.5);
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    while hi - lo > 1e-9 {
        let (c, d) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
        if on_axis(c) > on_axis(d) {
            hi = d;
        } else {
            lo = c;
        }
    }
    let (z_max, exact) = (0.5 * (lo + hi), on_axis(0.5 * (lo + hi)));
    let (max, y, z) = panel_max(yz);
    let cell = 4.0 / 127.0;
    assert!(y.abs() < 0.5 * cell, "{y}");
    assert!((z - z_max).abs() < cell, "{z} vs {z_max}");
    // Measured 3.0e-4 (0.61059 against 0.61077 p0 at z = 0.622a; 127² cells, the nearest row).
    assert!((max - exact).abs() < 1e-3 * exact, "{max} vs {exact}");
    assert_eq!(scene.panels[1].at, 0.0);
    // Off the axis: the xz section of the ellipse with its semi-axes swapped (b/a = 1/2, in
    // units of its own a, half this one's), sampled at the same points turned.
    let (_, turned) = scene_of(0.5, "");
    let xz = &turned.panels[0];
    assert_eq!(xz.values.dim(), yz.values.dim());
    assert!((2.0 * xz.x.max - yz.x.max).abs() < 1e-12 && (2.0 * xz.z.max - yz.z.max).abs() < 1e-12);
    let largest = yz
        .values
        .iter()
        .zip(&xz.values)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    // Measured 9e-16: the same sums in another order.
    assert!(largest < 1e-12, "{largest}");
}
