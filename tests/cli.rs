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

pub(crate) fn run_with_stdin(args: &[&str], stdin: &str) -> Output {
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

/// Issue 13, case 6: the references of a regression run are read within a limit too: a
/// reference that is a huge file (or a device) fails at once, naming it and the limit.
#[cfg(unix)]
#[test]
fn regression_references_are_read_within_a_limit() {
    let (dir, scene) = scene_file(SMALL_SCENE);
    let reference = dir.path().join("reference");
    std::fs::create_dir(&reference).expect("mkdir");
    // Sparse files of a tebibyte (no disk space); devices are read up to the limit (unit test
    // of `input::read_bytes` with /dev/zero).
    for name in ["case.png", "case.npz"] {
        let file = std::fs::File::create(reference.join(name)).expect("create");
        file.set_len(1 << 40).expect("sparse");
    }
    let out = dir.path().join("out");
    let output = run(&[
        "render",
        scene.to_str().expect("utf8"),
        "--out-dir",
        out.to_str().expect("utf8"),
        "--compare",
        reference.to_str().expect("utf8"),
    ]);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    let text = format!("{}{}", stdout(&output), stderr(&output));
    for fragment in ["case.png", "case.npz", "larger than the 1 GiB allowed"] {
        assert!(text.contains(fragment), "missing `{fragment}` in:\n{text}");
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
    ("format = 1\n[contact]\nkind = \"line\"\nfriction = -0.1\n", "key `contact.friction`", "0..=10"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"-40 kN/m\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.load`", "between 1e-12 N/m and 1e12 N/m"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"nan kN/m\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.load`", "does not start with a number"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.load`", "per unit length"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN/m\"\n[contact.body1]\nradius = \"0 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.body1.radius`", "between 1e-9 m and 1e6 m"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN/m\"\n[contact.body1]\nradius = \"10 mm\"\nmodulus = \"0 GPa\"\npoisson = 0.3\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.body1.modulus`", "between 1000 Pa and 1e13 Pa"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN/m\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"-5 mm\"\nmaterial = \"steel\"\n", "key `contact.body2.radius`", "concave"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nx = [2.0, -2.0]\n", "key `figure.x`", "min < max"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nz = [-1.0, 1.0]\n", "key `figure.z`", "into the body"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nx = [-1.0, 1.0]\nz = [0.0, 40.0]\nresolution = 20000\n", "key `figure.resolution`", "MiB"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nquantity = \"vonmises\"\n", "key `figure.quantity`", "von_mises"),
    ("format = 1\n[contact]\nkind = \"line\"\na = \"0 mm\"\np0 = \"1 GPa\"\n", "key `contact.a`", "between 1e-12 m"),
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
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"friction\"\nvalues = [0.1, -0.2]\n", "key `sweep.values[1]`", "0..=10"),
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
    // Issue 13, case 2: friction is bounded wherever it is written.
    ("format = 1\n[contact]\nkind = \"line\"\nfriction = 1e300\n", "key `contact.friction`", "weld"),
    ("format = 1\n[contact]\nkind = \"point\"\n[[panel]]\nfriction = 11.0\n", "key `panel[0].friction`", "0..=10"),
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"friction\"\nvalues = [0.1, 1e300]\n", "key `sweep.values[1]`", "got 1e300"),
    // Case 3: the inputs of Hertz theory, named as written.
    ("format = 1\n[contact]\nkind = \"point\"\nload = \"5e-324 N\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.load`", "got `5e-324 N`"),
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"1.7e308 N/m\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.load`", "got `1.7e308 N/m`"),
    ("format = 1\n[contact]\nkind = \"point\"\nload = \"100 N\"\n[contact.body1]\nradius = \"10 mm\"\nmodulus = \"5e-324 Pa\"\npoisson = 0.3\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.body1.modulus`", "diamond"),
    ("format = 1\n[contact]\nkind = \"point\"\nload = \"100 N\"\n[contact.body1]\nradius = \"5e-324 m\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.body1.radius`", "got `5e-324 m`"),
    ("format = 1\n[contact]\nkind = \"point\"\nload = \"100 N\"\nyield_strength = \"5e-324 Pa\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n", "key `contact.yield_strength`", "got `5e-324 Pa`"),
    ("format = 1\n[contact]\nkind = \"line\"\na = \"1 mm\"\np0 = \"1e300 GPa\"\n", "key `contact.p0`", "1e13 Pa"),
    ("format = 1\n[contact]\nkind = \"point\"\nload = \"300 N\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"6 mm\"\nmaterial = \"steel\"\n[figure]\nlength_unit = \"mm\"\n[sweep]\nparameter = \"load\"\nvalues = [\"100 N\", \"1e300 N\"]\n", "key `sweep.values[1]`", "got `1e300 N`"),
    // Case 4: ranges in units of a, dimensional ones converted.
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nx = [0.0, 1e300]\n", "key `figure.x`", "10000 a"),
    ("format = 1\n[contact]\nkind = \"point\"\nload = \"100 N\"\n[contact.body1]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n[figure]\nsection = \"xy\"\ny = [-0.5, 1e308]\n", "key `figure.y`", "`1e308 mm`"),
    ("format = 1\n[contact]\nkind = \"point\"\n[figure]\nat = 1e300\n", "key `figure.at`", "10000 a"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nx = [-1000.0, 1000.0]\nz = [0.0, 1.0]\n", "key `figure.z`", "between 1/50 and 50"),
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nx = [0.0, 1e-9]\nz = [0.0, 1e-9]\n", "key `figure.x`", "1e-6 a"),
    ("format = 1\n[contact]\nkind = \"point\"\n[volume]\nx = [0.0, 1e300]\n", "key `volume.x`", "10000 a"),
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"position\"\nvalues = [0.0, 1e300]\n", "key `sweep.values[1]`", "10000 a"),
    // Case 7: the memory of the whole figure (three panels at the largest resolution).
    ("format = 1\n[contact]\nkind = \"line\"\n[figure]\nresolution = 20000\n[[panel]]\nfriction = 0.0\n[[panel]]\nfriction = 0.2\n[[panel]]\nfriction = 0.4\n", "key `figure.resolution`", "bytes a point"),
    // Case 12: the key the user wrote, not a generated value.
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"friction\"\nfrom = inf\nto = 0.5\nsteps = 3\n", "key `sweep.from`", "finite"),
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"position\"\nfrom = -1.7e308\nto = 1.7e308\nsteps = 3\n", "key `sweep.to`", "double precision"),
    // ... the value written, not a generated step (5e299 is the middle of 0 to 1e300).
    ("format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"friction\"\nfrom = 0.0\nto = 1e300\nsteps = 3\n", "key `sweep.to`", "got 1e300"),
    // Case 3: derived values: a gear pair's radii at the pitch point, an ellipse's b/a.
    ("format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN/m\"\n[contact.gears]\nmodule = \"5 mm\"\nteeth = [20, 40]\npressure_angle = \"1e-300 deg\"\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n", "key `contact.gears`", "radius of curvature at the pitch point is 8.727e-304 m"),
    ("format = 1\n[contact]\nkind = \"elliptical\"\nload = \"1 kN\"\nmethod = \"numerical\"\n[contact.body1]\nradius_x = \"26.15 mm\"\nradius_y = \"-6.35000000001 mm\"\nmaterial = \"bearing_steel\"\n[contact.body2]\nradius = \"6.35 mm\"\nmaterial = \"bearing_steel\"\n", "key `contact.body2.radius_y`", "b/a = 3492000"),
];

