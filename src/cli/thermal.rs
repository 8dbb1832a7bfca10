//! `thermal`: the frictional heating of a scene reported ([`stressfield::study::commands`]
//! computes it, as for `hertz` and `contact`), and its heating sheet.

use std::path::Path;

use anyhow::{bail, Context, Result};

use super::console::{print_out, progress_bar, StudyBars};
use super::npy::{has_extension, is_device, npy_bytes, npy_path, Reserved};
use stressfield::io::output::Staged;
use stressfield::report::commands::heating_report;
use stressfield::scene::Scene;
use stressfield::study;
use stressfield::study::commands::{CommandError, Heating};
use stressfield::study::gear_heating::GearHeating;
use stressfield::study::thermal::ThermalStudy;

/// The heating of a scene with `[thermal]` as `thermal` computes it (a rough scene's on its
/// solved contact; gears along their path), with progress bars: the study the Python
/// package's `Scene.thermal` runs too (issue 50).
fn heating(scene: &Scene) -> Result<Heating> {
    let mut bars = StudyBars::new(scene);
    let heating = study::commands::thermal(scene, &mut |p| bars.show(p));
    bars.finish(None);
    Ok(heating?)
}

/// The heating sheet of `study` (with the gears' path), its sections computed with a
/// progress bar.
fn heating_sheet(
    scene: &Scene,
    study: &ThermalStudy,
    gear: Option<&GearHeating>,
) -> Result<stressfield::render::chart::Sheet> {
    let bar = progress_bar(study::thermal_sections::SECTION_STEPS as u64 + 1);
    bar.set_message("thermal sections by depth");
    let sections = study::thermal_sections::sections(study, &mut |done, total| {
        bar.set_length(total as u64);
        bar.set_position(done as u64)
    });
    bar.finish_and_clear();
    let sections = sections.context("heating sections")?;
    Ok(stressfield::figure::thermal::thermal_sheet(
        &scene.name,
        study,
        &sections,
        gear,
    ))
}

/// The heating sheet of a Hertz or gear scene with `[thermal]` as a PNG, for `render`'s
/// batch (`NAME_heating.png` beside the scene's figure).
pub(crate) fn heating_png(scene: &Scene) -> Result<Vec<u8>> {
    // `render` names the scene in front of its errors: the heating's step alone here.
    let mut bars = StudyBars::new(scene);
    let heating = study::commands::thermal(scene, &mut |p| bars.show(p));
    bars.finish(None);
    let heating = heating.map_err(|e| match e {
        CommandError::Heating { error, .. } => anyhow::Error::new(*error),
        other => anyhow::Error::new(other),
    })?;
    let sheet = heating_sheet(scene, heating.study(), heating.gears())?;
    Ok(stressfield::render::encode_png(
        &stressfield::render::chart::sheet_png(&sheet)?,
    )?)
}

/// `thermal SCENE [--json] [--temperature FILE.npy] [--figure FILE.png|svg]`.
///
/// The outputs follow one policy (issue 42, classes 5 and 6): their paths are checked and
/// reserved before anything is computed (an extension in any case; a device or FIFO written
/// through whatever its name; a missing directory refused at once), and they are written all
/// or none once everything is computed.
pub fn thermal(
    scene_path: &Path,
    json: bool,
    temperature: Option<&Path>,
    figure: Option<&Path>,
) -> Result<()> {
    let scene = stressfield::study::load_scene(scene_path)?;
    if scene.thermal.is_none() {
        bail!(
            "{} has no [thermal] table\nhint: add [thermal] with speed = \"2 m/s\" and the bodies' thermal properties (material = \"steel\", or conductivity, diffusivity, expansion); see docs/heating.md",
            scene_path.display()
        );
    }
    if let Some(path) = temperature {
        npy_path("--temperature", path)?;
    }
    // The sheet's format from the extension (any case); a device without one takes a PNG.
    let svg = match figure {
        None => false,
        Some(path) if has_extension(path, "svg") => true,
        Some(path) if has_extension(path, "png") || is_device(path) => false,
        Some(path) => bail!(
            "--figure {}: the figure is written as .png or .svg\nhint: give a file name ending in .png or .svg",
            path.display()
        ),
    };
    let mut staged = Staged::new();
    let temperature_file = temperature
        .map(|path| Reserved::new(&mut staged, path))
        .transpose()?;
    let figure_file = figure
        .map(|path| Reserved::new(&mut staged, path))
        .transpose()?;
    let (heating, drawing) = heating_outputs(&scene, figure.is_some(), svg)?;
    let (report, study) = (heating_report(&heating), heating.study());
    if let Some(file) = &temperature_file {
        file.fill(&npy_bytes(&study.body1.temperature_k, "temperature")?)?;
    }
    if let (Some(file), Some(bytes)) = (&figure_file, &drawing) {
        file.fill(bytes)?;
    }
    staged.commit()?;
    if json {
        print_out(&format!("{}\n", report.json()))
    } else {
        let mut text = format!("scene {}\n", scene.name);
        text.push_str(&report.text(study));
        if let Some(path) = figure {
            text.push_str(&format!("heating sheet written to {}\n", path.display()));
        }
        if let Some(path) = temperature {
            text.push_str(&format!(
                "body 1's surface temperature rise written to {} (K, float64, [rows, columns], row = y)\n",
                path.display()
            ));
        }
        print_out(&text)
    }
}

/// What `thermal` computes: the heating, and the heating sheet when asked for (its errors
/// named by the scene).
fn heating_outputs(scene: &Scene, sheet: bool, svg: bool) -> Result<(Heating, Option<Vec<u8>>)> {
    let heating = heating(scene)?;
    let drawing = || -> Result<Vec<u8>> {
        let sheet = heating_sheet(scene, heating.study(), heating.gears())?;
        Ok(if svg {
            stressfield::render::chart::sheet_svg(&sheet)?.into_bytes()
        } else {
            stressfield::render::encode_png(&stressfield::render::chart::sheet_png(&sheet)?)?
        })
    };
    let drawing = match sheet {
        true => Some(drawing().with_context(|| format!("scene {}", scene.name))?),
        false => None,
    };
    Ok((heating, drawing))
}
