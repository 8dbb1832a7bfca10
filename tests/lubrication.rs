//! Lubricated contacts (issue 52): the `[lubricant]` table's contract on line, point and
//! elliptical scenes, `hertz`'s lubrication block, `ehl`'s JSON and `.npy`, the gears' path of
//! contact, and every class of bad input refused with its key.

use std::path::PathBuf;

use crate::cli::{repo, run, stderr};
use stressfield::lubrication::film::{hamrock_dowson, pan_hamrock, FilmConditions};
use stressfield::scene::Scene;

/// The contract's lubricant: 0.05 Pa s, 20 GPa⁻¹, 2 m/s, 0.1 µm.
const LUBRICANT: &str = "[lubricant]\nviscosity = \"0.05 Pa s\"\npressure_viscosity = \"20 GPa^-1\"\nentrainment_speed = \"2 m/s\"\nroughness = \"0.1 um\"\n";

const LINE: &str = "format = 1\n[contact]\nkind = \"line\"\nload = \"200 kN/m\"\n[contact.body1]\nradius = \"4 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"35 mm\"\nmaterial = \"steel\"\n";
const POINT: &str = "format = 1\n[contact]\nkind = \"point\"\nload = \"300 N\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"6.35 mm\"\nmaterial = \"steel\"\n";
const ELLIPSE: &str = "format = 1\n[contact]\nkind = \"elliptical\"\nload = \"1 kN\"\nmethod = \"numerical\"\n[contact.body1]\nradius_x = \"20 mm\"\nradius_y = \"40 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[numerical]\ncells = 31\n";

fn write(text: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("lubricated.toml");
    std::fs::write(&path, text).expect("write scene");
    (dir, path)
}

fn json(args: &[&str]) -> serde_json::Value {
    let output = run(args);
    assert!(output.status.success(), "{args:?}: {}", stderr(&output));
    serde_json::from_slice(&output.stdout).expect("JSON")
}

/// The contract's keys on line, point and elliptical scenes, with the films of the formula the
/// kind takes (computed again here from the bodies: steel, E' = 2E*).
#[test]
fn the_lubrication_object_on_every_kind() {
    let steel = stressfield::contact::material::Material {
        modulus_pa: 210e9,
        poisson: 0.3,
    };
    let e_prime = 2.0 * stressfield::contact::effective_modulus(&steel, &steel);
    let conditions = |radius: f64| FilmConditions {
        viscosity_pa_s: 0.05,
        alpha_per_pa: 2e-8,
        reduced_modulus_pa: e_prime,
        entrainment_m_per_s: 2.0,
        radius_x_m: radius,
    };
    for (kind, base) in [("line", LINE), ("point", POINT), ("elliptical", ELLIPSE)] {
        let (_dir, path) = write(&format!("{base}{LUBRICANT}"));
        let report = json(&["hertz", path.to_str().expect("utf-8"), "--json"]);
        let l = &report["lubrication"];
        for key in [
            "entrainment_speed_m_per_s",
            "central_film_m",
            "minimum_film_m",
            "film_formula",
            "composite_roughness_m",
            "lambda",
            "regime",
        ] {
            assert!(l.get(key).is_some(), "{kind}: {key} missing in {l}");
        }
        assert_eq!(l["entrainment_speed_m_per_s"], 2.0);
        assert_eq!(l["composite_roughness_m"], 1e-7);
        let (formula, expected) = match kind {
            "line" => {
                let r = 1.0 / (1.0 / 4e-3 + 1.0 / 35e-3);
                ("pan_hamrock_1989", pan_hamrock(&conditions(r), 200e3))
            }
            "point" => (
                "hamrock_dowson_1977",
                hamrock_dowson(&conditions(6.35e-3), 300.0, 1.0),
            ),
            _ => {
                let scene = Scene::load(&path).expect("valid");
                let Some(stressfield::scene::Hertz::Elliptical(e)) =
                    scene.contact.dimensional.map(|d| d.hertz)
                else {
                    panic!("an ellipse")
                };
                let rx = 0.5 / e.curvature.half_curvature_x_per_m;
                let k = e.semi_axis_y_m / e.semi_axis_x_m;
                assert!(k > 1.0, "{k}");
                (
                    "hamrock_dowson_1977",
                    hamrock_dowson(&conditions(rx), 1000.0, k),
                )
            }
        };
        assert_eq!(l["film_formula"], formula);
        let central = l["central_film_m"].as_f64().expect("number");
        let minimum = l["minimum_film_m"].as_f64().expect("number");
        assert!((central / expected.central_m - 1.0).abs() < 1e-12, "{kind}");
        assert!((minimum / expected.minimum_m - 1.0).abs() < 1e-12, "{kind}");
        let lambda = l["lambda"].as_f64().expect("number");
        assert!((lambda - minimum / 1e-7).abs() < 1e-9 * lambda);
        let regime = if lambda < 1.0 {
            "boundary"
        } else if lambda <= 3.0 {
            "mixed"
        } else {
            "full_film"
        };
        assert_eq!(l["regime"], regime, "{kind}");
    }
}

