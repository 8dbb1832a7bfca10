//! Elastic-plastic contact (`[plasticity]`, `stressfield plastic`, issue 51): the JSON
//! contract on a small grid, the fields archive, and bad input refused naming the key.

use std::path::PathBuf;

use crate::cli::{run, stderr};

/// A rigid ball on a steel flat at p0(Hertz) = 2.5 Y on a coarse grid (a second or two).
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
hardening_modulus = "10 GPa"
steps = 2
unload_steps = 1
grid_cells = 32
depth_cells = 16
"#;

fn scene(text: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("case.toml");
    std::fs::write(&path, text).expect("write scene");
    (dir, path)
}

#[test]
fn plastic_json_has_the_contract_s_keys_and_the_fields_archive_its_arrays() {
    let (dir, path) = scene(SMALL);
    let fields = dir.path().join("fields.npz");
    let output = run(&[
        "plastic",
        path.to_str().expect("utf-8"),
        "--json",
        "--fields",
        fields.to_str().expect("utf-8"),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).expect("one JSON object");
    for key in [
        "load_n",
        "yield_strength_pa",
        "hardening_modulus_pa",
        "converged",
        "iterations",
    ] {
        assert!(json.get(key).is_some(), "missing {key}");
    }
    assert_eq!(json["hardening_modulus_pa"], 10e9);
    let loaded = &json["loaded"];
    for key in [
        "max_pressure_pa",
        "mean_pressure_pa",
        "contact_area_m2",
        "contact_radius_m",
        "approach_m",
        "max_plastic_strain",
        "max_plastic_strain_depth_m",
        "plastic_zone_depth_m",
        "plastic_volume_m3",
        "von_mises_max_pa",
        "von_mises_max_depth_m",
        "elastic_max_pressure_pa",
    ] {
        assert!(loaded[key].is_number(), "loaded.{key}");
    }
    // Beyond first yield the peak pressure lies below Hertz's and the body flowed.
    let peak = loaded["max_pressure_pa"].as_f64().expect("number");
    assert!(peak < 0.9 * loaded["elastic_max_pressure_pa"].as_f64().expect("number"));
    assert!(loaded["max_plastic_strain"].as_f64().expect("number") > 1e-4);
    let unloaded = &json["unloaded"];
    for key in [
        "residual_depth_m",
        "residual_von_mises_max_pa",
        "residual_von_mises_max_depth_m",
        "residual_von_mises_max_r_m",
    ] {
        assert!(unloaded[key].is_number(), "unloaded.{key}");
    }
    assert!(unloaded["residual_depth_m"].as_f64().expect("number") > 0.0);
    let bytes = std::fs::read(&fields).expect("the archive");
    let mut npz = ndarray_npy::NpzReader::new(std::io::Cursor::new(bytes)).expect("npz");
    let names = npz.names().expect("names");
    for name in [
        "plastic_strain",
        "residual_stress",
        "pressure",
        "x",
        "y",
        "z",
    ] {
        assert!(
            names.iter().any(|n| n.trim_end_matches(".npy") == name),
            "{name}: {names:?}"
        );
    }
    let strain: ndarray::Array3<f64> = npz.by_name("plastic_strain").expect("plastic_strain");
    assert_eq!(strain.dim(), (16, 32, 32));
    let residual: ndarray::Array4<f64> = npz.by_name("residual_stress").expect("residual");
    assert_eq!(residual.dim(), (16, 32, 32, 6));
}

#[test]
fn bad_plasticity_is_refused_naming_the_key() {
    let cases: [(&str, &str, &str); 6] = [
        (
            "yield_strength = \"1 GPa\"",
            "yield_strength = \"-1 GPa\"",
            "plasticity.yield_strength",
        ),
        (
            "yield_strength = \"1 GPa\"",
            "yield_strength = \"0 GPa\"",
            "plasticity.yield_strength",
        ),
        (
            "hardening_modulus = \"10 GPa\"",
            "hardening_modulus = \"-1 GPa\"",
            "plasticity.hardening_modulus",
        ),
        ("steps = 2", "steps = 0", "plasticity.steps"),
        (
            "grid_cells = 32",
            "grid_cells = 16",
            "plasticity.grid_cells",
        ),
        (
            "kind = \"point\"\n",
            "kind = \"point\"\nyield_strength = \"2 GPa\"\n",
            "plasticity.yield_strength",
        ),
    ];
    for (from, to, key) in cases {
        let (_dir, path) = scene(&SMALL.replacen(from, to, 1));
        let output = run(&["plastic", path.to_str().expect("utf-8"), "--json"]);
        assert!(!output.status.success(), "{to} accepted");
        assert!(output.stdout.is_empty(), "{to}: output written");
        let message = stderr(&output);
        assert!(message.contains(key), "{to}: {message}");
    }
    // With heating: refused naming [thermal].
    let (_dir, path) = scene(&format!("{SMALL}[thermal]\nspeed = \"1 m/s\"\n"));
    let output = run(&["plastic", path.to_str().expect("utf-8")]);
    assert!(!output.status.success());
    assert!(stderr(&output).contains("thermal"), "{}", stderr(&output));
}

/// A rough ball (R = 2 mm, Sq 0.05 µm) on a steel flat, 0.5 N, on a 48² map of 1.5 µm:
/// elastic-plastic under its spots.
const ROUGH: &str = r#"format = 1
[contact]
kind = "rough"
load = "0.5 N"
[contact.body1]
material = "steel"
[contact.body2]
material = "steel"
[surface.generate]
samples = 48
spacing = "1.5 um"
hurst = 0.8
rolloff = "24 um"
cutoff = "4.5 um"
rms_height = "0.05 um"
sphere_radius = "2 mm"
seed = 3
[plasticity]
yield_strength = "1 GPa"
steps = 2
unload_steps = 1
depth_cells = 8
"#;

/// A rigid ellipsoid (radii 20 mm and 10 mm) on a steel flat beyond first yield, coarse.
const ELLIPSE: &str = r#"format = 1
[contact]
kind = "elliptical"
load = "150 N"
method = "numerical"   # the elastic field `render` draws
[contact.body1]
radius = "flat"
material = "steel"
[contact.body2]
radius_x = "20 mm"
radius_y = "10 mm"
material = "rigid"
[plasticity]
yield_strength = "1 GPa"
steps = 2
unload_steps = 1
grid_cells = 24
depth_cells = 10
extent_over_a = 1.5
depth_over_a = 1.5
"#;

#[test]
fn rough_and_elliptical_contacts_keep_the_json_contract() {
    for text in [ROUGH, ELLIPSE] {
        let (_dir, path) = scene(text);
        let output = run(&["plastic", path.to_str().expect("utf-8"), "--json"]);
        assert!(output.status.success(), "{}", stderr(&output));
        let json: serde_json::Value =
            serde_json::from_slice(&output.stdout).expect("one JSON object");
        assert_eq!(json["converged"], true);
        let loaded = &json["loaded"];
        let area = loaded["contact_area_m2"].as_f64().expect("area");
        let radius = loaded["contact_radius_m"].as_f64().expect("radius");
        assert!((radius / (area / std::f64::consts::PI).sqrt() - 1.0).abs() < 1e-12);
        assert!(loaded["max_plastic_strain"].as_f64().expect("strain") > 1e-4);
        let peak = loaded["max_pressure_pa"].as_f64().expect("peak");
        assert!(peak < loaded["elastic_max_pressure_pa"].as_f64().expect("elastic"));
        assert!(json["unloaded"]["residual_depth_m"].as_f64().expect("dent") > 0.0);
    }
}

#[test]
fn bad_rough_plasticity_is_refused_naming_the_key() {
    for (from, to, key) in [
        (
            "depth_cells = 8",
            "depth_cells = 8\ngrid_cells = 32",
            "plasticity.grid_cells",
        ),
        (
            "depth_cells = 8",
            "depth_cells = 8\nextent_over_a = 2.0",
            "plasticity.extent_over_a",
        ),
        (
            "load = \"0.5 N\"",
            "approach = \"0.1 um\"",
            "contact.approach",
        ),
        (
            "material = \"steel\"\n[contact.body2]",
            "material = \"rigid\"\n[contact.body2]",
            "contact.body1.material",
        ),
        ("samples = 48", "samples = 600", "surface"),
    ] {
        let (_dir, path) = scene(&ROUGH.replacen(from, to, 1));
        let output = run(&["plastic", path.to_str().expect("utf-8"), "--json"]);
        assert!(!output.status.success(), "{to} accepted");
        assert!(output.stdout.is_empty(), "{to}: output written");
        let message = stderr(&output);
        assert!(message.contains(key), "{to}: {message}");
    }
}

#[test]
fn check_refuses_a_plastic_volume_beyond_the_memory_naming_its_size() {
    let big = ROUGH.replacen("samples = 48", "samples = 512", 1).replacen(
        "depth_cells = 8",
        "depth_cells = 256",
        1,
    );
    let (_dir, path) = scene(&big);
    let output = run(&["check", path.to_str().expect("utf-8")]);
    assert!(!output.status.success());
    let message = stderr(&output);
    assert!(message.contains("512 x 512 x 256 cells"), "{message}");
    // The small map passes, with its estimate.
    let (_dir, path) = scene(ROUGH);
    let output = run(&["check", path.to_str().expect("utf-8")]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(text.contains("plastic: 48 x 48 x 8 cells"), "{text}");
}

/// A rigid roller on a steel flat at p0(Hertz) = 2.2 Y, sliding at mu = 0.3 (well under a
/// second).
const LINE: &str = r#"format = 1
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
steps = 4
unload_steps = 2
grid_cells = 64
depth_cells = 24
extent_over_a = 3.0
tolerance = 1e-4
"#;

#[test]
fn a_line_contact_reports_the_line_s_keys_and_one_row_fields() {
    let (dir, path) = scene(LINE);
    let fields = dir.path().join("fields.npz");
    let output = run(&[
        "plastic",
        path.to_str().expect("utf-8"),
        "--json",
        "--fields",
        fields.to_str().expect("utf-8"),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).expect("one JSON object");
    assert!(json["load_n_per_m"].as_f64().expect("load_n_per_m") == 660e3);
    assert!(json.get("load_n").is_none());
    let loaded = &json["loaded"];
    for key in [
        "max_pressure_pa",
        "mean_pressure_pa",
        "contact_area_m2",
        "half_width_m",
        "approach_m",
        "max_plastic_strain",
        "max_plastic_strain_depth_m",
        "plastic_zone_depth_m",
        "plastic_area_m2",
        "von_mises_max_pa",
        "von_mises_max_depth_m",
        "elastic_max_pressure_pa",
    ] {
        assert!(loaded[key].is_number(), "loaded.{key}");
    }
    assert!(loaded.get("contact_radius_m").is_none() && loaded.get("plastic_volume_m3").is_none());
    let peak = loaded["max_pressure_pa"].as_f64().expect("number");
    assert!(peak < 0.95 * loaded["elastic_max_pressure_pa"].as_f64().expect("number"));
    // Sliding at 0.3: the plastic zone reaches the surface (its largest strain in the top layer).
    let top_layer = 2.0 * 190.83e-6 / 24.0;
    assert!(
        loaded["max_plastic_strain_depth_m"]
            .as_f64()
            .expect("number")
            < top_layer
    );
    assert!(
        json["unloaded"]["residual_depth_m"]
            .as_f64()
            .expect("number")
            > 0.0
    );
    let bytes = std::fs::read(&fields).expect("the archive");
    let mut npz = ndarray_npy::NpzReader::new(std::io::Cursor::new(bytes)).expect("npz");
    let strain: ndarray::Array3<f64> = npz.by_name("plastic_strain").expect("plastic_strain");
    assert_eq!(strain.dim(), (24, 1, 64));
    let residual: ndarray::Array4<f64> = npz.by_name("residual_stress").expect("residual");
    assert_eq!(residual.dim(), (24, 1, 64, 6));
    let pressure: ndarray::Array2<f64> = npz.by_name("pressure").expect("pressure");
    assert_eq!(pressure.dim(), (1, 64));
    // The readable report says "line".
    let output = run(&["plastic", path.to_str().expect("utf-8")]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(String::from_utf8_lossy(&output.stdout).contains("line contact"));
    // `check` plans the x–z cells of the line (it planned a 64 x 64 x 24 volume before).
    let output = run(&["check", path.to_str().expect("utf-8")]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = String::from_utf8_lossy(&output.stdout).to_string() + &stderr(&output);
    assert!(text.contains("plastic: 64 x 1 x 24 cells"), "{text}");
}
