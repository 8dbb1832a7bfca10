//! Contact evolution with sliding (`[wear]`, `[[series]]`, `stressfield wear`): the shipped
//! ball's plastic area against its growing scar, the JSON contract, the first step against
//! `contact`, a series read back from `--heights-out`, and bad input.

use std::path::Path;
use std::sync::OnceLock;

use serde_json::Value;
use stressfield::scene::Scene;
use stressfield::study::wear::WearStudy;

use crate::cli::{repo, run, stderr};
use crate::contracts::json;

/// The shipped worn ball and its study, computed once for every test that reads it.
pub(crate) fn shipped_ball() -> &'static (Scene, WearStudy) {
    static STUDY: OnceLock<(Scene, WearStudy)> = OnceLock::new();
    STUDY.get_or_init(|| {
        let scene = stressfield::study::load_scene(&repo("scenes/wear_rough_ball.toml"))
            .unwrap_or_else(|e| panic!("{e}"));
        let study =
            stressfield::study::wear::study(&scene, &mut |_| {}).unwrap_or_else(|e| panic!("{e}"));
        (scene, study)
    })
}

/// A small rough ball worn on a flat: 48² cells of 4 µm, 0.5 N, six steps.
fn small_scene(extra: &str) -> String {
    format!(
        "format = 1\n[contact]\nkind = \"rough\"\nload = \"0.5 N\"\nfriction = 0.2\n{extra}\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n[surface.generate]\nsamples = 48\nspacing = \"4 um\"\nhurst = 0.8\nrolloff = \"48 um\"\ncutoff = \"16 um\"\nrms_height = \"0.1 um\"\nsphere_radius = \"3 mm\"\nseed = 2\n"
    )
}

const SMALL_WEAR: &str =
    "[wear]\ncoefficient = \"2e-6 mm^3/(N m)\"\ndistance = \"5 m\"\nsteps = 6\n";

fn write(dir: &Path, name: &str, text: &str) -> std::path::PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write");
    path
}

fn steps(report: &serde_json::Map<String, Value>) -> Vec<serde_json::Map<String, Value>> {
    report["steps"]
        .as_array()
        .expect("steps")
        .iter()
        .map(|s| s.as_object().expect("step").clone())
        .collect()
}

#[test]
fn the_shipped_ball_keeps_its_plastic_area_while_the_scar_grows() {
    // Siniawski et al. (2003): once wear begins, the plastically deformed area stays nearly
    // constant while the contact (the scar) keeps growing. Checked on the shipped ball: after
    // the first step the plastic area varies by at most 15 % (coefficient of variation) and
    // stays within 0.75 to 1.35 times its mean, while the scar grows at least fourfold; the
    // plastic area never exceeds W / H (the cap carries at most H per unit area).
    let (_, study) = shipped_ball();
    let hardness = study.hardness_pa.expect("a hardness");
    let bound = study.load_n / hardness;
    for step in &study.steps {
        assert!(step.plastic_area_m2() <= bound * (1.0 + 1e-12));
    }
    let worn = &study.steps[1..];
    let plastic: Vec<f64> = worn.iter().map(|s| s.plastic_area_m2()).collect();
    let mean = plastic.iter().sum::<f64>() / plastic.len() as f64;
    let spread = (plastic.iter().map(|p| (p - mean).powi(2)).sum::<f64>() / plastic.len() as f64)
        .sqrt()
        / mean;
    let (low, high) = plastic
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &p| (a.min(p), b.max(p)));
    let scar_growth = worn.last().expect("steps").scar_area_m2() / worn[0].scar_area_m2();
    eprintln!(
        "measured: shipped ball: plastic area {:.0} µm² on average after wear begins (CV {:.1} %, {:.2} to {:.2} of the mean; unworn {:.0} µm², W/H {:.0} µm²) while the scar grows {:.2} times ({:.4} to {:.4} mm²)",
        mean * 1e12,
        100.0 * spread,
        low / mean,
        high / mean,
        study.steps[0].plastic_area_m2() * 1e12,
        bound * 1e12,
        scar_growth,
        worn[0].scar_area_m2() * 1e6,
        worn.last().expect("steps").scar_area_m2() * 1e6
    );
    assert!(spread < 0.15, "{spread}");
    assert!(low / mean > 0.75 && high / mean < 1.35);
    assert!(scar_growth > 4.0, "{scar_growth}");
    // Archard's volume at every step, to 1e-9.
    for step in &study.steps[1..] {
        let expected = 2e-15 * study.load_n * step.sliding_distance_m;
        assert!((step.worn_volume_m3 / expected - 1.0).abs() < 1e-9);
    }
}

