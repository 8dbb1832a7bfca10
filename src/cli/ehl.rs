//! `ehl SCENE [--json] [--pressure FILE.npy]`: the numerical EHL solution of a lubricated line
//! contact and the stress under it.

use std::path::Path;

use anyhow::{bail, Context, Result};

use super::console::{print_out, spinner};
use super::npy::{npy_bytes, npy_path, Reserved};
use stressfield::io::output::Staged;
use stressfield::report::lubrication::EhlReport;

/// `ehl SCENE [--json] [--pressure FILE.npy]`.
pub fn ehl(scene_path: &Path, json: bool, pressure: Option<&Path>) -> Result<()> {
    let scene = stressfield::study::load_scene(scene_path)?;
    if let Some(path) = pressure {
        npy_path("--pressure", path)?;
    }
    // Reserved before the solve: a missing directory is said at once.
    let mut staged = Staged::new();
    let pressure_file = pressure
        .map(|path| Reserved::new(&mut staged, path))
        .transpose()?;
    let bar = spinner("solving the elastohydrodynamic film");
    let study = stressfield::study::ehl::solve(&scene);
    bar.finish_and_clear();
    let study = study.with_context(|| format!("scene {}", scene.name))?;
    let report = EhlReport::new(&scene, &study);
    if !study.solution.converged {
        // Said, never written as a solution: no file, a non-zero exit.
        let text = if json { report.json() } else { report.text() };
        print_out(&format!("{text}\n"))?;
        bail!(
            "scene {}: the EHL solution did not converge after {} Newton iterations{}\nhint: the solver is checked for Moes' M from 0.2 to 2000 and L up to 46 (docs/lubrication.md); outside that range, or with extreme lubricants, it may fail",
            scene.name,
            study.solution.iterations,
            if pressure.is_some() { " (no .npy written)" } else { "" }
        );
    }
    if let Some(file) = &pressure_file {
        let array = stressfield::study::ehl::solution_array(&study.solution);
        file.fill(&npy_bytes(&array, "EHL solution")?)?;
    }
    staged.commit()?;
    if json {
        return print_out(&format!("{}\n", report.json()));
    }
    let mut text = report.text();
    if let Some(path) = pressure {
        text.push_str(&format!(
            "solution written to {} (float64, (n, 3): x m, pressure Pa, film m; entrainment in +x)\n",
            path.display()
        ));
    }
    print_out(&text)
}

/// The EHL sheet of a lubricated line scene as PNG bytes (`render` writes it beside the
/// scene's figure as `NAME_ehl.png`): a scene whose solution does not converge is refused.
pub(crate) fn ehl_png(scene: &stressfield::scene::Scene) -> Result<Vec<u8>> {
    let study = stressfield::study::ehl::solve(scene)?;
    if !study.solution.converged {
        bail!(
            "the EHL solution did not converge after {} Newton iterations: no sheet drawn\nhint: `stressfield ehl {}` reports the iterations (docs/lubrication.md)",
            study.solution.iterations,
            scene.name
        );
    }
    let sections = stressfield::study::ehl::sections(
        &study,
        stressfield::study::ehl::SHEET_COLUMNS,
        stressfield::study::ehl::SHEET_ROWS,
    )?;
    let title = scene.title.clone().unwrap_or_else(|| scene.name.clone());
    let sheet = stressfield::figure::ehl::ehl_sheet(&title, &study, &sections);
    Ok(stressfield::render::encode_png(
        &stressfield::render::chart::sheet_png(&sheet)?,
    )?)
}