/// Without a roughness λ and the regime are null, and the text says why; a scene without
/// [lubricant] has no lubrication key.
#[test]
fn lambda_needs_a_roughness() {
    let lubricant = LUBRICANT.replace("roughness = \"0.1 um\"\n", "");
    let (_dir, path) = write(&format!("{LINE}{lubricant}"));
    let path = path.to_str().expect("utf-8");
    let report = json(&["hertz", path, "--json"]);
    assert!(report["lubrication"]["lambda"].is_null());
    assert!(report["lubrication"]["regime"].is_null());
    assert!(report["lubrication"]["composite_roughness_m"].is_null());
    let text = String::from_utf8_lossy(&run(&["hertz", path]).stdout).into_owned();
    assert!(
        text.contains("λ                            not computed: give lubricant.roughness"),
        "{text}"
    );
    let (_dir, dry) = write(LINE);
    let report = json(&["hertz", dry.to_str().expect("utf-8"), "--json"]);
    assert!(report.get("lubrication").is_none());
}

/// `ehl --json` keeps its contract, and `--pressure` writes (n, 3) float64: x increasing with
/// the spike downstream (entrainment in +x), p >= 0, the film positive, the load carried.
#[test]
fn ehl_json_and_npy() {
    let dir = tempfile::tempdir().expect("temp dir");
    let npy = dir.path().join("ehl.npy");
    let scene = repo("scenes/lubricated_roller_bearing.toml");
    let scene = scene.to_str().expect("utf-8");
    let report = json(&[
        "ehl",
        scene,
        "--json",
        "--pressure",
        npy.to_str().expect("utf-8"),
    ]);
    for key in [
        "central_film_m",
        "minimum_film_m",
        "minimum_film_x_m",
        "max_pressure_pa",
        "hertz_max_pressure_pa",
        "half_width_m",
        "spike_x_m",
        "von_mises_max_pa",
        "von_mises_max_depth_m",
        "moes_m",
        "moes_l",
        "iterations",
        "converged",
    ] {
        assert!(report.get(key).is_some(), "{key} missing");
    }
    assert_eq!(report["converged"], true);
    let array: ndarray::Array2<f64> = ndarray_npy::read_npy(&npy).expect("npy");
    assert_eq!(array.ncols(), 3);
    assert!(array.nrows() > 100);
    let x = array.column(0);
    assert!(x.windows(2).into_iter().all(|w| w[1] > w[0]));
    assert!(array.column(1).iter().all(|&p| p >= 0.0));
    assert!(array.column(2).iter().all(|&h| h > 0.0));
    let spike = report["spike_x_m"].as_f64().expect("a spike");
    let b = report["half_width_m"].as_f64().expect("b");
    assert!(spike > 0.5 * b && spike < b, "{spike} vs b = {b}");
    // ∫ p dx = w (trapezoids of the piecewise-linear pressure).
    let load: f64 = (0..array.nrows() - 1)
        .map(|i| 0.5 * (array[[i, 1]] + array[[i + 1, 1]]) * (array[[i + 1, 0]] - array[[i, 0]]))
        .sum();
    assert!((load / 200e3 - 1.0).abs() < 1e-9, "{load}");
    // The film's minimum in the file is the report's.
    let minimum = array
        .column(2)
        .iter()
        .zip(array.column(1))
        .filter(|(_, p)| **p > 0.0)
        .map(|(h, _)| *h)
        .fold(f64::INFINITY, f64::min);
    assert!((minimum / report["minimum_film_m"].as_f64().expect("h")) - 1.0 < 1e-12);
}

