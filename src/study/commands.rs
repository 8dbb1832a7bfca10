//! What the reporting commands compute of one scene, `hertz`, `contact` and `thermal`: which
//! study each kind of scene takes (a coated body's, a rough contact's with its findings and
//! heating, a surface's characterisation, the closed forms' maxima with their heating), in one
//! place for the command line and the Python package (`Scene.hertz`, `Scene.contact`,
//! `Scene.thermal`, `batch`), so that the two say the same by construction (issue 50: the
//! package once reported a coated scene as the uncoated Hertz contact of its coating).
//!
//! Errors carry the scene's name and the step that failed, as the command line prints them
//! after `error: ` ([`crate::io::text::error_text`] of the chain). The progress reports each
//! phase and answers whether to go on: a stop asked during the rough contact's solve ends it
//! between two iterations, one asked in another phase ends the study before the next phase
//! ([`CommandError::Interrupted`], never a result).

use std::ops::ControlFlow;

use crate::contact::rough::RoughSolution;
use crate::scene::{ContactKind, Scene};
use crate::study::assess::SceneMaxima;
use crate::study::coated::{CoatedStudy, CoatedStudyError};
use crate::study::gear_heating::GearHeating;
use crate::study::rough::{ContactFindings, RoughStudyError};
use crate::study::surface::SurfaceStudyError;
use crate::study::thermal::{ContactMaxima, ThermalStudy, ThermalStudyError};
use crate::surface::stats::Characterisation;

/// What a command's study reports while it works.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Progress {
    /// The rough contact's solver after an iteration.
    Solving { iteration: usize, residual: f64 },
    /// The rough contact is solved; its subsurface maxima are searched down to `depth_m`.
    Maxima { depth_m: f64 },
    /// The frictional heating's progress.
    Heating(crate::study::thermal::Progress),
}

