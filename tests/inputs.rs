//! Hostile and unusual input files end to end (issue 24): reference archives declaring huge
//! arrays, number-and-unit flags in exponent notation, byte-order marks and units in scenes,
//! and causes said once.

use std::io::Write;

use crate::cli::{run, stderr, SMALL_SCENE};

/// A reference `.npz` of a few hundred bytes whose arrays declare shape (100000, 100000) (80 GB)
/// or (3000000000, 1): the comparison reports the scene as failed and names the member, the
/// report is written, and the process exits 1 instead of aborting.
#[test]
fn a_reference_declaring_a_huge_array_fails_its_scene_without_aborting() {
    let dir = tempfile::tempdir().expect("dir");
    let scene = dir.path().join("case.toml");
    std::fs::write(&scene, SMALL_SCENE).expect("scene");
    let (scene, refs) = (scene.to_str().expect("utf8"), dir.path().join("refs"));
    let refs = refs.to_str().expect("utf8");
    let made = run(&["render", scene, "--out-dir", refs, "--save-field"]);
    assert!(made.status.success(), "{}", stderr(&made));
    for shape in ["(100000, 100000)", "(3000000000, 1)"] {
        let mut forged = Vec::new();
        {
            let mut npz = zip::ZipWriter::new(std::io::Cursor::new(&mut forged));
            let options = zip::write::SimpleFileOptions::default();
            let dict = format!("{{'descr': '<f8', 'fortran_order': False, 'shape': {shape}, }}");
            let mut npy = b"\x93NUMPY\x01\x00".to_vec();
            npy.extend_from_slice(&(dict.len() as u16).to_le_bytes());
            npy.extend_from_slice(dict.as_bytes());
            npy.extend_from_slice(&[0; 8]);
            for name in ["values_0.npy", "horizontal_0.npy", "vertical_0.npy"] {
                npz.start_file(name, options).expect("entry");
                npz.write_all(&npy).expect("npy");
            }
            npz.finish().expect("zip");
        }
        assert!(forged.len() < 1024);
        std::fs::write(dir.path().join("refs/case.npz"), &forged).expect("forge");
        let report = dir.path().join("report");
        let report = report.to_str().expect("utf8");
        let output = run(&[
            "render",
            scene,
            "--out-dir",
            report,
            "--compare",
            refs,
            "--report",
            report,
        ]);
        let text = format!(
            "{}{}",
            stderr(&output),
            String::from_utf8_lossy(&output.stdout)
        );
        assert_eq!(output.status.code(), Some(1), "{text}");
        assert!(
            text.contains(&format!("values_0.npy: declares shape {shape}")),
            "{text}"
        );
        assert!(dir.path().join("report/index.html").exists());
    }
}

