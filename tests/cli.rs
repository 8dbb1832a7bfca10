//! The command line: every subcommand, and every class of bad input gives a clear message, a
//! non-zero exit and no partial output.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

use crate::line_contact::flamant_quadrature;

fn stressfield() -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_stressfield"));
    command
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("CI", "true");
    command
}

pub(crate) fn run(args: &[&str]) -> Output {
    stressfield().args(args).output().expect("the binary runs")
}

fn run_with_stdin(args: &[&str], stdin: &str) -> Output {
    let mut child = stressfield()
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    // The program may refuse its arguments before reading its input: a broken pipe is fine.
    let _ = child
        .stdin
        .take()
        .expect("stdin")
        .write_all(stdin.as_bytes());
    child.wait_with_output().expect("finishes")
}

pub(crate) fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

pub(crate) fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

/// Writes a scene into a fresh temporary directory and returns both.
fn scene_file(text: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("case.toml");
    std::fs::write(&path, text).expect("write scene");
    (dir, path)
}

pub(crate) const SMALL_SCENE: &str = "format = 1\n[contact]\nkind = \"line\"\nfriction = 0.2\n[figure]\nquantity = \"von_mises\"\nresolution = 81\nwidth = 300\n";

/// The numbers of a successful `probe` run's CSV rows (header dropped).
fn probe_rows(args: &[&str], input: &str) -> Vec<Vec<f64>> {
    let output = run_with_stdin(args, input);
    assert!(output.status.success(), "{}", stderr(&output));
    stdout(&output)
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().expect("number")).collect())
        .collect()
}

/// Asserts a failed run whose message contains every fragment.
pub(crate) fn assert_fails_with(output: &Output, fragments: &[&str]) {
    assert!(
        !output.status.success(),
        "expected failure, got success; stderr: {}",
        stderr(output)
    );
    let message = stderr(output);
    for fragment in fragments {
        assert!(
            message.contains(fragment),
            "missing `{fragment}` in:\n{message}"
        );
    }
}

