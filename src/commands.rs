//! The subcommands. Library errors get their context here and are reported once, by main.

use std::io::{BufRead, IsTerminal, Write};
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use indicatif::{ProgressBar, ProgressStyle};

use crate::cli::{Command, ContactArg, MethodArg, ProbeArgs};
use crate::compare_run::{self, CompareOptions, Rendered};
use figure::Drawing;
use stressfield::field_file::{self, PanelField};
use stressfield::output::Staged;
use stressfield::probe;
use stressfield::scene::{ContactKind, Method, PanelSpec, Scene};
use stressfield::solution::Solution;
use stressfield::study;
use stressfield::text;
use stressfield::{figure, render, report};

pub fn run(command: Command) -> Result<()> {
    match command {
        Command::Render(args) => {
            let named = !args.scenes.is_empty();
            let scenes = scene_paths(args.scenes, &args.scenes_dir)?;
            if args.rrd.is_some() && scenes.len() != 1 {
                bail!("--rrd FILE records one scene, got {}\nhint: name one scene, or use `stressfield record` for several (one out/<scene>.rrd each)", scenes.len());
            }
            let compare = CompareOptions::from_args(&args.compare, args.save_field, &args.out_dir)?;
            let options = RenderOptions {
                svg: args.svg,
                save_field: args.save_field,
                compare: compare.as_ref(),
                rrd: args.rrd.as_deref(),
                named,
            };
            render_all(&scenes, &args.out_dir, &options)
        }
        Command::Record {
            mut scenes,
            output,
            spawn,
            connect,
            out_dir,
            scenes_dir,
        } => {
            // `--connect SCENE.toml`: the flag's value was a scene, not an address.
            let connect = match connect {
                Some(url) if !url.contains("://") => {
                    scenes.insert(0, PathBuf::from(url));
                    Some(crate::cli::DEFAULT_VIEWER_URL.to_string())
                }
                other => other,
            };
            let scenes = scene_paths(scenes, &scenes_dir)?;
            let stdout = output.as_deref() == Some(Path::new("-"));
            if output.is_some() && scenes.len() != 1 {
                bail!("-o {} records one scene, got {}\nhint: name one scene, or leave out -o to write <out-dir>/<scene>.rrd for each", if stdout { "-" } else { "FILE.rrd" }, scenes.len());
            }
            let target = match (output, spawn, connect) {
                (Some(_), _, _) if stdout => Target::Stdout,
                (Some(path), _, _) => Target::File(path),
                (None, true, _) => Target::Spawn,
                (None, false, Some(url)) => Target::Connect(url),
                (None, false, None) => Target::OutDir(out_dir),
            };
            record_all(&scenes, &target)
        }
        Command::Hertz { scene: scene_path } => {
            let scene = Scene::load(&scene_path)?;
            match scene.contact.kind {
                ContactKind::Rough => crate::surface_commands::contact(&scene_path, false, None),
                ContactKind::Surface => crate::surface_commands::surface_of_scene(&scene_path),
                _ => {
                    let mut text = report::hertz(&scene);
                    if scene.thermal.is_some() {
                        let (report, study) = crate::thermal_commands::hertz_heating(&scene)?;
                        text.push_str(&report.text(&study));
                    }
                    print_out(&text)
                }
            }
        }
        Command::Check { scenes } => check(&scenes),
        Command::Probe(args) => probe_command(&args),
        Command::Contact {
            scene,
            json,
            pressure,
        } => crate::surface_commands::contact(&scene, json, pressure.as_deref()),
        Command::Surface(args) => crate::surface_commands::surface(&args),
        Command::Thermal {
            scene,
            json,
            temperature,
            figure,
        } => crate::thermal_commands::thermal(
            &scene,
            json,
            temperature.as_deref(),
            figure.as_deref(),
        ),
    }
}

/// Writes `text` to standard output (see [`with_stdout`]).
pub(crate) fn print_out(text: &str) -> Result<()> {
    with_stdout(|out| out.write_all(text.as_bytes()))
}

