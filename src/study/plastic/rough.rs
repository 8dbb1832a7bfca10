//! A rough map on an elastic-plastic body 1 (issue 51): the rough scene's heights (levelled,
//! with the counter-surface's, as the rough contact uses them) are the undeformed gap;
//! `[plasticity]` replaces the hardness cap.
//!
//! ## The grid
//! Laterally the map's own cells (no coarsening: the plastic flow sits under the asperities,
//! whose contact spots are a few cells across; a map too large for the memory limit is
//! refused, naming its size). In depth `depth_cells` layers down to `depth_over_a` times the
//! equivalent radius `√(A/π)` of the largest contact spot of the elastic contact at the full
//! load (no cap), solved first on the same map; graded ([`depth_layers`]): the asperities'
//! plastic zones lie within a cell or two of the surface, so the top layers are as thin as
//! the map's cells and the layers grow geometrically below. Under one spot of radius `c` the
//! stress of its pressure decays below about `2 c` (Hertz's: the von Mises maximum at
//! `0.48 c`, the plastic zone of a ball at 2.5 Y down to `1.16 c`, docs/plasticity.md), so
//! the default `2 c` holds the plastic zone of the largest spot, and the study refuses a
//! zone that reaches the bottom layer (raise `depth_over_a`). Where spots crowd under a
//! macroscopic load (a rough ball) their fields add up below them over the whole contact;
//! that deeper, elastic field is outside the grid, and if it yields the zone reaches the
//! bottom and the study says so.
//!
//! ## Isolated or periodic
//! As the scene's `contact.periodic`: isolated, the transforms zero-padded to twice the map
//! (the contact and the plastic strain alone on an infinite flat, as DC-FFT); periodic, the
//! map is one period of the contact and of the plastic strain, the transforms the map's own
//! (no padding; [`crate::plasticity::halfspace`]). The contact solver inside the loop is the
//! rough contact's, periodic or isolated alike.
//!
//! ## What is reported
//! As for a ball, with the map's centre as the axis; the "dent" `residual_depth_m` is the
//! largest permanent surface displacement over the map (a rough map has no axis).

use super::{
    solve_setup, Edges, PlasticKind, PlasticStudy, PlasticStudyError, RoughPlastic, Setup,
};
use crate::contact::rough::{self, Control, RoughContactProblem};
use crate::contact::PointContact;
use crate::operator::elastic::Periodicity;
use crate::plasticity::column::DepthCells;
use crate::plasticity::halfspace::VolumeGrid;
use crate::plasticity::loading::{Progress, PLASTIC_ZONE_STRAIN};
use crate::scene::{PlasticitySpec, Scene};

/// The load of a rough problem's control: its load, or its mean pressure times the map's
/// nominal area (an approach has none: refused by the scene's validation).
pub fn load_n(problem: &RoughContactProblem) -> Option<f64> {
    let (ny, nx) = problem.heights_m.dim();
    let area = nx as f64 * problem.spacing_m[0] * ny as f64 * problem.spacing_m[1];
    match problem.control {
        Control::Load { newtons } => Some(newtons),
        Control::MeanPressure { pa } => Some(pa * area),
        Control::Approach { .. } => None,
    }
}