#[test]
fn render_writes_png_and_svg_atomically() {
    let (dir, scene) = scene_file(SMALL_SCENE);
    let out = dir.path().join("images");
    let output = run(&[
        "render",
        scene.to_str().expect("utf8"),
        "--out-dir",
        out.to_str().expect("utf8"),
        "--svg",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let png = image::open(out.join("case.png"))
        .expect("a decodable PNG")
        .to_rgb8();
    assert!(png.width() >= 300 && png.height() > 100);
    let svg = std::fs::read_to_string(out.join("case.svg")).expect("an SVG");
    assert!(
        svg.starts_with("<svg") || svg.starts_with("<?xml"),
        "{}",
        &svg[..40.min(svg.len())]
    );
    let names: Vec<_> = std::fs::read_dir(&out)
        .expect("list")
        .map(|e| e.expect("entry").file_name())
        .collect();
    assert_eq!(
        names.len(),
        2,
        "only the two outputs, no temporary files: {names:?}"
    );
}

#[test]
fn render_without_scenes_renders_the_scenes_directory() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scenes = dir.path().join("scenes");
    std::fs::create_dir(&scenes).expect("mkdir");
    std::fs::write(scenes.join("one.toml"), SMALL_SCENE).expect("write");
    std::fs::write(
        scenes.join("two.toml"),
        SMALL_SCENE.replace("von_mises", "tau1"),
    )
    .expect("write");
    std::fs::write(scenes.join("notes.txt"), "not a scene").expect("write");
    let out = dir.path().join("out");
    let output = run(&[
        "render",
        "--scenes-dir",
        scenes.to_str().expect("utf8"),
        "--out-dir",
        out.to_str().expect("utf8"),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(out.join("one.png").is_file() && out.join("two.png").is_file());
}

#[test]
fn render_to_an_unwritable_place_fails_cleanly() {
    let (dir, scene) = scene_file(SMALL_SCENE);
    // A regular file where the output directory should be.
    let blocker = dir.path().join("blocker");
    std::fs::write(&blocker, "").expect("write");
    let out = blocker.join("out");
    let output = run(&[
        "render",
        scene.to_str().expect("utf8"),
        "--out-dir",
        out.to_str().expect("utf8"),
    ]);
    assert_fails_with(&output, &["output directory", "--out-dir"]);
    // A read-only directory (skipped when running as root, which can write anyway).
    let readonly = dir.path().join("readonly");
    std::fs::create_dir(&readonly).expect("mkdir");
    let mut permissions = std::fs::metadata(&readonly).expect("meta").permissions();
    std::os::unix::fs::PermissionsExt::set_mode(&mut permissions, 0o555);
    std::fs::set_permissions(&readonly, permissions).expect("chmod");
    if std::fs::write(readonly.join("probe"), "").is_err() {
        let output = run(&[
            "render",
            scene.to_str().expect("utf8"),
            "--out-dir",
            readonly.to_str().expect("utf8"),
        ]);
        assert_fails_with(&output, &["cannot write", "case.png"]);
        assert_eq!(
            std::fs::read_dir(&readonly).expect("list").count(),
            0,
            "no partial file"
        );
    }
}

#[test]
fn render_compare_detects_changes_and_writes_a_diff() {
    let (dir, scene) = scene_file(SMALL_SCENE);
    let reference = dir.path().join("reference");
    let out = dir.path().join("out");
    let scene = scene.to_str().expect("utf8");
    let output = run(&[
        "render",
        scene,
        "--out-dir",
        reference.to_str().expect("utf8"),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let same = run(&[
        "render",
        scene,
        "--out-dir",
        out.to_str().expect("utf8"),
        "--compare",
        reference.to_str().expect("utf8"),
    ]);
    assert!(same.status.success(), "{}", stderr(&same));
    // Change the physics: the comparison must fail and leave a diff image.
    std::fs::write(
        dir.path().join("case.toml"),
        SMALL_SCENE.replace("friction = 0.2", "friction = 0.4"),
    )
    .expect("write");
    let differs = run(&[
        "render",
        scene,
        "--out-dir",
        out.to_str().expect("utf8"),
        "--compare",
        reference.to_str().expect("utf8"),
    ]);
    assert_fails_with(&differs, &["differ", "case"]);
    assert!(out.join("case.diff.png").is_file());
}

#[test]
fn hertz_reports_the_seed_gear_problem() {
    let output = run(&["hertz", "scenes/gear_pitch_point.toml"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    // Reference values computed by hand from the seed notes' data (Problem 1, nu = 0.3):
    // R1 = 50 sin 20° = 17.1010 mm, R2 = 34.2020 mm, R = 11.4007 mm, E* = 115.385 GPa,
    // a = sqrt(4PR/(pi E*)) = 70.938 µm, p0 = 2P/(pi a) = 358.97 MPa, pm = 281.94 MPa,
    // Y = 300 * 9.80665 / 3 = 981 MPa; sigma_vM,max = 0.5568 p0 = 199.9 MPa; no yield.
    for fragment in [
        "R1 = r1 sin φ = 17.1010 mm",
        "R2 = r2 sin φ = 34.2020 mm",
        "E* = 115.385 GPa",
        "R  = 11.4007 mm",
        "a  = 70.938 µm",
        "p0 = 358.97 MPa",
        "pm = 281.94 MPa",
        "Y  = 981 MPa",
        "below the surface",
        "no yield",
    ] {
        assert!(text.contains(fragment), "missing `{fragment}` in:\n{text}");
    }
}

#[test]
fn check_accepts_every_shipped_scene() {
    let mut scenes: Vec<String> = std::fs::read_dir(repo("scenes"))
        .expect("scenes/")
        .map(|e| e.expect("entry").path().display().to_string())
        .filter(|p| p.ends_with(".toml"))
        .collect();
    scenes.sort();
    assert!(scenes.len() >= 4);
    let mut args = vec!["check"];
    args.extend(scenes.iter().map(String::as_str));
    let output = run(&args);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(
        stdout(&output)
            .lines()
            .filter(|l| l.starts_with("ok "))
            .count(),
        scenes.len()
    );
}

/// Each bad scene, the key its message must name, and a fragment of the fix.
const BAD_SCENES: &[(&str, &str, &str)] = &[
    ("format = 1\n[contact\nkind = \"line\"\n", "case.toml:2:", "invalid"),
    ("format = 1\n[contact]\nkind = \"line\"\npoison = 0.3\n", "key `contact.poison`", "unknown field"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nresolutoin = 100\n", "key `figure.resolutoin`", "unknown field"),
    ("format = 1\n[contact]\nkind = \"line\"\npoisson = 0.7\n", "key `contact.poisson`", "(-1, 0.5]"),
    ("format = 1\n[contact]\nkind = \"line\"\npoisson = -1.0\n", "key `contact.poisson`", "(-1, 0.5]"),
    ("format = 1\n[contact]\nkind = \"line\"\nfriction = -0.1\n", "key `contact.friction`", ">= 0"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"-40 kN/m\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.load`", "positive"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"nan kN/m\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.load`", "does not start with a number"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.load`", "unknown unit `kN`"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN/m\"\n[contact.body1]\nradius = \"0 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.body1.radius`", "non-zero"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN/m\"\n[contact.body1]\nradius = \"10 mm\"\nmodulus = \"0 GPa\"\npoisson = 0.3\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.body1.modulus`", "positive"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN/m\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"-5 mm\"\nmaterial = \"steel\"\n", "key `contact.body2.radius`", "concave"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nx = [2.0, -2.0]\n", "key `figure.x`", "min < max"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nz = [-1.0, 1.0]\n", "key `figure.z`", "into the body"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nx = [-1.0, 1.0]\nz = [0.0, 100.0]\nresolution = 20000\n", "key `figure.resolution`", "MiB"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nquantity = \"vonmises\"\n", "key `figure.quantity`", "von_mises"),
    ("format = 1\n[contact]\nkind = \"line\"\na = \"0 mm\"\np0 = \"1 GPa\"\n", "key `contact.a`", "positive"),
    ("format = 1\n[contact]\nkind = \"line\"\na = 2.0\np0 = 1.0\n", "key `contact.a`", "must be 1"),
    ("format = 1\n[contact]\nkind = \"line\"\na = \"0.2 mm\"\n", "key `contact.p0`", "p0 = "),
    ("format = 1\n[contact]\nkind = \"line\"\nhardness = \"300 HB\"\n", "key `contact.hardness`", "dimensional"),
    ("format = 2\n[contact]\nkind = \"line\"\n", "key `format`", "format = 1"),
    ("format = 1\n[contact]\nkind = \"sphere\"\n", "key `contact.kind`", "\"point\" (spheres)"),
    ("format = 1\n[contact]\nkind = \"point\"\nload = \"40 kN/m\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.load`", "unknown unit `kN/m`"),
    ("format = 1\n[contact]\nkind = \"point\"\nload = \"1 kN\"\n[contact.gears]\nmodule = \"4 mm\"\nteeth = [20, 40]\npressure_angle = \"20 deg\"\n", "key `contact.gears`", "kind = \"line\""),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nsection = \"xy\"\n", "key `figure.section`", "plane strain"),
    ("format = 1\n[contact]\nkind = \"point\"\n[figure]\nsection = \"zx\"\n", "key `figure.section`", "\"yz\""),
    ("format = 1\n[contact]\nkind = \"point\"\n[figure]\ny = [-1.0, 1.0]\n", "key `figure.y`", "figure.at"),
    ("format = 1\n[contact]\nkind = \"point\"\n[figure]\nsection = \"xy\"\nat = -0.5\n", "key `figure.at`", "surface"),
    ("format = 1\n[contact]\nkind = \"line\"\n[[panel]]\nat = 0.5\n", "key `panel[0].at`", "point contacts"),
    ("format = 1\n[contact]\nkind = \"point\"\nmethod = \"fft\"\n", "key `contact.method`", "\"difference\""),
    ("format = 1\n[contact]\nkind = \"point\"\n[[panel]]\nmethod = \"exact\"\n", "key `panel[0].method`", "\"closed_form\""),
    ("format = 1\n[contact]\nkind = \"point\"\n[numerical]\ncells = 3\n", "key `numerical.cells`", "8..=2048"),
    ("format = 1\n[contact]\nkind = \"point\"\n[numerical]\nextent = 0.5\n", "key `numerical.extent`", "cover the contact"),
    ("format = 1\n[contact]\nkind = \"line\"\n[numerical]\nextent = 2.0\n", "key `numerical.extent`", "numerical.cells"),
    ("format = 1\n[contact]\nkind = \"tractions\"\nmethod = \"numerical\"\n", "key `tractions`", "[tractions]"),
    ("format = 1\n[contact]\nkind = \"tractions\"\nfriction = 0.2\nmethod = \"numerical\"\n[tractions]\nfile = \"t.csv\"\n", "key `contact.friction`", "qx"),
    ("format = 1\n[contact]\nkind = \"tractions\"\nmethod = \"numerical\"\n[tractions]\nfile = \"missing.csv\"\n", "key `tractions.file`", "relative to the scene file"),
    ("format = 1\n[contact]\nkind = \"tractions\"\nmethod = \"numerical\"\n[tractions]\nfile = \"t.csv\"\nlength_unit = \"mm\"\n", "key `tractions.length_unit`", "contact.a"),
    ("format = 1\n[contact]\nkind = \"point\"\n[tractions]\nfile = \"t.csv\"\n", "key `tractions`", "kind = \"tractions\""),
    // Recording scenes.
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"speed\"\nvalues = [1.0]\n", "key `sweep.parameter`", "\"position\""),
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"friction\"\n", "key `sweep`", "from = 0.0, to = 0.5, steps = 11"),
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"friction\"\nfrom = 0.0\nto = 0.5\nsteps = 1000\n", "key `sweep.steps`", "2..=400"),
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"friction\"\nvalues = [0.1, -0.2]\n", "key `sweep.values[1]`", ">= 0"),
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"load\"\nvalues = [\"1 kN/m\"]\n", "key `sweep.parameter`", "contact.load"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN/m\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n[figure]\nlength_unit = \"a\"\nstress_unit = \"p0\"\n[sweep]\nparameter = \"load\"\nvalues = [\"10 kN/m\", \"20 kN/m\"]\n", "key `figure.length_unit`", "length_unit = \"mm\""),
    ("format = 1\n[contact]\nkind = \"point\"\nload = \"300 N\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"6 mm\"\nmaterial = \"steel\"\n[sweep]\nparameter = \"load\"\nvalues = [\"100 N/m\"]\n", "key `sweep.values[0]`", "unknown unit `N/m`"),
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"friction\"\nvalues = [0.1]\nmaterial_points = [[0.0, 0.5]]\n", "key `sweep.material_points`", "parameter = \"position\""),
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"position\"\nvalues = [0.0]\nmaterial_points = [[0.0, -0.5]]\n", "key `sweep.material_points[0]`", "z >= 0"),
    ("format = 1\n[contact]\nkind = \"point\"\nmethod = \"numerical\"\n[sweep]\nparameter = \"position\"\nvalues = [0.0, 1.0]\n", "key `sweep.parameter`", "closed_form"),
    ("format = 1\n[contact]\nkind = \"line\"\n[volume]\npoints = 32\n", "key `volume`", "kind = \"point\""),
    ("format = 1\n[contact]\nkind = \"point\"\n[volume]\npoints = 1000\n", "key `volume.points`", "48 to 96"),
    ("format = 1\n[contact]\nkind = \"point\"\n[volume]\nthreshold = 1.5\n", "key `volume.threshold`", "[0, 1)"),
    ("format = 1\n[contact]\nkind = \"point\"\n[volume]\nz = [-1.0, 1.0]\n", "key `volume.z`", ">= 0"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nx = [-1.0, 1.0]\nz = [0.0, 2.0]\nresolution = 8000\n[sweep]\nparameter = \"position\"\nfrom = -1.0\nto = 1.0\nsteps = 400\n", "key `sweep`", "fewer steps"),
    ("format = 1\n[contact]\nkind = \"elliptical\"\naspect = 3.0\nmethod = \"numerical\"\n[volume]\npoints = 32\n", "key `volume`", "record sections"),
];