/// Spur gears: the pinion's speed gives the pitch point's entrainment `(V1 + V2)/2`, and the
/// film along the path of contact; the shipped scene runs in mixed lubrication.
#[test]
fn gears_along_the_path_of_contact() {
    let path = repo("scenes/lubricated_gear_pitch_point.toml");
    let report = json(&["hertz", path.to_str().expect("utf-8"), "--json"]);
    let l = &report["lubrication"];
    // 1500 rpm, flank radius 50 mm sin 20°: V = ω ρ at the pitch point, equal on both flanks.
    let v = 1500.0 * std::f64::consts::PI / 30.0 * 0.05 * 20f64.to_radians().sin();
    assert!((l["entrainment_speed_m_per_s"].as_f64().expect("u") / v - 1.0).abs() < 1e-12);
    let points = l["gear_path"].as_array().expect("a path");
    // Evenly spaced points, the pitch point and both sides of each change of the pairs in mesh.
    assert!(points.len() > stressfield::study::gear_heating::PATH_POINTS);
    // The pitch point's film is the scene's; the films elsewhere differ.
    let pitch = points
        .iter()
        .min_by(|a, b| {
            a["s_m"]
                .as_f64()
                .expect("s")
                .abs()
                .total_cmp(&b["s_m"].as_f64().expect("s").abs())
        })
        .expect("points");
    assert!(pitch["s_m"].as_f64().expect("s").abs() < 1e-9);
    assert_eq!(pitch["minimum_film_m"], l["minimum_film_m"]);
    assert_eq!(l["regime"], "mixed");
    // A warning says the light seed load leaves the film thicker than the flattening.
    assert!(l["warnings"][0]
        .as_str()
        .expect("text")
        .contains("elastic flattening"));
}

/// Each class of bad input: a clear message naming the key, a non-zero exit.
#[test]
fn bad_lubricants_are_refused_by_key() {
    let cases: [(&str, String, &str); 11] = [
        (
            "no speed",
            format!("{LINE}[lubricant]\nviscosity = \"0.05 Pa s\"\npressure_viscosity = \"20 GPa^-1\"\n"),
            "lubricant.entrainment_speed",
        ),
        ("zero viscosity", format!("{LINE}{}", LUBRICANT.replace("0.05 Pa s", "0 Pa s")), "lubricant.viscosity"),
        (
            "negative α",
            format!("{LINE}{}", LUBRICANT.replace("20 GPa^-1", "-20 GPa^-1")),
            "lubricant.pressure_viscosity",
        ),
        (
            "rigid body",
            format!("{}{LUBRICANT}", POINT.replace("radius = \"flat\"\nmaterial = \"steel\"", "radius = \"flat\"\nmaterial = \"rigid\"")),
            "contact.body1.material",
        ),
        (
            "no viscosity",
            format!("{LINE}[lubricant]\npressure_viscosity = \"20 GPa^-1\"\nentrainment_speed = \"2 m/s\"\n"),
            "lubricant.viscosity",
        ),
        (
            "grade without its 100 C viscosity",
            format!("{LINE}[lubricant]\ngrade = \"ISO VG 220\"\ntemperature = \"70 C\"\ndensity = \"870 kg/m^3\"\npressure_viscosity = \"20 GPa^-1\"\nentrainment_speed = \"2 m/s\"\n"),
            "lubricant.viscosity_100c",
        ),
        (
            "not a grade",
            format!("{LINE}[lubricant]\ngrade = \"ISO VG 200\"\nviscosity_100c = \"19 mm^2/s\"\ntemperature = \"70 C\"\ndensity = \"870 kg/m^3\"\npressure_viscosity = \"20 GPa^-1\"\nentrainment_speed = \"2 m/s\"\n"),
            "lubricant.grade",
        ),
        (
            "two viscosities",
            format!("{LINE}{LUBRICANT}grade = 220\n"),
            "lubricant.grade",
        ),
        (
            "a normalised contact",
            format!("format = 1\n[contact]\nkind = \"line\"\n{LUBRICANT}"),
            "lubricant",
        ),
        (
            "a pinion speed without gears",
            format!("{LINE}{LUBRICANT}pinion_speed = \"1500 rpm\"\n"),
            "lubricant.pinion_speed",
        ),
        (
            "a misspelt key",
            format!("{LINE}{LUBRICANT}viscosty = \"1 Pa s\"\n"),
            "lubricant.viscosty",
        ),
    ];
    for (what, text, key) in cases {
        let (_dir, path) = write(&text);
        let output = run(&["hertz", path.to_str().expect("utf-8")]);
        assert!(!output.status.success(), "{what}");
        let message = stderr(&output);
        assert!(message.contains(&format!("`{key}`")), "{what}: {message}");
        assert!(
            message.contains("hint:") || what == "a misspelt key",
            "{what}: {message}"
        );
    }
}

