//! The output contracts of `surface` and `contact` (issues 11 and 12): the JSON keys scripts
//! read, in SI units, and the NumPy files, checked against the library and against each other.

use std::path::Path;

use ndarray::Array2;
use ndarray_npy::read_npy;
use serde_json::Value;

use crate::cli::{run, stderr};
use stressfield::surface::read::{read_surface, ReadOptions};
use stressfield::surface::stats::{characterise, Options};

const WORN: &str = "scenes/surfaces/worn.asc";

pub(crate) fn json(output: &std::process::Output) -> serde_json::Map<String, Value> {
    assert!(output.status.success(), "{}", stderr(output));
    match serde_json::from_slice(&output.stdout).expect("one JSON object") {
        Value::Object(map) => map,
        other => panic!("not an object: {other}"),
    }
}

pub(crate) fn number(map: &serde_json::Map<String, Value>, key: &str) -> f64 {
    map.get(key)
        .unwrap_or_else(|| panic!("key {key} missing"))
        .as_f64()
        .unwrap_or_else(|| panic!("{key} is not a number: {:?}", map[key]))
}

#[test]
fn surface_json_has_the_contract_keys_in_si_and_the_heights_file_is_the_map() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let heights = dir.path().join("worn.npy");
    let output = run(&[
        "surface",
        WORN,
        "--json",
        "--heights",
        heights.to_str().expect("utf-8"),
    ]);
    let report = json(&output);
    for key in [
        "Sa",
        "Sq",
        "Ssk",
        "Sku",
        "Sp",
        "Sv",
        "Sz",
        "Sdq",
        "Sdr",
        "Sal",
        "Str",
        "hurst",
        "nayak_alpha",
        "summit_density_per_m2",
        "summit_radius_m",
        "summit_height_std_m",
    ] {
        assert!(number(&report, key).is_finite(), "{key}");
    }
    // The file says its heights are in um: Sq in metres is of the order of 1e-7..1e-6 m.
    let map = read_surface(Path::new(WORN), &ReadOptions::default()).expect("worn surface");
    let stats = characterise(&map, &Options::default()).expect("statistics");
    // serde_json parses decimals to within an ulp or so (without its float_roundtrip feature).
    let close = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b.abs();
    assert!(close(number(&report, "Sq"), stats.height.sq));
    assert!(number(&report, "Sq") > 1e-8 && number(&report, "Sq") < 1e-5);
    // Sdr as a fraction, Sz = Sp + Sv.
    assert!(close(number(&report, "Sdr"), stats.sdr));
    assert!(number(&report, "Sdr") < 1.0);
    let (sp, sv, sz) = (
        number(&report, "Sp"),
        number(&report, "Sv"),
        number(&report, "Sz"),
    );
    assert!((sp + sv - sz).abs() <= 1e-14 * sz);
    // The heights as read, bit for bit.
    let written: Array2<f64> = read_npy(&heights).expect("heights.npy");
    assert_eq!(&written, map.heights_m());
}

#[test]
fn contact_json_and_pressure_file_agree_with_each_other() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let pressure = dir.path().join("p.npy");
    let scene = "scenes/rough_worn_on_flat.toml";
    let output = run(&[
        "contact",
        scene,
        "--json",
        "--pressure",
        pressure.to_str().expect("utf-8"),
    ]);
    let report = json(&output);
    for key in [
        "contact_fraction",
        "spots",
        "load_n",
        "mean_pressure_pa",
        "max_pressure_pa",
        "approach_m",
        "mean_gap_m",
        "iterations",
        "residual",
        "von_mises_max_pa",
        "von_mises_max_depth_m",
    ] {
        assert!(number(&report, key).is_finite(), "{key}");
    }
    let map = read_surface(Path::new(WORN), &ReadOptions::default()).expect("worn surface");
    let p: Array2<f64> = read_npy(&pressure).expect("p.npy");
    assert_eq!(p.dim(), map.heights_m().dim(), "[rows, columns] of the map");
    let [dx, dy] = map.spacing_m();
    let load = p.sum() * dx * dy;
    let load_n = number(&report, "load_n");
    assert!((load / load_n - 1.0).abs() < 1e-9, "{load} vs {load_n}");
    // The scene asks for 50 MPa over the nominal area.
    let mean = number(&report, "mean_pressure_pa");
    assert!((mean / 50e6 - 1.0).abs() < 1e-9, "{mean}");
    assert!((load_n / (mean * p.len() as f64 * dx * dy) - 1.0).abs() < 1e-9);
    let max = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert!((max / number(&report, "max_pressure_pa") - 1.0).abs() < 1e-15);
    assert!(p.iter().all(|&v| v >= 0.0), "no tension");
    let fraction = p.iter().filter(|&&v| v > 0.0).count() as f64 / p.len() as f64;
    assert!((fraction - number(&report, "contact_fraction")).abs() < 1e-12);
    // Subsurface maximum under the surface, residual within the default tolerance.
    assert!(number(&report, "von_mises_max_depth_m") >= 0.0);
    assert!(number(&report, "residual") <= 1e-8);
}

