//! The elastic-plastic point contact's `hertz` yield assessment, render sheet and recording
//! (issue 51).

use crate::cli::{run, stderr};

/// `hertz` of a `[plasticity]` scene assesses yield against `plasticity.yield_strength` (it
/// read `contact.yield_strength` only and reported "yield strength not given").
#[test]
fn hertz_of_a_plastic_scene_uses_the_plasticity_yield_strength() {
    let scene = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/plastic_rigid_ball_on_flat.toml"
    );
    let output = run(&["hertz", scene, "--json"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).expect("one JSON object");
    assert_eq!(json["yield_strength_pa"], 1e9);
    // p0 = 2.5 Y and σvM,max = 0.6200 p0 (Hamilton's closed form on the axis): 1.550 Y.
    let ratio = json["von_mises_over_yield"].as_f64().expect("a number");
    assert!((ratio - 2.5 * 0.62).abs() < 2e-3, "σvM/Y = {ratio}");
    assert_eq!(json["verdict"], "subsurface");
    // First yield at p0 = Y / 0.6200: the load scales as p0³.
    let load = json["load_at_first_yield"].as_f64().expect("a number");
    let expected = 151.62 * (1.0 / (0.620 * 2.5f64)).powi(3);
    assert!(
        (load / expected - 1.0).abs() < 1e-3,
        "{load} N, {expected} N"
    );
    let text = run(&["hertz", scene]);
    assert!(text.status.success(), "{}", stderr(&text));
    let text = String::from_utf8_lossy(&text.stdout).into_owned();
    assert!(
        text.contains("Y  = 1000 MPa (plasticity.yield_strength)"),
        "{text}"
    );
    assert!(!text.contains("yield strength not given"), "{text}");
}

/// A rigid ball on a perfectly plastic steel flat at p0(Hertz) = 2.5 Y, coarse (under a
/// second): 3 load and 2 unload steps.
const SMALL: &str = r#"format = 1
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
steps = 3
unload_steps = 2
grid_cells = 24
depth_cells = 12
"#;

fn small_study() -> stressfield::study::plastic::PlasticStudy {
    let scene = stressfield::scene::Scene::parse(SMALL, "small", "small.toml").expect("valid");
    stressfield::study::plastic::study(&scene, &mut |_| {}).expect("solves")
}

/// The per-step history the sheet and the recording draw agrees with the report's loaded and
/// unloaded states (the same steps, read by the observer instead of the snapshots).
#[test]
fn the_step_history_agrees_with_the_loaded_and_unloaded_states() {
    let study = small_study();
    let history = &study.history;
    assert_eq!(history.points.len(), 5);
    assert_eq!(history.sections.len(), 5);
    let unloading: Vec<bool> = history.points.iter().map(|p| p.unloading).collect();
    assert_eq!(unloading, [false, false, false, true, true]);
    let loaded = &history.points[2];
    assert_eq!(loaded.max_pressure_pa, study.loaded.max_pressure_pa);
    assert_eq!(loaded.mean_pressure_pa, study.loaded.mean_pressure_pa);
    assert_eq!(loaded.contact_radius_m, study.loaded.contact_radius_m);
    assert_eq!(loaded.approach_m, Some(study.loaded.approach_m));
    let last = &history.points[4];
    assert_eq!(last.load_n, 0.0);
    assert_eq!(last.approach_m, None);
    let unloaded = study.unloaded.as_ref().expect("unloaded");
    assert_eq!(last.axis_displacement_m, unloaded.residual_depth_m);
    assert!(unloaded.residual_depth_m > 0.0);
    // The loaded step's section is the snapshot's section on y = 0, value for value.
    let sections = stressfield::study::plastic::history::sheet_sections(&study);
    assert_eq!(history.sections[2], sections.loaded);
    assert_eq!(Some(&history.sections[4]), sections.unloaded.as_ref());
    // The section's largest von Mises is the volume's (on the axis, the section holds it).
    let largest = sections
        .loaded
        .von_mises_pa
        .iter()
        .fold(0.0f64, |m, &v| m.max(v));
    assert!((largest / study.loaded.von_mises_max_pa - 1.0).abs() < 1e-12);
    // The load grows, the plastic strain never shrinks, the mean pressure stays below
    // Hertz's p_m of each load (the plastic contact is wider and flatter).
    for pair in history.points[..3].windows(2) {
        assert!(pair[1].load_n > pair[0].load_n);
        assert!(pair[1].max_plastic_strain >= pair[0].max_plastic_strain);
    }
}

/// The recording holds every step on the `load step` timeline: the sections, the growing
/// charts and the series with the history's values.
#[cfg(feature = "rerun")]
#[test]
fn the_recording_has_every_load_step() {
    use crate::record::Contents;
    let study = small_study();
    let scene = stressfield::scene::Scene::parse(SMALL, "small", "small.toml").expect("valid");
    let (stream, storage) = rerun::RecordingStreamBuilder::new(stressfield::record::APPLICATION_ID)
        .memory()
        .expect("an in-memory recording");
    let summary = stressfield::record::plastic::record(&scene, &study, &stream, false, &|| Ok(()))
        .expect("recorded");
    stream.flush_blocking().expect("flushed");
    let contents = Contents::from_messages(storage.take());
    assert_eq!(summary.steps, 5);
    let paths = contents.paths();
    for path in [
        "/sheet",
        "/description",
        "/plastic/strain/field",
        "/plastic/von_mises/field",
        "/curves/load_approach",
        "/curves/mean_pressure",
        "/log",
    ] {
        assert!(paths.contains(&path), "{path} missing from {paths:?}");
    }
    let y = study.spec.yield_strength_pa;
    let logged = contents.scalars("/series/max_pressure_over_y", "load step");
    let expected: Vec<(i64, f64)> = study
        .history
        .points
        .iter()
        .enumerate()
        .map(|(k, p)| (k as i64 + 1, p.max_pressure_pa / y))
        .collect();
    assert_eq!(logged, expected);
}