#[test]
fn bad_scenes_name_the_key_and_the_fix() {
    for (text, key, fix) in BAD_SCENES {
        let (dir, scene) = scene_file(text);
        let out = dir.path().join("out");
        for args in [
            vec!["check", scene.to_str().expect("utf8")],
            vec![
                "render",
                scene.to_str().expect("utf8"),
                "--out-dir",
                out.to_str().expect("utf8"),
            ],
        ] {
            let output = run(&args);
            assert_fails_with(&output, &[key, fix]);
        }
        assert!(!out.join("case.png").exists(), "no output for a bad scene");
    }
}

#[test]
fn hertz_and_probe_reject_a_missing_scene() {
    assert_fails_with(
        &run(&["hertz", "scenes/no_such_scene.toml"]),
        &["cannot read the scene"],
    );
    assert_fails_with(
        &run(&["probe", "scenes/no_such_scene.toml", "--points", "-"]),
        &["cannot read the scene"],
    );
}

#[test]
fn probe_agrees_with_flamant_quadrature_to_1e9_p0() {
    let mut input = String::from("# depth sweep and off-axis points\nx,y,z\n");
    let mut points = Vec::new();
    for x in [-2.5, -1.0, -0.6, 0.0, 0.3, 0.99, 1.0, 1.7] {
        for z in [0.0, 0.03, 0.2, 0.5, 0.786, 1.3, 3.0] {
            input.push_str(&format!("{x},0.5,{z}\n"));
            points.push((x, z));
        }
    }
    let output = run_with_stdin(
        &[
            "probe",
            "--friction",
            "0.3",
            "--poisson",
            "0.25",
            "--points",
            "-",
        ],
        &input,
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("x,y,z,sxx,syy,szz,syz,sxz,sxy,s1,s2,s3,von_mises,max_shear")
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().expect("a number")).collect())
        .collect();
    assert_eq!(rows.len(), points.len());
    for (row, &(x, z)) in rows.iter().zip(&points) {
        assert_eq!(row.len(), 14);
        assert_eq!((row[0], row[1], row[2]), (x, 0.5, z));
        let expected = if z == 0.0 {
            // On the surface the exact values are known in closed form (boundary conditions).
            let p = if x.abs() < 1.0 {
                (1.0f64 - x * x).sqrt()
            } else {
                0.0
            };
            let n = if x.abs() > 1.0 {
                x.signum() * (x * x - 1.0f64).sqrt()
            } else {
                0.0
            };
            let sxx = -p + 2.0 * 0.3 * (n - x);
            [sxx, 0.25 * (sxx - p), -p, 0.0, -0.3 * p, 0.0]
        } else {
            let s = flamant_quadrature(x, z, 0.3, 0.25);
            [s.xx, s.yy, s.zz, s.yz, s.xz, s.xy]
        };
        for (k, value) in expected.iter().enumerate() {
            assert!(
                (row[3 + k] - value).abs() < 1e-9,
                "x={x} z={z} column {k}: {} vs {value}",
                row[3 + k]
            );
        }
        // Derived columns: von Mises from the components.
        let s = stressfield::stress::Stress {
            xx: row[3],
            yy: row[4],
            zz: row[5],
            yz: row[6],
            xz: row[7],
            xy: row[8],
        };
        assert!((row[12] - s.von_mises()).abs() < 1e-12);
        assert!(row[9] >= row[10] && row[10] >= row[11]);
    }
}

