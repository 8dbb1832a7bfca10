//! Every scene in scenes/ renders, and the shipped figures show what their captions promise
//! (assertions on the computed maps rather than on pixels).

use std::path::Path;

use stressfield::scene::Scene;
use stressfield::{figure, render};

fn shipped_scenes() -> Vec<std::path::PathBuf> {
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
        let built = figure::build(&scene, &|| {}).expect("evaluates");
        let image =
            render::render_png(&built).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(image.width() >= scene.figure.width_px * scene.panels.len() as u32);
        assert!(render::render_svg(&built).expect("svg").len() > 1000);
    }
}

fn load(name: &str) -> (Scene, render::Figure) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(format!("{name}.toml"));
    let scene = Scene::load(&path).expect("valid");
    let built = figure::build(&scene, &|| {}).expect("evaluates");
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