/// Exponent notation before a unit in the surface flags (class 9), and the same units as
/// scenes and file headers.
#[test]
fn surface_flags_take_exponents() {
    let dir = tempfile::tempdir().expect("dir");
    let path = dir.path().join("s.asc");
    let rows: Vec<String> = (0..16)
        .map(|j| {
            (0..16)
                .map(|i| format!("{}", ((i * 7 + j * 13) % 11) as f64 * 0.1))
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect();
    std::fs::write(&path, rows.join("\n")).expect("write");
    let path = path.to_str().expect("utf8");
    let output = run(&[
        "surface",
        path,
        "--spacing",
        "1e-6m",
        "--height-unit",
        "μm",
        "--e-star",
        "1.15e11Pa",
        "--hardness",
        "1e3HV",
        "--band",
        "2.5e-6m,8e-6 m",
        "--json",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let bad = run(&[
        "surface",
        path,
        "--spacing",
        "1e-6m",
        "--height-unit",
        "um",
        "--e-star",
        "1e3HV",
    ]);
    assert!(
        !bad.status.success() && stderr(&bad).contains("a hardness is not a modulus"),
        "{}",
        stderr(&bad)
    );
}

/// A scene saved with a byte-order mark, and lengths in pm and μm as files and flags take
/// them (classes 10 and 16).
#[test]
fn scenes_take_a_byte_order_mark_and_every_length_unit() {
    let dir = tempfile::tempdir().expect("dir");
    let path = dir.path().join("rough.toml");
    let scene = "\u{feff}format = 1\n[contact]\nkind = \"rough\"\nload = \"0.5 N\"\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n[surface.generate]\nsamples = 32\nspacing = \"0.5 μm\"\nhurst = 0.8\nrolloff = \"8e-6m\"\nrms_height = \"50000 pm\"\nsphere_radius = \"2 mm\"\n";
    std::fs::write(&path, scene).expect("write");
    let output = run(&["check", path.to_str().expect("utf8")]);
    assert!(output.status.success(), "{}", stderr(&output));
}

/// A missing file's cause is said once (class 16).
#[test]
fn a_missing_file_says_its_cause_once() {
    let output = run(&["surface", "no-such-surface.asc", "--spacing", "1um"]);
    let text = stderr(&output);
    assert!(!output.status.success());
    assert_eq!(text.matches("os error 2").count(), 1, "{text}");
}

/// `hertz` keeps the hardness scale the scene wrote (class 19): "700 HV", never "700 HB".
#[test]
fn hertz_reports_the_hardness_on_the_scale_written() {
    let dir = tempfile::tempdir().expect("dir");
    let scene = dir.path().join("hv.toml");
    std::fs::write(
        &scene,
        "format = 1\n[contact]\nkind = \"point\"\nload = \"300 N\"\nhardness = \"700 HV\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"6 mm\"\nmaterial = \"steel\"\n",
    )
    .expect("scene");
    let output = run(&["hertz", scene.to_str().expect("utf8")]);
    let text = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        text.contains("from 700 HV:") && !text.contains("HB"),
        "{text}"
    );
}

/// The README's probe example prints what the README shows (class 20).
#[test]
fn the_readmes_probe_example_prints_what_it_shows() {
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).expect("README");
    let command = "printf 'x,y,z\\n0,0,0.786\\n-1,0,0\\n' | stressfield probe --friction 0.3 --points -\n```\n```\n";
    let at = readme.find(command).expect("the example is in the README") + command.len();
    let shown = &readme[at..at + readme[at..].find("```").expect("block end")];
    let output = crate::cli::run_with_stdin(
        &["probe", "--friction", "0.3", "--points", "-"],
        "x,y,z\n0,0,0.786\n-1,0,0\n",
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(String::from_utf8_lossy(&output.stdout), shown);
}

/// With E*, `surface` prints the Greenwood-Williamson values the README promises (class 20).
#[test]
fn surface_prints_the_greenwood_williamson_values() {
    let scene = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/surface_worn_homework.toml"
    );
    let text = run(&["surface", scene]);
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(
        text.contains("Greenwood-Williamson") && text.contains("(zs+0σs)"),
        "{text}"
    );
    let json = run(&["surface", scene, "--json"]);
    let json: serde_json::Value = serde_json::from_slice(&json.stdout).expect("json");
    let rows = json["greenwood_williamson"].as_array().expect("rows");
    assert_eq!(rows.len(), 4);
    assert!(rows[3]["pressure_pa"].as_f64().expect("pressure") > 0.0);
}

/// Generator defaults fit the samples given (class 15): `samples = 12` without roll-off or
/// cutoff is accepted; a conflict names the key the user gave and the default it met.
#[test]
fn generator_defaults_fit_the_samples_given() {
    let dir = tempfile::tempdir().expect("dir");
    let scene = |extra: &str| {
        let path = dir.path().join("gen.toml");
        std::fs::write(
            &path,
            format!("format = 1\n[contact]\nkind = \"surface\"\n[surface.generate]\nsamples = 12\nspacing = \"1 um\"\nhurst = 0.8\nrms_height = \"0.1 um\"\n{extra}"),
        )
        .expect("scene");
        run(&["check", path.to_str().expect("utf8")])
    };
    for extra in ["", "cutoff = \"5 um\"\n"] {
        let output = scene(extra);
        assert!(output.status.success(), "{extra}: {}", stderr(&output));
    }
    let short = scene("rolloff = \"1 um\"\n");
    assert!(
        stderr(&short).contains("key `surface.generate.rolloff`")
            && stderr(&short).contains("two sample spacings"),
        "{}",
        stderr(&short)
    );
    let long = scene("cutoff = \"20 um\"\n");
    assert!(
        stderr(&long).contains("key `surface.generate.cutoff`"),
        "{}",
        stderr(&long)
    );
}

/// Statistics that mean nothing are `null` with a reason (class 11): Rsk and Rku of rows flat
/// to rounding, a Hurst exponent outside (0, 1], the Hertz asperity of a tip too flat for the
/// map.
#[test]
fn meaningless_statistics_are_null_with_a_reason() {
    let dir = tempfile::tempdir().expect("dir");
    let surface = |name: &str, height: &dyn Fn(usize, usize) -> f64| {
        let path = dir.path().join(name);
        let text: String = (0..32)
            .map(|j| {
                let row: Vec<String> = (0..32).map(|i| format!("{:.9}", height(i, j))).collect();
                row.join(" ") + "\n"
            })
            .collect();
        std::fs::write(&path, text).expect("surface");
        let args = [
            "surface",
            path.to_str().expect("utf8"),
            "--spacing",
            "0.5um",
        ];
        let flags = ["--height-unit", "um", "--e-star", "115GPa"];
        let text = run(&[&args[..], &flags[..]].concat());
        let json = run(&[&args[..], &flags[..], &["--json"]].concat());
        assert!(json.status.success(), "{}", stderr(&json));
        let json: serde_json::Value = serde_json::from_slice(&json.stdout).expect("json");
        (String::from_utf8_lossy(&text.stdout).into_owned(), json)
    };
    let (text, json) = surface("rows.asc", &|_, j| {
        0.1 * (j % 5) as f64 + 0.01 * (j % 3) as f64
    });
    assert!(json["Rsk"].is_null() && json["Rku"].is_null(), "{json}");
    assert!(
        json["hurst"].is_null() && json["fractal_dimension"].is_null(),
        "{json}"
    );
    assert!(
        text.contains("n/a: Rsk, Rku: 32 of 32 rows are flat"),
        "{text}"
    );
    assert!(text.contains("n/a: hurst, fractal_dimension"), "{text}");
    // No summit on rows flat along x: the measured summit statistics are null, not inf or -0.
    assert_eq!(json["summits"], 0, "{json}");
    assert!(
        json["summit_height_std_m"].is_null() && json["summit_mean_height_m"].is_null(),
        "{json}"
    );
    assert!(text.contains("n/a: summit_radius_m"), "{text}");
    assert!(!text.contains("inf"), "{text}");
    // The highest sample 1e-5 um above its neighbours along x: a tip radius of about 1 cm.
    let (text, json) = surface("tip.asc", &|i, j| match (i, j) {
        (16, 16) => 1.00001,
        (15 | 17, 16) => 1.0,
        _ => 0.1 * ((7 * i + 3 * j) % 5) as f64,
    });
    assert!(
        json["asperity_radius_m"].is_null() && json["asperity_load_n"].is_null(),
        "{json}"
    );
    assert!(text.contains("n/a: asperity"), "{text}");
}

/// Class 13: one policy for every output path (`io::output::target`). `--heights` (and every
/// other output) through a link to /dev/full fails with the device's error instead of
/// replacing the link and exiting 0; through a link to a file it replaces the file and keeps
/// the link; `render`'s figure through a link does the same.
#[cfg(unix)]
#[test]
fn outputs_follow_links_and_report_device_errors() {
    let dir = tempfile::tempdir().expect("dir");
    let is_link = |path: &std::path::Path| {
        std::fs::symlink_metadata(path)
            .expect("exists")
            .file_type()
            .is_symlink()
    };
    if std::path::Path::new("/dev/full").exists() {
        let full = dir.path().join("full.npy");
        std::os::unix::fs::symlink("/dev/full", &full).expect("symlink");
        let output = run(&[
            "surface",
            "scenes/surfaces/worn.asc",
            "--heights",
            full.to_str().expect("utf8"),
        ]);
        assert!(!output.status.success());
        assert!(
            stderr(&output).contains("No space left"),
            "{}",
            stderr(&output)
        );
        assert!(is_link(&full), "the link is kept");
    }
    let real = dir.path().join("real.npy");
    std::fs::write(&real, b"old").expect("write");
    let link = dir.path().join("link.npy");
    std::os::unix::fs::symlink(&real, &link).expect("symlink");
    let output = run(&[
        "surface",
        "scenes/surfaces/worn.asc",
        "--heights",
        link.to_str().expect("utf8"),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(is_link(&link));
    assert!(std::fs::read(&real)
        .expect("read")
        .starts_with(b"\x93NUMPY"));

    let scene = dir.path().join("case.toml");
    std::fs::write(&scene, SMALL_SCENE).expect("scene");
    let out = dir.path().join("out");
    std::fs::create_dir(&out).expect("mkdir");
    let figure = dir.path().join("figure.png");
    std::os::unix::fs::symlink(&figure, out.join("case.png")).expect("symlink");
    std::fs::write(&figure, b"old").expect("write");
    let output = run(&[
        "render",
        scene.to_str().expect("utf8"),
        "--out-dir",
        out.to_str().expect("utf8"),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(is_link(&out.join("case.png")));
    assert!(std::fs::read(&figure)
        .expect("read")
        .starts_with(b"\x89PNG"));
}

/// Class 6: a periodic approach that closes the gap everywhere is refused by `check` as full
/// contact (it used to run 5000 iterations to "did not converge"), and each load of a rough
/// sweep is held to the scene's own limits (1e12 N passed `check` and failed in `record`).
#[test]
fn rough_controls_beyond_any_solution_are_refused_at_check() {
    let dir = tempfile::tempdir().expect("dir");
    let worn = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/surfaces/worn.asc");
    let scene = |name: &str, control: &str, sweep: &str| {
        let path = dir.path().join(name);
        let text = format!(
            "format = 1\n[contact]\nkind = \"rough\"\n{control}\nperiodic = true\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n[surface]\nfile = \"{worn}\"\n{sweep}"
        );
        std::fs::write(&path, text).expect("scene");
        path
    };
    let check = |path: &std::path::Path| run(&["check", path.to_str().expect("utf8")]);
    let closing = scene("closing.toml", "approach = \"0.8 um\"", "");
    let output = check(&closing);
    assert_eq!(output.status.code(), Some(1));
    let message = stderr(&output);
    assert!(
        message.contains("contact.approach") && message.contains("full contact"),
        "{message}"
    );
    let reaching = scene("reaching.toml", "approach = \"0.5 um\"", "");
    let output = check(&reaching);
    assert!(output.status.success(), "{}", stderr(&output));
    let sweep = scene(
        "sweep.toml",
        "load = \"1 N\"",
        "[sweep]\nparameter = \"load\"\nvalues = [\"1 N\", \"1e12 N\"]\n",
    );
    let output = check(&sweep);
    assert_eq!(output.status.code(), Some(1));
    let message = stderr(&output);
    assert!(
        message.contains("sweep.values[1]") && message.contains("combined modulus"),
        "{message}"
    );
}

/// Class 4: a periodic rough scene on a map 1024 times longer than wide is refused by `check`
/// naming `contact.periodic` (it took 44 s and 4.6 GB to solve).
#[test]
fn a_periodic_strip_is_refused_at_check() {
    let dir = tempfile::tempdir().expect("dir");
    let path = dir.path().join("strip.toml");
    std::fs::write(
        &path,
        "format = 1\n[contact]\nkind = \"rough\"\nmean_pressure = \"1 GPa\"\nperiodic = true\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"rigid\"\n[surface.generate]\nsamples = [8, 8192]\nspacing = \"1 um\"\nhurst = 0.8\nrolloff = \"8 um\"\ncutoff = \"4 um\"\nrms_slope = 0.1\n",
    )
    .expect("scene");
    let output = run(&["check", path.to_str().expect("utf8")]);
    assert_eq!(output.status.code(), Some(1));
    let message = stderr(&output);
    assert!(
        message.contains("contact.periodic") && message.contains("1024 times longer"),
        "{message}"
    );
}

/// `[[panel]] section` (issue 23, item 13): a panel's own plane, refused where it cannot be
/// drawn, each error naming the key and the fix; and a figure of xz, yz and xy panels accepted.
#[test]
fn a_panels_section_is_refused_naming_the_key_and_the_fix() {
    const POINT: &str = "format = 1\n[contact]\nkind = \"point\"\n";
    const THERMAL: &str = "format = 1\n[contact]\nkind = \"point\"\nload = \"50 N\"\nfriction = 0.1\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"10 mm\"\nmaterial = \"steel\"\n[thermal]\nspeed = \"1 m/s\"\npartition = \"blok\"\n[sweep]\nparameter = \"peclet\"\nfrom = 0.1\nto = 10.0\nsteps = 3\n";
    const ROUGH: &str = "format = 1\n[contact]\nkind = \"rough\"\nload = \"0.5 N\"\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n[surface.generate]\nsamples = 32\nspacing = \"0.5 um\"\nhurst = 0.8\nrolloff = \"8 um\"\nrms_height = \"0.05 um\"\nsphere_radius = \"2 mm\"\n";
    let cases: &[(String, &[&str])] = &[
        (
            format!("{POINT}[[panel]]\n[[panel]]\nsection = \"xq\"\n"),
            &["key `panel[1].section`", "unknown section `xq`", "\"yz\" (depth across it)"],
        ),
        (
            "format = 1\n[contact]\nkind = \"line\"\n[[panel]]\nsection = \"yz\"\n".into(),
            &["key `panel[0].section`", "plane strain", "kind = \"point\""],
        ),
        // figure.at is a y: a yz panel needs its own x.
        (
            format!("{POINT}[figure]\nat = 0.5\n[[panel]]\n[[panel]]\nsection = \"yz\"\n"),
            &["key `panel[1].at`", "figure.at is the y of the figure's xz sections", "give panel[1].at, the x of the yz section"],
        ),
        // A panel's position along its own plane's normal.
        (
            format!("{POINT}[figure]\nsection = \"xy\"\nat = 0.5\n[[panel]]\nsection = \"xz\"\nat = nan\n"),
            &["key `panel[0].at`", "must be a finite y"],
        ),
        (
            format!("{POINT}[[panel]]\nsection = \"xy\"\nat = -0.5\n"),
            &["key `panel[0].at`", "z points into the body", "0 is the surface"],
        ),
        // The yz section's shape, checked with its own ranges.
        (
            format!("{POINT}[figure]\ny = [-0.005, 0.005]\nz = [0.0, 1.0]\n[[panel]]\n[[panel]]\nsection = \"yz\"\n"),
            &["key `figure.z`", "the yz section would be drawn 100 times as tall"],
        ),
        (
            format!("{POINT}[sweep]\nparameter = \"position\"\nvalues = [0.0, 1.0]\nmaterial_points = [[0.0, 0.5]]\n[[panel]]\n[[panel]]\nsection = \"yz\"\n"),
            &["key `panel[1].section`", "material points (x, z) lie in xz sections", "remove panel[1].section"],
        ),
        (
            format!("{THERMAL}[[panel]]\nsection = \"xz\"\n"),
            &["key `panel[0].section`", "Péclet sweep records its own sections", "scene without [sweep]"],
        ),
        (
            format!("{ROUGH}[[panel]]\nsection = \"yz\"\n"),
            &["key `panel[0].section`", "chooses its own sections", "kind = \"point\" or \"elliptical\""],
        ),
    ];
    let dir = tempfile::tempdir().expect("dir");
    for (k, (text, fragments)) in cases.iter().enumerate() {
        let path = dir.path().join(format!("case{k}.toml"));
        std::fs::write(&path, text).expect("scene");
        crate::cli::assert_fails_with(&run(&["check", path.to_str().expect("utf8")]), fragments);
    }
    // Each panel in its own plane, y drawn by the yz panel.
    let path = dir.path().join("mixed.toml");
    std::fs::write(
        &path,
        format!("{POINT}[figure]\ny = [-1.0, 1.0]\n[[panel]]\n[[panel]]\nsection = \"yz\"\nat = 0.3\n[[panel]]\nsection = \"xy\"\nat = 0.5\n"),
    )
    .expect("scene");
    let output = run(&["check", path.to_str().expect("utf8")]);
    assert!(output.status.success(), "{}", stderr(&output));
}

// Issue 42: the heating surface ([thermal]) refuses what it cannot do.

/// A steel ball (radius 6.35 mm) on a steel flat under 20 N, μ = 0.2, with `thermal` as the
/// body of its `[thermal]` table.
fn heated_point(thermal: &str) -> String {
    format!(
        "format = 1\n[contact]\nkind = \"point\"\nload = \"20 N\"\nfriction = 0.2\n[contact.body1]\nradius = \"6.35 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n[thermal]\n{thermal}\n"
    )
}

/// Issue 42, class 3: the sliding speed is |V1 - V2|. A `speed` that disagrees with the
/// bodies' speeds is refused naming the keys (equal speeds: no sliding at all), the bodies'
/// speeds alone give it, and when body 2's surface is the faster friction on body 1 acts in
/// -x (the report says so; the contact stress of the study is mirrored).
#[test]
fn contradictory_speeds_are_refused_and_the_sliding_speed_is_their_difference() {
    use stressfield::scene::TractionDirection;
    let refused = [
        (
            "speed = \"3 m/s\"\nbody1_speed = \"1 m/s\"\nbody2_speed = \"1 m/s\"",
            "thermal.speed",
            "slide at |V1 - V2| = 0 m/s",
        ),
        (
            "speed = \"1 m/s\"\nbody1_speed = \"0 m/s\"\nbody2_speed = \"1.5 m/s\"",
            "thermal.speed",
            "|V1 - V2| = 1.5 m/s",
        ),
        // body1_speed defaults to speed: 1 and 1 do not slide.
        (
            "speed = \"1 m/s\"\nbody2_speed = \"1 m/s\"",
            "thermal.speed",
            "thermal.speed, as body1_speed is not given",
        ),
        (
            "body1_speed = \"0.7 m/s\"\nbody2_speed = \"0.7 m/s\"",
            "thermal.body2_speed",
            "the surfaces do not slide",
        ),
        (
            "body2_speed = \"0.7 m/s\"",
            "thermal.body1_speed",
            "missing the speed of the contact over body 1",
        ),
    ];
    for (thermal, key, fragment) in refused {
        let error = stressfield::study::parse_scene(&heated_point(thermal), "t", "t.toml")
            .expect_err(thermal);
        assert_eq!(error.key.as_deref(), Some(key), "{thermal}: {error}");
        assert!(error.to_string().contains(fragment), "{thermal}: {error}");
    }
    let spec = |thermal: &str| {
        stressfield::study::parse_scene(&heated_point(thermal), "t", "t.toml")
            .unwrap_or_else(|e| panic!("{thermal}: {e}"))
            .thermal
            .expect("[thermal]")
    };
    // Derived, and agreeing.
    let slow_over_body1 = spec("body1_speed = \"0.25 m/s\"\nbody2_speed = \"1 m/s\"");
    assert_eq!(slow_over_body1.sliding_speed_m_per_s, 0.75);
    assert_eq!(slow_over_body1.traction, TractionDirection::MinusX);
    let agreeing =
        spec("speed = \"0.75 m/s\"\nbody1_speed = \"1 m/s\"\nbody2_speed = \"0.25 m/s\"");
    assert_eq!(agreeing.sliding_speed_m_per_s, 0.75);
    assert_eq!(agreeing.traction, TractionDirection::PlusX);
    assert_eq!(spec("speed = \"2 m/s\"").traction, TractionDirection::PlusX);

    // Body 2 sliding over a stationary body 1 (q in -x), and body 1 over a stationary body 2
    // at the same speed (q in +x): the contact stress alone is mirrored (the same materials,
    // so the same grid).
    let study = |thermal: &str| {
        let scene =
            stressfield::study::parse_scene(&heated_point(thermal), "t", "t.toml").expect("valid");
        stressfield::study::thermal::study(&scene, None, &mut |_| {}).expect("study")
    };
    let minus = study("body1_speed = \"0 m/s\"\nbody2_speed = \"0.5 m/s\"");
    let plus = study("body1_speed = \"0.5 m/s\"\nbody2_speed = \"0 m/s\"");
    assert_eq!(minus.shape, plus.shape);
    let (xm, xp) = (minus.contact_von_mises.x_m, plus.contact_von_mises.x_m);
    assert!(xp.abs() > 2.0 * plus.spacing_m[0], "off the axis: {xp}");
    assert!(
        (xm + xp).abs() <= 1.01 * plus.spacing_m[0],
        "mirrored: {xm} against {xp}"
    );
    assert!(
        (minus.contact_von_mises.value_pa / plus.contact_von_mises.value_pa - 1.0).abs() < 1e-2
    );
    let report = stressfield::report::thermal::ThermalReport::new(&minus);
    assert_eq!(report.traction_on_body1, "-x");
    assert!(report
        .text(&minus)
        .contains("friction on body 1 acts in -x"));
}

/// Spur gears `[contact.gears]` with these teeth and pressure angle, 40 kN/m, steel.
fn gears(teeth: &str, angle: &str, thermal: &str) -> String {
    format!(
        "format = 1\n[contact]\nkind = \"line\"\nload = \"40 kN/m\"\n[contact.gears]\nmodule = \"5 mm\"\nteeth = [{teeth}]\npressure_angle = \"{angle}\"\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n{thermal}"
    )
}

/// Issue 42, class 7: pointed teeth (a pressure angle near 90 deg gave a contact ratio of 365)
/// and interfering teeth are refused by `[contact.gears]` itself, with or without
/// `[thermal]`, naming the key and the limit for these teeth.
#[test]
fn pointed_or_interfering_teeth_are_refused_with_the_limit() {
    let running = "[thermal]\npinion_speed = \"1500 rpm\"\nfriction = 0.05\n";
    let cases = [
        (
            "20, 40",
            "60 deg",
            "",
            "contact.gears.pressure_angle",
            "must be below 36.0 deg",
        ),
        (
            "30, 90",
            "1.2 rad",
            running,
            "contact.gears.pressure_angle",
            "are pointed",
        ),
        (
            "12, 200",
            "20 deg",
            "",
            "contact.gears.teeth",
            "at least 17 teeth",
        ),
        (
            "10, 60",
            "20 deg",
            running,
            "contact.gears.teeth",
            "the teeth interfere",
        ),
    ];
    for (teeth, angle, thermal, key, fragment) in cases {
        let error = stressfield::study::parse_scene(&gears(teeth, angle, thermal), "g", "g.toml")
            .expect_err(angle);
        assert_eq!(
            error.key.as_deref(),
            Some(key),
            "{teeth} at {angle}: {error}"
        );
        assert!(
            error.to_string().contains(fragment),
            "{teeth} at {angle}: {error}"
        );
    }
    for (teeth, angle) in [
        ("20, 40", "20 deg"),
        ("17, 80", "20 deg"),
        ("20, 40", "30 deg"),
    ] {
        stressfield::study::parse_scene(&gears(teeth, angle, running), "g", "g.toml")
            .unwrap_or_else(|e| panic!("{teeth} at {angle}: {e}"));
    }
}

/// Issue 42, class 8: equivalent spellings of the heat partition mean the same. A line
/// contact whose body 2 stays under the contact takes `partition = 1.0` (and `1`, `"1"`,
/// `"Body1"`) as it takes `"body1"`: all heat into body 1, body 2's speed not needed; a
/// fraction below 1 still needs body 2's speed.
#[test]
fn equivalent_partitions_are_accepted_alike() {
    let line = |partition: &str| {
        format!(
            "format = 1\n[contact]\nkind = \"line\"\nload = \"100 kN/m\"\nfriction = 0.1\n[contact.body1]\nradius = \"20 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"flat\"\nmaterial = \"steel\"\n[thermal]\nspeed = \"1 m/s\"\npartition = {partition}\n"
        )
    };
    let mut specs = Vec::new();
    for partition in ["\"body1\"", "1.0", "1", "\"1\"", "\" Body1 \""] {
        let scene = stressfield::study::parse_scene(&line(partition), "l", "l.toml")
            .unwrap_or_else(|e| panic!("partition = {partition}: {e}"));
        specs.push(scene.thermal.expect("[thermal]"));
    }
    assert!(specs.iter().all(|s| *s == specs[0]), "{specs:?}");
    assert_eq!(
        specs[0].partition,
        stressfield::thermal::heating::Partition::Body1
    );
    for partition in ["0.5", "\"BLOK\""] {
        let error =
            stressfield::study::parse_scene(&line(partition), "l", "l.toml").expect_err(partition);
        assert_eq!(error.key.as_deref(), Some("thermal.body2_speed"), "{error}");
    }
}

/// Issue 42, class 10: a value of the wrong kind is refused in the user's words: what the key
/// takes, never a Rust type (`untagged enum NumberOrText`, `struct RawThermal`, `f64`).
#[test]
fn wrong_kinds_of_values_are_refused_in_the_users_words() {
    let point = heated_point("speed = \"1 m/s\"");
    let cases = [
        (
            point.replace("speed = \"1 m/s\"", "speed = \"1 m/s\"\npartition = false"),
            "a fraction from 0 to 1, \"body1\" or \"blok\"",
        ),
        (
            point.replace("speed = \"1 m/s\"", "speed = \"1 m/s\"\npartition = [0.5]"),
            "a fraction from 0 to 1, \"body1\" or \"blok\"",
        ),
        (
            point
                .replace("[thermal]\nspeed = \"1 m/s\"\n", "")
                .replace("format = 1\n", "format = 1\nthermal = \"fast\"\n"),
            "expected a table: [thermal] on a line of its own",
        ),
        (
            point.replace("friction = 0.2", "friction = \"lots\""),
            "expected a number",
        ),
        (
            point.replace(
                "[thermal]\nspeed = \"1 m/s\"\n",
                "[thermal]\nspeed = \"1 m/s\"\ncoupled = \"yes\"\n",
            ),
            "expected true or false",
        ),
        (
            "format = 1\n[contact]\nkind = \"point\"\na = true\np0 = 1\n".to_string(),
            "expected a number, or a text with its unit",
        ),
    ];
    for (text, fragment) in cases {
        let error = stressfield::study::parse_scene(&text, "t", "t.toml").expect_err(fragment);
        let message = error.to_string();
        assert!(message.contains(fragment), "{message}\n{text}");
        for internal in ["untagged", "NumberOrText", "struct Raw", "f64", "variant"] {
            assert!(!message.contains(internal), "{message}");
        }
    }
}

/// Issue 42, class 11: `[thermal]` on a contact without a load and bodies gets one hint that
/// leads out (a load and two bodies with radius and material), the same for a normalised
/// contact and one given by a and p0; following it gives a valid scene.
#[test]
fn the_heating_hint_leads_out_in_one_step() {
    let thermal = "[thermal]\nspeed = \"1 m/s\"\n";
    let scenes = [
        format!("format = 1\n[contact]\nkind = \"point\"\nfriction = 0.2\n{thermal}"),
        format!("format = 1\n[contact]\nkind = \"line\"\na = \"0.2 mm\"\np0 = \"1 GPa\"\nfriction = 0.2\n{thermal}"),
        format!("format = 1\n[contact]\nkind = \"elliptical\"\naspect = 0.5\na = \"0.2 mm\"\np0 = \"1 GPa\"\nfriction = 0.2\n[contact.body1]\nmaterial = \"steel\"\n{thermal}"),
    ];
    for text in &scenes {
        let error = stressfield::study::parse_scene(text, "t", "t.toml").expect_err(text);
        assert_eq!(error.key.as_deref(), Some("thermal"), "{error}");
        let hint = error.hint.clone().unwrap_or_default();
        assert!(
            error.message.contains("needs a load and two bodies")
                && hint.contains("contact.load")
                && hint.contains("[contact.body1] and [contact.body2]")
                && hint.contains("radius and material"),
            "{error}"
        );
    }
    // The hint followed.
    stressfield::study::parse_scene(&heated_point("speed = \"1 m/s\""), "t", "t.toml")
        .expect("a load and two bodies");
}

/// Issue 42, class 9: keys that a command would ignore are refused, naming them: `[[panel]]`
/// in a Péclet sweep, a repeated sweep value or `from = to` (several steps at one point of the
/// recording), `[thermal]` with a friction, load or position sweep, and `record` of a heated
/// scene without a Péclet sweep (one state, or a volume).
#[test]
fn keys_a_recording_would_ignore_are_refused() {
    let speed_sweep = |sweep: &str| {
        format!(
            "{}[sweep]\nparameter = \"peclet\"\n{sweep}\n",
            heated_point("speed = \"1 m/s\"\npartition = \"blok\"")
        )
    };
    let cases = [
        (
            speed_sweep("from = 0.1\nto = 10.0\nsteps = 3\n[[panel]]\nfriction = 0.3"),
            "panel[0]",
            "would be ignored",
        ),
        (speed_sweep("values = [0.5, 2.0, 0.5]"), "sweep.values[2]", "repeats sweep.values[0]"),
        (speed_sweep("from = 3.0\nto = 3.0\nsteps = 4"), "sweep.to", "from and to are both 3"),
        (
            format!(
                "{}[sweep]\nparameter = \"load\"\nvalues = [\"10 N\", \"20 N\"]\n[figure]\nlength_unit = \"mm\"\nstress_unit = \"MPa\"\n",
                heated_point("speed = \"1 m/s\"")
            ),
            "thermal",
            "a load sweep records the contact's stress field without heating",
        ),
        (
            "format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"friction\"\nvalues = [0.1, 0.2, 0.1]\n".to_string(),
            "sweep.values[2]",
            "repeats sweep.values[0]",
        ),
    ];
    for (text, key, fragment) in &cases {
        let error = stressfield::study::parse_scene(text, "t", "t.toml").expect_err(key);
        assert_eq!(error.key.as_deref(), Some(*key), "{error}\n{text}");
        assert!(error.to_string().contains(fragment), "{error}");
    }
    // A heated scene of one state, and one with a volume: record refuses, naming [thermal].
    let dir = tempfile::tempdir().expect("dir");
    let volume = format!(
        "{}[volume]\npoints = 8\n",
        heated_point("speed = \"1 m/s\"")
    );
    for (k, text) in [heated_point("speed = \"1 m/s\""), volume]
        .iter()
        .enumerate()
    {
        let path = dir.path().join(format!("heated{k}.toml"));
        std::fs::write(&path, text).expect("scene");
        let rrd = dir.path().join(format!("heated{k}.rrd"));
        crate::cli::assert_fails_with(
            &run(&[
                "record",
                path.to_str().expect("utf8"),
                "-o",
                rrd.to_str().expect("utf8"),
            ]),
            &[
                "key `thermal`",
                "would be left out",
                "parameter = \"peclet\"",
            ],
        );
        assert!(!rrd.exists());
    }
}

/// The shipped ball on a coated disc (coupled, all heat into the stationary ball) with body 1's
/// `extra` thermal keys.
fn ball_on_disc(extra: &str) -> String {
    std::fs::read_to_string(crate::cli::repo("scenes/thermal_ball_on_disc.toml"))
        .expect("shipped scene")
        .replace(
            "material = \"steel\"\n",
            &format!("material = \"steel\"\n{extra}"),
        )
}

/// Issue 42, class 1: a coupled contact that runs away is an error naming `thermal.coupled`
/// and what happened, with the last resolved state, never a converged solution: a ball whose
/// expansion is 20 to 90 times steel's (the contact shrank below a tenth of its area, and to
/// one cell, while reported as converged); one so poorly conducting that the isothermal
/// pressure already heats it beyond any solid; the shipped scene still converges.
#[test]
fn a_thermoelastic_runaway_is_an_error_not_a_converged_solution() {
    use stressfield::study::coupled::{
        CoupledError, MAX_FLASH_TEMPERATURE_RISE_K, MIN_AREA_FRACTION,
    };
    use stressfield::study::thermal::ThermalStudyError;
    let study = |text: &str| {
        let scene = stressfield::study::parse_scene(text, "b", "b.toml").expect("valid scene");
        stressfield::study::thermal::study(&scene, None, &mut |_| {})
    };
    for expansion in ["2.5e-4 /K", "1e-3 /K"] {
        let text = ball_on_disc(&format!(
            "conductivity = \"20 W/(m K)\"\nexpansion = \"{expansion}\"\n"
        ));
        match study(&text) {
            Err(ThermalStudyError::Coupled(CoupledError::Runaway(runaway))) => {
                let (at, last, isothermal) = (runaway.at, runaway.last, runaway.isothermal);
                assert!(
                    at.iteration > 0 && at.area_fraction < MIN_AREA_FRACTION,
                    "{at:?}"
                );
                assert!(last.iteration < at.iteration && last.area_fraction >= MIN_AREA_FRACTION);
                assert_eq!(isothermal.iteration, 0);
            }
            other => panic!("{expansion}: {other:?}"),
        }
    }
    match study(&ball_on_disc("conductivity = \"1 W/(m K)\"\n")) {
        Err(ThermalStudyError::Coupled(CoupledError::BeyondAnySolid { isothermal })) => {
            assert!(isothermal.max_temperature_rise_k > MAX_FLASH_TEMPERATURE_RISE_K);
        }
        other => panic!("{other:?}"),
    }
    let shipped = study(&ball_on_disc("")).expect("the shipped scene converges");
    let coupled = shipped.coupled.expect("coupled");
    assert!(coupled.iterations < 20);
    // On the command line: exit 1, the key, what happened and the last resolved state.
    let dir = tempfile::tempdir().expect("dir");
    let path = dir.path().join("runaway.toml");
    std::fs::write(
        &path,
        ball_on_disc("conductivity = \"20 W/(m K)\"\nexpansion = \"5e-4 /K\"\n"),
    )
    .expect("scene");
    crate::cli::assert_fails_with(
        &run(&["thermal", path.to_str().expect("utf8")]),
        &[
            "thermal.coupled",
            "runs away",
            "thermoelastic instability",
            "The last resolved state was iteration",
            "hint: lower the heat",
        ],
    );
}

/// Issue 42, classes 5 and 6: `thermal`'s outputs are checked before anything is computed
/// (a missing directory is said at once, even for a scene whose heating would fail), written
/// all or none, through a device whatever its name, with extensions in any case; `render`
/// leaves no figure when its heating sheet goes to a full device.
#[cfg(unix)]
#[test]
fn heating_outputs_are_checked_first_and_written_all_or_none() {
    let dir = tempfile::tempdir().expect("dir");
    let path = |name: &str| dir.path().join(name).to_str().expect("utf8").to_string();
    // A scene whose computation fails (a runaway): the bad path is reported instead.
    std::fs::write(
        path("runaway.toml"),
        ball_on_disc("conductivity = \"20 W/(m K)\"\nexpansion = \"5e-4 /K\"\n"),
    )
    .expect("scene");
    let output = run(&[
        "thermal",
        &path("runaway.toml"),
        "--temperature",
        &path("t.npy"),
        "--figure",
        &path("missing/f.svg"),
    ]);
    crate::cli::assert_fails_with(&output, &["missing/f.svg", "No such file or directory"]);
    assert!(
        !stderr(&output).contains("runs away"),
        "{}",
        stderr(&output)
    );
    assert!(!dir.path().join("t.npy").exists());
    // Upper-case extensions and a device.
    let sliding = crate::cli::repo("scenes/thermal_sliding_sphere.toml");
    let sliding = sliding.to_str().expect("utf8");
    let output = run(&[
        "thermal",
        sliding,
        "--temperature",
        "/dev/null",
        "--figure",
        &path("SHEET.SVG"),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let svg = std::fs::read_to_string(dir.path().join("SHEET.SVG")).expect("svg written");
    assert!(svg.starts_with("<svg") || svg.starts_with("<?xml"));
    if std::path::Path::new("/dev/full").exists() {
        // The sheet onto a full device: neither output is left.
        std::os::unix::fs::symlink("/dev/full", dir.path().join("full.png")).expect("link");
        let output = run(&[
            "thermal",
            sliding,
            "--temperature",
            &path("T.NPY"),
            "--figure",
            &path("full.png"),
        ]);
        crate::cli::assert_fails_with(&output, &["No space left"]);
        assert!(!dir.path().join("T.NPY").exists());
        // render: the heating sheet through a link to /dev/full leaves no figure.
        let out = dir.path().join("out");
        std::fs::create_dir(&out).expect("out");
        std::os::unix::fs::symlink("/dev/full", out.join("thermal_sliding_sphere_heating.png"))
            .expect("link");
        let output = run(&["render", sliding, "--out-dir", out.to_str().expect("utf8")]);
        crate::cli::assert_fails_with(&output, &["No space left"]);
        assert!(!out.join("thermal_sliding_sphere.png").exists());
    }
}

/// Issue 42, class 2: the heating's memory and time are estimated before anything is
/// computed, by `check` too: a rough ball of 4096² samples with `[thermal]` (before issue 41,
/// 2048² climbed past 4 GB and aborted after 189 s; since, 2048² heats within the memory its
/// contact takes) is refused at once naming the map's size, a sphere
/// slid at Pe 190 (the grid refined to 640 x 480 cells) naming the speed; an accepted scene's
/// `check` line states the estimate.
#[test]
fn the_heatings_cost_is_estimated_and_refused_at_check() {
    let dir = tempfile::tempdir().expect("dir");
    let rough = "format = 1\n[contact]\nkind = \"rough\"\nload = \"0.5 N\"\nfriction = 0.1\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n[surface.generate]\nsamples = 4096\nspacing = \"0.03125 um\"\nhurst = 0.8\nrolloff = \"32 um\"\ncutoff = \"4 um\"\nrms_height = \"0.05 um\"\nsphere_radius = \"2 mm\"\nseed = 3\n[thermal]\nspeed = \"2 m/s\"\n";
    let path = dir.path().join("rough.toml");
    std::fs::write(&path, rough).expect("scene");
    let started = std::time::Instant::now();
    crate::cli::assert_fails_with(
        &run(&["check", path.to_str().expect("utf8")]),
        &[
            "key `surface.generate.samples`",
            "of a 4096 x 4096 map",
            "min of CPU",
            "GiB",
            "half the samples a side",
        ],
    );
    assert!(started.elapsed().as_secs() < 20, "refused before computing");
    // A sphere at Pe 190: its grid is refined to 640 x 481 cells (an odd count: a row at y = 0).
    let fast = std::fs::read_to_string(crate::cli::repo("scenes/thermal_sliding_sphere.toml"))
        .expect("shipped")
        .replace("speed = \"2 m/s\"", "speed = \"11.8 m/s\"");
    let path = dir.path().join("fast.toml");
    std::fs::write(&path, fast).expect("scene");
    for command in ["check", "thermal"] {
        crate::cli::assert_fails_with(
            &run(&[command, path.to_str().expect("utf8")]),
            &[
                "key `thermal.speed`",
                "640 x 481 cells",
                "262144 cells allowed",
                "Péclet number of about 148",
            ],
        );
    }
    let output = run(&[
        "check",
        crate::cli::repo("scenes/thermal_sliding_sphere.toml")
            .to_str()
            .expect("utf8"),
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let line = String::from_utf8_lossy(&output.stdout).to_string();
    assert!(
        line.contains("heating: 129 x 97 cells, about") && line.contains("of CPU"),
        "{line}"
    );
}

/// Issue 42, class 4: a speed the heating's grid cannot resolve is refused by `check`, under
/// the key the scene wrote (gears have no thermal.speed): the pinion's speed, a body's speed;
/// `hertz` and `render` refuse alike, with the file, and name the scene once.
#[test]
fn speeds_beyond_the_grid_are_refused_at_check_under_the_key_written() {
    let dir = tempfile::tempdir().expect("dir");
    let gears = std::fs::read_to_string(crate::cli::repo("scenes/gear_pitch_point.toml"))
        .expect("shipped")
        .replace(
            "pinion_speed = \"1500 rpm\"",
            "pinion_speed = \"150000 rpm\"",
        );
    let path = dir.path().join("gears.toml");
    std::fs::write(&path, gears).expect("scene");
    let out = dir.path().join("out");
    let path = path.to_str().expect("utf8");
    for args in [
        vec!["check", path],
        vec!["thermal", path],
        vec!["hertz", path],
        vec!["render", path, "--out-dir", out.to_str().expect("utf8")],
    ] {
        let output = run(&args);
        crate::cli::assert_fails_with(
            &output,
            &[
                "gears.toml",
                "key `thermal.pinion_speed`",
                "on the path of contact",
                "Péclet number",
            ],
        );
        let message = stderr(&output);
        assert!(!message.contains("thermal.speed"), "{message}");
        assert!(!message.contains("scene gears: scene gears"), "{message}");
    }
    // A line contact whose body 2 (a fast roller) sets the grid: named by body2_speed.
    let line = "format = 1\n[contact]\nkind = \"line\"\nload = \"100 kN/m\"\nfriction = 0.1\n[contact.body1]\nradius = \"20 mm\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"30 mm\"\nmaterial = \"steel\"\n[thermal]\nbody1_speed = \"1 m/s\"\nbody2_speed = \"400 m/s\"\npartition = \"blok\"\n";
    let error = stressfield::study::parse_scene(line, "l", "l.toml").expect_err("too fast");
    assert_eq!(error.key.as_deref(), Some("thermal.body2_speed"), "{error}");
}

/// Issue 42, the leftovers of round two: generated spacings too unequal for the default band
/// are refused naming `surface.generate.spacing` (they named `cutoff`, a key not written);
/// `--compare` given a file says it is not a directory; a directory given as an `.x3p` says
/// it is a directory.
#[test]
fn round_two_leftovers_name_their_cause() {
    let generated = |spacing: &str, extra: &str| {
        format!(
            "format = 1\n[contact]\nkind = \"surface\"\n[surface.generate]\nsamples = [64, 32]\nspacing = {spacing}\nhurst = 0.8\nrms_height = \"0.1 um\"\n{extra}"
        )
    };
    let error =
        stressfield::study::parse_scene(&generated("[\"0.5 um\", \"40 um\"]", ""), "s", "s.toml")
            .expect_err("unequal");
    assert_eq!(
        error.key.as_deref(),
        Some("surface.generate.spacing"),
        "{error}"
    );
    assert!(
        error.to_string().contains("the spacings differ too much"),
        "{error}"
    );
    // Given a band, the same spacings are taken; equal ones need none.
    stressfield::study::parse_scene(
        &generated(
            "[\"0.5 um\", \"40 um\"]",
            "rolloff = \"100 um\"\ncutoff = \"80 um\"\n",
        ),
        "s",
        "s.toml",
    )
    .expect("a band given");
    stressfield::study::parse_scene(&generated("\"0.5 um\"", ""), "s", "s.toml")
        .expect("equal spacings");

    let dir = tempfile::tempdir().expect("dir");
    let scene = dir.path().join("case.toml");
    std::fs::write(&scene, SMALL_SCENE).expect("scene");
    let file = dir.path().join("refs.txt");
    std::fs::write(&file, "not a directory").expect("file");
    let out = dir.path().join("out");
    for update in [false, true] {
        let mut args = vec![
            "render",
            scene.to_str().expect("utf8"),
            "--out-dir",
            out.to_str().expect("utf8"),
            "--compare",
            file.to_str().expect("utf8"),
        ];
        if update {
            args.push("--update");
        }
        let output = run(&args);
        crate::cli::assert_fails_with(&output, &["refs.txt", "is not a directory"]);
        assert!(
            !stderr(&output).contains("does not exist"),
            "{}",
            stderr(&output)
        );
    }
    let x3p = dir.path().join("heights.x3p");
    std::fs::create_dir(&x3p).expect("a directory named .x3p");
    let output = run(&["surface", x3p.to_str().expect("utf8")]);
    crate::cli::assert_fails_with(&output, &["heights.x3p", "it is a directory"]);
    assert!(!stderr(&output).contains("zip"), "{}", stderr(&output));
}

/// Issue 50, round four of hardening. An output directory that takes no file (`/proc`: not
/// even root creates files there) is found before anything is computed: the scenes here would
/// fail in their computation (an isolated contact reaching its map's edge), so an output
/// directory checked only afterwards says the computation's error instead. And a rigid body 2
/// refuses a Poisson ratio in a rough scene as it does in a coated one, naming the key.
#[test]
fn outputs_are_checked_first_and_a_rigid_body_has_no_constants() {
    let dir = tempfile::tempdir().expect("temp");
    // A 300 mm ball under 5 N on a 96 µm map: its unworn contact covers the map.
    let edge = "format = 1\n[contact]\nkind = \"rough\"\nload = \"5 N\"\n[contact.body1]\nmaterial = \"steel\"\n[contact.body2]\nmaterial = \"steel\"\n[surface.generate]\nsamples = 24\nspacing = \"4 um\"\nhurst = 0.8\nrolloff = \"24 um\"\ncutoff = \"8 um\"\nrms_height = \"0.1 um\"\nsphere_radius = \"300 mm\"\nseed = 2\n";
    let rough = dir.path().join("edge.toml");
    std::fs::write(&rough, edge).expect("scene");
    let output = run(&[
        "render",
        rough.to_str().expect("utf8"),
        "--out-dir",
        "/proc",
    ]);
    assert!(!output.status.success());
    let message = stderr(&output);
    assert!(
        message.contains("cannot write into the output directory /proc"),
        "{message}"
    );
    assert!(!message.contains("edge"), "{message}");
    let wear = dir.path().join("edge_wear.toml");
    std::fs::write(
        &wear,
        format!(
            "{edge}[wear]\ncoefficient = \"2e-6 mm^3/(N m)\"\ndistance = \"0.1 m\"\nsteps = 2\n"
        ),
    )
    .expect("scene");
    let output = run(&[
        "wear",
        wear.to_str().expect("utf8"),
        "--heights-out",
        "/proc",
    ]);
    assert!(!output.status.success());
    let message = stderr(&output);
    assert!(
        message.contains("--heights-out /proc: cannot write into it"),
        "{message}"
    );
    assert!(!message.contains("edge of"), "{message}");

    let rigid = edge.replace(
        "[contact.body2]\nmaterial = \"steel\"",
        "[contact.body2]\nmaterial = \"rigid\"\npoisson = 0.3",
    );
    let scene = dir.path().join("rigid.toml");
    std::fs::write(&scene, rigid).expect("scene");
    let output = run(&["check", scene.to_str().expect("utf8")]);
    assert!(!output.status.success());
    let message = stderr(&output);
    assert!(message.contains("`contact.body2.poisson`"), "{message}");
    assert!(
        message.contains("a rigid body has no elastic constants"),
        "{message}"
    );
}