#[test]
fn probe_prints_full_precision() {
    let output = run_with_stdin(&["probe", "--points", "-"], "0,0,0.786\n");
    assert!(output.status.success(), "{}", stderr(&output));
    let row = stdout(&output).lines().nth(1).expect("a row").to_string();
    let szz = row.split(',').nth(5).expect("szz");
    // -1/sqrt(1 + 0.786^2) to the last bit.
    assert_eq!(
        szz.parse::<f64>().expect("number"),
        -1.0 / (1.0f64 + 0.786 * 0.786).sqrt()
    );
    assert!(szz.trim_start_matches('-').len() >= 14, "{szz}");
}

#[test]
fn probe_rejects_bad_input() {
    let cases: &[(&[&str], &str, &[&str])] = &[
        (
            &["probe", "--points", "-"],
            "0,0\n",
            &["line 1", "expected 3 fields"],
        ),
        (
            &["probe", "--points", "-"],
            "x,y,z\n0,0,1\n0,zero,1\n",
            &["line 3", "not a number"],
        ),
        (
            &["probe", "--points", "-"],
            "0,0,-0.5\n",
            &["line 1", "outside the body"],
        ),
        (
            &["probe", "--points", "-"],
            "# only a comment\n",
            &["no points"],
        ),
        (
            &[
                "probe",
                "--contact",
                "point",
                "--method",
                "numerical",
                "--extent",
                "0.5",
                "--points",
                "-",
            ],
            "0,0,1\n",
            &["--extent must lie in 1..=20", "cover the contact"],
        ),
        (
            &[
                "probe",
                "--method",
                "numerical",
                "--strips",
                "0",
                "--points",
                "-",
            ],
            "0,0,1\n",
            &["--strips", "1..=1000000"],
        ),
        (
            &["probe", "--poisson", "0.7", "--points", "-"],
            "0,0,1\n",
            &["--poisson", "(-1, 0.5]"],
        ),
        (
            &["probe", "--friction", "-1", "--points", "-"],
            "0,0,1\n",
            &["--friction"],
        ),
        (
            &["probe", "--points", "/no/such/file.csv"],
            "",
            &["cannot open the points file"],
        ),
    ];
    for (args, input, fragments) in cases {
        let output = run_with_stdin(args, input);
        assert_fails_with(&output, fragments);
        assert!(stdout(&output).is_empty(), "no partial CSV for {args:?}");
    }
}

