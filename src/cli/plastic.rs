//! `plastic SCENE [--json] [--fields FILE.npz]`: the elastic-plastic contact of a scene with
//! `[plasticity]`, loaded step by step and unloaded.

use std::io::Cursor;
use std::path::Path;

use anyhow::{bail, Context, Result};
use ndarray::Array1;
use ndarray_npy::NpzWriter;

use super::console::{print_err, print_out, progress_bar};
use super::npy::{has_extension, is_device, Reserved};
use stressfield::io::output::Staged;
use stressfield::report::plastic::PlasticReport;
use stressfield::study::plastic::{
    self, components_last, final_plastic_strain, final_surface_displacement, PlasticStudy,
};

/// `plastic SCENE [--json] [--fields FILE.npz]`.
pub fn plastic(scene_path: &Path, json: bool, fields: Option<&Path>) -> Result<()> {
    let scene = stressfield::study::load_scene(scene_path)?;
    let Some(spec) = scene.plasticity else {
        bail!(plastic::not_plastic_message(
            &scene_path.display().to_string()
        ));
    };
    if let Some(path) = fields {
        if !has_extension(path, "npz") && !is_device(path) {
            bail!(
                "--fields writes a NumPy archive: give a path ending in .npz, got {}",
                path.display()
            );
        }
    }
    // The output reserved before anything is computed: a path that takes no file fails now.
    let mut staged = Staged::new();
    let reserved = fields
        .map(|path| Reserved::new(&mut staged, path))
        .transpose()?;
    let total = spec.steps + if spec.unload { spec.unload_steps } else { 0 };
    let bar = progress_bar(total as u64);
    let result = plastic::study(&scene, &mut |progress| {
        bar.set_position(progress.step as u64);
        bar.set_message(format!(
            "step {}: it. {}, {:.0e}",
            progress.step + 1,
            progress.iteration,
            progress.residual
        ));
    });
    bar.finish_and_clear();
    let study = result.with_context(|| format!("scene {}", scene.name))?;
    let report = PlasticReport::new(&study);
    if let Some(reserved) = &reserved {
        reserved.fill(&fields_npz(&study)?)?;
    }
    staged.commit()?;
    if json {
        print_out(&report.json())?;
        for warning in &study.warnings {
            print_err(&format!("warning: {warning}"));
        }
    } else {
        print_out(&report.text(&study))?;
    }
    Ok(())
}

/// The fields as a NumPy archive: `plastic_strain` (nz, ny, nx, the equivalent plastic
/// strain after the last step), `residual_stress` (nz, ny, nx, 6, Pa, after unloading;
/// components xx, yy, zz, yz, xz, xy), `stress` (the same at full load, the total stress),
/// `pressure` (ny, nx, Pa, at full load), `surface_displacement` (ny, nx, m, positive into the
/// body: the surface displacement of the plastic strain after the last step, the dent's
/// profile after unloading), `x`, `y` (cell centres from the axis), `z` (cell centres' depth), m.
/// A line contact's have one row in y (`ny = 1`, `y = [0]`).
fn fields_npz(study: &PlasticStudy) -> Result<Vec<u8>> {
    let error = |e: ndarray_npy::WriteNpzError| anyhow::anyhow!("encoding the fields: {e}");
    let mut npz = NpzWriter::new(Cursor::new(Vec::new()));
    npz.add_array("plastic_strain", final_plastic_strain(study))
        .map_err(error)?;
    npz.add_array(
        "stress",
        &components_last(&study.loaded_snapshot().stress_pa),
    )
    .map_err(error)?;
    if let Some(state) = study.unloaded_snapshot() {
        npz.add_array("residual_stress", &components_last(&state.stress_pa))
            .map_err(error)?;
    }
    npz.add_array("pressure", &study.loaded_snapshot().pressure_pa)
        .map_err(error)?;
    npz.add_array("surface_displacement", final_surface_displacement(study))
        .map_err(error)?;
    for (name, values) in [("x", &study.x_m), ("y", &study.y_m), ("z", &study.z_m)] {
        npz.add_array(name, &Array1::from(values.clone()))
            .map_err(error)?;
    }
    let cursor = npz.finish().map_err(error)?;
    Ok(cursor.into_inner())
}

/// The study of a `[plasticity]` scene for `render` and `record` (a progress bar over the
/// steps), the scene named in its error.
pub(crate) fn solve(scene: &stressfield::scene::Scene) -> Result<PlasticStudy> {
    let Some(spec) = scene.plasticity else {
        bail!("scene {} has no [plasticity]", scene.name);
    };
    let total = spec.steps + if spec.unload { spec.unload_steps } else { 0 };
    let bar = progress_bar(total as u64);
    let result = plastic::study(scene, &mut |progress| {
        bar.set_position(progress.step as u64);
        bar.set_message(format!(
            "{}: step {}, it. {}",
            scene.name,
            progress.step + 1,
            progress.iteration
        ));
    });
    bar.finish_and_clear();
    let study = result.with_context(|| format!("scene {}", scene.name))?;
    for warning in &study.warnings {
        print_err(&format!("warning: scene {}: {warning}", scene.name));
    }
    Ok(study)
}

/// The sheet of a `[plasticity]` scene (`render`'s PNG): the study's figures
/// ([`stressfield::figure::plastic`]).
pub(crate) fn sheet(
    scene: &stressfield::scene::Scene,
    study: &PlasticStudy,
) -> stressfield::render::chart::Sheet {
    let sections = plastic::history::sheet_sections(study);
    let title = scene.title.clone().unwrap_or_else(|| scene.name.clone());
    stressfield::figure::plastic::plastic_sheet(&title, study, &sections)
}
