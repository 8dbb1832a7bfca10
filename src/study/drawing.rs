//! What a scene's figure or sheet draws, computed once here, so that the sinks (the `render`
//! command, the recordings, the tests) only draw: the panels' fields of a figure, a coated
//! body's study, a rough contact's maxima and sheet fields, a surface's characterisation.

use crate::contact::rough::RoughSolution;
use crate::field::FieldError;
use crate::scene::{ContactKind, Scene};

use super::assess::StressMaxima;
use super::coated::{CoatedStudy, CoatedStudyError};
use super::panels::PanelField;
use super::rough_sheet::{RoughSheetError, RoughSheetFields};
use super::surface::SurfaceStudyError;
use crate::surface::stats::Characterisation;

/// The computed inputs of a scene's drawing.
#[derive(Debug)]
pub enum DrawingInputs {
    /// A figure's panels ([`super::panel_fields`]).
    Panels(Vec<PanelField>),
    /// A coated body's section ([`super::coated::solve`]).
    Coated(Box<CoatedStudy>),
    /// A rough contact's sheet: the report's maxima ([`super::rough::scene_maxima`]) and
    /// the fields through them ([`super::rough_sheet::sheet_fields`]).
    Rough {
        maxima: StressMaxima,
        fields: Box<RoughSheetFields>,
    },
    /// A surface scene's sheet ([`super::surface::characterise`]).
    Surface(Box<Characterisation>),
}

/// Why a scene's drawing cannot be computed.
#[derive(Debug, thiserror::Error)]
pub enum DrawingError {
    #[error(transparent)]
    Field(#[from] FieldError),
    #[error(transparent)]
    Coated(#[from] CoatedStudyError),
    #[error(transparent)]
    Sheet(#[from] RoughSheetError),
    #[error(transparent)]
    Surface(#[from] SurfaceStudyError),
    #[error(
        "a rough scene's sheet draws its solved contact: solve it first (study::rough::solve)"
    )]
    Unsolved,
}

/// Computes what `scene`'s drawing needs; a rough scene's contact as solved by
/// [`super::rough::solve`] (`rough`). `on_row` is called per evaluated grid row.
pub fn inputs(
    scene: &Scene,
    rough: Option<&RoughSolution>,
    on_row: &(dyn Fn() + Sync),
) -> Result<DrawingInputs, DrawingError> {
    if scene.contact.coating.is_some() && scene.contact.kind != ContactKind::Rough {
        return Ok(DrawingInputs::Coated(Box::new(super::coated::solve(
            scene,
        )?)));
    }
    Ok(match scene.contact.kind {
        ContactKind::Rough => {
            let solution = rough.ok_or(DrawingError::Unsolved)?;
            let (maxima, _) = super::rough::scene_maxima(scene, solution)
                .map_err(|e| FieldError::Numerical(e.to_string()))?;
            rough_inputs(scene, solution, maxima, on_row)?
        }
        ContactKind::Surface => {
            DrawingInputs::Surface(Box::new(super::surface::characterise(scene)?))
        }
        _ => DrawingInputs::Panels(super::panel_fields(scene, on_row)?),
    })
}

/// A rough contact's sheet inputs through maxima already found (the report's).
pub fn rough_inputs(
    scene: &Scene,
    solution: &RoughSolution,
    maxima: StressMaxima,
    on_row: &(dyn Fn() + Sync),
) -> Result<DrawingInputs, DrawingError> {
    let fields = super::rough_sheet::sheet_fields(scene, solution, &maxima, on_row)?;
    Ok(DrawingInputs::Rough {
        maxima,
        fields: Box::new(fields),
    })
}