#[test]
fn probe_numerical_method_agrees_with_the_closed_form() {
    let mut input = String::new();
    for x in [-2.0, -1.0, -0.4, 0.0, 0.7, 1.3] {
        for z in [0.1, 0.5, 1.0, 2.5] {
            input.push_str(&format!("{x},0,{z}\n"));
        }
    }
    let args = |method: &'static str| {
        [
            "probe",
            "--friction",
            "0.25",
            "--method",
            method,
            "--points",
            "-",
        ]
    };
    let numerical = run_with_stdin(&args("numerical"), &input);
    let closed = run_with_stdin(&args("closed-form"), &input);
    assert!(numerical.status.success(), "{}", stderr(&numerical));
    let parse = |output: &Output| -> Vec<Vec<f64>> {
        stdout(output)
            .lines()
            .skip(1)
            .map(|l| l.split(',').map(|v| v.parse().expect("number")).collect())
            .collect()
    };
    let (a, b) = (parse(&numerical), parse(&closed));
    assert_eq!(a.len(), 24);
    for (row_a, row_b) in a.iter().zip(&b) {
        for (u, v) in row_a.iter().zip(row_b).skip(3) {
            // 2000 strips (the default): the discretisation error is below 1e-4 p0 at z >= 0.1a.
            assert!((u - v).abs() < 1e-4, "{row_a:?} vs {row_b:?}");
        }
    }
}