/// The one path of every command's output: `write` into standard output (buffered), then
/// flush. A closed pipe (`| head`) ends quietly, as the reader asked for no more; any other
/// failure (a full disk, `> /dev/full`) is an error naming standard output.
pub(crate) fn with_stdout(write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>) -> Result<()> {
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    match write(&mut out).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(e).context("cannot write to standard output"),
    }
}

/// Writes a line to standard error. Messages and errors are the last thing a run can say:
/// when standard error itself cannot be written (closed, full), there is nobody left to tell,
/// and the exit code still reports the failure.
pub(crate) fn print_err(line: &str) {
    let mut err = std::io::stderr().lock();
    let _ = writeln!(err, "{line}");
}

/// The scenes named, or every `*.toml` in `scenes_dir` in name order.
fn scene_paths(named: Vec<PathBuf>, scenes_dir: &Path) -> Result<Vec<PathBuf>> {
    if !named.is_empty() {
        return Ok(named);
    }
    let entries = std::fs::read_dir(scenes_dir).with_context(|| {
        format!("cannot list scenes in {}\nhint: run from the repository root, or pass scene files or --scenes-dir", scenes_dir.display())
    })?;
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    if paths.is_empty() {
        bail!("no *.toml scenes in {}", scenes_dir.display());
    }
    Ok(paths)
}

pub(crate) fn progress_bar(total: u64) -> ProgressBar {
    let quiet = !std::io::stderr().is_terminal() || std::env::var_os("CI").is_some();
    if quiet {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(total);
    if let Ok(style) =
        ProgressStyle::with_template("{spinner} {msg:24} [{bar:40}] {percent:>3}% {elapsed}")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    bar
}

/// Prints a line above the progress bar, or on stderr when the bar is hidden (not a terminal).
fn say(bar: &ProgressBar, line: impl AsRef<str>) {
    if bar.is_hidden() {
        print_err(line.as_ref());
    } else {
        bar.println(line);
    }
}

/// Options of `render`.
struct RenderOptions<'a> {
    svg: bool,
    /// Write `<scene>.npz` beside the PNG.
    save_field: bool,
    compare: Option<&'a CompareOptions>,
    /// Record the (single) scene to this file too.
    rrd: Option<&'a Path>,
    /// Scenes were named on the command line (a recording scene is then drawn as a figure
    /// too); otherwise recording scenes are only recorded.
    named: bool,
}

/// Whether a scene is a recording (a sweep or a volume) rather than a figure.
fn is_recording(scene: &Scene) -> bool {
    scene.sweep.is_some() || scene.volume.is_some()
}

fn load_scenes(paths: &[PathBuf], failures: &mut Vec<String>) -> Vec<Scene> {
    let mut scenes = Vec::new();
    for path in paths {
        match Scene::load(path) {
            Ok(scene) => scenes.push(scene),
            Err(e) => {
                print_err(&format!("error: {e}"));
                failures.push(path.display().to_string());
            }
        }
    }
    scenes
}

fn create_out_dir(out_dir: &Path) -> Result<()> {
    std::fs::create_dir_all(out_dir).with_context(|| {
        format!(
            "cannot create the output directory {}\nhint: choose a writable one with --out-dir",
            out_dir.display()
        )
    })
}

