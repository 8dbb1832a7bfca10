//! What a surface scene computes: the characterisation of body 1's heights (ISO 25178
//! parameters, spectra, summits), as the scene's options say. Computed once here; the surface
//! sheet, the report and the recording receive it.

use crate::scene::Scene;
use crate::surface::stats::{self, Characterisation, Options, StatsError};

/// Why a scene's surface cannot be characterised.
#[derive(Debug, thiserror::Error)]
pub enum SurfaceStudyError {
    #[error("this scene has no surface")]
    NoSurface,
    #[error(transparent)]
    Stats(#[from] StatsError),
}

/// The statistics of a scene's surface (body 1's heights), as its options say.
pub fn characterise(scene: &Scene) -> Result<Characterisation, SurfaceStudyError> {
    let surface = scene.surface.as_ref().ok_or(SurfaceStudyError::NoSurface)?;
    Ok(stats::characterise(
        &surface.body1,
        &Options {
            form: surface.form,
            band_m: surface.band_m,
            window: !surface.generated,
        },
    )?)
}
