//! Regression runs of `render --compare`: the CI lines and summary, the HTML report (parsed),
//! the image measures, `--update`, field comparison, and a scene's outputs written all or none.

use std::path::{Path, PathBuf};
use std::process::Output;

use base64::Engine as _;

use crate::cli::{assert_fails_with, run, stderr, SMALL_SCENE};

fn utf8(path: &Path) -> &str {
    path.to_str().expect("utf8 path")
}

/// The file names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("list")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// A temporary directory with the scenes `a.toml` (SMALL_SCENE) and `b.toml` (τ1 of the same
/// contact).
struct Workspace {
    dir: tempfile::TempDir,
}

impl Workspace {
    fn new() -> Self {
        let dir = tempfile::tempdir().expect("temp dir");
        std::fs::write(dir.path().join("a.toml"), SMALL_SCENE).expect("write");
        std::fs::write(
            dir.path().join("b.toml"),
            SMALL_SCENE.replace("von_mises", "tau1"),
        )
        .expect("write");
        Self { dir }
    }

    fn path(&self, name: &str) -> PathBuf {
        self.dir.path().join(name)
    }

    /// `render a.toml b.toml --out-dir <out>` followed by `extra`.
    fn render(&self, out: &str, extra: &[&str]) -> Output {
        let (a, b, out) = (self.path("a.toml"), self.path("b.toml"), self.path(out));
        let mut args = vec!["render", utf8(&a), utf8(&b), "--out-dir", utf8(&out)];
        args.extend_from_slice(extra);
        run(&args)
    }

    /// Changes the friction of scene b (image and field move).
    fn change_b(&self, friction: &str) {
        std::fs::write(
            self.path("b.toml"),
            SMALL_SCENE
                .replace("von_mises", "tau1")
                .replace("friction = 0.2", &format!("friction = {friction}")),
        )
        .expect("write");
    }
}

fn assert_success(output: &Output) {
    assert!(output.status.success(), "{}", stderr(output));
}

/// The lines of stderr starting with `prefix`.
fn lines_starting(output: &Output, prefix: &str) -> Vec<String> {
    stderr(output)
        .lines()
        .filter(|l| l.starts_with(prefix))
        .map(str::to_string)
        .collect()
}

/// One scene of the report: its class, its name and the PNG bytes of its figures by caption.
struct ReportScene {
    class: String,
    name: String,
    text: String,
    images: Vec<(String, Vec<u8>)>,
}

/// Parses the report as XML (it is well-formed) and returns its scenes in page order.
fn parse_report(path: &Path) -> (String, Vec<ReportScene>) {
    let html = std::fs::read_to_string(path).expect("the report");
    let options = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..Default::default()
    };
    let document = roxmltree::Document::parse_with_options(&html, options)
        .unwrap_or_else(|e| panic!("the report is well-formed: {e}"));
    let root = document.root_element();
    assert_eq!(root.tag_name().name(), "html");
    let summary = root
        .descendants()
        .find(|n| n.attribute("class") == Some("summary"))
        .map(|n| n.descendants().filter_map(|t| t.text()).collect::<String>())
        .expect("a summary");
    let scenes = root
        .descendants()
        .filter(|n| n.tag_name().name() == "section")
        .map(|section| {
            let images = section
                .descendants()
                .filter(|n| n.tag_name().name() == "figure")
                .map(|figure| {
                    let caption = figure
                        .children()
                        .find(|n| n.tag_name().name() == "figcaption")
                        .and_then(|n| n.text())
                        .expect("caption")
                        .to_string();
                    let src = figure
                        .children()
                        .find(|n| n.tag_name().name() == "img")
                        .and_then(|n| n.attribute("src"))
                        .expect("img src");
                    let data = src
                        .strip_prefix("data:image/png;base64,")
                        .expect("embedded PNG");
                    let bytes = base64::engine::general_purpose::STANDARD
                        .decode(data)
                        .expect("base64");
                    (caption, bytes)
                })
                .collect();
            ReportScene {
                class: section.attribute("class").unwrap_or("").to_string(),
                name: section.attribute("id").unwrap_or("").to_string(),
                text: section
                    .descendants()
                    .filter_map(|n| n.text())
                    .collect::<Vec<_>>()
                    .join(" "),
                images,
            }
        })
        .collect();
    (summary, scenes)
}

