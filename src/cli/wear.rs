//! `wear SCENE [--json] [--heights-out DIR]`: a rough contact's evolution with sliding
//! distance, step by step.

use std::path::Path;

use anyhow::{bail, Context, Result};

use super::console::{print_out, progress_bar};
use stressfield::io::output::Staged;
use stressfield::report::wear::WearReport;
use stressfield::study::wear::{self, WearProgress, WearStudy};

/// The study of a wear scene, with a progress bar on a terminal.
pub(crate) fn study(scene: &stressfield::scene::Scene) -> Result<WearStudy> {
    let total = scene
        .wear
        .as_ref()
        .map_or(0, stressfield::study::wear::step_count);
    let bar = progress_bar(total as u64);
    let result = wear::study(scene, &mut |progress| match progress {
        WearProgress::Solving {
            step,
            iteration,
            residual,
            ..
        } => {
            bar.set_position(step as u64);
            bar.set_message(format!("step {step}: it. {iteration}, {residual:.0e}"));
        }
        WearProgress::Maxima { step, .. } => {
            bar.set_message(format!("step {step}: maxima"));
        }
    });
    bar.finish_and_clear();
    Ok(result?)
}

/// The `.npy` file of step `index` under `dir`, and the `[[series]]` fragment that reads them
/// back.
fn step_file(scene: &str, index: usize) -> String {
    format!("{scene}_step_{index:03}.npy")
}

/// `wear SCENE [--json] [--heights-out DIR]`.
pub fn wear(scene_path: &Path, json: bool, heights_out: Option<&Path>) -> Result<()> {
    let scene = stressfield::study::load_scene(scene_path)?;
    if scene.wear.is_none() {
        bail!(
            "{} has no [wear] or [[series]]\nhint: add [wear] with coefficient = \"2e-6 mm^3/(N m)\", distance = \"20 m\" and steps = 40 to a rough scene (contact.kind = \"rough\"); see docs/wear.md",
            scene_path.display()
        );
    }
    if let Some(dir) = heights_out {
        match std::fs::metadata(dir) {
            Ok(meta) if meta.is_dir() => {}
            Ok(_) => bail!(
                "--heights-out {}: is not a directory\nhint: give a directory for the steps' .npy files",
                dir.display()
            ),
            Err(e) => bail!(
                "--heights-out {}: {e}\nhint: create the directory first (mkdir -p {})",
                dir.display(),
                dir.display()
            ),
        }
        // Before anything is computed: a directory that takes no file is said at once.
        if let Err(e) = stressfield::io::output::probe_directory(dir) {
            bail!(
                "--heights-out {}: cannot write into it ({e})\nhint: give a writable directory",
                dir.display()
            );
        }
    }
    let study = study(&scene).with_context(|| format!("scene {}", scene.name))?;
    let report = WearReport::new(&study);
    if let Some(dir) = heights_out {
        let mut staged = Staged::new();
        let [dx, dy] = report.spacing_m;
        let mut fragment = format!(
            "# The worn heights of {} at each step (m, float64, [rows, columns], row = y), as a\n# measured series: paste below a rough scene's [contact] tables (replacing its [surface]\n# and [wear]). The simulation's heights are in its own frame, with no mounting tilt:\n# level = \"none\" solves them as the simulation did (the default, the first map's\n# least-squares plane removed from every map, would tilt a conformal scar).\n\n[surface]\nspacing = [\"{} m\", \"{} m\"]   # dx, dy\nlevel = \"none\"\n",
            scene.name,
            stressfield::io::text::number(dx),
            stressfield::io::text::number(dy)
        );
        for (index, step) in study.steps.iter().enumerate() {
            let name = step_file(&scene.name, index);
            let mut bytes = Vec::new();
            ndarray_npy::WriteNpyExt::write_npy(step.heights_m.as_ref(), &mut bytes)
                .context("encoding the heights as .npy")?;
            staged.add(&dir.join(&name), &bytes)?;
            fragment.push_str(&format!(
                "\n[[series]]\nfile = \"{name}\"\ndistance = \"{} m\"\n",
                stressfield::io::text::number(step.sliding_distance_m)
            ));
        }
        staged.add(
            &dir.join(format!("{}_series.toml", scene.name)),
            fragment.as_bytes(),
        )?;
        staged.commit()?;
    }
    if json {
        print_out(&format!("{}\n", report.json()))
    } else {
        let mut text = report.text(&scene);
        if let Some(dir) = heights_out {
            text.push_str(&format!(
                "worn heights written to {} ({}_step_NNN.npy: m, float64, [rows, columns], row = y; {}_series.toml lists them as a [[series]])\n",
                dir.display(),
                scene.name,
                scene.name
            ));
        }
        print_out(&text)
    }
}