/// A small rough scene (a 32² generated surface on a steel flat) for [`ROUGH_EXTREMES`].
const ROUGH_BASE: &str = "format = 1\n[contact]\nkind = \"rough\"\nload = \"0.5 N\"\nfriction = 0.1\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n[surface.generate]\nsamples = 32\nspacing = \"0.5 um\"\nhurst = 0.8\nrolloff = \"8 um\"\nrms_height = \"0.05 um\"\nsphere_radius = \"2 mm\"\n";

/// Issue 13 in rough scenes: a line of [`ROUGH_BASE`] replaced, the key named in the error
/// and the limit.
const ROUGH_EXTREMES: &[(&str, &str, &str, &str)] = &[
    (
        "load = \"0.5 N\"",
        "load = \"5e-324 N\"",
        "key `contact.load`",
        "between 1e-12 N and 1e12 N, got `5e-324 N`",
    ),
    (
        "load = \"0.5 N\"",
        "load = \"1e12 N\"",
        "key `contact.load`",
        "more than the combined modulus E*",
    ),
    (
        "load = \"0.5 N\"",
        "mean_pressure = \"1e300 Pa\"",
        "key `contact.mean_pressure`",
        "1e13 Pa",
    ),
    (
        "load = \"0.5 N\"",
        "mean_pressure = \"1000 GPa\"",
        "key `contact.mean_pressure`",
        "more than the combined modulus E*",
    ),
    // Issue 22: 0.5 N over the map's 256 µm² is 1.95 GPa, more than 100 HV (0.98 GPa) carries.
    (
        "friction = 0.1",
        "friction = 0.1\nhardness = \"100 HV\"",
        "key `contact.load`",
        "more than the fully plastic surface carries",
    ),
    (
        "load = \"0.5 N\"",
        "approach = \"1 mm\"",
        "key `contact.approach`",
        "peak-to-valley",
    ),
    (
        "friction = 0.1",
        "friction = 1e300",
        "key `contact.friction`",
        "0..=10",
    ),
    (
        "spacing = \"0.5 um\"",
        "spacing = \"1e300 um\"",
        "key `surface.generate.spacing`",
        "between 1e-10 m and 1 m",
    ),
    (
        "rms_height = \"0.05 um\"",
        "rms_height = \"1e300 um\"",
        "key `surface.generate.rms_height`",
        "0.1 m",
    ),
    (
        "rms_height = \"0.05 um\"",
        "rms_slope = 1e300",
        "key `surface.generate.rms_slope`",
        "between 1e-6 and 10",
    ),
    (
        "hurst = 0.8",
        "hurst = 5.0",
        "key `surface.generate.hurst`",
        "(0, 1]",
    ),
    (
        "rolloff = \"8 um\"",
        "rolloff = \"1e300 m\"",
        "key `surface.generate.rolloff`",
        "10000 m",
    ),
    (
        "sphere_radius = \"2 mm\"",
        "sphere_radius = \"1e300 m\"",
        "key `surface.generate.sphere_radius`",
        "1e6 m",
    ),
];

