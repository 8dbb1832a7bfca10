//! Frictional heating through the command line (issue 21): the `thermal` output contract (JSON
//! keys in SI, the temperature file), the same values in `hertz`, and bad input refused with
//! the key and the fix.

use crate::cli::{assert_fails_with, repo, run, stderr};
use crate::contracts::{json, number};
use ndarray::Array2;
use ndarray_npy::read_npy;
use stressfield::scene::Scene;

const SLIDING: &str = "scenes/thermal_sliding_sphere.toml";

/// The `thermal --json` keys the output contract names.
const CONTRACT: [&str; 10] = [
    "peclet",
    "sliding_speed_m_per_s",
    "heat_partition_body1",
    "max_temperature_rise_k",
    "mean_temperature_rise_k",
    "max_temperature_x_m",
    "max_temperature_y_m",
    "thermal_von_mises_max_pa",
    "total_von_mises_max_pa",
    "total_von_mises_max_depth_m",
];

#[test]
fn thermal_json_keeps_the_contract_and_the_temperature_file_is_the_map() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let file = dir.path().join("t.npy");
    let output = run(&[
        "thermal",
        SLIDING,
        "--json",
        "--temperature",
        file.to_str().expect("utf-8"),
    ]);
    let report = json(&output);
    for key in CONTRACT {
        assert!(number(&report, key).is_finite(), "{key}");
    }
    // The Péclet number is V a / (2κ) of body 1, from the scene's own Hertz radius.
    let scene = Scene::load(&repo(SLIDING)).expect("scene");
    let spec = scene.thermal.expect("[thermal]");
    let expected = spec.body1.speed_m_per_s * scene.contact.half_width_m()
        / (2.0 * spec.body1.properties.diffusivity_m2_per_s);
    assert!((number(&report, "peclet") / expected - 1.0).abs() < 1e-12);
    assert_eq!(number(&report, "sliding_speed_m_per_s"), 2.0);
    // Blok's partition: equal mean flash temperatures, body 1 (moving, Pe 32) takes more.
    let share = number(&report, "heat_partition_body1");
    assert!(share > 0.5 && share < 1.0, "{share}");
    let mean1 = number(&report, "mean_temperature_rise_k");
    let mean2 = number(&report, "body2_mean_temperature_rise_k");
    assert!((mean1 / mean2 - 1.0).abs() < 1e-9, "{mean1} vs {mean2}");
    // The hottest point of a fast source lies behind the centre (-x), on the axis.
    assert!(number(&report, "max_temperature_x_m") < 0.0);
    assert!(number(&report, "max_temperature_y_m").abs() < 1e-12);
    assert!(number(&report, "max_temperature_rise_k") > mean1);
    // The file: [rows, columns] in K, its maximum the reported one.
    let map: Array2<f64> = read_npy(&file).expect("npy");
    assert_eq!(
        [map.nrows(), map.ncols()],
        [
            number(&report, "rows") as usize,
            number(&report, "columns") as usize
        ]
    );
    let max = map.iter().copied().fold(f64::MIN, f64::max);
    assert!((max / number(&report, "max_temperature_rise_k") - 1.0).abs() < 1e-12);
    // `hertz` prints the same values.
    let hertz = run(&["hertz", SLIDING]);
    assert!(hertz.status.success(), "{}", stderr(&hertz));
    let text = String::from_utf8_lossy(&hertz.stdout);
    let line = format!("max {:.2} K", number(&report, "max_temperature_rise_k"));
    assert!(text.contains(&line), "`{line}` not in:\n{text}");
}

#[test]
fn a_pin_is_heated_by_a_stationary_source() {
    // The lecture notes' ball on a coated disc: the contact stays on the ball (Pe 0), all heat
    // into it; the hottest point is the centre (the grid's cells nearest it) and the thermal
    // stress is largest on the surface.
    let report = json(&run(&[
        "thermal",
        "scenes/thermal_ball_on_disc.toml",
        "--json",
    ]));
    assert_eq!(number(&report, "peclet"), 0.0);
    assert_eq!(number(&report, "heat_partition_body1"), 1.0);
    let dx = report["spacing_m"][0].as_f64().expect("dx");
    assert!(number(&report, "max_temperature_x_m").abs() <= dx);
    assert!(number(&report, "max_temperature_y_m").abs() <= dx);
    assert_eq!(number(&report, "thermal_von_mises_max_depth_m"), 0.0);
    // Coupled (as Liu & Wang's model): the ball's bulge shrinks the contact and raises the
    // peak pressure; the load is the same, the iteration converged.
    let coupled = report["coupled"].as_object().expect("a coupled object");
    for key in [
        "iterations",
        "tolerance",
        "pressure_changes",
        "isothermal_contact_area_m2",
        "contact_area_m2",
        "isothermal_spots",
        "spots",
        "isothermal_max_pressure_pa",
        "max_pressure_pa",
        "distortion_over_contact_m",
    ] {
        assert!(!coupled[key].is_null(), "coupled.{key} missing");
    }
    let changes = coupled["pressure_changes"].as_array().expect("changes");
    assert_eq!(
        changes.len() as u64,
        coupled["iterations"].as_u64().expect("n")
    );
    assert!(changes.last().and_then(|c| c.as_f64()).expect("last") < 1e-6);
    assert!(number(coupled, "contact_area_m2") < number(coupled, "isothermal_contact_area_m2"));
    assert!(number(coupled, "max_pressure_pa") > number(coupled, "isothermal_max_pressure_pa"));
    assert!(number(coupled, "distortion_over_contact_m") > 0.0);
}