#[test]
fn probe_point_contact_gives_the_sphere_field() {
    let input = "x,y,z\n0,0,0.5\n0.3,-0.4,0.2\n1,0,0\n";
    let output = run_with_stdin(
        &[
            "probe",
            "--contact",
            "point",
            "--friction",
            "0.2",
            "--poisson",
            "0.3",
            "--points",
            "-",
        ],
        input,
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let rows: Vec<Vec<f64>> = stdout(&output)
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().expect("number")).collect())
        .collect();
    assert_eq!(rows.len(), 3);
    // On the axis the normal part gives szz = -1/(1 + z²) (Johnson §3.4); the traction adds
    // nothing to szz on the axis (odd in x).
    assert!((rows[0][5] + 1.0 / 1.25).abs() < 1e-12, "{:?}", rows[0]);
    // y is used: the off-axis point has shear stresses out of the xz plane.
    assert!(
        rows[1][6].abs() > 1e-3 && rows[1][8].abs() > 1e-3,
        "{:?}",
        rows[1]
    );
    // Contact edge on the surface: szz = 0, and the y column is echoed.
    assert!(rows[2][5].abs() < 1e-12 && rows[2][1] == 0.0);
    for row in &rows {
        let s =
            stressfield::solution::sphere_hertz::stress_over_p0(row[0], row[1], row[2], 0.2, 0.3);
        assert_eq!(
            [row[3], row[4], row[5], row[6], row[7], row[8]],
            [s.xx, s.yy, s.zz, s.yz, s.xz, s.xy]
        );
    }
    // A scene describes a line contact: refuse the combination.
    let refused = run_with_stdin(
        &[
            "probe",
            "scenes/line_tau1.toml",
            "--contact",
            "point",
            "--points",
            "-",
        ],
        input,
    );
    assert_fails_with(&refused, &["--contact point", "scene"]);
}

