//! The x–z volume of a line `[plasticity]` scene (`contact.kind = "line"`, issue 51): a
//! cylinder or a rigid roller pressed on body 1 in plane strain, solved by the one load-step
//! loop ([`crate::plasticity::loading::run`] on the plane-strain body of
//! [`crate::plasticity::line`]) and reported by [`super::solve_setup`] as every other kind.
//!
//! The x–z volume is centred on the contact's axis: `grid_cells` columns over
//! `±extent_over_a` Hertz half-widths `b` (a column centred on the axis), `depth_cells` uniform
//! layers down to `depth_over_a` half-widths. It is held as a [`VolumeGrid`] of one row whose
//! width in y is 1 m, so that the study's areas and volumes are per metre of length: the
//! contact area is the contact's width times 1 m, the plastic volume the plastic zone's area in
//! the x–z section (reported as `plastic_area_m2`), and `contact_radius_m` holds half the
//! width of the cells in contact (reported as `half_width_m`). Definitions in
//! docs/plasticity.md.

use super::{Edges, PlasticKind, PlasticStudy, PlasticStudyError, Setup, SetupBody};
use crate::contact::LineContact;
use crate::operator::elastic::Periodicity;
use crate::plasticity::column::DepthCells;
use crate::plasticity::halfspace::VolumeGrid;
use crate::plasticity::line::LineGrid;
use crate::plasticity::loading::Progress;
use crate::scene::PlasticitySpec;

/// The width in y of the line's one row of cells (m): the study's areas and volumes are per
/// metre of length.
pub const ROW_WIDTH_M: f64 = 1.0;

/// The x–z grid of `spec` about a contact of half-width `b_m`.
pub fn line_grid(spec: &PlasticitySpec, b_m: f64) -> Result<LineGrid, PlasticStudyError> {
    let depth = DepthCells::uniform(
        spec.depth_cells,
        spec.depth_over_a * b_m / spec.depth_cells as f64,
    )
    .map_err(|e| PlasticStudyError::Grid {
        key: "depth_cells",
        message: e.0,
    })?;
    Ok(LineGrid {
        cells: spec.grid_cells,
        spacing_m: 2.0 * spec.extent_over_a * b_m / spec.grid_cells as f64,
        depth,
    })
}

/// The one-row [`VolumeGrid`] of a line grid (module doc).
pub fn row_grid(grid: &LineGrid) -> VolumeGrid {
    VolumeGrid {
        shape: [1, grid.cells],
        spacing_m: [grid.spacing_m, ROW_WIDTH_M],
        depth: grid.depth.clone(),
        periodicity: Periodicity::NonPeriodic,
    }
}

/// The study of a cylinder pressed on an elastic-plastic body 1 (`hertz` its elastic
/// contact; `counter` body 2's modulus and Poisson's ratio, `None` when rigid).
pub fn study_line(
    spec: &PlasticitySpec,
    hertz: &LineContact,
    counter: Option<(f64, f64)>,
    friction: f64,
    progress: &mut dyn FnMut(Progress),
) -> Result<PlasticStudy, PlasticStudyError> {
    let line_grid = line_grid(spec, hertz.half_width_m)?;
    let x_m = line_grid.x_m();
    let radius = hertz.effective_radius_m;
    let gap_m: Vec<f64> = x_m.iter().map(|x| x * x / (2.0 * radius)).collect();
    let setup = Setup {
        hertz: super::ElasticHertz::Line(*hertz),
        kind: PlasticKind::Line,
        grid: row_grid(&line_grid),
        x_m,
        y_m: vec![0.0],
        body: SetupBody::Line {
            grid: line_grid,
            gap_m,
            counter,
        },
        elastic_max_pressure_pa: hertz.p0_pa,
        edges: Edges::Bounded,
    };
    super::solve_setup(spec, setup, friction, progress)
}
