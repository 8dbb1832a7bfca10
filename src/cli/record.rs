//! `record`: Rerun recordings of scenes, to files, standard output or a viewer.

use std::path::{Path, PathBuf};

use anyhow::Result;
use indicatif::ProgressBar;

use super::console::{progress_bar, say};
use super::render::{create_out_dir, fail_if_any, load_scenes};
use stressfield::contact::rough::RoughSolution;
use stressfield::scene::Scene;

/// Records a scene and says so, or reports its error and adds it to `failures`.
pub(super) fn record_reporting(
    scene: &Scene,
    path: &Path,
    bar: &ProgressBar,
    failures: &mut Vec<String>,
) {
    match recordable(scene).and_then(|()| record_scene(scene, path, bar)) {
        Ok(line) => say(bar, line),
        Err(e) => {
            say(bar, format!("error: scene {}: {e:#}", scene.name));
            failures.push(scene.name.clone());
        }
    }
}

/// Refuses a scene whose recording would leave out part of it
/// ([`stressfield::study::admit::unrecorded_heating`]).
pub(super) fn recordable(scene: &Scene) -> Result<()> {
    match stressfield::study::admit::unrecorded_heating(scene) {
        Some(message) => anyhow::bail!("{message}"),
        None => Ok(()),
    }
}