#[test]
fn compare_reports_fails_and_updates_only_what_differs() {
    let ws = Workspace::new();
    // References, with their fields.
    assert_success(&ws.render("ref", &["--save-field"]));
    assert_eq!(names(&ws.path("ref")), ["a.npz", "a.png", "b.npz", "b.png"]);
    let reference = ws.path("ref");
    let reference = utf8(&reference);
    // An identical run passes, image and field, and says so.
    let same = ws.render("out", &["--compare", reference]);
    assert_success(&same);
    assert_eq!(lines_starting(&same, "pass ").len(), 2, "{}", stderr(&same));
    assert!(
        stderr(&same).contains("regression: 0 of 2 scene(s) differ"),
        "{}",
        stderr(&same)
    );
    assert!(
        stderr(&same).contains("field: largest difference 0 p0"),
        "{}",
        stderr(&same)
    );
    // Scene b changes: one FAIL line with its measures, the summary, exit 1, a diff image,
    // and the report with b first.
    ws.change_b("0.4");
    let report_dir = ws.path("report");
    let differs = ws.render(
        "out",
        &["--compare", reference, "--report", utf8(&report_dir)],
    );
    assert_fails_with(
        &differs,
        &[
            "regression: 1 of 2 scene(s) differ",
            "(0 updated, 1 passed): b",
        ],
    );
    let failing = lines_starting(&differs, "FAIL ");
    assert_eq!(failing.len(), 1, "{}", stderr(&differs));
    for fragment in [
        "FAIL b: image: ",
        "pixel(s) differ by more than 16 (limit 0)",
        "field: largest difference",
        "diff image",
    ] {
        assert!(
            failing[0].contains(fragment),
            "`{fragment}` in {}",
            failing[0]
        );
    }
    assert!(ws.path("out/b.diff.png").is_file() && !ws.path("out/a.diff.png").exists());
    let (summary, scenes) = parse_report(&report_dir.join("index.html"));
    assert!(summary.contains("1 failed"), "{summary}");
    assert_eq!(scenes.len(), 2);
    assert_eq!(
        (scenes[0].name.as_str(), scenes[0].class.as_str()),
        ("b", "scene fail"),
        "failures first"
    );
    assert_eq!(
        (scenes[1].name.as_str(), scenes[1].class.as_str()),
        ("a", "scene pass")
    );
    let captions: Vec<&str> = scenes[0].images.iter().map(|(c, _)| c.as_str()).collect();
    assert_eq!(captions, ["reference", "actual", "difference"]);
    // The embedded images are the reference, the output and a diff of the same size.
    let read = |path: &str| std::fs::read(ws.path(path)).expect("read");
    assert_eq!(scenes[0].images[0].1, read("ref/b.png"));
    assert_eq!(scenes[0].images[1].1, read("out/b.png"));
    let diff = image::load_from_memory(&scenes[0].images[2].1).expect("a PNG");
    let actual = image::load_from_memory(&read("out/b.png")).expect("a PNG");
    assert_eq!(
        (diff.width(), diff.height()),
        (actual.width(), actual.height())
    );
    for fragment in [
        "image (OUTSIDE tolerance)",
        "field (OUTSIDE tolerance): largest difference",
        "p0 in panel 0 at x/a = ",
    ] {
        assert!(
            scenes[0].text.contains(fragment),
            "`{fragment}` in {}",
            scenes[0].text
        );
    }
    assert!(
        scenes[1].text.contains("within tolerance"),
        "{}",
        scenes[1].text
    );

    // --update rewrites b (image and field) and leaves a untouched, byte for byte and in time.
    let a_before = (read("ref/a.png"), read("ref/a.npz"));
    let a_modified = std::fs::metadata(ws.path("ref/a.png"))
        .and_then(|m| m.modified())
        .expect("mtime");
    let updated = ws.render("out", &["--compare", reference, "--update"]);
    assert_success(&updated);
    let lines = lines_starting(&updated, "updated ");
    assert_eq!(lines.len(), 1, "{}", stderr(&updated));
    assert!(lines[0].starts_with("updated b: image: "), "{}", lines[0]);
    assert!(
        lines[0].contains(&format!("wrote {reference}/b.png, {reference}/b.npz")),
        "{}",
        lines[0]
    );
    assert!(
        stderr(&updated).contains("(1 updated, 1 passed)"),
        "{}",
        stderr(&updated)
    );
    assert_eq!(read("ref/b.png"), read("out/b.png"));
    assert_eq!((read("ref/a.png"), read("ref/a.npz")), a_before);
    assert_eq!(
        std::fs::metadata(ws.path("ref/a.png"))
            .and_then(|m| m.modified())
            .expect("mtime"),
        a_modified
    );
    assert_eq!(
        names(&ws.path("ref")),
        ["a.npz", "a.png", "b.npz", "b.png"],
        "no temporary files"
    );
    // Now everything passes, and the stale diff image is gone.
    assert_success(&ws.render("out", &["--compare", reference]));
    assert!(!ws.path("out/b.diff.png").exists());
    // A missing reference fails with a hint; --update creates it.
    std::fs::remove_file(ws.path("ref/a.png")).expect("remove");
    let missing = ws.render("out", &["--compare", reference]);
    assert_fails_with(
        &missing,
        &["FAIL a: no reference image", "--update creates it"],
    );
    let created = ws.render("out", &["--compare", reference, "--update"]);
    assert_success(&created);
    assert!(
        stderr(&created).contains(&format!("wrote {reference}/a.png")),
        "{}",
        stderr(&created)
    );
    assert_eq!(read("ref/a.png"), read("out/a.png"));
    // A scene within tolerance that lacks its field gains it with --update --save-field, its
    // image untouched.
    std::fs::remove_file(ws.path("ref/b.npz")).expect("remove");
    let b_png = read("ref/b.png");
    let gained = ws.render("out", &["--compare", reference, "--update", "--save-field"]);
    assert_success(&gained);
    let lines = lines_starting(&gained, "updated ");
    assert_eq!(lines.len(), 1, "{}", stderr(&gained));
    assert!(
        lines[0].ends_with(&format!("wrote {reference}/b.npz")),
        "{}",
        lines[0]
    );
    assert_eq!(read("ref/b.png"), b_png);
    assert_eq!(read("ref/b.npz"), read("out/b.npz"));
}