/// Issue 13: extreme values in rough and surface scenes are refused at `check`, naming the key,
/// instead of a NaN surface or a solver that never converges.
#[test]
fn rough_and_surface_extremes_are_refused() {
    for (line, replacement, key, fix) in ROUGH_EXTREMES {
        assert!(ROUGH_BASE.contains(line), "{line}");
        let (_dir, scene) = scene_file(&ROUGH_BASE.replace(line, replacement));
        assert_fails_with(&run(&["check", scene.to_str().expect("utf8")]), &[key, fix]);
    }
    // A measured surface whose heights are far beyond any roughness (a wrong height unit).
    let dir = tempfile::tempdir().expect("temp dir");
    let mut rows = vec![vec!["0.1"; 8]; 8];
    rows[1][1] = "1e300";
    let asc: String = rows.iter().map(|r| r.join(" ") + "\n").collect();
    std::fs::write(dir.path().join("s.asc"), asc).expect("write");
    let scene = dir.path().join("s.toml");
    std::fs::write(
        &scene,
        "format = 1\n[contact]\nkind = \"surface\"\n[surface]\nfile = \"s.asc\"\nspacing = \"1 um\"\nheight_unit = \"um\"\n",
    )
    .expect("write");
    assert_fails_with(
        &run(&["check", scene.to_str().expect("utf8")]),
        &["key `surface.file`", "row 1, column 1", "1e294 m", "1 m"],
    );
    let asc = dir.path().join("s.asc");
    assert_fails_with(
        &run(&[
            "surface",
            asc.to_str().expect("utf8"),
            "--spacing",
            "1um",
            "--height-unit",
            "um",
        ]),
        &["row 1, column 1", "1e294 m"],
    );
}

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