#[test]
fn hertz_reports_a_ball_on_a_flat() {
    let output = run(&["hertz", "scenes/sphere_ball_on_flat.toml"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    // By hand (Johnson 1985 §4.2(a)), steel E = 210 GPa, nu = 0.3, W = 300 N, R = 6.35 mm:
    // E* = E / (2 (1 - nu^2)) = 115.385 GPa, a = (3 W R / (4 E*))^(1/3) = 231.350 µm,
    // p0 = 3 W / (2 pi a^2) = 2676.23 MPa, pm = 2 p0 / 3 = 1784.15 MPa, delta = a^2/R = 8.4288 µm.
    for fragment in [
        "contact: point",
        "W  = 300.0000 N",
        "E* = 115.385 GPa",
        "R  = 6.3500 mm",
        "a  = 231.350 µm",
        "p0 = 2676.23 MPa",
        "pm = 1784.15 MPa",
        "δ  = 8.4288 µm",
        "Y  = 1800 MPa",
        "no yield",
        // W ∝ p0³: first yield at W (Y / sigma_vM,max)^3 with sigma_vM,max = 0.6244 p0.
        "W_Y = 37",
    ] {
        assert!(text.contains(fragment), "missing `{fragment}` in:\n{text}");
    }
}

#[test]
fn hertz_gives_first_yield_of_a_frictionless_sphere() {
    let (_dir, scene) = scene_file("format = 1\n[contact]\nkind = \"point\"\npoisson = 0.3\n");
    let output = run(&["hertz", scene.to_str().expect("utf8")]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    // Johnson (1985) §6.2: under a sphere (nu = 0.3) yield begins at p0 = 1.60 Y, at 0.48a
    // below the centre, by both criteria (on the axis two principal stresses are equal). The
    // book rounds: tau_max = 0.3100 p0 gives 1/(2 x 0.31) = 1.613.
    for fragment in ["below the surface, at z = 0.48", "y = 0.000 a"] {
        assert!(text.contains(fragment), "missing `{fragment}` in:\n{text}");
    }
    let number_after = |key: &str| -> f64 {
        let start = text
            .find(key)
            .unwrap_or_else(|| panic!("no `{key}` in:\n{text}"))
            + key.len();
        let digits: String = text[start..]
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '.')
            .collect();
        digits.parse().expect("a number")
    };
    let von_mises = number_after("when p0 = ");
    let tresca = number_after("(Tresca: p0 = ");
    assert!((von_mises - 1.60).abs() < 0.015, "{von_mises}");
    assert!((tresca - von_mises).abs() < 1e-9, "{tresca}");
}

#[test]
fn probe_takes_the_point_contact_from_a_scene() {
    let input = "x,y,z\n0,0,0.5\n0.3,0.4,0.7\n-1.2,0.5,0\n";
    let from_scene = run_with_stdin(
        &[
            "probe",
            "scenes/sphere_von_mises_friction.toml",
            "--friction",
            "0.25",
            "--points",
            "-",
        ],
        input,
    );
    assert!(from_scene.status.success(), "{}", stderr(&from_scene));
    let explicit = run_with_stdin(
        &[
            "probe",
            "--contact",
            "point",
            "--friction",
            "0.25",
            "--poisson",
            "0.3",
            "--points",
            "-",
        ],
        input,
    );
    assert!(explicit.status.success(), "{}", stderr(&explicit));
    assert_eq!(stdout(&from_scene), stdout(&explicit));
    // y matters: a line contact would give the same row for (0.3, 0.4) and (0.3, 0).
    assert_ne!(
        stdout(&from_scene),
        stdout(&run_with_stdin(
            &["probe", "--friction", "0.25", "--points", "-"],
            input
        ))
    );
    let contradiction = run_with_stdin(
        &[
            "probe",
            "scenes/sphere_max_shear.toml",
            "--contact",
            "line",
            "--points",
            "-",
        ],
        input,
    );
    assert_fails_with(
        &contradiction,
        &["--contact line contradicts", "drop --contact"],
    );
}

#[test]
fn probe_integrates_a_point_contact_numerically() {
    let input = "x,y,z\n0,0,0.5\n0.4,-0.3,0.25\n-1.1,0.2,0.3\n0.5,0.5,1.5\n";
    let rows = |args: &[&str]| probe_rows(args, input);
    let exact = rows(&[
        "probe",
        "--contact",
        "point",
        "--friction",
        "0.3",
        "--points",
        "-",
    ]);
    let coarse = rows(&[
        "probe",
        "--contact",
        "point",
        "--friction",
        "0.3",
        "--method",
        "numerical",
        "--cells",
        "63",
        "--points",
        "-",
    ]);
    let fine = rows(&[
        "probe",
        "--contact",
        "point",
        "--friction",
        "0.3",
        "--method",
        "numerical",
        "--cells",
        "191",
        "--points",
        "-",
    ]);
    // Cells of 4a/63 and 4a/191 over [-2a, 2a]²: the error falls with the cell size (about
    // second order) and is 1e-3 p0 or less at these depths (z >= 0.25a) on the finer grid.
    let error = |rows: &[Vec<f64>]| -> f64 {
        rows.iter()
            .zip(&exact)
            .flat_map(|(a, b)| a[3..].iter().zip(&b[3..]).map(|(u, v)| (u - v).abs()))
            .fold(0.0, f64::max)
    };
    let (coarse_error, fine_error) = (error(&coarse), error(&fine));
    assert!(fine_error < 1e-3, "{fine_error}");
    assert!(
        fine_error < coarse_error / 4.0,
        "{coarse_error} -> {fine_error}"
    );
    let bad = run_with_stdin(
        &[
            "probe",
            "--contact",
            "point",
            "--method",
            "numerical",
            "--cells",
            "4",
            "--points",
            "-",
        ],
        input,
    );
    assert_fails_with(&bad, &["--cells must lie in 8..=2048"]);
}

#[test]
fn traction_files_are_read_in_their_units() {
    use stressfield::solution::point_numerical::PointTractions;
    // The sliding Hertz sphere's cell means (31 cells over [-2a, 2a]), written in mm and MPa
    // for a = 0.2 mm and p0 = 1.5 GPa: the scene must integrate exactly the same tractions as
    // `probe --contact point --method numerical` on the same grid.
    let tractions = PointTractions::hertz_sphere(31, 2.0, 0.3, 0.3).expect("grid");
    let grid = tractions.grid();
    let [ny, nx] = grid.shape();
    let mut csv = String::from("# Hertz sphere, mu = 0.3\nqx,x,y,p\n");
    // Rows in reverse order: the reader must place them by their coordinates.
    for row in (0..ny).rev() {
        for column in (0..nx).rev() {
            let (x, y) = grid.cell_centre(row, column);
            let (p, qx, _) = grid.traction(row, column);
            csv.push_str(&format!(
                "{},{},{},{}\n",
                qx * 1500.0,
                x * 0.2,
                y * 0.2,
                p * 1500.0
            ));
        }
    }
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::write(dir.path().join("sphere.csv"), csv).expect("write csv");
    let scene = dir.path().join("sphere.toml");
    std::fs::write(
        &scene,
        "format = 1\n[contact]\nkind = \"tractions\"\na = \"0.2 mm\"\np0 = \"1.5 GPa\"\npoisson = 0.3\nmethod = \"numerical\"\n[tractions]\nfile = \"sphere.csv\"\nlength_unit = \"mm\"\nstress_unit = \"MPa\"\n",
    )
    .expect("write scene");
    let input = "x,y,z\n0,0,0.5\n-0.7,0.4,0.3\n1.2,-0.2,0.8\n";
    let rows = |args: &[&str]| probe_rows(args, input);
    let from_file = rows(&["probe", scene.to_str().expect("utf8"), "--points", "-"]);
    let built_in = rows(&[
        "probe",
        "--contact",
        "point",
        "--friction",
        "0.3",
        "--method",
        "numerical",
        "--cells",
        "31",
        "--extent",
        "2",
        "--points",
        "-",
    ]);
    for (a, b) in from_file.iter().zip(&built_in) {
        for (u, v) in a.iter().zip(b) {
            assert!((u - v).abs() < 1e-9, "{a:?} vs {b:?}");
        }
    }
    // The hertz report adds up the file's resultants: P = 2 pi a^2 p0 / 3 = 125.664 N here
    // (the cell means on 31 cells give 125.669 N), Qx = 0.3 P = 37.70 N.
    let output = run(&["hertz", scene.to_str().expect("utf8")]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    assert!(text.contains("P  = 125.6"), "{text}");
    assert!(text.contains("Qx = 37.70"), "{text}");
}

#[test]
fn hertz_reports_maxima_of_a_contact_without_closed_form() {
    let output = run(&["hertz", "scenes/ellipse_bearing_groove.toml"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    // The grid maxima (DC-FFT at cell centres): the figure test finds the von Mises maximum
    // of this long ellipse between the line (0.557 p0 at 0.70a) and the sphere (0.620 p0 at
    // 0.48a) values; the report must agree (0.5746 p0 at z = 0.724a on its 127² grid).
    for fragment in [
        "stress maxima by DC-FFT at the cell centres of the 127 x 127 traction grid",
        "von Mises σvM                0.57",
        "first yield (von Mises) starts below the surface, at z = 0.7",
    ] {
        assert!(text.contains(fragment), "missing `{fragment}` in:\n{text}");
    }
    let output = run(&["hertz", "scenes/asperities.toml"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    assert!(text.contains("stress maxima in the body"), "{text}");
    assert!(
        !text.contains("when p0 ="),
        "tractions from a file have no Hertz p0:\n{text}"
    );
}

#[test]
fn record_writes_one_recording_per_scene_and_refuses_bad_outputs() {
    let (dir, scene) = scene_file(&format!(
        "{SMALL_SCENE}[sweep]\nparameter = \"friction\"\nvalues = [0.0, 0.3]\n"
    ));
    let scene = scene.to_str().expect("utf8");
    let out = dir.path().join("out");
    let output = run(&["record", scene, "--out-dir", out.to_str().expect("utf8")]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("2 steps on the timeline `friction`"),
        "{}",
        stderr(&output)
    );
    let bytes = std::fs::read(out.join("case.rrd")).expect("out/case.rrd");
    assert!(bytes.len() > 1000);
    // -o names the file; it takes one scene only.
    let file = dir.path().join("named.rrd");
    let output = run(&["record", scene, "-o", file.to_str().expect("utf8")]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(file.exists());
    assert_fails_with(
        &run(&["record", scene, scene, "-o", "x.rrd"]),
        &["one scene", "-o"],
    );
    // An unwritable place: a clear error and nothing left behind.
    let missing = dir.path().join("no").join("such.rrd");
    assert_fails_with(
        &run(&["record", scene, "-o", missing.to_str().expect("utf8")]),
        &["cannot write", "writable"],
    );
    assert!(!dir.path().join("no").exists());
    // render --rrd: the figure and its recording.
    let figure_dir = dir.path().join("figures");
    let recording = dir.path().join("figure.rrd");
    let output = run(&[
        "render",
        scene,
        "--out-dir",
        figure_dir.to_str().expect("utf8"),
        "--rrd",
        recording.to_str().expect("utf8"),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(figure_dir.join("case.png").exists() && recording.exists());
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .expect("listed")
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().contains(".part"))
        .collect();
    assert!(leftovers.is_empty(), "temporary files left: {leftovers:?}");
}