#[test]
fn wear_json_keeps_its_contract_and_its_first_step_is_the_contact() {
    let dir = tempfile::tempdir().expect("temp");
    let scene = write(dir.path(), "ball.toml", &(small_scene("") + SMALL_WEAR));
    let path = scene.to_str().expect("utf8");
    let output = run(&["wear", path, "--json"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let report = json(&output);
    for key in ["load_n", "hardness_pa", "coefficient_m2_per_n", "steps"] {
        assert!(report.contains_key(key), "{key}");
    }
    assert!(report["hardness_pa"].is_null());
    assert_eq!(report["load_n"].as_f64(), Some(0.5));
    let steps = steps(&report);
    assert_eq!(steps.len(), 7);
    for step in &steps {
        for key in [
            "sliding_distance_m",
            "contact_area_m2",
            "plastic_area_m2",
            "spots",
            "max_pressure_pa",
            "mean_pressure_pa",
            "worn_volume_m3",
            "max_wear_depth_m",
            "von_mises_max_pa",
            "von_mises_max_depth_m",
            "iterations",
        ] {
            assert!(step[key].is_number(), "{key}");
        }
        assert!(!step.contains_key("max_temperature_rise_k"));
    }
    assert_eq!(steps[0]["sliding_distance_m"].as_f64(), Some(0.0));
    assert_eq!(steps[6]["sliding_distance_m"].as_f64(), Some(5.0));
    // The first step is the scene's static contact, to the last digit of the JSON.
    let contact = run(&["contact", path, "--json"]);
    assert!(contact.status.success(), "{}", stderr(&contact));
    let contact = json(&contact);
    for key in [
        "spots",
        "max_pressure_pa",
        "mean_pressure_pa",
        "von_mises_max_pa",
        "von_mises_max_depth_m",
        "max_shear_max_pa",
        "max_shear_max_depth_m",
        "iterations",
    ] {
        assert_eq!(steps[0][key], contact[key], "{key}");
    }
    let [dx, dy] = [4e-6, 4e-6];
    let area = contact["contact_fraction"].as_f64().expect("fraction") * 48.0 * 48.0 * dx * dy;
    let ours = steps[0]["contact_area_m2"].as_f64().expect("area");
    assert!((ours / area - 1.0).abs() < 1e-12);
    // With [thermal], every step has its flash temperature.
    let heated = write(
        dir.path(),
        "heated.toml",
        &(small_scene("") + SMALL_WEAR + "[thermal]\nspeed = \"0.5 m/s\"\nbody1_speed = \"0 m/s\"\nbody2_speed = \"0.5 m/s\"\npartition = \"body1\"\n"),
    );
    let output = run(&["wear", heated.to_str().expect("utf8"), "--json"]);
    assert!(output.status.success(), "{}", stderr(&output));
    for step in self::steps(&json(&output)) {
        assert!(step["max_temperature_rise_k"].as_f64().expect("ΔT") > 0.0);
    }
}

#[test]
fn a_coupled_worn_contact_is_the_heated_one_at_every_step() {
    // With coupled heating each step's contact is the thermo-mechanical one: the bulge of the
    // heated ball shrinks the contact (Liu & Wang 2001) at every step, and the wear keeps
    // Archard's volume (the bulge wears nothing).
    let dir = tempfile::tempdir().expect("temp");
    let heating = "[thermal]\nspeed = \"2 m/s\"\nbody1_speed = \"0 m/s\"\nbody2_speed = \"2 m/s\"\npartition = \"body1\"\n";
    let plain = write(
        dir.path(),
        "plain.toml",
        &(small_scene("") + SMALL_WEAR + heating),
    );
    let coupled = write(
        dir.path(),
        "coupled.toml",
        &(small_scene("") + SMALL_WEAR + heating + "coupled = true\n"),
    );
    let (plain, coupled) = (wear_steps(&plain, &[]), wear_steps(&coupled, &[]));
    for (p, c) in plain.iter().zip(&coupled) {
        let area =
            |s: &serde_json::Map<String, Value>| s["contact_area_m2"].as_f64().expect("area");
        assert!(area(c) <= area(p), "{} > {}", area(c), area(p));
        let volume = |s: &serde_json::Map<String, Value>| s["worn_volume_m3"].as_f64().expect("V");
        assert!((volume(c) - volume(p)).abs() <= 1e-9 * volume(p).max(1e-30));
    }
    let peak = |s: &serde_json::Map<String, Value>| s["max_pressure_pa"].as_f64().expect("p");
    assert!(peak(&coupled[0]) > peak(&plain[0]));
}

/// Steps of a `wear --json` run of `scene`.
fn wear_steps(scene: &Path, extra: &[&str]) -> Vec<serde_json::Map<String, Value>> {
    let mut args = vec!["wear", scene.to_str().expect("utf8"), "--json"];
    args.extend_from_slice(extra);
    let output = run(&args);
    assert!(output.status.success(), "{}", stderr(&output));
    steps(&json(&output))
}

#[test]
fn a_series_read_back_from_heights_out_gives_the_simulated_steps() {
    // The simulation's worn heights (`--heights-out`, with its [[series]] fragment, which
    // carries its own [surface] table: both spacings and level = "none") read back as a
    // measured series, with the same contact and hardness: each step solved again from its
    // map gives the same contact (area and spots exactly, the peak pressure and the von Mises
    // maximum within 1e-6, relative: the solver's tolerance is 1e-8), and the volume the maps
    // lack is the simulation's worn plus flattened volume within 1e-9 of the total. With a
    // rough counter-surface too: it slides by each entry's distance in both. On an
    // anisotropic grid (4 x 6 µm cells) the fragment states both spacings (issue 50: it wrote
    // dx alone, and the surface read back was another). Read back with the default levelling
    // instead (every map less the first map's least-squares plane: one datum for the
    // specimen), the maps' differences, and so the worn volume, are unchanged.
    for (case, extra) in [
        ("capped", "hardness = \"300 HV\""),
        ("counter", "hardness = \"300 HV\""),
        ("anisotropic", "hardness = \"300 HV\""),
    ] {
        let dir = tempfile::tempdir().expect("temp");
        let counter = if case == "counter" {
            "[counter_surface.generate]\nsamples = 48\nspacing = \"4 um\"\nhurst = 0.8\nrolloff = \"48 um\"\ncutoff = \"16 um\"\nrms_height = \"0.2 um\"\nseed = 9\n"
        } else {
            ""
        };
        let mut body = small_scene(extra) + counter;
        if case == "anisotropic" {
            body = body.replace("spacing = \"4 um\"", "spacing = [\"4 um\", \"6 um\"]");
        }
        let scene = write(dir.path(), "sim.toml", &(body.clone() + SMALL_WEAR));
        let out = dir.path().join("heights");
        std::fs::create_dir(&out).expect("mkdir");
        let simulated = wear_steps(&scene, &["--heights-out", out.to_str().expect("utf8")]);
        let fragment = std::fs::read_to_string(out.join("sim_series.toml")).expect("fragment");
        // The series scene: the contact and counter of the simulation, the maps from the files.
        let generated = body
            .split("[surface.generate]")
            .next()
            .expect("head")
            .to_string();
        let series = write(
            &out,
            "series.toml",
            &format!("{generated}{counter}{fragment}"),
        );
        let measured = wear_steps(&series, &[]);
        assert_eq!(measured.len(), simulated.len());
        let mut worst = 0.0f64;
        for (m, s) in measured.iter().zip(&simulated) {
            for key in [
                "sliding_distance_m",
                "contact_area_m2",
                "spots",
                "plastic_area_m2",
            ] {
                assert_eq!(m[key], s[key], "{case}: {key}");
            }
            for key in ["max_pressure_pa", "von_mises_max_pa"] {
                let (a, b) = (m[key].as_f64().expect("a"), s[key].as_f64().expect("b"));
                worst = worst.max((a / b - 1.0).abs());
            }
            let lost = m["worn_volume_m3"].as_f64().expect("lost");
            let total = s["worn_volume_m3"].as_f64().expect("worn")
                + s["plastic_volume_m3"].as_f64().expect("flattened");
            assert!(
                (lost - total).abs() <= 1e-9 * total.max(1e-30),
                "{case}: {lost} {total}"
            );
        }
        eprintln!("measured: series read back ({case}): largest relative difference of the peak pressure and von Mises maximum {worst:.1e}");
        assert!(worst < 1e-6, "{case}: {worst}");
        // The default levelling: one datum, so the same worn volume and depth at every step.
        let levelled = write(
            &out,
            "levelled.toml",
            &format!(
                "{generated}{counter}{}",
                fragment.replace("level = \"none\"", "")
            ),
        );
        for (l, m) in wear_steps(&levelled, &[]).iter().zip(&measured) {
            for key in ["worn_volume_m3", "max_wear_depth_m"] {
                let (a, b) = (l[key].as_f64().expect("a"), m[key].as_f64().expect("b"));
                assert!(
                    (a - b).abs() <= 1e-9 * b.abs().max(1e-30),
                    "{case}: {key} {a} {b}"
                );
            }
        }
    }
}

/// Runs `check` on a scene and returns its error text (the check must fail).
fn refused(text: &str, files: &[(&str, &[u8])]) -> String {
    let dir = tempfile::tempdir().expect("temp");
    for (name, bytes) in files {
        std::fs::write(dir.path().join(name), bytes).expect("write");
    }
    let scene = write(dir.path(), "case.toml", text);
    let output = run(&["check", scene.to_str().expect("utf8")]);
    assert!(!output.status.success(), "accepted: {text}");
    stderr(&output)
}

/// A `.npy` of float64 heights `[rows, columns]`.
fn npy(rows: usize, columns: usize, f: impl Fn(usize, usize) -> f64) -> Vec<u8> {
    let array = ndarray::Array2::from_shape_fn((rows, columns), |(j, i)| f(j, i));
    let mut bytes = Vec::new();
    ndarray_npy::WriteNpyExt::write_npy(&array, &mut bytes).expect("npy");
    bytes
}

#[test]
fn bad_wear_input_is_refused_naming_the_key() {
    let with = |wear: &str| small_scene("") + wear;
    for (wear, key) in [
        ("[wear]\ncoefficient = \"-1e-6 mm^3/(N m)\"\ndistance = \"5 m\"\n", "wear.coefficient"),
        ("[wear]\ncoefficient = \"0 m^2/N\"\ndistance = \"5 m\"\n", "wear.coefficient"),
        ("[wear]\ncoefficient = \"1e-6 MPa\"\ndistance = \"5 m\"\n", "wear.coefficient"),
        ("[wear]\ndistance = \"5 m\"\n", "wear.coefficient"),
        ("[wear]\ncoefficient = \"1e-6 mm^3/(N m)\"\ndistance = \"0 m\"\n", "wear.distance"),
        ("[wear]\ncoefficient = \"1e-6 mm^3/(N m)\"\n", "wear.distance"),
        ("[wear]\ncoefficient = \"1e-6 mm^3/(N m)\"\ndistance = \"5 m\"\nsteps = 0\n", "wear.steps"),
        ("[wear]\ncoefficient = \"1e-6 mm^3/(N m)\"\ndistance = \"5 m\"\nstep = 4\n", "wear.step"),
        // More wear than the ball holds above its lowest point.
        ("[wear]\ncoefficient = \"1e-3 mm^3/(N m)\"\ndistance = \"1000 km\"\n", "wear.distance"),
        (
            "[wear]\ncoefficient = \"1e-6 mm^3/(N m)\"\ndistance = \"5 m\"\n[sweep]\nparameter = \"load\"\nvalues = [\"0.1 N\", \"0.2 N\"]\n",
            "sweep",
        ),
    ] {
        let message = refused(&with(wear), &[]);
        assert!(message.contains(&format!("`{key}`")), "{key}: {message}");
    }
    // A coupled worn contact under a rough sliding counter-surface is refused.
    let coupled = small_scene("")
        + SMALL_WEAR
        + "[counter_surface.generate]\nsamples = 48\nspacing = \"4 um\"\nhurst = 0.8\nrms_height = \"0.1 um\"\nseed = 3\n[thermal]\nspeed = \"0.5 m/s\"\nbody1_speed = \"0 m/s\"\nbody2_speed = \"0.5 m/s\"\npartition = \"body1\"\ncoupled = true\n";
    assert!(refused(&coupled, &[]).contains("`thermal.coupled`"));
    // A measured counter-surface cannot slide (its edges do not meet).
    let measured = npy(48, 48, |j, i| ((i + 2 * j) as f64).sin() * 1e-7);
    let message = refused(
        &(small_scene("")
            + SMALL_WEAR
            + "[counter_surface]\nfile = \"c.npy\"\nspacing = \"4 um\"\n"),
        &[("c.npy", &measured)],
    );
    assert!(message.contains("`counter_surface.file`"), "{message}");
    // An approach cannot drive wear.
    let approach =
        small_scene("").replace("load = \"0.5 N\"", "approach = \"0.1 um\"") + SMALL_WEAR;
    assert!(refused(&approach, &[]).contains("`contact.approach`"));
    // [wear] and [[series]] on scenes that cannot take them.
    let line = "format = 1\n[contact]\nkind = \"line\"\n".to_string() + SMALL_WEAR;
    assert!(refused(&line, &[]).contains("`wear`"));
    let on_surface = small_scene("")
        .replace("kind = \"rough\"", "kind = \"surface\"")
        .replace("load = \"0.5 N\"\nfriction = 0.2\n", "")
        + SMALL_WEAR;
    assert!(refused(&on_surface, &[]).contains("`wear`"));

    // Series: unequal grids, distances not increasing, one map only, both tables.
    let a = npy(16, 16, |j, i| -((i * i + j * j) as f64) * 1e-9);
    let b = npy(16, 18, |_, _| 0.0);
    let head = "format = 1\n[contact]\nkind = \"rough\"\nload = \"0.01 N\"\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n[surface]\nspacing = \"1 um\"\n";
    let entry = |file: &str, distance: &str| {
        format!("[[series]]\nfile = \"{file}\"\ndistance = \"{distance}\"\n")
    };
    let message = refused(
        &format!("{head}{}{}", entry("a.npy", "0 m"), entry("b.npy", "1 m")),
        &[("a.npy", &a), ("b.npy", &b)],
    );
    assert!(
        message.contains("`series[1].file`") && message.contains("b.npy"),
        "{message}"
    );
    let message = refused(
        &format!("{head}{}{}", entry("a.npy", "2 m"), entry("a.npy", "1 m")),
        &[("a.npy", &a)],
    );
    assert!(message.contains("`series[1].distance`"), "{message}");
    let message = refused(
        &format!("{head}{}", entry("a.npy", "0 m")),
        &[("a.npy", &a)],
    );
    assert!(message.contains("`series`"), "{message}");
    let message = refused(
        &format!(
            "{head}{SMALL_WEAR}{}{}",
            entry("a.npy", "0 m"),
            entry("a.npy", "1 m")
        ),
        &[("a.npy", &a)],
    );
    assert!(message.contains("`wear`"), "{message}");
    let message = refused(
        &format!(
            "{}{}{}",
            head.replace(
                "[surface]\nspacing = \"1 um\"\n",
                "[surface]\nspacing = \"1 um\"\nfile = \"a.npy\"\n"
            ),
            entry("a.npy", "0 m"),
            entry("a.npy", "1 m")
        ),
        &[("a.npy", &a)],
    );
    assert!(message.contains("`surface.file`"), "{message}");
    let message = refused(
        &format!(
            "{head}[[series]]\nfile = \"a.npy\"\n{}",
            entry("a.npy", "1 m")
        ),
        &[("a.npy", &a)],
    );
    assert!(message.contains("`series[0].distance`"), "{message}");
}

#[test]
fn wear_outputs_are_checked_before_computing_and_written_all_or_none() {
    let dir = tempfile::tempdir().expect("temp");
    let scene = write(dir.path(), "ball.toml", &(small_scene("") + SMALL_WEAR));
    let path = scene.to_str().expect("utf8");
    // A missing directory, and a file where the directory should be: refused at once.
    let missing = dir.path().join("missing");
    let output = run(&[
        "wear",
        path,
        "--heights-out",
        missing.to_str().expect("utf8"),
    ]);
    assert!(!output.status.success());
    assert!(
        stderr(&output).contains("--heights-out"),
        "{}",
        stderr(&output)
    );
    assert!(!missing.exists());
    let output = run(&["wear", path, "--heights-out", path]);
    assert!(!output.status.success());
    assert!(
        stderr(&output).contains("not a directory"),
        "{}",
        stderr(&output)
    );
    // A scene without [wear]: the command says what to add.
    let plain = write(dir.path(), "plain.toml", &small_scene(""));
    let output = run(&["wear", plain.to_str().expect("utf8")]);
    assert!(!output.status.success());
    assert!(stderr(&output).contains("[wear]"), "{}", stderr(&output));
    // Written: one file per step and the fragment, nothing left over.
    let out = dir.path().join("out");
    std::fs::create_dir(&out).expect("mkdir");
    let output = run(&["wear", path, "--heights-out", out.to_str().expect("utf8")]);
    assert!(output.status.success(), "{}", stderr(&output));
    let mut names: Vec<String> = std::fs::read_dir(&out)
        .expect("read")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names.len(), 8, "{names:?}");
    assert!(names.iter().all(|n| n.starts_with("ball_")), "{names:?}");
}

/// A measured series is one specimen (issue 50): its maps are levelled by one datum. Two maps
/// of a rough flat (32², 2 µm cells) with a bump that carries the contact, the second worn by
/// a 0.3 µm deep pit off the middle (12 x 12 cells, 1728 µm³) and remounted with a tilt of
/// 2e-3 along x and -1e-3 along y
/// (0.13 and 0.06 µm across the map, the order of the pit): each map's plane fitted on the
/// unworn border (`datum_region`) removes the mounting tilt and the worn volume is the pit's
/// (to 1e-9); the default (the first map's plane, one frame for both) keeps the second map's
/// tilt, which the datum offset cannot remove, and the volume is off; `datum = "each"`, the
/// old default, fits the worn map's plane through its pit, and is off too. And the datum keys
/// are refused where they mean nothing, named.
#[test]
fn a_series_is_levelled_by_one_datum() {
    let n = 32;
    let rough = |j: usize, i: usize| {
        let (x, y) = (i as f64 / n as f64, j as f64 / n as f64);
        let bump = (-((i as f64 - 10.0).powi(2) + (j as f64 - 16.0).powi(2)) / 8.0).exp();
        0.05e-6 * (2.0 * std::f64::consts::PI * (3.0 * x + 2.0 * y)).sin()
            + 0.03e-6 * (2.0 * std::f64::consts::PI * (5.0 * x - 4.0 * y) + 1.0).cos()
            + 1e-6 * bump
    };
    let pit = |j: usize, i: usize| (18..30).contains(&i) && (10..22).contains(&j);
    let first = npy(n, n, rough);
    let worn = npy(n, n, |j, i| {
        rough(j, i) - if pit(j, i) { 0.3e-6 } else { 0.0 } + 2e-3 * (i as f64 * 2e-6)
            - 1e-3 * (j as f64 * 2e-6)
    });
    let head = "format = 1\n[contact]\nkind = \"rough\"\nload = \"0.01 N\"\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n";
    let series = "[[series]]\nfile = \"a.npy\"\ndistance = \"0 m\"\n[[series]]\nfile = \"b.npy\"\ndistance = \"1 m\"\n";
    let dir = tempfile::tempdir().expect("temp");
    std::fs::write(dir.path().join("a.npy"), &first).expect("a");
    std::fs::write(dir.path().join("b.npy"), &worn).expect("b");
    let volume = |surface: &str| -> f64 {
        let scene = write(
            dir.path(),
            "series.toml",
            &format!("{head}[surface]\nspacing = \"2 um\"\n{surface}\n{series}"),
        );
        let steps = wear_steps(&scene, &[]);
        steps[1]["worn_volume_m3"].as_f64().expect("volume")
    };
    let pit_m3 = 12.0 * 12.0 * 0.3e-6 * 4e-12;
    // The unworn border: the first four columns and the whole height (x 0 to 6 µm).
    let region = volume("datum_region = [\"0 um\", \"6 um\", \"0 um\", \"62 um\"]");
    assert!(
        (region - pit_m3).abs() <= 1e-9 * pit_m3,
        "{region} against {pit_m3}"
    );
    let first_datum = volume("");
    assert!(
        (first_datum - pit_m3).abs() > 0.05 * pit_m3,
        "{first_datum}"
    );
    assert_eq!(volume("datum = \"first\""), first_datum);
    let each = volume("datum = \"each\"");
    assert!((each - pit_m3).abs() > 0.05 * pit_m3, "{each}");

    let files: &[(&str, &[u8])] = &[("a.npy", &first), ("b.npy", &worn)];
    for (surface, key) in [
        ("datum = \"last\"", "surface.datum"),
        (
            "datum = \"each\"\ndatum_region = [\"0 um\", \"6 um\", \"0 um\", \"62 um\"]",
            "surface.datum",
        ),
        (
            "datum_region = [\"0 um\", \"6 um\", \"0 um\"]",
            "surface.datum_region",
        ),
        (
            "datum_region = [\"6 um\", \"0 um\", \"0 um\", \"62 um\"]",
            "surface.datum_region",
        ),
        (
            "datum_region = [\"0 um\", \"1 um\", \"0 um\", \"62 um\"]",
            "surface.datum_region",
        ),
        (
            "datum_region = [\"0 um\", \"6 MPa\", \"0 um\", \"62 um\"]",
            "surface.datum_region",
        ),
        ("level = \"none\"\ndatum = \"first\"", "surface.datum"),
    ] {
        let message = refused(
            &format!("{head}[surface]\nspacing = \"2 um\"\n{surface}\n{series}"),
            files,
        );
        assert!(
            message.contains(&format!("`{key}`")),
            "{surface}: {message}"
        );
    }
    // Not a series: the datum means nothing.
    let message = refused(
        &format!("{head}[surface]\nfile = \"a.npy\"\nspacing = \"2 um\"\ndatum = \"first\"\n"),
        files,
    );
    assert!(message.contains("`surface.datum`"), "{message}");
}

/// A wear scene whose unworn contact already reaches the map's edge (a 300 mm ball under 5 N
/// on a 192 µm map: a Hertz radius of about 210 µm) is refused with the contact's own hint:
/// at step 0 nothing is worn, so "shorten wear.distance" would not help (issue 50).
#[test]
fn an_unworn_contact_at_the_edge_gets_the_contact_s_hint() {
    let dir = tempfile::tempdir().expect("temp");
    let text = small_scene("")
        .replace("sphere_radius = \"3 mm\"", "sphere_radius = \"300 mm\"")
        .replace("load = \"0.5 N\"", "load = \"5 N\"")
        + &SMALL_WEAR.replace("distance = \"5 m\"", "distance = \"0.1 m\"");
    let scene = write(dir.path(), "edge.toml", &text);
    let output = run(&["wear", scene.to_str().expect("utf8")]);
    assert!(!output.status.success());
    let message = stderr(&output);
    assert!(message.contains("(step 0)"), "{message}");
    assert!(message.contains("enlarge the domain"), "{message}");
    assert!(!message.contains("wear.distance"), "{message}");
}

/// A series map that grew (material added, nothing worn: a 0.2 µm bump beside a ball's
/// contact) reports no wear and no scar, and says that the map stands higher (issue 50: each
/// map levelled by its own plane made the bump a tilt, 6 nm of wear and a scar 15 times the
/// contact).
#[test]
fn a_series_map_that_grew_shows_no_wear_and_says_it_stands_higher() {
    let n = 48;
    let ball = |j: usize, i: usize| {
        let (x, y) = ((i as f64 - 24.0) * 2e-6, (j as f64 - 24.0) * 2e-6);
        -(x * x + y * y) / (2.0 * 3e-3)
            + 0.01e-6 * ((0.7 * i as f64).sin() + (1.3 * j as f64 + 0.5).cos())
    };
    let first = npy(n, n, ball);
    let grown = npy(n, n, |j, i| {
        ball(j, i)
            + 0.2e-6 * (-((i as f64 - 12.0).powi(2) + (j as f64 - 36.0).powi(2)) / 20.0).exp()
    });
    let dir = tempfile::tempdir().expect("temp");
    std::fs::write(dir.path().join("a.npy"), &first).expect("a");
    std::fs::write(dir.path().join("b.npy"), &grown).expect("b");
    let scene = write(
        dir.path(),
        "grown.toml",
        "format = 1\n[contact]\nkind = \"rough\"\nload = \"0.2 N\"\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n[surface]\nspacing = \"2 um\"\n[[series]]\nfile = \"a.npy\"\ndistance = \"0 m\"\n[[series]]\nfile = \"b.npy\"\ndistance = \"1 m\"\n",
    );
    let output = run(&["wear", scene.to_str().expect("utf8"), "--json"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let report = json(&output);
    let last = &steps(&report)[1];
    assert_eq!(last["worn_volume_m3"].as_f64(), Some(0.0), "{last:?}");
    assert_eq!(last["scar_area_m2"].as_f64(), Some(0.0), "{last:?}");
    let warnings = report["warnings"].as_array().expect("warnings");
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    let text = warnings[0].as_str().expect("text");
    assert!(
        text.contains("series[1] (b.npy) stands up to 0.2"),
        "{text}"
    );
    // The first map against itself: nothing to say.
    let same = write(
        dir.path(),
        "same.toml",
        &std::fs::read_to_string(&scene)
            .expect("scene")
            .replace("b.npy", "a.npy"),
    );
    let output = run(&["wear", same.to_str().expect("utf8"), "--json"]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(json(&output)["warnings"].as_array().map(Vec::len), Some(0));
}

/// `check` of a wear scene states the whole run (issue 50: it stated one contact's estimate,
/// and none with `[thermal]`): every step's fields (32 bytes a cell a step, exactly), more
/// time for more steps, a counter-surface, heating and coupling, each by its measured factor.
/// The estimate against measured runs is in docs/benchmarks.md (within 20 %).
#[test]
fn check_estimates_the_whole_wear_run() {
    let dir = tempfile::tempdir().expect("temp");
    let heating = "[thermal]\nspeed = \"0.5 m/s\"\nbody1_speed = \"0 m/s\"\nbody2_speed = \"0.5 m/s\"\npartition = \"body1\"\n";
    let counter = "[counter_surface.generate]\nsamples = 48\nspacing = \"4 um\"\nhurst = 0.8\nrolloff = \"48 um\"\ncutoff = \"16 um\"\nrms_height = \"0.2 um\"\nseed = 9\n";
    let cost = |name: &str, text: &str| -> (usize, f64, String) {
        let path = write(dir.path(), name, text);
        let scene = stressfield::study::load_scene(&path).unwrap_or_else(|e| panic!("{e}"));
        let (bytes, seconds) = stressfield::study::heating_plan::wear_cost(&scene, [48, 48]);
        let output = run(&["check", path.to_str().expect("utf8")]);
        assert!(output.status.success(), "{}", stderr(&output));
        (
            bytes,
            seconds,
            String::from_utf8_lossy(&output.stdout).into_owned(),
        )
    };
    let thirty = SMALL_WEAR.replace("steps = 6", "steps = 30");
    let (b6, s6, said) = cost("six.toml", &(small_scene("") + SMALL_WEAR));
    assert!(
        said.contains("wear: about") && said.contains("in all"),
        "{said}"
    );
    let (b30, s30, _) = cost("thirty.toml", &(small_scene("") + &thirty));
    assert_eq!(b30 - b6, 24 * 32 * 48 * 48);
    assert!(s30 > 2.0 * s6, "{s30} {s6}");
    let (_, heated, said) = cost("heated.toml", &(small_scene("") + &thirty + heating));
    assert!(said.contains("wear: about"), "{said}");
    let (_, sliding, _) = cost("counter.toml", &(small_scene("") + counter + &thirty));
    let (_, coupled, _) = cost(
        "coupled.toml",
        &(small_scene("") + &thirty + heating + "coupled = true\n"),
    );
    assert!(
        heated > s30 && sliding > heated && coupled > heated,
        "{s30} {heated} {sliding} {coupled}"
    );
}

/// A smooth steel ball (R = 6.35 mm) worn on a B4C flat under 20 N, 64² cells of 7.5 µm (the
/// Hertz radius 85 µm is 11 cells, its von Mises peak 5.5 cells deep), `steps` steps over 5 m.
fn smooth_ball_scene(steps: usize) -> Scene {
    let text = format!(
        "format = 1\n[contact]\nkind = \"rough\"\nload = \"20 N\"\nfriction = 0.2\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"boron_carbide\"\n[surface.generate]\nsamples = 64\nspacing = \"7.5 um\"\nhurst = 0.8\nrolloff = \"60 um\"\ncutoff = \"24 um\"\nrms_height = \"0.001 nm\"\nsphere_radius = \"6.35 mm\"\nseed = 5\n[wear]\ncoefficient = \"2e-6 mm^3/(N m)\"\ndistance = \"5 m\"\nsteps = {steps}\n"
    );
    Scene::parse(&text, "smooth_ball", "smooth_ball.toml").unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn warm_started_maxima_stay_within_their_tolerance_of_the_full_search() {
    // The warm-started search (the default) against the full search of `contact` at every
    // step: never lower than WARM_TOLERANCE below it, nor higher by more (both search the same
    // cell centres; only the depth's refinement differs), and the steps whose pressure barely
    // changed searched warm (fewer full searches than half the steps), on a smooth ball (whose
    // maximum moves from the axis, 0.5a deep, to the scar's edge a quarter of a cell deep) and
    // on a small rough ball capped at its hardness.
    use stressfield::study::wear::{study_with, MaximaSearch, WARM_TOLERANCE};
    let small = Scene::parse(
        &format!("{}{SMALL_WEAR}", small_scene("hardness = \"200 HV\"")),
        "small",
        "small.toml",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let cases = [
        ("smooth ball", smooth_ball_scene(16), true),
        ("small rough ball, 200 HV", small, false),
    ];
    for (name, scene, warm_expected) in cases {
        let full = study_with(&scene, MaximaSearch::Full, &mut |_| {}).expect("full");
        let warm = study_with(&scene, MaximaSearch::Warm, &mut |_| {}).expect("warm");
        assert_eq!(full.full_maxima_searches, full.steps.len());
        let mut worst: f64 = 0.0;
        for (k, (f, w)) in full.steps.iter().zip(&warm.steps).enumerate() {
            assert_eq!(f.solution, w.solution, "{name}: step {k}'s contact");
            for (label, a, b) in [
                ("von Mises", &f.maxima.von_mises, &w.maxima.von_mises),
                ("Tresca", &f.maxima.max_shear, &w.maxima.max_shear),
            ] {
                let change = b.value_over_p0 / a.value_over_p0 - 1.0;
                worst = worst.max(change.abs());
                assert!(
                    change.abs() <= WARM_TOLERANCE,
                    "{name}: step {k}'s {label} maximum {} warm against {} full ({change:+.2e}), at depths {} and {}",
                    b.value_over_p0,
                    a.value_over_p0,
                    b.z_over_a,
                    a.z_over_a
                );
            }
        }
        if warm_expected {
            assert!(
                warm.full_maxima_searches < warm.steps.len() / 2,
                "{name}: {} of {} steps searched in full",
                warm.full_maxima_searches,
                warm.steps.len()
            );
        }
        eprintln!(
            "{name}: {} of {} steps searched in full; the warm maxima within {worst:.2e} of the full ones",
            warm.full_maxima_searches,
            warm.steps.len()
        );
    }
}