#[test]
fn the_image_measure_is_selectable() {
    let ws = Workspace::new();
    assert_success(&ws.render("ref", &[]));
    let before = image::open(ws.path("ref/b.png")).expect("png").to_rgb8();
    ws.change_b("0.25");
    assert_success(&ws.render("new", &[]));
    let after = image::open(ws.path("new/b.png")).expect("png").to_rgb8();
    let rms = stressfield::regression::compare::rms_difference(&after, &before);
    assert!(rms > 0.1, "the change shows: RMS {rms}");
    let reference = ws.path("ref");
    let reference = utf8(&reference);
    // matplotlib's RMS measure, on either side of the RMS the change makes.
    let above = format!("{}", rms * 1.01);
    let below = format!("{}", rms * 0.99);
    let passes = ws.render(
        "out",
        &[
            "--compare",
            reference,
            "--measure",
            "rms",
            "--rms-tolerance",
            &above,
        ],
    );
    assert_success(&passes);
    assert!(
        lines_starting(&passes, "pass b: image: RMS ").len() == 1,
        "{}",
        stderr(&passes)
    );
    let fails = ws.render(
        "out",
        &[
            "--compare",
            reference,
            "--measure",
            "rms",
            "--rms-tolerance",
            &below,
        ],
    );
    assert_fails_with(
        &fails,
        &[&format!("FAIL b: image: RMS {rms:.3} (limit {below})")],
    );
    // The per-pixel measure with a budget: the differing pixels counted at tolerance 16 decide.
    let strict = ws.render("out", &["--compare", reference]);
    let line = lines_starting(&strict, "FAIL b: ").join("");
    let differing: usize = line
        .split("image: ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("a pixel count in {line}"));
    let budget = differing.to_string();
    assert_success(&ws.render(
        "out",
        &["--compare", reference, "--max-differing-pixels", &budget],
    ));
    let short = (differing - 1).to_string();
    assert_fails_with(
        &ws.render(
            "out",
            &["--compare", reference, "--max-differing-pixels", &short],
        ),
        &["FAIL b: image: "],
    );
    // Flags of the other measure, or comparison flags without --compare, are refused.
    assert_fails_with(
        &ws.render("out", &["--compare", reference, "--rms-tolerance", "2"]),
        &["--rms-tolerance applies to --measure rms"],
    );
    assert_fails_with(
        &ws.render(
            "out",
            &[
                "--compare",
                reference,
                "--measure",
                "rms",
                "--tolerance",
                "3",
            ],
        ),
        &["--measure pixels"],
    );
    assert_fails_with(&ws.render("out", &["--update"]), &["--compare"]);
    assert_fails_with(
        &ws.render("ref", &["--compare", reference]),
        &["the same directory", "overwritten"],
    );
    assert_fails_with(
        &ws.render("out", &["--compare", utf8(&ws.path("nowhere"))]),
        &["does not exist", "--update"],
    );
}

/// σxx of a sliding line contact: the traction adds −2μ p0 x/a on the surface inside the
/// contact (Johnson 1985, eq. 7.19), so raising μ by 5e-4 moves σxx by 1e-3 p0 at x = ±a, z = 0
/// and less everywhere else.
#[test]
fn field_comparison_catches_a_change_of_1e_3_p0() {
    let scene = "format = 1\n[contact]\nkind = \"line\"\nfriction = 0.2\n[figure]\nquantity = \"sxx\"\nresolution = 81\nwidth = 300\n";
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("edge.toml");
    std::fs::write(&path, scene).expect("write");
    let render = |extra: &[&str]| {
        let mut args = vec!["render", utf8(&path), "--out-dir"];
        args.extend_from_slice(extra);
        run(&args)
    };
    let reference = dir.path().join("ref");
    assert_success(&render(&[utf8(&reference), "--save-field"]));
    let out = dir.path().join("out");
    let compare = [
        utf8(&out),
        "--compare",
        utf8(&reference),
        "--field-tolerance",
        "5e-4",
    ];
    let same = render(&compare);
    assert_success(&same);
    assert!(
        stderr(&same).contains("pass edge: image: 0 pixel(s) differ")
            && stderr(&same).contains("field: largest difference 0 p0"),
        "{}",
        stderr(&same)
    );
    // A lenient image measure leaves the verdict to the field (the subtitle, the marked
    // maximum and a contour label move by a few pixels: RMS about 8).
    std::fs::write(&path, scene.replace("0.2", "0.2005")).expect("write");
    let compare = [
        utf8(&out),
        "--compare",
        utf8(&reference),
        "--measure",
        "rms",
        "--rms-tolerance",
        "255",
        "--field-tolerance",
        "5e-4",
    ];
    let moved = render(&compare);
    assert_fails_with(&moved, &["FAIL edge: "]);
    let line = lines_starting(&moved, "FAIL edge: ").join("");
    assert!(line.contains("(limit 255)"), "the image passes: {line}");
    // The field check fails, with the largest difference and where it is.
    let field = line.split("field: ").nth(1).expect("a field check");
    let largest: f64 = field
        .strip_prefix("largest difference ")
        .and_then(|s| s.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("a number in {field}"));
    assert!((largest - 1e-3).abs() < 1e-6, "{line}");
    assert!(
        field.contains("p0 in panel 0 at x/a = -1, z/a = 0 ")
            || field.contains("p0 in panel 0 at x/a = 1, z/a = 0 "),
        "at a contact edge on the surface: {field}"
    );
    assert!(field.contains("(limit 5e-4 p0)"), "{field}");
    // The same change within a looser tolerance passes the field check.
    let loose = [
        utf8(&out),
        "--compare",
        utf8(&reference),
        "--measure",
        "rms",
        "--rms-tolerance",
        "255",
        "--field-tolerance",
        "2e-3",
    ];
    let within = render(&loose);
    assert_success(&within);
    assert!(
        stderr(&within).contains("(limit 2e-3 p0)"),
        "{}",
        stderr(&within)
    );
}

/// Issue 13, case 9: a run that fails part-way keeps nothing of the scene it was writing.
#[test]
fn a_scene_is_written_all_or_none() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scene = dir.path().join("case.toml");
    std::fs::write(&scene, SMALL_SCENE).expect("write");
    // The recording cannot be written: no PNG either.
    let out = dir.path().join("out");
    let missing = dir.path().join("not-a-dir").join("x.rrd");
    let output = run(&[
        "render",
        utf8(&scene),
        "--out-dir",
        utf8(&out),
        "--rrd",
        utf8(&missing),
    ]);
    assert_fails_with(&output, &["x.rrd"]);
    let left: Vec<String> = if out.exists() {
        names(&out)
    } else {
        Vec::new()
    };
    assert!(left.is_empty(), "left behind: {left:?}");
    // The SVG cannot be written (a directory is in its place): the PNG is not written either,
    // and an earlier PNG stays as it was.
    let out = dir.path().join("out2");
    std::fs::create_dir_all(out.join("case.svg")).expect("mkdir");
    std::fs::write(out.join("case.png"), b"earlier").expect("write");
    let output = run(&["render", utf8(&scene), "--out-dir", utf8(&out), "--svg"]);
    assert_fails_with(&output, &["case.svg", "it is a directory"]);
    assert_eq!(
        std::fs::read(out.join("case.png")).expect("read"),
        b"earlier"
    );
    assert_eq!(names(&out), ["case.png", "case.svg"], "no temporary files");
}

