//! Golden images: small figures compared pixel by pixel with references in tests/golden/,
//! through the same comparison as `stressfield render --compare`.
//!
//! `UPDATE_GOLDEN=1 cargo test --release golden` rewrites the references; a failure leaves the
//! actual and the diff image under target/golden-failures/.

use std::path::{Path, PathBuf};

use stressfield::regression::compare::{compare, diff_image, Tolerance};
use stressfield::scene::Scene;
use stressfield::{figure, render};

fn golden_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests")
        .join("golden")
}

fn check_golden(name: &str) {
    let scene =
        Scene::load(&golden_dir().join(format!("{name}.toml"))).expect("golden scene is valid");
    let built = figure::build(
        &scene,
        &stressfield::study::panel_fields(&scene, &|| {}).expect("field evaluates"),
    );
    let actual = render::render_png(&built).expect("renders");
    check_image(name, &actual);
}

/// Compares `actual` with the reference `tests/golden/<name>.png` (or rewrites it).
fn check_image(name: &str, actual: &image::RgbImage) {
    let reference = golden_dir().join(format!("{name}.png"));
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        let bytes = render::encode_png(actual).expect("encodes");
        stressfield::io::output::write_atomic(&reference, &bytes).expect("writes the reference");
        return;
    }
    let expected = image::open(&reference)
        .unwrap_or_else(|e| {
            panic!(
                "cannot open {}: {e}; run with UPDATE_GOLDEN=1 to create it",
                reference.display()
            )
        })
        .to_rgb8();
    // Anti-aliased text and lines may move by a shade between platforms; 0.2 % of the pixels may
    // differ by more than 24 of 255 in some channel.
    let pixels = (actual.width() * actual.height()) as usize;
    let tolerance = Tolerance {
        per_channel: 24,
        max_differing_pixels: pixels / 500,
    };
    let comparison = compare(actual, &expected, tolerance);
    if !comparison.passed() {
        let failures = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("target")
            .join("golden-failures");
        std::fs::create_dir_all(&failures).expect("mkdir");
        actual
            .save(failures.join(format!("{name}.actual.png")))
            .expect("save actual");
        if actual.dimensions() == expected.dimensions() {
            diff_image(actual, &expected, tolerance.per_channel)
                .save(failures.join(format!("{name}.diff.png")))
                .expect("save diff");
        }
        panic!("{name}: {comparison}; see {}", failures.display());
    }
}

#[test]
fn golden_tau1() {
    check_golden("tau1");
}

#[test]
fn golden_von_mises_friction() {
    check_golden("von_mises_friction");
}

#[test]
fn golden_gear_mpa() {
    check_golden("gear_mpa");
}

#[test]
fn golden_sphere_surface() {
    check_golden("sphere_surface");
}

#[test]
fn golden_sphere_sections() {
    check_golden("sphere_sections");
}

#[test]
fn golden_cross_check() {
    check_golden("cross_check");
}

/// The elastic-plastic sheet (issue 51) of a coarse rigid ball at p0(Hertz) = 2.5 Y: the
/// solve, its history and the sheet's sections drawn by `render`'s path.
#[test]
fn golden_plastic_sheet() {
    let scene =
        Scene::load(&golden_dir().join("plastic_sheet.toml")).expect("golden scene is valid");
    let study = stressfield::study::plastic::study(&scene, &mut |_| {}).expect("solves");
    let sections = stressfield::study::plastic::history::sheet_sections(&study);
    let title = scene.title.clone().unwrap_or_default();
    let sheet = figure::plastic::plastic_sheet(&title, &study, &sections);
    let actual = render::chart::sheet_png(&sheet).expect("renders");
    check_image("plastic_sheet", &actual);
}

/// The elastic-plastic sheet of a line contact (plane strain): a coarse rigid roller at
/// p0(Hertz) = 2.2 Y sliding at μ = 0.3, drawn by `render`'s path.
#[test]
fn golden_plastic_line_sheet() {
    let scene =
        Scene::load(&golden_dir().join("plastic_line_sheet.toml")).expect("golden scene is valid");
    let study = stressfield::study::plastic::study(&scene, &mut |_| {}).expect("solves");
    let sections = stressfield::study::plastic::history::sheet_sections(&study);
    let title = scene.title.clone().unwrap_or_default();
    let sheet = figure::plastic::plastic_sheet(&title, &study, &sections);
    let actual = render::chart::sheet_png(&sheet).expect("renders");
    check_image("plastic_line_sheet", &actual);
}