/// Why a command's study failed; the text is the command line's.
#[derive(Debug, thiserror::Error)]
pub enum CommandError {
    /// A coated line, point or elliptical contact ([`crate::study::coated`]).
    #[error("scene {scene}")]
    Coated {
        scene: String,
        #[source]
        error: Box<CoatedStudyError>,
    },
    /// The rough contact's solve.
    #[error("scene {scene}")]
    Solve {
        scene: String,
        #[source]
        error: Box<RoughStudyError>,
    },
    /// The rough contact's findings (subsurface maxima, plasticity index).
    #[error(transparent)]
    Findings(Box<RoughStudyError>),
    #[error("scene {scene}")]
    Heating {
        scene: String,
        #[source]
        error: Box<HeatingError>,
    },
    /// A surface scene's characterisation (`surface` names its source).
    #[error("characterising {surface}")]
    Surface {
        surface: String,
        #[source]
        error: Box<SurfaceStudyError>,
    },
    /// The progress asked to stop before `next` began.
    #[error("scene {scene}: interrupted before {next}: no result")]
    Interrupted { scene: String, next: &'static str },
}

impl CommandError {
    /// Whether the study stopped because its progress asked it to (here, or in the rough
    /// contact's solver).
    pub fn is_interrupted(&self) -> bool {
        match self {
            CommandError::Interrupted { .. } => true,
            CommandError::Solve { error, .. } => matches!(
                **error,
                RoughStudyError::Contact(
                    crate::contact::rough::RoughContactError::Interrupted { .. }
                )
            ),
            _ => false,
        }
    }
}

/// The heating's step that failed.
#[derive(Debug, thiserror::Error)]
pub enum HeatingError {
    #[error("frictional heating")]
    Contact(#[source] ThermalStudyError),
    #[error("frictional heating of the gears")]
    Gears(#[source] ThermalStudyError),
}

/// The frictional heating of a scene with `[thermal]`: at the contact, or along the path of
/// contact of running spur gears (with the full study at the hottest point).
#[derive(Clone, Debug, PartialEq)]
pub enum Heating {
    Contact(Box<ThermalStudy>),
    Gears(Box<GearHeating>),
}

impl Heating {
    /// The heating's study (the gears': at the hottest point of the path).
    pub fn study(&self) -> &ThermalStudy {
        match self {
            Heating::Contact(study) => study,
            Heating::Gears(gear) => &gear.study,
        }
    }

    /// The gears' heating along the path, if that is what this is.
    pub fn gears(&self) -> Option<&GearHeating> {
        match self {
            Heating::Contact(_) => None,
            Heating::Gears(gear) => Some(gear),
        }
    }
}

/// What `contact` computes of a rough scene: the solved contact, its findings, and with
/// `[thermal]` the heating on it (given the findings' maxima, which are its contact alone's).
#[derive(Clone, Debug, PartialEq)]
pub struct ContactStudy {
    pub solution: RoughSolution,
    pub findings: ContactFindings,
    pub heating: Option<ThermalStudy>,
}

/// What `hertz` computes of a scene, by its kind.
#[derive(Clone, Debug)]
pub enum HertzStudy {
    /// A coated line, point or elliptical contact: the coated study (its heating, if any, is
    /// not computed here: the coated report has none).
    Coated(Box<CoatedStudy>),
    /// A rough scene: what `contact` computes.
    Rough(Box<ContactStudy>),
    /// A surface scene: the characterisation of its surface.
    Surface(Box<Characterisation>),
    /// A Hertz or traction scene: its stress maxima and yield assessment, and with
    /// `[thermal]` its heating.
    Closed {
        maxima: Box<SceneMaxima>,
        heating: Option<Heating>,
    },
}

/// `hertz SCENE`'s study.
pub fn hertz(
    scene: &Scene,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
) -> Result<HertzStudy, CommandError> {
    if scene.contact.coating.is_some() && scene.contact.kind != ContactKind::Rough {
        let coated_error = |error| CommandError::Coated {
            scene: scene.name.clone(),
            error: Box::new(error),
        };
        let mut study = crate::study::coated::solve(scene).map_err(coated_error)?;
        if study.spec.strengths.any() {
            study.first_failure =
                crate::study::coated_layers::first_failure(scene, &study).map_err(coated_error)?;
        }
        return Ok(HertzStudy::Coated(Box::new(study)));
    }
    match scene.contact.kind {
        ContactKind::Rough => Ok(HertzStudy::Rough(Box::new(contact(scene, progress)?))),
        ContactKind::Surface => {
            let characterisation = crate::study::surface::characterise(scene).map_err(|error| {
                CommandError::Surface {
                    surface: scene
                        .surface
                        .as_ref()
                        .map_or_else(|| scene.name.clone(), |s| s.source.clone()),
                    error: Box::new(error),
                }
            })?;
            Ok(HertzStudy::Surface(Box::new(characterisation)))
        }
        _ => {
            let maxima = crate::study::assess::scene_maxima(scene);
            let heating = match scene.thermal {
                Some(_) => Some(hertz_heating(scene, progress)?),
                None => None,
            };
            Ok(HertzStudy::Closed {
                maxima: Box::new(maxima),
                heating,
            })
        }
    }
}

/// `contact SCENE`'s study of a rough scene (another kind is [`RoughStudyError::NotRough`]).
pub fn contact(
    scene: &Scene,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
) -> Result<ContactStudy, CommandError> {
    let solution = solve(scene, progress)?;
    let depth_m = crate::study::rough::search_depth_m(&solution);
    if progress(Progress::Maxima { depth_m }).is_break() {
        return Err(interrupted(scene, "the subsurface maxima"));
    }
    let findings = crate::study::rough::findings(scene, &solution)
        .map_err(|error| CommandError::Findings(Box::new(error)))?;
    let heating = match scene.thermal {
        Some(_) => {
            let known = ContactMaxima {
                maxima: &findings.maxima,
                friction: scene.contact.friction,
                poisson: scene.contact.poisson,
            };
            Some(heated(scene, progress, |on| {
                crate::study::thermal::study_with(scene, Some(&solution), Some(known), on)
            })?)
        }
        None => None,
    };
    Ok(ContactStudy {
        solution,
        findings,
        heating,
    })
}

/// `thermal SCENE`'s study: the heating of a scene with `[thermal]` (a rough scene's on its
/// solved contact, whose maxima are searched anew: not `contact`'s).
pub fn thermal(
    scene: &Scene,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
) -> Result<Heating, CommandError> {
    if scene.contact.kind != ContactKind::Rough {
        return hertz_heating(scene, progress);
    }
    let solution = solve(scene, progress)?;
    let study = heated(scene, progress, |on| {
        crate::study::thermal::study(scene, Some(&solution), on)
    })?;
    Ok(Heating::Contact(Box::new(study)))
}

/// The heating of a Hertz or gear scene with `[thermal]` (the gears' along their path), as
/// `hertz` and `thermal` report it.
pub fn hertz_heating(
    scene: &Scene,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
) -> Result<Heating, CommandError> {
    if scene.thermal.and_then(|t| t.gear).is_some() {
        let mut stop = false;
        let gear = crate::study::gear_heating::gear_heating(scene, &mut |p| {
            stop |= progress(Progress::Heating(p)).is_break();
        })
        .map_err(|error| CommandError::Heating {
            scene: scene.name.clone(),
            error: Box::new(HeatingError::Gears(error)),
        })?;
        if stop {
            return Err(interrupted(scene, "the report"));
        }
        return Ok(Heating::Gears(Box::new(gear)));
    }
    let study = heated(scene, progress, |on| {
        crate::study::thermal::study(scene, None, on)
    })?;
    Ok(Heating::Contact(Box::new(study)))
}

/// The rough scene's contact solved, the progress told of each iteration and heard.
fn solve(
    scene: &Scene,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
) -> Result<RoughSolution, CommandError> {
    crate::study::rough::solve_interruptible(scene, &mut |iteration, residual| {
        progress(Progress::Solving {
            iteration,
            residual,
        })
    })
    .map_err(|error| CommandError::Solve {
        scene: scene.name.clone(),
        error: Box::new(error),
    })
}

/// A heating study run with the progress passed on; a stop asked while it ran ends the
/// command after it (the heating has no stop of its own).
fn heated(
    scene: &Scene,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
    run: impl FnOnce(
        &mut dyn FnMut(crate::study::thermal::Progress),
    ) -> Result<ThermalStudy, ThermalStudyError>,
) -> Result<ThermalStudy, CommandError> {
    let mut stop = false;
    let study = run(&mut |p| {
        stop |= progress(Progress::Heating(p)).is_break();
    })
    .map_err(|error| CommandError::Heating {
        scene: scene.name.clone(),
        error: Box::new(HeatingError::Contact(error)),
    })?;
    if stop {
        return Err(interrupted(scene, "the report"));
    }
    Ok(study)
}

fn interrupted(scene: &Scene, next: &'static str) -> CommandError {
    CommandError::Interrupted {
        scene: scene.name.clone(),
        next,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(name: &str) -> Scene {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenes")
            .join(format!("{name}.toml"));
        crate::study::load_scene(&path).expect("a shipped scene")
    }

    /// Issue 50: `hertz` of a coated point or line scene is the coated study (the contact of
    /// the layered body), not the Hertz contact of its coating's material.
    #[test]
    fn a_coated_scene_s_hertz_is_the_coated_study() {
        for name in ["coated_ball_on_b4c_10um", "coated_roller_babbitt_on_steel"] {
            let scene = scene(name);
            let study = hertz(&scene, &mut |_| ControlFlow::Continue(())).expect("computes");
            let HertzStudy::Coated(coated) = &study else {
                panic!("{name}: {study:?}")
            };
            let reference = crate::study::coated::solve(&scene).expect("coated");
            assert_eq!(
                crate::report::coated::CoatedReport::new(coated),
                crate::report::coated::CoatedReport::new(&reference)
            );
        }
    }

    /// A stop asked when the subsurface maxima are about to be searched ends the command with
    /// no result; a stop in the solve ends it there.
    #[test]
    fn a_stop_is_an_error_naming_the_next_phase() {
        let scene = scene("rough_worn_on_flat");
        let error = contact(&scene, &mut |p| match p {
            Progress::Maxima { .. } => ControlFlow::Break(()),
            _ => ControlFlow::Continue(()),
        })
        .expect_err("stopped");
        assert!(error.is_interrupted(), "{error}");
        assert_eq!(
            error.to_string(),
            "scene rough_worn_on_flat: interrupted before the subsurface maxima: no result"
        );
        let error = contact(&scene, &mut |p| match p {
            Progress::Solving { iteration: 2, .. } => ControlFlow::Break(()),
            _ => ControlFlow::Continue(()),
        })
        .expect_err("stopped");
        assert!(error.is_interrupted(), "{error}");
        let text = crate::io::text::error_text(&anyhow::Error::new(error));
        assert!(
            text.starts_with(
                "scene rough_worn_on_flat: the solve was interrupted after 2 iterations"
            ),
            "{text}"
        );
    }
}