fn render_all(paths: &[PathBuf], out_dir: &Path, options: &RenderOptions) -> Result<()> {
    let mut failures = Vec::new();
    let scenes = load_scenes(paths, &mut failures);
    if !scenes.is_empty() {
        create_out_dir(out_dir)?;
    }
    let total_rows: usize = scenes
        .iter()
        .map(|s| {
            let figure: usize = s.panels.iter().map(|p| study::plane(s, p).v.count).sum();
            // A recording evaluates its sections at every step.
            match (is_recording(s) && !options.named, options.rrd.is_some()) {
                (true, _) => recording_rows(s),
                (false, true) => figure + recording_rows(s),
                (false, false) => figure,
            }
        })
        .sum();
    let bar = progress_bar(total_rows as u64);
    let mut outcomes = Vec::new();
    let mut recordings = 0;
    for scene in &scenes {
        bar.set_message(scene.name.clone());
        // The main job (no scenes named): a recording scene is recorded, not drawn (nor
        // compared).
        if is_recording(scene) && !options.named {
            let path = out_dir.join(format!("{}.rrd", scene.name));
            record_reporting(scene, &path, &bar, &mut failures);
            recordings += 1;
            continue;
        }
        match render_scene(scene, out_dir, options, &bar) {
            Ok(output) => {
                for line in &output.lines {
                    say(&bar, line);
                }
                if let Some(compare) = options.compare {
                    let rendered = Rendered {
                        name: &scene.name,
                        image: &output.image,
                        png: &output.png,
                        field: output.field.as_deref(),
                        stress_unit: scene.figure.stress_unit.symbol(),
                        axes: {
                            let (horizontal, vertical, _) = scene.figure.section.coordinates();
                            let unit = scene.figure.length_unit;
                            [unit.axis_label(horizontal), unit.axis_label(vertical)]
                        },
                    };
                    let outcome = compare_run::check_scene(&rendered, compare, out_dir);
                    say(&bar, outcome.line());
                    outcomes.push(outcome);
                }
            }
            Err(e) => {
                say(&bar, format!("error: scene {}: {e:#}", scene.name));
                failures.push(scene.name.clone());
            }
        }
    }
    bar.finish_and_clear();
    if let Some(compare) = options.compare {
        let say = |line: String| print_err(&line);
        return compare_run::finish(&outcomes, compare, out_dir, &failures, recordings, &say);
    }
    fail_if_any(&failures, paths.len())?;
    Ok(())
}

/// Fails with the names of the scenes that failed, if any.
fn fail_if_any(failures: &[String], total: usize) -> Result<()> {
    if !failures.is_empty() {
        bail!(
            "{} of {} scenes failed: {}",
            failures.len(),
            total,
            failures.join(", ")
        );
    }
    Ok(())
}

/// Records a scene and says so, or reports its error and adds it to `failures`.
fn record_reporting(scene: &Scene, path: &Path, bar: &ProgressBar, failures: &mut Vec<String>) {
    match record_scene(scene, path, bar) {
        Ok(line) => say(bar, line),
        Err(e) => {
            say(bar, format!("error: scene {}: {e:#}", scene.name));
            failures.push(scene.name.clone());
        }
    }
}

/// Where `record` sends its recordings.
#[derive(Clone, Debug)]
enum Target {
    /// `<dir>/<scene>.rrd` for each scene.
    OutDir(PathBuf),
    /// `-o FILE.rrd` (one scene).
    File(PathBuf),
    /// `-o -` (one scene).
    Stdout,
    /// `--spawn`: a new viewer.
    Spawn,
    /// `--connect [URL]`: a running viewer.
    Connect(String),
}

/// `record`: one recording per scene, to files, standard output or a viewer.
fn record_all(paths: &[PathBuf], target: &Target) -> Result<()> {
    let mut failures = Vec::new();
    let scenes = load_scenes(paths, &mut failures);
    if let (Target::OutDir(out_dir), false) = (target, scenes.is_empty()) {
        create_out_dir(out_dir)?;
    }
    let bar = progress_bar(scenes.iter().map(recording_rows).sum::<usize>() as u64);
    for scene in &scenes {
        bar.set_message(scene.name.clone());
        let result = match target {
            Target::OutDir(dir) => {
                record_scene(scene, &dir.join(format!("{}.rrd", scene.name)), &bar)
            }
            Target::File(path) => record_scene(scene, path, &bar),
            other => stream_scene(scene, other, &bar),
        };
        match result {
            Ok(line) => say(&bar, line),
            Err(e) => {
                say(&bar, format!("error: scene {}: {e:#}", scene.name));
                failures.push(scene.name.clone());
            }
        }
    }
    bar.finish_and_clear();
    fail_if_any(&failures, paths.len())?;
    Ok(())
}

#[cfg(feature = "rerun")]
fn recording_rows(scene: &Scene) -> usize {
    stressfield::record::rows(scene)
}

