//! `thermal`: the frictional heating of a scene reported; the study shared with `hertz` and
//! `contact`.

use std::path::Path;

use anyhow::{bail, Context, Result};

use super::console::{print_out, progress_bar};
use super::npy::{has_extension, is_device, npy_bytes, npy_path, Reserved};
use stressfield::contact::rough::RoughSolution;
use stressfield::io::output::Staged;
use stressfield::report::thermal::ThermalReport;
use stressfield::scene::{ContactKind, Scene};
use stressfield::study;
use stressfield::study::gear_heating::GearHeating;
use stressfield::study::thermal::ThermalStudy;

/// The heating of `scene` (which has `[thermal]`), with a progress bar over the depths; `known`:
/// `contact`'s own maxima of the rough contact, when already found.
pub(crate) fn study(
    scene: &Scene,
    rough: Option<&RoughSolution>,
    known: Option<study::thermal::ContactMaxima>,
) -> Result<ThermalStudy> {
    let bar = progress_bar(study::thermal::DEPTHS_OVER_A.len() as u64);
    bar.set_message("thermal stress by depth");
    let result = study::thermal::study_with(scene, rough, known, &mut |progress| match progress {
        study::thermal::Progress::Coupled { iteration, change } => bar.set_message(format!(
            "coupled iteration {iteration}: pressure change {change:.1e}"
        )),
        study::thermal::Progress::Depth { done, total } => {
            bar.set_message("thermal stress by depth");
            bar.set_length(total as u64);
            bar.set_position(done as u64)
        }
        study::thermal::Progress::Path { .. } => {}
    });
    bar.finish_and_clear();
    // The caller names the scene (`render` prefixes each scene's error with it).
    result.context("frictional heating")
}

/// The heating of running spur gears along the path of contact, with a progress bar.
fn gear_heating(scene: &Scene) -> Result<GearHeating> {
    let total = (study::gear_heating::PATH_POINTS + study::thermal::DEPTHS_OVER_A.len()) as u64;
    let bar = progress_bar(total);
    bar.set_message("flash temperature along the path of contact");
    let result = study::gear_heating::gear_heating(scene, &mut |progress| match progress {
        study::thermal::Progress::Path { done, .. } => bar.set_position(done as u64),
        study::thermal::Progress::Depth { done, .. } => {
            bar.set_message("thermal stress by depth at the hottest point");
            bar.set_position((study::gear_heating::PATH_POINTS + done) as u64)
        }
        study::thermal::Progress::Coupled { .. } => {}
    });
    bar.finish_and_clear();
    result.context("frictional heating of the gears")
}

/// The heating of a Hertz scene with `[thermal]` (gears along their path) as reported by
/// `hertz` and `thermal`, and the study its stresses come from.
pub(crate) fn hertz_heating(scene: &Scene) -> Result<(ThermalReport, ThermalStudy)> {
    let (report, study, _) = heating(scene)?;
    Ok((report, study))
}

/// As [`hertz_heating`], with the gears' path when there is one.
fn heating(scene: &Scene) -> Result<(ThermalReport, ThermalStudy, Option<GearHeating>)> {
    let with_gears = scene.thermal.and_then(|t| t.gear).is_some();
    Ok(if with_gears {
        let gear = gear_heating(scene)?;
        (
            ThermalReport::for_gears(&gear),
            gear.study.clone(),
            Some(gear),
        )
    } else {
        let study = study(scene, None, None)?;
        (ThermalReport::new(&study), study, None)
    })
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
    let (_, study, gear) = heating(scene)?;
    let sheet = heating_sheet(scene, &study, gear.as_ref())?;
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
    let computed = heating_outputs(&scene, figure.is_some(), svg)
        .with_context(|| format!("scene {}", scene.name))?;
    let (report, study, drawing) = computed;
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
        text.push_str(&report.text(&study));
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

/// What `thermal` computes: the report, the study, and the heating sheet when asked for.
fn heating_outputs(
    scene: &Scene,
    sheet: bool,
    svg: bool,
) -> Result<(ThermalReport, ThermalStudy, Option<Vec<u8>>)> {
    let rough = if scene.contact.kind == ContactKind::Rough {
        Some(study::rough::solve(scene, &mut |_, _| {})?)
    } else {
        None
    };
    let (report, study, gear) = match &rough {
        Some(solution) => {
            let study = study(scene, Some(solution), None)?;
            (ThermalReport::new(&study), study, None)
        }
        None => heating(scene)?,
    };
    let drawing = if sheet {
        let sheet = heating_sheet(scene, &study, gear.as_ref())?;
        Some(if svg {
            stressfield::render::chart::sheet_svg(&sheet)?.into_bytes()
        } else {
            stressfield::render::encode_png(&stressfield::render::chart::sheet_png(&sheet)?)?
        })
    } else {
        None
    };
    Ok((report, study, drawing))
}