#[test]
fn the_heating_sheet_is_written_and_a_bad_figure_name_refused() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let png = dir.path().join("heating.png");
    let output = run(&[
        "thermal",
        "scenes/thermal_ball_on_disc.toml",
        "--figure",
        png.to_str().expect("utf-8"),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let image = image::open(&png).expect("a PNG").to_rgb8();
    assert!(image.width() > 800 && image.height() > 800);
    let bad = dir.path().join("heating.jpg");
    let output = run(&[
        "thermal",
        "scenes/thermal_ball_on_disc.toml",
        "--figure",
        bad.to_str().expect("utf-8"),
    ]);
    assert_fails_with(&output, &["--figure", ".png or .svg"]);
    assert!(!bad.exists());
}

const BASE: &str = "format = 1\n[contact]\nkind = \"point\"\nload = \"100 N\"\nfriction = 0.2\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"10 mm\"\nmaterial = \"steel\"\n";

#[test]
fn bad_thermal_input_names_the_key_and_the_fix() {
    let cases: [(String, &str, &str); 9] = [
        (format!("{BASE}[thermal]\nspeed = \"0 m/s\"\n"), "thermal.speed", "must be positive"),
        (format!("{BASE}[thermal]\nspeed = \"-1 m/s\"\n"), "thermal.speed", "must lie between"),
        (format!("{BASE}[thermal]\nspeed = \"2 m\"\n"), "thermal.speed", "unknown unit"),
        (format!("{BASE}[thermal]\nspeed = \"2 m/s\"\npartition = \"half\"\n"), "thermal.partition", "blok"),
        (format!("{BASE}[thermal]\nspeed = \"2 m/s\"\npartition = 1.5\n"), "thermal.partition", "[0, 1]"),
        (
            "format = 1\n[contact]\nkind = \"line\"\nload = \"100 kN/m\"\nfriction = 0.1\n[contact.body1]\nradius = \"20 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"20 mm\"\nmaterial = \"steel\"\n[thermal]\nspeed = \"1 m/s\"\ncoupled = true\n".to_string(),
            "thermal.coupled",
            "coupled = false",
        ),
        (
            "format = 1\n[contact]\nkind = \"point\"\nload = \"100 N\"\nfriction = 0.2\n[contact.body1]\nradius = \"flat\"\nmodulus = \"210 GPa\"\npoisson = 0.3\n[contact.body2]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[thermal]\nspeed = \"2 m/s\"\n".to_string(),
            "contact.body1.conductivity",
            "material = \"steel\"",
        ),
        (
            "format = 1\n[contact]\nkind = \"point\"\nload = \"100 N\"\nfriction = 0.2\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\nconductivity = \"-5 W/(m K)\"\n[contact.body2]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[thermal]\nspeed = \"2 m/s\"\n".to_string(),
            "contact.body1.conductivity",
            "must lie between",
        ),
        (
            "format = 1\n[contact]\nkind = \"point\"\nfriction = 0.2\n[thermal]\nspeed = \"2 m/s\"\n".to_string(),
            "thermal",
            "needs a load and two bodies",
        ),
    ];
    let dir = tempfile::tempdir().expect("temporary directory");
    for (k, (text, key, fix)) in cases.iter().enumerate() {
        let path = dir.path().join(format!("case{k}.toml"));
        std::fs::write(&path, text).expect("write");
        for command in ["check", "thermal"] {
            let output = run(&[command, path.to_str().expect("utf-8")]);
            assert_fails_with(&output, &[key, fix]);
        }
    }
    // Blok's partition of a line contact needs body 2 to move.
    let line = "format = 1\n[contact]\nkind = \"line\"\nload = \"100 kN/m\"\nfriction = 0.1\n[contact.body1]\nradius = \"20 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"20 mm\"\nmaterial = \"steel\"\n[thermal]\nspeed = \"1 m/s\"\npartition = \"blok\"\n";
    let path = dir.path().join("line.toml");
    std::fs::write(&path, line).expect("write");
    assert_fails_with(
        &run(&["check", path.to_str().expect("utf-8")]),
        &["thermal.body2_speed", "steady"],
    );
    // A scene without [thermal].
    assert_fails_with(
        &run(&["thermal", "scenes/sphere_ball_on_flat.toml"]),
        &["no [thermal] table", "speed"],
    );
    // A rough grid too coarse for the speed: refused with the key.
    let rough = std::fs::read_to_string(repo("scenes/rough_ball_on_flat.toml")).expect("scene")
        + "\n[thermal]\nspeed = \"1000 m/s\"\n";
    let path = dir.path().join("rough.toml");
    std::fs::write(&path, rough).expect("write");
    assert_fails_with(
        &run(&["thermal", path.to_str().expect("utf-8")]),
        &["thermal.speed", "cell Péclet"],
    );
}

#[test]
fn a_line_contact_report_has_a_steady_band_temperature() {
    // Two steel rollers rolling with slip: body 1 passes the contact at 3 m/s, body 2 at 2 m/s,
    // sliding 1 m/s; Blok's partition. The band's maximum lies behind the centre, and the
    // partition falls between the body-1 share of the effusivity ratio at these speeds: with
    // equal materials the faster surface (shorter heating time) takes more than half.
    let dir = tempfile::tempdir().expect("temporary directory");
    let line = "format = 1\n[contact]\nkind = \"line\"\nload = \"200 kN/m\"\nfriction = 0.05\n[contact.body1]\nradius = \"20 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"30 mm\"\nmaterial = \"steel\"\n[thermal]\nspeed = \"1 m/s\"\nbody1_speed = \"3 m/s\"\nbody2_speed = \"2 m/s\"\npartition = \"blok\"\n";
    let path = dir.path().join("line.toml");
    std::fs::write(&path, line).expect("write");
    let report = json(&run(&["thermal", path.to_str().expect("utf-8"), "--json"]));
    let share = number(&report, "heat_partition_body1");
    // At high Péclet numbers Blok's share tends to √V1 / (√V1 + √V2) for equal materials.
    let limit = 3f64.sqrt() / (3f64.sqrt() + 2f64.sqrt());
    assert!((share - limit).abs() < 0.03, "{share} vs {limit}");
    assert!(number(&report, "max_temperature_x_m") < 0.0);
    assert!(number(&report, "thermal_von_mises_max_pa") > 0.0);
}

#[test]
fn running_gears_report_the_path_of_contact_and_refuse_what_does_not_belong() {
    // The lecture notes' spur gears (Problem 1) at 1500 rpm: the contract keys at the hottest
    // point of the path and the path itself, zero heat at the pitch point.
    let report = json(&run(&["thermal", "scenes/gear_pitch_point.toml", "--json"]));
    for key in CONTRACT {
        assert!(number(&report, key).is_finite(), "{key}");
    }
    let path = report.get("gear_path").expect("gear_path");
    let array = |key: &str| -> Vec<f64> {
        path.get(key)
            .and_then(|v| v.as_array())
            .unwrap_or_else(|| panic!("gear_path.{key}"))
            .iter()
            .map(|v| v.as_f64().expect("number"))
            .collect()
    };
    let s = array("s_m");
    let sliding = array("sliding_speed_m_per_s");
    let t1 = array("max_temperature_rise_k");
    let pitch = s.iter().position(|&s| s == 0.0).expect("pitch point");
    assert_eq!(sliding[pitch], 0.0);
    assert_eq!(t1[pitch], 0.0);
    let hottest = path
        .get("hottest_s_m")
        .and_then(|v| v.as_f64())
        .expect("hottest");
    let max = t1.iter().cloned().fold(0.0, f64::max);
    assert!((number(&report, "max_temperature_rise_k") - max).abs() < 1e-12 * max);
    assert!(hottest != 0.0);
    // `hertz` answers the homework's normal approach (two cylinders) and prints the path.
    let output = run(&["hertz", "scenes/gear_pitch_point.toml"]);
    assert!(output.status.success());
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(text.contains("approach of the axes"), "{text}");
    assert!(
        text.contains("<- hottest") && text.contains("<- pitch point"),
        "{text}"
    );

    let gears = "format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN/m\"\n[contact.gears]\nmodule = \"5 mm\"\nteeth = [20, 40]\npressure_angle = \"20 deg\"\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n";
    let cases = [
        (format!("{gears}[thermal]\nfriction = 0.05\n"), "thermal.pinion_speed", "rpm"),
        (
            format!("{gears}[thermal]\npinion_speed = \"1500 rpm\"\nspeed = \"2 m/s\"\nfriction = 0.05\n"),
            "thermal.speed",
            "pinion_speed",
        ),
        (format!("{gears}[thermal]\npinion_speed = \"1500 rpm\"\n"), "thermal.friction", "pitch point"),
        (
            format!("{gears}[thermal]\npinion_speed = \"1500 m/s\"\nfriction = 0.05\n"),
            "thermal.pinion_speed",
            "unknown unit",
        ),
        (
            format!("{BASE}[thermal]\nspeed = \"2 m/s\"\npinion_speed = \"1500 rpm\"\n"),
            "thermal.pinion_speed",
            "[contact.gears]",
        ),
        (
            gears.replace("[20, 40]", "[12, 200]").replace("5 mm", "1 mm")
                + "[thermal]\npinion_speed = \"1500 rpm\"\nfriction = 0.05\n",
            "contact.gears",
            "interfere",
        ),
    ];
    let dir = tempfile::tempdir().expect("temporary directory");
    for (k, (text, key, fix)) in cases.iter().enumerate() {
        let path = dir.path().join(format!("gears{k}.toml"));
        std::fs::write(&path, text).expect("write");
        assert_fails_with(&run(&["check", path.to_str().expect("utf-8")]), &[key, fix]);
    }
}