/// `ehl` on a point contact is refused, and writes no file.
#[test]
fn ehl_refuses_point_contacts_and_writes_nothing() {
    let (dir, path) = write(&format!("{POINT}{LUBRICANT}"));
    let npy = dir.path().join("out.npy");
    let output = run(&[
        "ehl",
        path.to_str().expect("utf-8"),
        "--pressure",
        npy.to_str().expect("utf-8"),
    ]);
    assert!(!output.status.success());
    assert!(
        stderr(&output).contains("line contacts"),
        "{}",
        stderr(&output)
    );
    assert!(!npy.exists());
    let leftovers: Vec<_> = std::fs::read_dir(dir.path()).expect("dir").collect();
    assert_eq!(leftovers.len(), 1, "{leftovers:?}");
}

/// The bodies' speeds of [thermal] entrain the oil at `(V1 + V2)/2`.
#[test]
fn entrainment_from_the_thermal_speeds() {
    let lubricant = LUBRICANT.replace("entrainment_speed = \"2 m/s\"\n", "");
    let text = format!("{}{lubricant}[thermal]\nbody1_speed = \"3 m/s\"\nbody2_speed = \"1 m/s\"\npartition = \"blok\"\n", LINE.replace("load = ", "friction = 0.05\nload = "));
    let (_dir, path) = write(&text);
    let scene = Scene::load(&path).expect("valid");
    let lubricant = scene.lubricant.expect("lubricant");
    assert_eq!(lubricant.entrainment_m_per_s, 2.0);
}