// Issue 13: bad input found by fuzzing. Each test names the case it guards.

/// Every number of every row of a successful `probe` is finite.
fn assert_rows_finite(rows: &[Vec<f64>]) {
    assert!(!rows.is_empty());
    for row in rows {
        assert!(row.iter().all(|v| v.is_finite()), "{row:?}");
    }
}

/// Case 1: on a strip or cell edge at the surface, the numerical probe gives the mean of the
/// values at the neighbouring strip (cell) centres, never NaN.
#[test]
fn numerical_probe_on_strip_and_cell_edges_is_finite() {
    let line = probe_rows(
        &["probe", "--method", "numerical", "--points", "-"],
        "0,0,0\n1,0,0\n-1,0,0\n",
    );
    assert_rows_finite(&line);
    // At the centre, between two strips of 2000: szz = -p, sxx = -p (frictionless) to the
    // discretisation error; at the contact edge half the last strip's pressure.
    assert!((line[0][5] + 1.0).abs() < 1e-5, "{:?}", line[0]);
    assert!((line[0][3] + 1.0).abs() < 1e-3, "{:?}", line[0]);
    assert!(line[1][5] < 0.0 && line[1][5] > -0.02, "{:?}", line[1]);
    let sliding = probe_rows(
        &[
            "probe",
            "--method",
            "numerical",
            "--friction",
            "0.3",
            "--points",
            "-",
        ],
        "0,0,0\n",
    );
    assert_rows_finite(&sliding);
    let point = probe_rows(
        &[
            "probe",
            "--contact",
            "point",
            "--method",
            "numerical",
            "--cells",
            "8",
            "--points",
            "-",
        ],
        "0,0,0\n0.5,0.25,0\n1,1,0\n",
    );
    assert_rows_finite(&point);
}

/// Case 2: friction is bounded on the command line as in scenes; case 12: the message names
/// the flag, not a cell of the traction grid.
#[test]
fn probe_refuses_friction_beyond_a_few() {
    for args in [
        &["probe", "--friction", "1e300", "--points", "-"][..],
        &[
            "probe",
            "--contact",
            "point",
            "--method",
            "numerical",
            "--friction",
            "1e308",
            "--points",
            "-",
        ][..],
    ] {
        let output = run_with_stdin(args, "0,0,1\n");
        assert_fails_with(&output, &["--friction", "0..=10", "weld"]);
        assert!(!stderr(&output).contains("shear_x"), "{}", stderr(&output));
    }
}

/// Case 5: numbers print short (exponent notation where decimals would run on), and no text
/// makes a figure wide.
#[test]
fn numbers_and_texts_keep_outputs_small() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("out");
    let tiny = dir.path().join("tiny.toml");
    std::fs::write(
        &tiny,
        "format = 1\n[contact]\nkind = \"line\"\nfriction = 5e-324\n[figure]\nresolution = 81\nwidth = 300\n",
    )
    .expect("write");
    let long = dir.path().join("long.toml");
    std::fs::write(
        &long,
        format!(
            "format = 1\ntitle = \"{}\"\n[contact]\nkind = \"point\"\n[figure]\nresolution = 41\nwidth = 300\n[[panel]]\nsubtitle = \"{}\"\n[[panel]]\nat = 0.5\n",
            "A very long title ".repeat(500),
            "a very long subtitle ".repeat(500)
        ),
    )
    .expect("write");
    let args = [
        "render",
        tiny.to_str().expect("utf8"),
        long.to_str().expect("utf8"),
        "--out-dir",
        out.to_str().expect("utf8"),
    ];
    let output = run(&args);
    assert!(output.status.success(), "{}", stderr(&output));
    // Two panels 300 px wide: the long subtitle is cut to its budget (about 900 px), and the
    // second panel's says where the body's maximum is, off its section (about 560 px).
    for (name, widest) in [("tiny", 800), ("long", 1800)] {
        let image = image::open(out.join(format!("{name}.png"))).expect("png");
        assert!(image.width() <= widest, "{name}: {} px wide", image.width());
    }
    let report = stdout(&run(&["hertz", tiny.to_str().expect("utf8")]));
    assert!(report.contains("μ = 5e-324"), "{report}");
    assert!(report.lines().all(|l| l.chars().count() < 200), "{report}");
    let output = run_with_stdin(&["probe", "--points", "-"], "1e8,0,1e-7\n1e-300,0,1\n");
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    assert!(text.lines().nth(1).expect("row").starts_with("1e8,0,1e-7,"));
    for field in text.lines().skip(1).flat_map(|l| l.split(',')) {
        assert!(field.len() <= 24, "{field}");
    }
}