#[cfg(not(feature = "rerun"))]
fn recording_rows(_scene: &Scene) -> usize {
    0
}

/// The end of the line that reports a recording: its steps and volume.
#[cfg(feature = "rerun")]
fn summary_text(scene: &Scene, summary: &stressfield::record::Summary) -> String {
    let mut line = String::new();
    if summary.steps > 1 {
        let timeline = stressfield::record::timeline(scene);
        line.push_str(&format!(
            " ({} steps on the timeline `{timeline}`)",
            summary.steps
        ));
    }
    if summary.volume_triangles > 0 {
        line.push_str(&format!(
            ", iso-surfaces of {} triangles",
            summary.volume_triangles
        ));
    }
    line
}

/// Records one scene to `path` (atomically, or through a device or FIFO); returns the line to
/// print.
fn record_scene(scene: &Scene, path: &Path, bar: &ProgressBar) -> Result<String> {
    record_scene_as(scene, path, path, bar)
}

/// Records one scene into `file` (atomically, or through a device or FIFO), saying it was
/// recorded to `shown` (the final name of a staged file); returns the line to print.
#[cfg(feature = "rerun")]
fn record_scene_as(scene: &Scene, file: &Path, shown: &Path, bar: &ProgressBar) -> Result<String> {
    let summary = stressfield::record::record_to_file(scene, file, &|| bar.inc(1));
    let summary = if file == shown {
        summary?
    } else {
        summary.with_context(|| format!("cannot record {}", shown.display()))?
    };
    Ok(format!(
        "recorded {}{}",
        shown.display(),
        summary_text(scene, &summary)
    ))
}

/// Streams one scene to standard output or a viewer; returns the line to print.
#[cfg(feature = "rerun")]
fn stream_scene(scene: &Scene, target: &Target, bar: &ProgressBar) -> Result<String> {
    use stressfield::record::Destination;
    let destination = match target {
        Target::Stdout => Destination::Stdout,
        Target::Spawn => Destination::Spawn,
        Target::Connect(url) => Destination::Connect(url.clone()),
        Target::OutDir(dir) => Destination::File(dir.join(format!("{}.rrd", scene.name))),
        Target::File(path) => Destination::File(path.clone()),
    };
    let summary = stressfield::record::record_to(scene, &destination, &|| bar.inc(1))?;
    Ok(format!(
        "streamed {} to {destination}{}",
        scene.name,
        summary_text(scene, &summary)
    ))
}

#[cfg(not(feature = "rerun"))]
fn record_scene_as(
    scene: &Scene,
    _file: &Path,
    _shown: &Path,
    _bar: &ProgressBar,
) -> Result<String> {
    bail!(
        "scene {}: this build has no Rerun support (built with --no-default-features)\nhint: rebuild with the default features: cargo build --release",
        scene.name
    )
}

#[cfg(not(feature = "rerun"))]
fn stream_scene(scene: &Scene, target: &Target, _bar: &ProgressBar) -> Result<String> {
    let place = match target {
        Target::Connect(url) => format!("the viewer at {url}"),
        Target::Spawn => "a new viewer".to_string(),
        Target::Stdout => "standard output".to_string(),
        Target::OutDir(dir) => dir.display().to_string(),
        Target::File(path) => path.display().to_string(),
    };
    bail!(
        "scene {}: this build has no Rerun support (built with --no-default-features), so it cannot record to {place}\nhint: rebuild with the default features: cargo build --release",
        scene.name
    )
}

/// What `render` made of one scene.
struct SceneOutput {
    image: image::RgbImage,
    /// The PNG as written.
    png: Vec<u8>,
    /// The panels' values (a figure; a sheet has none).
    field: Option<Vec<PanelField>>,
    /// What to print: the files written.
    lines: Vec<String>,
}

