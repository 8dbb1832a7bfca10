//! `check`: validate scenes and say what each would draw.

use std::path::PathBuf;

use anyhow::{bail, Result};

use super::console::{print_err, print_out};
use stressfield::scene::{ContactKind, Scene};
use stressfield::study;

pub(super) fn check(paths: &[PathBuf]) -> Result<()> {
    let mut failed = 0;
    for path in paths {
        match stressfield::study::load_scene(path) {
            Ok(scene)
                if study::plastic::plan(&scene).is_some_and(|p| p.beyond_limits().is_some()) =>
            {
                let why = study::plastic::plan(&scene).and_then(|p| p.beyond_limits());
                print_err(&format!(
                    "error: {}: {}",
                    path.display(),
                    why.unwrap_or_default()
                ));
                failed += 1;
            }
            Ok(scene) => print_out(&format!(
                "ok {} ({}{})\n",
                path.display(),
                check_summary(&scene),
                heating_summary(&scene)
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
            if scene.wear.is_some() {
                // The whole run: every step, its maxima and its heating (issue 50).
                let (bytes, seconds) = study::heating_plan::wear_cost(scene, [ny, nx]);
                return format!(
                    "{kind}, {nx} x {ny} samples; wear: about {} of CPU and {} in all",
                    study::heating_plan::duration(seconds),
                    stressfield::io::text::bytes(bytes as u64)
                );
            }
            if scene.contact.kind == ContactKind::Rough && scene.thermal.is_none() {
                // What `contact` will take (issue 41): estimated before anything is computed.
                let (bytes, seconds, _) = study::heating_plan::rough_contact_cost(scene, [ny, nx]);
                return format!(
                    "{kind}, {nx} x {ny} samples; contact: about {} of CPU and {}",
                    study::heating_plan::duration(seconds),
                    stressfield::io::text::bytes(bytes as u64)
                );
            }
            format!("{kind}, {nx} x {ny} samples")
        }
        (None, _) if scene.contact.coating.is_some() => {
            // What `hertz` of a coated scene will take (issue 50), the grid already admitted.
            let line = scene.contact.kind == ContactKind::Line;
            let cells = scene.numerical.cells;
            match study::coated::admit_grid(scene) {
                Ok(Some((bytes, seconds))) => format!(
                    "coated contact, {}; about {} of CPU and {}",
                    if line {
                        format!("{cells} strips")
                    } else {
                        format!("{cells} x {cells} cells")
                    },
                    study::heating_plan::duration(seconds),
                    stressfield::io::text::bytes(bytes as u64)
                ),
                _ => "coated contact".into(),
            }
        }
        (None, Some(_)) => {
            let sizes: Vec<(usize, usize)> = scene
                .panels
                .iter()
                .map(|panel| {
                    let plane = study::plane(scene, panel);
                    (plane.u.count, plane.v.count)
                })
                .collect();
            let text = |(u, v): (usize, usize)| format!("{u} x {v}");
            if sizes.iter().all(|s| *s == sizes[0]) {
                format!("{} panel(s), {} points each", sizes.len(), text(sizes[0]))
            } else {
                // Panels in different planes (or on another grid): each its own.
                let all: Vec<String> = sizes.into_iter().map(text).collect();
                format!("{} panel(s), {} points", all.len(), all.join(", "))
            }
        }
        (None, None) => "no panels".into(),
    }
}

/// What the heating of a scene with `[thermal]` will take (`; heating: 129 x 97 cells, about
/// 8 s of CPU ...`), or nothing.
fn heating_summary(scene: &Scene) -> String {
    if let Some(plan) = study::plastic::plan(scene) {
        let [nz, ny, nx] = plan.cells;
        return format!(
            "; plastic: {nx} x {ny} x {nz} cells, {} steps, about {} of CPU and {}",
            plan.steps,
            study::heating_plan::duration(plan.cpu_seconds),
            stressfield::io::text::bytes(plan.bytes as u64)
        );
    }
    if let Some(spec) = &scene.wear {
        // A wear scene heats each step's contact: its flash temperature only (and the coupled
        // contact, with coupled = true), not the heating study's stresses.
        return match &scene.thermal {
            Some(thermal) => format!(
                "; {} wear steps, each with its flash temperature{}",
                study::wear::step_count(spec),
                if thermal.coupled {
                    " and its coupled contact"
                } else {
                    ""
                }
            ),
            None => format!("; {} wear steps", study::wear::step_count(spec)),
        };
    }
    match study::heating_plan::plan(scene) {
        Ok(Some(plan)) if plan.line => format!(
            "; heating: a plane problem of {} strips, {}",
            plan.shape[1],
            study::heating_plan::duration(plan.cpu_seconds + plan.sheet_cpu_seconds)
        ),
        Ok(Some(plan)) => format!("; heating: {}", plan.summary()),
        _ => String::new(),
    }
}
