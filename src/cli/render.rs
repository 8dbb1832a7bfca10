//! `render`: figures of scenes into a folder (PNG, SVG, field archive, heating sheet), and
//! the regression comparison of what was drawn.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use indicatif::ProgressBar;

use super::compare::{self, CompareOptions, Rendered};
use super::console::{print_err, progress_bar, say};
use super::record::{
    record_plastic_as, record_reporting, record_scene_as, record_wear_as, recording_rows,
};
use stressfield::figure::{self, Drawing};
use stressfield::io::output::Staged;
use stressfield::regression::field_file::{self, PanelField};
use stressfield::render;
use stressfield::scene::{ContactKind, Scene};
use stressfield::study;

/// Options of `render`.
pub(super) struct RenderOptions<'a> {
    pub(super) svg: bool,
    /// Write `<scene>.npz` beside the PNG.
    pub(super) save_field: bool,
    pub(super) compare: Option<&'a CompareOptions>,
    /// Record the (single) scene to this file too.
    pub(super) rrd: Option<&'a Path>,
    /// Scenes were named on the command line (a recording scene is then drawn as a figure
    /// too); otherwise recording scenes are only recorded.
    pub(super) named: bool,
}

/// Whether a scene is a recording (a sweep or a volume) rather than a figure.
pub(super) fn is_recording(scene: &Scene) -> bool {
    scene.sweep.is_some() || scene.volume.is_some()
}

pub(super) fn load_scenes(paths: &[PathBuf], failures: &mut Vec<String>) -> Vec<Scene> {
    let mut scenes = Vec::new();
    for path in paths {
        match stressfield::study::load_scene(path) {
            Ok(scene) => scenes.push(scene),
            Err(e) => {
                print_err(&format!("error: {e}"));
                failures.push(path.display().to_string());
            }
        }
    }
    scenes
}

/// Creates the output directory and checks that it takes files, before any scene is computed.
pub(super) fn create_out_dir(out_dir: &Path) -> Result<()> {
    std::fs::create_dir_all(out_dir)
        .and_then(|()| stressfield::io::output::probe_directory(out_dir))
        .with_context(|| {
            format!(
                "cannot write into the output directory {}\nhint: choose a writable one with --out-dir",
                out_dir.display()
            )
        })
}

pub(super) fn render_all(paths: &[PathBuf], out_dir: &Path, options: &RenderOptions) -> Result<()> {
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
                        axes: scene
                            .panels
                            .iter()
                            .map(|panel| {
                                let (horizontal, vertical, _) = panel.section.coordinates();
                                let unit = scene.figure.length_unit;
                                [unit.axis_label(horizontal), unit.axis_label(vertical)]
                            })
                            .collect(),
                    };
                    let outcome = compare::check_scene(&rendered, compare, out_dir);
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
        return compare::finish(&outcomes, compare, out_dir, &failures, recordings, &say);
    }
    fail_if_any(&failures, paths.len())?;
    Ok(())
}

/// Fails with the names of the scenes that failed, if any.
pub(super) fn fail_if_any(failures: &[String], total: usize) -> Result<()> {
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
    // The recording's place first: a bad --rrd path (or a recording that would leave out
    // the scene's heating) fails before any work.
    let recording = match options.rrd {
        Some(path) => {
            super::record::recordable(scene)?;
            Some((staged.reserve(path)?, path))
        }
        None => None,
    };
    let on_row = || bar.inc(1);
    // A wear scene's steps are solved once, for the sheet and the recording.
    let wear = match &scene.wear {
        Some(_) => Some(super::wear::study(scene)?),
        None => None,
    };
    // A rough scene's contact is solved once, for the sheet and the recording.
    let rough = match (scene.contact.kind, &wear) {
        // The caller names the scene (once).
        (ContactKind::Rough, None) => Some(study::rough::solve(scene, &mut |_, _| {})?),
        _ => None,
    };
    // A [plasticity] scene's load steps are solved once, for the sheet and the recording.
    let plastic = match (&scene.plasticity, &wear) {
        (Some(_), None) if scene.draws_plastic_sheet() => Some(super::plastic::solve(scene)?),
        _ => None,
    };
    let drawing = match (&wear, &plastic) {
        (Some(study), _) => Drawing::Sheet(figure::wear::wear_sheet(scene, study)),
        (None, Some(study)) => Drawing::Sheet(super::plastic::sheet(scene, study)),
        (None, None) => {
            let inputs = study::drawing::inputs(scene, rough.as_ref(), &on_row)?;
            figure::draw(scene, rough.as_ref(), &inputs)?
        }
    };
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
        staged.add(&heating_path, &super::thermal::heating_png(scene)?)?;
        written.push(heating_path.display().to_string());
    }
    // A lubricated line contact also gets its EHL sheet (the solved pressure and film, the
    // stress under them beside the dry contact's).
    if stressfield::study::ehl::problem(scene).is_ok() {
        let ehl_path = out_dir.join(format!("{}_ehl.png", scene.name));
        staged.add(&ehl_path, &super::ehl::ehl_png(scene)?)?;
        written.push(ehl_path.display().to_string());
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
                "note: {} draws a sheet (a surface, rough, wear or plastic scene), which has no single field: no .npz written",
                scene.name
            )),
        }
    }
    lines.insert(0, format!("rendered {}", written.join(", ")));
    match (recording, &wear, &plastic) {
        (Some((file, path)), Some(study), _) => {
            lines.push(record_wear_as(scene, &file, path, study)?)
        }
        (Some((file, path)), None, Some(study)) => {
            lines.push(record_plastic_as(scene, &file, path, study)?)
        }
        (Some((file, path)), None, None) => {
            lines.push(record_scene_as(scene, &file, path, bar, rough.as_ref())?)
        }
        // The main job records a wear scene beside its figure, from the same study.
        (None, Some(study), _) if !options.named && cfg!(feature = "rerun") => {
            let path = out_dir.join(format!("{}.rrd", scene.name));
            let file = staged.reserve(&path)?;
            lines.push(record_wear_as(scene, &file, &path, study)?);
        }
        // And a [plasticity] scene's load steps, from the same study.
        (None, None, Some(study)) if !options.named && cfg!(feature = "rerun") => {
            let path = out_dir.join(format!("{}.rrd", scene.name));
            let file = staged.reserve(&path)?;
            lines.push(record_plastic_as(scene, &file, &path, study)?);
        }
        _ => {}
    }
    staged.commit()?;
    Ok(SceneOutput {
        image,
        png,
        field,
        lines,
    })
}