/// Renders one scene and writes its outputs, all or none: the PNG, the SVG (`--svg` or the
/// scene's `svg = true`), the field archive (`--save-field`) and the recording (`--rrd`) are
/// prepared in temporary files beside their targets and moved into place together once all
/// of them are complete; a failure leaves every target as it was.
fn render_scene(
    scene: &Scene,
    out_dir: &Path,
    options: &RenderOptions,
    bar: &ProgressBar,
) -> Result<SceneOutput> {
    let mut staged = Staged::new();
    // The recording's place first: a bad --rrd path fails before any work.
    let recording = match options.rrd {
        Some(path) => Some((staged.reserve(path)?, path)),
        None => None,
    };
    let on_row = || bar.inc(1);
    let drawing = figure::draw(scene, &on_row)?;
    let image = drawing.png()?;
    let png = render::encode_png(&image)?;
    let png_path = out_dir.join(format!("{}.png", scene.name));
    staged.add(&png_path, &png)?;
    let mut written = vec![png_path.display().to_string()];
    if options.svg || scene.figure.svg {
        let svg_path = out_dir.join(format!("{}.svg", scene.name));
        staged.add(&svg_path, drawing.svg()?.as_bytes())?;
        written.push(svg_path.display().to_string());
    }
    let field = match &drawing {
        Drawing::Figure(figure) => Some(PanelField::of_figure(figure)),
        Drawing::Sheet(_) => None,
    };
    // A Hertz or gear scene with [thermal] also gets its heating sheet (a rough scene's:
    // `stressfield thermal SCENE --figure`, which solves its contact once).
    if scene.thermal.is_some()
        && !matches!(
            scene.contact.kind,
            ContactKind::Rough | ContactKind::Surface
        )
    {
        let heating_path = out_dir.join(format!("{}_heating.png", scene.name));
        staged.add(&heating_path, &crate::thermal_commands::heating_png(scene)?)?;
        written.push(heating_path.display().to_string());
    }
    let mut lines = Vec::new();
    if options.save_field {
        match &field {
            Some(panels) => {
                let field_path = out_dir.join(format!("{}.npz", scene.name));
                staged.add(&field_path, &field_file::encode(panels)?)?;
                written.push(field_path.display().to_string());
            }
            None => lines.push(format!(
                "note: {} draws a sheet (a surface or rough contact scene), which has no single field: no .npz written",
                scene.name
            )),
        }
    }
    lines.insert(0, format!("rendered {}", written.join(", ")));
    if let Some((file, path)) = recording {
        lines.push(record_scene_as(scene, &file, path, bar)?);
    }
    staged.commit()?;
    Ok(SceneOutput {
        image,
        png,
        field,
        lines,
    })
}

fn check(paths: &[PathBuf]) -> Result<()> {
    let mut failed = 0;
    for path in paths {
        match Scene::load(path) {
            Ok(scene) => print_out(&format!(
                "ok {} ({})\n",
                path.display(),
                check_summary(&scene)
            ))?,
            Err(e) => {
                print_err(&format!("error: {e}"));
                failed += 1;
            }
        }
    }
    if failed > 0 {
        bail!("{failed} of {} scenes are invalid", paths.len());
    }
    Ok(())
}

/// What `check` says of a valid scene: its panels and grid, or its surface.
fn check_summary(scene: &Scene) -> String {
    match (&scene.surface, scene.panels.first()) {
        (Some(surface), _) => {
            let [ny, nx] = surface.heights.shape();
            let kind = if scene.contact.kind == ContactKind::Rough {
                "rough contact"
            } else {
                "surface"
            };
            format!("{kind}, {nx} x {ny} samples")
        }
        (None, Some(panel)) => {
            let plane = study::plane(scene, panel);
            format!(
                "{} panel(s), {} x {} points each",
                scene.panels.len(),
                plane.u.count,
                plane.v.count
            )
        }
        (None, None) => "no panels".into(),
    }
}

