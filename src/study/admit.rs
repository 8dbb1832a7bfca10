//! Whether a validated scene can be computed here: the second stage of reading a scene, after
//! [`crate::scene`] has checked what the user wrote. The checks need what only the study knows
//! (the grid planes of the panels, the speed sweep's grid), so they live here rather than in
//! the file format: the figure's memory, the memory of a recording's sections, which
//! scenes a speed sweep can take and how fast it can go, and the heating's grid, memory and
//! time ([`super::heating_plan`]).
//!
//! Every command reads its scenes through [`load_scene`] (or [`parse_scene`]), so a scene that
//! passes `check` can be computed.

use std::path::Path;

use super::memory::{figure_bytes, KEPT_BYTES_PER_POINT, WORKING_BYTES_PER_POINT};
use super::plane;
use super::thermal_sweep::{peclet_limit, refusal, SWEEP_CELLS};
use crate::field::{memory_limit_bytes, MAX_FIELD_BYTES};
use crate::scene::{Scene, SceneError, SweepParameter};

/// Reads and validates a scene file ([`Scene::load`]), then [`admit`]s it.
pub fn load_scene(path: &Path) -> Result<Scene, SceneError> {
    let scene = Scene::load(path)?;
    admit(&scene, &path.display().to_string())?;
    Ok(scene)
}

/// Parses and validates scene text ([`Scene::parse`]), then [`admit`]s it.
pub fn parse_scene(text: &str, name: &str, file: &str) -> Result<Scene, SceneError> {
    let scene = Scene::parse(text, name, file)?;
    admit(&scene, file)?;
    Ok(scene)
}

/// Refuses a valid `scene` (read from `file`) that cannot be computed here, with the key to
/// change and how.
pub fn admit(scene: &Scene, file: &str) -> Result<(), SceneError> {
    let error = |key: &str, message: String, hint: &str| SceneError {
        file: file.into(),
        key: Some(key.into()),
        line_column: None,
        message,
        hint: Some(hint.into()),
    };
    // The whole figure: every panel's grid and buffers, and the image.
    let bytes = figure_bytes(scene);
    if bytes > MAX_FIELD_BYTES {
        let points: usize = scene.panels.iter().map(|p| plane(scene, p).points()).sum();
        return Err(error(
            "figure.resolution",
            format!(
                "{points} points in {} panel(s) need about {} MiB to draw (the grids at about {} bytes a point, and the image), more than the {} MiB allowed",
                scene.panels.len(),
                bytes >> 20,
                KEPT_BYTES_PER_POINT + WORKING_BYTES_PER_POINT,
                MAX_FIELD_BYTES >> 20
            ),
            "lower figure.resolution (600 to 1200 is plenty for a figure)",
        ));
    }
    // A wear scene keeps every step's pressure, gap, worn heights and wear depth, besides the
    // contact's solver and search ([`super::heating_plan::wear_cost`]).
    if let (Some(spec), Some(surface)) = (&scene.wear, &scene.surface) {
        let steps = super::wear::step_count(spec);
        let shape = surface.heights.shape();
        let (bytes, _) = super::heating_plan::wear_cost(scene, shape);
        let limit = memory_limit_bytes();
        if bytes > limit {
            let key = match spec {
                crate::scene::WearSpec::Archard { .. } => "wear.steps",
                crate::scene::WearSpec::Series(_) => "series",
            };
            return Err(error(
                key,
                format!(
                    "{steps} steps of a {} x {} map need about {} MiB (each step's pressure, gap, worn heights and wear depth, {} bytes a cell, and the solver and search), more than the {} MiB this machine allows",
                    shape[1],
                    shape[0],
                    bytes >> 20,
                    super::wear::bytes_per_step([1, 1]),
                    limit >> 20
                ),
                "use fewer steps, or a coarser map",
            ));
        }
    }
    // A rough contact: the solve and the subsurface search within the memory allowed
    // (estimated, [`super::heating_plan::rough_contact_cost`], coated or not; issue 41).
    if let (crate::scene::ContactKind::Rough, Some(surface)) = (scene.contact.kind, &scene.surface)
    {
        let shape = surface.heights.shape();
        let (bytes, seconds, per_cell) = super::heating_plan::rough_contact_cost(scene, shape);
        let limit = memory_limit_bytes();
        if bytes > limit {
            let key = if surface.generated {
                "surface.generate.samples"
            } else {
                "surface.file"
            };
            return Err(error(
                key,
                format!(
                    "the contact of a {} x {} map needs about {} of CPU and {} ({} bytes a cell), more than the {} this machine allows",
                    shape[1],
                    shape[0],
                    super::heating_plan::duration(seconds),
                    crate::io::text::bytes(bytes as u64),
                    per_cell,
                    crate::io::text::bytes(limit as u64)
                ),
                "use a coarser map (half the samples a side takes a quarter of the memory)",
            ));
        }
    }
    // The heating: its grid resolves the speeds, and its memory and time are within the
    // limits (issue 42, classes 2 and 4), refused under the key the scene wrote.
    if let Err(refusal) = super::heating_plan::plan(scene) {
        return Err(error(&refusal.key, refusal.message, &refusal.hint));
    }
    let Some(sweep) = &scene.sweep else {
        return Ok(());
    };
    if sweep.parameter == SweepParameter::Peclet {
        if let Some((message, hint)) = refusal(scene) {
            return Err(error("sweep.parameter", message.into(), hint));
        }
        if let Some(spec) = &scene.thermal {
            // A hair below the limit, so that rounding in the grid cannot exceed it.
            let limit = peclet_limit(spec) * (1.0 - 1e-9);
            // Generated values lie between `from` and `to`, which name them.
            let last = sweep.values.len() - 1;
            let mut steps: Vec<usize> = (0..=last).collect();
            if sweep.generated {
                steps = vec![0, last];
            }
            if let Some(k) = steps.into_iter().find(|&k| sweep.values[k] > limit) {
                return Err(error(
                    &sweep.value_key(k),
                    format!(
                        "Pe = {} is beyond what the sweep's grid resolves: at most {} for these bodies ({SWEEP_CELLS} cells across 6a, a cell Péclet number V dx / (2κ) of at most 2 for every heated body)",
                        crate::io::text::number(sweep.values[k]),
                        crate::io::text::significant(limit, 4, 1e6, true)
                    ),
                    "lower it: beyond, the maximum temperature follows the fast (Jaeger, Blok) limit, growing as √Pe",
                ));
            }
        }
    }
    // A recording holds every step's sections (to give each panel one colour range).
    let plane_bytes: usize = scene
        .panels
        .iter()
        .map(|p| {
            let plane = plane(scene, p);
            plane.u.count * plane.v.count * 8
        })
        .sum();
    let bytes = plane_bytes.saturating_mul(sweep.values.len());
    let limit = memory_limit_bytes();
    if bytes > limit {
        return Err(error(
            "sweep",
            format!(
                "{} steps of {} MiB of sections need {} MiB, more than the {} MiB this machine allows",
                sweep.values.len(),
                plane_bytes >> 20,
                bytes >> 20,
                limit >> 20
            ),
            "use fewer steps or a lower figure.resolution",
        ));
    }
    Ok(())
}