/// The depth layers of a rough map of cell `cell_m` (the smaller of `dx`, `dy`): `count`
/// layers down to `depth_m`, the top one no thicker than `cell_m · 16 / count` (cubic cells at
/// the surface with the shipped 16 layers; doubling `count` halves it) and the others growing
/// geometrically to the depth; uniform when `depth_m / count` is no thicker than that.
pub fn depth_layers(
    count: usize,
    cell_m: f64,
    depth_m: f64,
) -> Result<DepthCells, PlasticStudyError> {
    let top = cell_m * 16.0 / count as f64;
    let error = |e: crate::plasticity::column::DepthCellsError| PlasticStudyError::Grid {
        key: "depth_cells",
        message: e.0,
    };
    if depth_m <= count as f64 * top * (1.0 + 1e-12) {
        return DepthCells::uniform(count, depth_m / count as f64).map_err(error);
    }
    // The growth g of top (g^count - 1) / (g - 1) = depth, by bisection (the sum grows with g).
    let reach = |g: f64| top * (0..count).map(|k| g.powi(k as i32)).sum::<f64>();
    let (mut lo, mut hi) = (1.0, 2.0);
    while reach(hi) < depth_m {
        hi *= 2.0;
    }
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if reach(mid) < depth_m {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let growth = 0.5 * (lo + hi);
    let mut faces = Vec::with_capacity(count + 1);
    let (mut z, mut h) = (0.0, top);
    faces.push(0.0);
    for _ in 0..count {
        z += h;
        faces.push(z);
        h *= growth;
    }
    DepthCells::new(faces).map_err(error)
}

/// The volume grid of a rough map of `shape` `[ny, nx]` and `spacing_m`, `depth_m` deep in
/// `spec.depth_cells` layers ([`depth_layers`]).
pub fn volume_grid(
    spec: &PlasticitySpec,
    shape: [usize; 2],
    spacing_m: [f64; 2],
    depth_m: f64,
    periodicity: Periodicity,
) -> Result<VolumeGrid, PlasticStudyError> {
    let depth = depth_layers(spec.depth_cells, spacing_m[0].min(spacing_m[1]), depth_m)?;
    Ok(VolumeGrid {
        shape,
        spacing_m,
        depth,
        periodicity,
    })
}

/// The study of a rough scene with `[plasticity]`.
pub fn study_rough(
    scene: &Scene,
    spec: &PlasticitySpec,
    progress: &mut dyn FnMut(Progress),
) -> Result<PlasticStudy, PlasticStudyError> {
    let problem = crate::study::rough::problem(scene).ok_or(PlasticStudyError::NotPlastic)?;
    study_map(&problem, spec, scene.contact.friction, progress)
}

/// The study of the rough contact `problem` (its heights, spacing, `E*`, periodicity and
/// load; its hardness is the cap compared with) with body 1 elastic-plastic.
pub fn study_map(
    problem: &RoughContactProblem,
    spec: &PlasticitySpec,
    friction: f64,
    progress: &mut dyn FnMut(Progress),
) -> Result<PlasticStudy, PlasticStudyError> {
    let load = load_n(problem).ok_or(PlasticStudyError::NotPlastic)?;
    let contact_error = |source| {
        PlasticStudyError::Solve(crate::plasticity::loading::PlasticContactError::Contact {
            step: 0,
            load_n: load,
            source,
        })
    };
    let loaded = RoughContactProblem {
        control: Control::Load { newtons: load },
        ..problem.clone()
    };
    // The elastic contact at the load, without the cap: the spots that size the depth.
    let elastic = rough::solve(
        &RoughContactProblem {
            hardness_pa: None,
            ..loaded.clone()
        },
        &mut |_, _| {},
    )
    .map_err(contact_error)?;
    let [dx, dy] = problem.spacing_m;
    let cell_area = dx * dy;
    let elastic_area = elastic.pressure_pa.iter().filter(|&&p| p > 0.0).count() as f64 * cell_area;
    let largest_spot_radius_m =
        (elastic.largest_spot_cells as f64 * cell_area / std::f64::consts::PI).sqrt();
    // The scene's own hardness-capped contact, to compare with.
    let capped = match problem.hardness_pa {
        Some(_) => Some(rough::solve(&loaded, &mut |_, _| {}).map_err(contact_error)?),
        None => None,
    };
    let (ny, nx) = problem.heights_m.dim();
    let grid = volume_grid(
        spec,
        [ny, nx],
        problem.spacing_m,
        spec.depth_over_a * largest_spot_radius_m,
        problem.periodicity,
    )?;
    let x_m: Vec<f64> = (0..nx).map(|i| (i as f64 - (nx / 2) as f64) * dx).collect();
    let y_m: Vec<f64> = (0..ny).map(|j| (j as f64 - (ny / 2) as f64) * dy).collect();
    let c = (elastic_area / std::f64::consts::PI).sqrt();
    let e_star = problem.e_star_pa;
    let hertz = PointContact {
        p0_pa: elastic.max_pressure_pa,
        mean_pressure_pa: load / elastic_area,
        approach_m: elastic.approach_m,
        ..PointContact::from_effective(load, e_star, 4.0 * e_star * c.powi(3) / (3.0 * load))
    };
    let kind = PlasticKind::Rough(RoughPlastic {
        periodic: problem.periodicity == Periodicity::Periodic,
        elastic_max_pressure_pa: elastic.max_pressure_pa,
        elastic_contact_area_m2: elastic_area,
        largest_spot_radius_m,
        capped_max_pressure_pa: capped.as_ref().map(|s| s.max_pressure_pa),
        capped_area_m2: capped.as_ref().map(|s| s.plastic_cells as f64 * cell_area),
        surface_plastic_area_m2: 0.0,
        plastic_footprint_m2: 0.0,
    });
    let setup = Setup {
        hertz: super::ElasticHertz::Point(hertz),
        kind,
        grid,
        x_m,
        y_m,
        body: super::SetupBody::Volume {
            heights: problem.heights_m.to_owned(),
        },
        elastic_max_pressure_pa: elastic.max_pressure_pa,
        edges: match problem.periodicity {
            Periodicity::Periodic => Edges::Periodic,
            Periodicity::NonPeriodic => Edges::Map,
        },
    };
    let mut study = solve_setup(spec, setup, friction, progress)?;
    // The plastic areas at the full load: the columns whose top cell flows, and those with a
    // plastic cell at any depth.
    let kappa = &study.loaded_snapshot().equivalent_plastic_strain;
    let mut surface_cells = 0;
    let mut footprint_cells = 0;
    let nz = kappa.dim().0;
    for j in 0..ny {
        for i in 0..nx {
            surface_cells += usize::from(kappa[[0, j, i]] > PLASTIC_ZONE_STRAIN);
            footprint_cells += usize::from((0..nz).any(|l| kappa[[l, j, i]] > PLASTIC_ZONE_STRAIN));
        }
    }
    if let PlasticKind::Rough(rough) = &mut study.kind {
        rough.surface_plastic_area_m2 = surface_cells as f64 * cell_area;
        rough.plastic_footprint_m2 = footprint_cells as f64 * cell_area;
    }
    Ok(study)
}

#[cfg(test)]
mod tests;