/// `render` draws the EHL sheet beside a lubricated line scene's figure (`NAME_ehl.png`).
#[test]
fn render_writes_the_ehl_sheet() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scene = repo("scenes/lubricated_roller_bearing.toml");
    let output = run(&[
        "render",
        scene.to_str().expect("utf-8"),
        "--out-dir",
        dir.path().to_str().expect("utf-8"),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let sheet =
        image::open(dir.path().join("lubricated_roller_bearing_ehl.png")).expect("the sheet");
    assert!(
        sheet.width() > 1000 && sheet.height() > 700,
        "{:?}",
        (sheet.width(), sheet.height())
    );
    assert!(dir.path().join("lubricated_roller_bearing.png").exists());
}

/// The sheet's maps are the study's: their largest samples lie within 0.5 % below the
/// searched maxima (0.01 b grid), the dry one's at Hertz's 0.5575 p_h.
#[test]
fn the_sheet_s_maps_peak_at_the_study_s_maxima() {
    let scene = Scene::load(&repo("scenes/lubricated_roller_bearing.toml")).expect("valid");
    let study = stressfield::study::ehl::solve(&scene).expect("solved");
    let sections = stressfield::study::ehl::sections(&study, 351, 121).expect("sections");
    for (map, searched) in [
        (&sections.lubricated_von_mises_over_p0, study.von_mises),
        (&sections.dry_von_mises_over_p0, study.dry_von_mises),
    ] {
        let largest = map.iter().fold(0.0f64, |a, &v| a.max(v));
        let gap = 1.0 - largest / searched.value_over_p0;
        assert!((-1e-9..0.005).contains(&gap), "{largest} vs {searched:?}");
    }
    assert!((study.dry_von_mises.value_over_p0 - 0.5575).abs() < 1e-4);
}

/// `sweep --json` of an entrainment-speed sweep (the roller bearing at 1 and 10 m/s; the
/// shipped ten-step scene is recorded by `record::every_shipped_recording_scene_records`): the
/// film thickens with the speed; against Pan & Hamrock's fit the minimum film within 15 % and
/// the central within 20 % (M = 35 and 11, L = 12 and 21: the agreement loosens as L grows,
/// from 6 % at L = 8 in the unit tests; measured 6.8 and 11.7 %, 11.4 and 16.5 %:
/// docs/lubrication.md).
#[test]
fn entrainment_speed_sweep_table() {
    let shipped =
        std::fs::read_to_string(repo("scenes/lubricated_roller_bearing.toml")).expect("shipped");
    let (_dir, scene) = write(&format!(
        "{}[sweep]\nparameter = \"entrainment_speed\"\nvalues = [\"1 m/s\", 10.0]\n",
        shipped.split("[figure]").next().expect("text")
    ));
    let table = json(&["sweep", scene.to_str().expect("utf-8"), "--json"]);
    let steps = table["steps"].as_array().expect("steps");
    assert_eq!(steps.len(), 2);
    let value = |step: &serde_json::Value, key: &str| step[key].as_f64().expect(key);
    assert_eq!(value(&steps[0], "entrainment_speed_m_per_s"), 1.0);
    assert_eq!(value(&steps[1], "entrainment_speed_m_per_s"), 10.0);
    assert_eq!(table["units"]["entrainment_speed_m_per_s"], "m/s");
    let loaded = Scene::load(&scene).expect("valid");
    let problem = stressfield::study::ehl::problem(&loaded).expect("a line");
    let lubricant = loaded.lubricant.expect("lubricant");
    assert!(value(&steps[1], "minimum_film_m") > 3.0 * value(&steps[0], "minimum_film_m"));
    for step in steps {
        let speed = value(step, "entrainment_speed_m_per_s");
        let formula = pan_hamrock(
            &FilmConditions {
                viscosity_pa_s: lubricant.viscosity_pa_s,
                alpha_per_pa: lubricant.alpha_per_pa,
                reduced_modulus_pa: problem.reduced_modulus_pa,
                entrainment_m_per_s: speed,
                radius_x_m: problem.radius_m,
            },
            problem.load_n_per_m,
        );
        let central = value(step, "central_film_m") / formula.central_m - 1.0;
        let minimum = value(step, "minimum_film_m") / formula.minimum_m - 1.0;
        println!(
            "u {speed} m/s, M {:.2}, L {:.2}: central {central:+.4}, minimum {minimum:+.4}, spike {:?} Pa, near-surface vM {:.4e} Pa, vM {:.4e} Pa",
            value(step, "moes_m"),
            value(step, "moes_l"),
            step["spike_pressure_pa"].as_f64(),
            value(step, "near_surface_von_mises_max_pa"),
            value(step, "von_mises_max_pa"),
        );
        assert!(
            central.abs() < 0.2 && minimum.abs() < 0.15,
            "u {speed}: {central} {minimum}"
        );
    }
}

/// An entrainment-speed sweep needs a lubricated line contact; its speeds must be positive.
#[test]
fn entrainment_speed_sweeps_are_refused_where_they_cannot_run() {
    let sweep = "[sweep]\nparameter = \"entrainment_speed\"\nfrom = 0.5\nto = 20.0\nsteps = 4\n";
    for (what, text, key) in [
        (
            "a point contact",
            format!("{POINT}{LUBRICANT}{sweep}"),
            "sweep.parameter",
        ),
        ("no lubricant", format!("{LINE}{sweep}"), "sweep.parameter"),
        (
            "a zero speed",
            format!(
                "{LINE}{LUBRICANT}{}",
                sweep.replace("from = 0.5", "from = 0.0")
            ),
            "sweep.from",
        ),
    ] {
        let (_dir, path) = write(&text);
        let output = run(&["check", path.to_str().expect("utf-8")]);
        assert!(!output.status.success(), "{what}");
        let message = stderr(&output);
        assert!(message.contains(&format!("`{key}`")), "{what}: {message}");
    }
}