#[test]
fn npy_outputs_must_be_npy_and_nothing_is_written_otherwise() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let target = dir.path().join("out.txt");
    let target = target.to_str().expect("utf-8");
    for (args, flag) in [
        (vec!["surface", WORN, "--heights", target], "--heights"),
        (
            vec![
                "contact",
                "scenes/rough_worn_on_flat.toml",
                "--pressure",
                target,
            ],
            "--pressure",
        ),
    ] {
        let output = run(&args);
        assert!(!output.status.success());
        let message = stderr(&output);
        assert!(
            message.contains(flag) && message.contains(".npy"),
            "{message}"
        );
        assert_eq!(
            std::fs::read_dir(dir.path()).expect("dir").count(),
            0,
            "nothing written"
        );
    }
}

/// `hertz --json` (issue 39): the contract keys in SI, equal to the library's contact and
/// maxima, the size key of each geometry, and Johnson's maxima of a frictionless sphere.
#[test]
fn hertz_json_has_the_contract_keys_and_the_study_s_values() {
    // A steel ball on a flat, μ = 0.1, with a yield strength.
    let report = json(&run(&[
        "hertz",
        "scenes/sphere_ball_on_flat.toml",
        "--json",
    ]));
    let scene = stressfield::study::load_scene(Path::new("scenes/sphere_ball_on_flat.toml"))
        .expect("scene");
    let (a_m, p0_pa) = (scene.contact.half_width_m(), scene.contact.p0_pa());
    // serde_json parses decimals to within an ulp or so (without its float_roundtrip
    // feature; Python's json reads them exactly, python/tests compares to the last digit).
    let close = |key: &str, value: f64| {
        let got = number(&report, key);
        assert!(
            (got - value).abs() <= 1e-15 * value.abs(),
            "{key}: {got} against {value}"
        );
    };
    close("contact_radius_m", a_m);
    close("max_pressure_pa", p0_pa);
    assert!(!report.contains_key("half_width_m"));
    let maxima = stressfield::study::assess::scene_maxima(&scene)
        .maxima
        .expect("maxima");
    close("von_mises_max_pa", maxima.von_mises.value_over_p0 * p0_pa);
    close("von_mises_max_depth_m", maxima.von_mises.z_over_a * a_m);
    close("max_shear_max_pa", maxima.max_shear.value_over_p0 * p0_pa);
    close("max_shear_max_depth_m", maxima.max_shear.z_over_a * a_m);
    for key in [
        "mean_pressure_pa",
        "approach_m",
        "load_n",
        "yield_strength_pa",
    ] {
        number(&report, key);
    }
    assert_eq!(report["verdict"], "elastic");
    // A frictionless line contact (normalised): Johnson's τ1 = 0.300 p0 at z = 0.78a, and a
    // half-width key that is null (no SI size).
    let line = json(&run(&["hertz", "scenes/line_tau1.toml", "--json"]));
    assert!(line["half_width_m"].is_null());
    assert!((number(&line, "max_shear_max_over_p0") - 0.300).abs() < 5e-4);
    assert!((number(&line, "max_shear_max_z_over_a") - 0.786).abs() < 1e-3);
    // An elliptical contact has both semi-axes.
    let ellipse = json(&run(&[
        "hertz",
        "scenes/ellipse_bearing_groove.toml",
        "--json",
    ]));
    assert!(number(&ellipse, "semi_axis_y_m") > number(&ellipse, "semi_axis_x_m"));
    // A rough scene's is that of `contact --json`.
    let rough = json(&run(&["hertz", "scenes/rough_ball_on_flat.toml", "--json"]));
    assert!(rough.contains_key("contact_fraction"));
}

/// `sweep --json` and `--csv` (issue 39): one row per step with the swept value and the
/// extremes its recording charts, equal to the library's table; a scene without a sweep is
/// refused with a hint.
#[test]
fn sweep_tables_have_one_row_per_step() {
    let path = "scenes/record_line_friction_sweep.toml";
    let scene = stressfield::study::load_scene(Path::new(path)).expect("scene");
    let table = stressfield::report::sweep::sweep_table(&scene, &mut |_, _| {}).expect("table");
    let report = json(&run(&["sweep", path, "--json"]));
    let steps = report["steps"].as_array().expect("steps");
    assert_eq!(steps.len(), 11);
    assert_eq!(report["parameter"], "friction");
    for (row, step) in table.rows.iter().zip(steps) {
        for ((name, _), value) in table.columns.iter().zip(row) {
            let got = step[name].as_f64();
            match (got, value) {
                (Some(got), Some(value)) => {
                    assert!((got - value).abs() <= 1e-15 * value.abs(), "{name}")
                }
                (None, None) => {}
                other => panic!("{name}: {other:?}"),
            }
        }
    }
    // Frictionless first step: the line contact's σvM maximum, 0.5575 p0 at z = 0.704a.
    assert!((number(steps[0].as_object().expect("row"), "panel0_maximum") - 0.5575).abs() < 1e-4);
    let csv = run(&["sweep", path, "--csv"]);
    let text = String::from_utf8_lossy(&csv.stdout);
    assert_eq!(text.lines().count(), 12);
    assert!(text.starts_with("friction,panel0_maximum,"));
    let refused = run(&["sweep", "scenes/line_tau1.toml"]);
    assert!(!refused.status.success());
    assert!(
        stderr(&refused).contains("has no [sweep] table"),
        "{}",
        stderr(&refused)
    );
}