fn probe_command(args: &ProbeArgs) -> Result<()> {
    let ProbeArgs {
        scene,
        contact,
        friction,
        poisson,
        method,
        strips,
        cells,
        extent,
        points,
    } = args;
    let (scene, contact, friction, poisson) = (scene.as_deref(), *contact, *friction, *poisson);
    let (method, strips, cells, extent) = (*method, *strips, *cells, *extent);
    let points = points.as_path();
    if !(1..=1_000_000).contains(&strips) {
        bail!("--strips must lie in 1..=1000000, got {strips}");
    }
    let (mut mu, mut nu, mut kind) = (0.0, 0.3, ContactArg::Line);
    let mut loaded = None;
    if let Some(path) = scene {
        let scene = Scene::load(path)?;
        (mu, nu) = (scene.contact.friction, scene.contact.poisson);
        kind = match scene.contact.kind {
            ContactKind::Line => ContactArg::Line,
            ContactKind::Point | ContactKind::Elliptical | ContactKind::Tractions => {
                ContactArg::Point
            }
            ContactKind::Rough | ContactKind::Surface => bail!(
                "probe takes Hertz and traction scenes; {} is a rough or surface scene\nhint: `stressfield contact {}` solves it and writes its pressure; `render` draws the stresses under it",
                path.display(),
                path.display()
            ),
        };
        if let Some(given) = contact.filter(|c| *c != kind) {
            bail!(
                "--contact {} contradicts the scene {}, a {} contact\nhint: drop --contact; the scene decides",
                if given == ContactArg::Line { "line" } else { "point" },
                path.display(),
                if kind == ContactArg::Line { "line" } else { "point" }
            );
        }
        loaded = Some(scene);
    } else if let Some(given) = contact {
        kind = given;
    }
    if !(8..=2048).contains(&cells) {
        bail!("--cells must lie in 8..=2048, got {cells}");
    }
    if !(extent.is_finite() && (1.0..=20.0).contains(&extent)) {
        bail!(
            "--extent must lie in 1..=20 (units of a; the grid must cover the contact), got {}",
            text::number(extent)
        );
    }
    if let Some(f) = friction {
        if let Some(message) = stressfield::scene::friction_requirement(f) {
            bail!(
                "--friction: {message}\nhint: {}",
                stressfield::scene::FRICTION_HINT
            );
        }
        mu = f;
    }
    if let Some(p) = poisson {
        if !(p > -1.0 && p <= 0.5) {
            bail!("--poisson must lie in (-1, 0.5], got {}", text::number(p));
        }
        nu = p;
    }
    let input: Box<dyn BufRead> = if points.as_os_str() == "-" {
        Box::new(std::io::stdin().lock())
    } else {
        let file = std::fs::File::open(points)
            .with_context(|| format!("cannot open the points file {}", points.display()))?;
        Box::new(std::io::BufReader::new(file))
    };
    let rows = probe::read_points(input).with_context(|| {
        format!(
            "in the points {}",
            if points.as_os_str() == "-" {
                "from standard input".into()
            } else {
                format!("file {}", points.display())
            }
        )
    })?;
    // A scene's contact may have no closed form (elliptical, partial slip, a traction file):
    // then its numerical method, with the scene's grid.
    let solution = match (loaded, kind, method) {
        (Some(scene), _, _) => {
            let panel = PanelSpec {
                method: match method {
                    MethodArg::ClosedForm => Method::ClosedForm,
                    MethodArg::Numerical => Method::Numerical,
                },
                friction: mu,
                poisson: nu,
                at: 0.0,
                subtitle: None,
            };
            match (scene.contact.kind, method) {
                (ContactKind::Line, MethodArg::Numerical) => {
                    Solution::line_numerical(mu, nu, strips)
                }
                _ => study::solution(&scene, &panel)?,
            }
        }
        (None, ContactArg::Line, MethodArg::ClosedForm) => Solution::LineHertz {
            friction: mu,
            poisson: nu,
        },
        (None, ContactArg::Line, MethodArg::Numerical) => Solution::line_numerical(mu, nu, strips),
        (None, ContactArg::Point, MethodArg::ClosedForm) => Solution::SphereHertz {
            friction: mu,
            poisson: nu,
        },
        (None, ContactArg::Point, MethodArg::Numerical) => {
            Solution::sphere_numerical(mu, nu, cells, extent)?
        }
    };
    with_stdout(|mut out| probe::write_csv(&mut out, &solution, &rows))
}