/// Why a recording of `scene` would leave out its `[thermal]`, or `None`: the heating is
/// recorded as a speed (Péclet) sweep only, so a recording of one state (no `[sweep]`, or a
/// `[volume]`) of a heated scene is refused rather than silently isothermal (issue 42, class
/// 9; a friction, load or position sweep with `[thermal]` is refused by the scene reader). A
/// wear scene records its own steps.
pub fn unrecorded_heating(scene: &Scene) -> Option<String> {
    let speed_sweep = scene
        .sweep
        .as_ref()
        .is_some_and(|s| s.parameter == SweepParameter::Peclet);
    if scene.thermal.is_none() || speed_sweep || scene.wear.is_some() {
        return None;
    }
    Some(
        "key `thermal`: a recording of one state records the contact's stress field without heating: [thermal] would be left out\nhint: `stressfield thermal SCENE` reports the heating (--figure draws it) and `render` draws the heating sheet beside the figure; to record the heating as the speed rises, add [sweep] with parameter = \"peclet\" (a line, point or elliptical contact)"
            .to_string(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOO_FINE: &str = "format = 1\n[contact]\nkind = \"line\"\n[figure]\nx = [-1.0, 1.0]\nz = [0.0, 40.0]\nresolution = 20000\n";

    /// The file format takes a figure too fine to draw; the study refuses it, by its key.
    #[test]
    fn a_figure_beyond_memory_is_valid_but_not_admitted() {
        let scene = Scene::parse(TOO_FINE, "t", "t.toml").expect("a valid scene");
        let error = parse_scene(TOO_FINE, "t", "t.toml").expect_err("refused");
        assert_eq!(error.key.as_deref(), Some("figure.resolution"));
        assert!(error.message.contains("MiB to draw"), "{error}");
        assert!(admit(&scene, "t.toml").is_err());
        let fine = TOO_FINE.replace("20000", "400");
        assert!(parse_scene(&fine, "t", "t.toml").is_ok());
    }

    /// A speed sweep beyond the grid's Péclet limit is named by the key the user wrote: the
    /// listed value, or `from`/`to` for generated steps (never a step between them).
    #[test]
    fn a_peclet_beyond_the_grid_names_the_value_written() {
        let base = "format = 1\n[contact]\nkind = \"point\"\nload = \"100 N\"\nfriction = 0.3\n[contact.body1]\nmaterial = \"steel\"\nradius = \"10 mm\"\n[contact.body2]\nmaterial = \"steel\"\nradius = \"flat\"\n[thermal]\nspeed = \"1 m/s\"\n[figure]\nx = [-2.0, 2.0]\nz = [0.0, 2.0]\nresolution = 60\n";
        let cases = [
            ("values = [1.0, 500.0, 2.0]", "sweep.values[1]"),
            ("from = 0.1\nto = 500.0\nsteps = 5", "sweep.to"),
            ("from = 500.0\nto = 0.1\nsteps = 5", "sweep.from"),
        ];
        for (values, key) in cases {
            let text = format!("{base}[sweep]\nparameter = \"peclet\"\n{values}\n");
            Scene::parse(&text, "t", "t.toml").expect("a valid scene");
            let error = parse_scene(&text, "t", "t.toml").expect_err("refused");
            assert_eq!(error.key.as_deref(), Some(key), "{values}: {error}");
            assert!(error.message.contains("Pe = 500"), "{error}");
        }
        let within =
            format!("{base}[sweep]\nparameter = \"peclet\"\nfrom = 0.1\nto = 100.0\nsteps = 4\n");
        assert!(parse_scene(&within, "t", "t.toml").is_ok());
    }
}