/// Without scene names, a recording scene is recorded as usual and not compared; the summary
/// counts it.
#[cfg(feature = "rerun")]
#[test]
fn recording_scenes_are_recorded_not_compared() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scenes = dir.path().join("scenes");
    std::fs::create_dir(&scenes).expect("mkdir");
    std::fs::write(scenes.join("figure.toml"), SMALL_SCENE).expect("write");
    std::fs::write(
        scenes.join("sweep.toml"),
        format!("{SMALL_SCENE}[sweep]\nparameter = \"friction\"\nvalues = [0.0, 0.3]\n"),
    )
    .expect("write");
    let render = |out: &str, extra: &[&str]| {
        let out = dir.path().join(out);
        let mut args = vec![
            "render",
            "--scenes-dir",
            utf8(&scenes),
            "--out-dir",
            utf8(&out),
        ];
        args.extend_from_slice(extra);
        run(&args)
    };
    let reference = dir.path().join("ref");
    assert_success(&render(
        "first",
        &["--compare", utf8(&reference), "--update"],
    ));
    assert_eq!(names(&reference), ["figure.png"], "only the figure");
    let output = render("out", &["--compare", utf8(&reference)]);
    assert_success(&output);
    assert!(
        stderr(&output).contains("regression: 0 of 1 scene(s) differ from the references in")
            && stderr(&output).contains("; 1 recording scene(s) recorded, not compared"),
        "{}",
        stderr(&output)
    );
    assert!(dir.path().join("out/sweep.rrd").is_file());
}