/// Case 6: scene, traction and point files are read within limits, so an endless file fails
/// at once with the limit in the message.
#[cfg(unix)]
#[test]
fn endless_inputs_stop_at_a_limit() {
    assert_fails_with(&run(&["check", "/dev/zero"]), &["/dev/zero", "1 MiB"]);
    assert_fails_with(
        &run(&["probe", "--points", "/dev/zero"]),
        &["/dev/zero", "64 KiB"],
    );
    let (_dir, scene) = scene_file(
        "format = 1\n[contact]\nkind = \"tractions\"\nmethod = \"numerical\"\n[tractions]\nfile = \"/dev/zero\"\n",
    );
    assert_fails_with(
        &run(&["check", scene.to_str().expect("utf8")]),
        &["key `tractions.file`", "256 MiB"],
    );
    assert_fails_with(
        &run(&[
            "surface",
            "/dev/zero",
            "--spacing",
            "1um",
            "--height-unit",
            "um",
        ]),
        &["/dev/zero"],
    );
    // Standard input too: a megabyte without a newline.
    let output = run_with_stdin(&["probe", "--points", "-"], &"7".repeat(1 << 20));
    assert_fails_with(&output, &["standard input", "64 KiB"]);
}

/// Case 10: every command prints through one path: a closed pipe ends quietly, a full disk is
/// an `error:` line with exit 1, and a full standard error is no panic.
#[test]
fn closed_pipes_end_quietly_and_full_disks_are_errors() {
    use std::io::Read;
    let points = "0,0,0.5\n".repeat(20_000);
    let scenes: Vec<String> = (0..1200)
        .map(|_| repo("scenes/line_tau1.toml").display().to_string())
        .collect();
    let mut check_args = vec!["check".to_string()];
    check_args.extend(scenes);
    let cases: [(Vec<String>, &str); 2] = [
        (
            ["probe", "--points", "-"].map(String::from).to_vec(),
            points.as_str(),
        ),
        (check_args, ""),
    ];
    for (args, input) in cases {
        let mut child = stressfield()
            .args(&args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("runs");
        let mut stdin = child.stdin.take().expect("stdin");
        let input = input.to_string();
        let writer = std::thread::spawn(move || {
            let _ = stdin.write_all(input.as_bytes());
        });
        // `| head -c 10`: read ten bytes, then close the pipe.
        let mut head = [0u8; 10];
        child
            .stdout
            .take()
            .expect("stdout")
            .read_exact(&mut head)
            .expect("ten bytes");
        let output = child.wait_with_output().expect("ends");
        writer.join().expect("writer");
        assert!(
            output.status.success(),
            "{}: {:?} {}",
            args[0],
            output.status,
            stderr(&output)
        );
        assert_eq!(stderr(&output), "", "{}", args[0]);
    }
    #[cfg(target_os = "linux")]
    {
        let full = || std::fs::File::create("/dev/full").expect("/dev/full");
        for args in [
            &["hertz", "scenes/line_tau1.toml"][..],
            &["check", "scenes/line_tau1.toml"][..],
            &["surface", "scenes/surface_worn_homework.toml"][..],
        ] {
            let output = stressfield()
                .args(args)
                .stdout(full())
                .output()
                .expect("runs");
            assert_eq!(output.status.code(), Some(1), "{args:?}");
            assert!(
                stderr(&output).starts_with("error: cannot write to standard output"),
                "{args:?}: {}",
                stderr(&output)
            );
        }
        let output = run_with_stdin(&["probe", "--points", "-"], "0,0,1\n");
        assert!(output.status.success());
        let output = stressfield()
            .args(["probe", "--points", "-"])
            .stdin(Stdio::null())
            .stderr(full())
            .output()
            .expect("runs");
        assert_eq!(output.status.code(), Some(1), "no panic on a full stderr");
    }
}

/// Case 12: a bad probe line is echoed in a few dozen characters, whatever its length.
#[test]
fn long_bad_probe_lines_are_cut_in_messages() {
    let line = format!("0,0,{}x\n", "9".repeat(60_000));
    let output = run_with_stdin(&["probe", "--points", "-"], &line);
    assert_fails_with(&output, &["line 1", "60005 characters", "not a number"]);
    assert!(stderr(&output).len() < 1000, "{}", stderr(&output).len());
    let output = run_with_stdin(&["probe", "--points", "-"], &"1".repeat(10 << 20));
    assert_fails_with(&output, &["line 1", "64 KiB"]);
    assert!(stderr(&output).len() < 1000);
}

/// Case 13: points farther than 1e9 a are refused for both contact kinds; nearer ones, however
/// far, give finite (vanishing) stresses.
#[test]
fn far_probe_points_are_refused_and_near_ones_are_finite() {
    for contact in ["line", "point"] {
        for point in ["1e79,0,1\n", "0,0,1e200\n", "0,-1e300,0\n"] {
            let output = run_with_stdin(&["probe", "--contact", contact, "--points", "-"], point);
            assert_fails_with(&output, &["line 1", "1e9 a"]);
        }
        let rows = probe_rows(
            &["probe", "--contact", contact, "--points", "-"],
            "1e9,0,1\n0,0,1e9\n-1e9,1e9,0\n",
        );
        assert_rows_finite(&rows);
        assert!(
            rows.iter().all(|r| r[3..].iter().all(|v| v.abs() < 1e-8)),
            "{rows:?}"
        );
    }
}

/// Cases 12 and 14: a traction table with a column named twice, a traction that overflows in
/// units of p0, and a grid too long along one side are refused, each naming what is wrong.
#[test]
fn bad_traction_tables_are_refused() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scene = dir.path().join("t.toml");
    std::fs::write(
        &scene,
        "format = 1\n[contact]\nkind = \"tractions\"\na = \"1 mm\"\np0 = \"1 GPa\"\nmethod = \"numerical\"\n[tractions]\nfile = \"t.csv\"\nlength_unit = \"mm\"\nstress_unit = \"MPa\"\n",
    )
    .expect("write scene");
    let scene = scene.to_str().expect("utf8");
    let grid = |p: &str| format!("0,0,1\n1,0,1\n0,1,{p}\n1,1,1\n");
    let long_grid: String = (0..20_000)
        .flat_map(|i| [format!("{i},0,1\n"), format!("{i},1,1\n")])
        .collect();
    let cases = [
        (
            format!("x,y,p,p\n{}", "0,0,1,2\n1,0,1,2\n0,1,1,2\n1,1,1,2\n"),
            vec!["`p` is named twice", "columns 3 and 4"],
        ),
        (
            format!("x,y,p\n{}", grid("1e308")),
            vec!["line 4", "p = 1e308 MPa", "1e12 p0"],
        ),
        (
            format!("x,y,p\n{long_grid}"),
            vec!["20000 x 2", "more than 4096 nodes along x"],
        ),
        (
            format!("x,y,p\n{}", "0,0,1\n1e300,0,1\n0,1,1\n1e300,1,1\n"),
            vec!["x = 1e300 mm", "10000 a"],
        ),
    ];
    for (csv, fragments) in cases {
        std::fs::write(dir.path().join("t.csv"), csv).expect("write csv");
        let mut fragments = fragments;
        fragments.push("key `tractions.file`");
        assert_fails_with(&run(&["check", scene]), &fragments);
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

#[cfg(feature = "rerun")]
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