/// Where `record` sends its recordings.
#[derive(Clone, Debug)]
pub(super) enum Target {
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
pub(super) fn record_all(paths: &[PathBuf], target: &Target) -> Result<()> {
    let mut failures = Vec::new();
    let scenes = load_scenes(paths, &mut failures);
    if let (Target::OutDir(out_dir), false) = (target, scenes.is_empty()) {
        create_out_dir(out_dir)?;
    }
    let bar = progress_bar(scenes.iter().map(recording_rows).sum::<usize>() as u64);
    for scene in &scenes {
        bar.set_message(scene.name.clone());
        let result = recordable(scene).and_then(|()| match target {
            Target::OutDir(dir) => {
                record_scene(scene, &dir.join(format!("{}.rrd", scene.name)), &bar)
            }
            Target::File(path) => record_scene(scene, path, &bar),
            other => stream_scene(scene, other, &bar),
        });
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
pub(super) fn recording_rows(scene: &Scene) -> usize {
    stressfield::record::rows(scene)
}

#[cfg(not(feature = "rerun"))]
pub(super) fn recording_rows(_scene: &Scene) -> usize {
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
    record_scene_as(scene, path, path, bar, None)
}

/// Records one scene into `file` (atomically, or through a device or FIFO), saying it was
/// recorded to `shown` (the final name of a staged file); returns the line to print.
#[cfg(feature = "rerun")]
pub(super) fn record_scene_as(
    scene: &Scene,
    file: &Path,
    shown: &Path,
    bar: &ProgressBar,
    rough: Option<&RoughSolution>,
) -> Result<String> {
    let destination = stressfield::record::Destination::File(file.to_path_buf());
    let summary = if scene.wear.is_some() {
        let study = super::wear::study(scene)?;
        record_wear(scene, &destination, &study)
    } else if scene.draws_plastic_sheet() {
        let study = super::plastic::solve(scene)?;
        stressfield::record::record_plastic_to(scene, &destination, &study)
    } else {
        stressfield::record::record_to_with(scene, &destination, &|| bar.inc(1), rough)
    };
    let summary = if file == shown {
        summary?
    } else {
        anyhow::Context::with_context(summary, || format!("cannot record {}", shown.display()))?
    };
    Ok(format!(
        "recorded {}{}",
        shown.display(),
        summary_text(scene, &summary)
    ))
}

/// Records a wear scene from its study into `file`, saying it was recorded to `shown`.
#[cfg(feature = "rerun")]
pub(super) fn record_wear_as(
    scene: &Scene,
    file: &Path,
    shown: &Path,
    study: &stressfield::study::wear::WearStudy,
) -> Result<String> {
    let destination = stressfield::record::Destination::File(file.to_path_buf());
    let summary = anyhow::Context::with_context(record_wear(scene, &destination, study), || {
        format!("cannot record {}", shown.display())
    })?;
    Ok(format!(
        "recorded {}{}",
        shown.display(),
        summary_text(scene, &summary)
    ))
}

/// Records a `[plasticity]` scene from its study into `file`, saying it was recorded to
/// `shown`.
#[cfg(feature = "rerun")]
pub(super) fn record_plastic_as(
    scene: &Scene,
    file: &Path,
    shown: &Path,
    study: &stressfield::study::plastic::PlasticStudy,
) -> Result<String> {
    let destination = stressfield::record::Destination::File(file.to_path_buf());
    let summary = anyhow::Context::with_context(
        stressfield::record::record_plastic_to(scene, &destination, study),
        || format!("cannot record {}", shown.display()),
    )?;
    Ok(format!(
        "recorded {}{}",
        shown.display(),
        summary_text(scene, &summary)
    ))
}

#[cfg(not(feature = "rerun"))]
pub(super) fn record_plastic_as(
    scene: &Scene,
    _file: &Path,
    _shown: &Path,
    _study: &stressfield::study::plastic::PlasticStudy,
) -> Result<String> {
    anyhow::bail!(
        "scene {}: this build has no Rerun support (built with --no-default-features)\nhint: rebuild with the default features: cargo build --release",
        scene.name
    )
}

#[cfg(not(feature = "rerun"))]
pub(super) fn record_wear_as(
    scene: &Scene,
    _file: &Path,
    _shown: &Path,
    _study: &stressfield::study::wear::WearStudy,
) -> Result<String> {
    anyhow::bail!(
        "scene {}: this build has no Rerun support (built with --no-default-features)\nhint: rebuild with the default features: cargo build --release",
        scene.name
    )
}

/// Records a wear scene's study (its steps' sections computed here, once) to `destination`.
#[cfg(feature = "rerun")]
pub(super) fn record_wear(
    scene: &Scene,
    destination: &stressfield::record::Destination,
    study: &stressfield::study::wear::WearStudy,
) -> Result<stressfield::record::Summary, stressfield::record::RecordError> {
    let bar = super::console::spinner("sections through each step's maximum");
    let sections = stressfield::study::wear::sections(study, &mut |_| bar.tick());
    bar.finish_and_clear();
    stressfield::record::record_wear_to(scene, destination, study, &sections?)
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
    let summary = if scene.wear.is_some() {
        let study = super::wear::study(scene)?;
        record_wear(scene, &destination, &study)?
    } else if scene.draws_plastic_sheet() {
        let study = super::plastic::solve(scene)?;
        stressfield::record::record_plastic_to(scene, &destination, &study)?
    } else {
        stressfield::record::record_to(scene, &destination, &|| bar.inc(1))?
    };
    Ok(format!(
        "streamed {} to {destination}{}",
        scene.name,
        summary_text(scene, &summary)
    ))
}

#[cfg(not(feature = "rerun"))]
pub(super) fn record_scene_as(
    _scene: &Scene,
    _file: &Path,
    _shown: &Path,
    _bar: &ProgressBar,
    _rough: Option<&RoughSolution>,
) -> Result<String> {
    anyhow::bail!(
        "this build has no Rerun support (built with --no-default-features)\nhint: rebuild with the default features: cargo build --release"
    )
}

#[cfg(not(feature = "rerun"))]
fn stream_scene(_scene: &Scene, target: &Target, _bar: &ProgressBar) -> Result<String> {
    let place = match target {
        Target::Connect(url) => format!("the viewer at {url}"),
        Target::Spawn => "a new viewer".to_string(),
        Target::Stdout => "standard output".to_string(),
        Target::OutDir(dir) => dir.display().to_string(),
        Target::File(path) => path.display().to_string(),
    };
    anyhow::bail!(
        "this build has no Rerun support (built with --no-default-features), so it cannot record to {place}\nhint: rebuild with the default features: cargo build --release"
    )
}
