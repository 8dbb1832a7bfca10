//! A stack of layers on body 1 (`[[contact.body1.layers]]`): the maxima of each layer and of
//! the interface under it, the strength check (each given strength against its governing
//! stress) and the load at which the first of them is reached.
//!
//! ## The strength check
//! Per layer, with the strengths given (Pa):
//! - `yield`: the largest von Mises stress in the layer over its `yield_strength` (von Mises'
//!   criterion; Johnson 1985, §1.5);
//! - `fracture`: the largest principal stress in the layer (tension positive) over its
//!   `tensile_strength` (the maximum-normal-stress criterion for brittle coatings, as Holmberg &
//!   Matthews, *Coatings Tribology* (2009) §3.2 apply it to the trailing-edge tension);
//! - `delamination`: the largest interface shear `sqrt(σxz² + σyz²)` on the interface under the
//!   layer over its `adhesion_strength`;
//! - the substrate's `yield`: its largest von Mises stress over `contact.body1.yield_strength`.
//!
//! The value is the utilisation at the scene's load. A coated Hertzian contact is **not**
//! linear in the load: the contact's size grows with the load and the layers' share of the
//! stress changes with `h / a`, so the first failure's load is not the scene's load over the
//! utilisation. It is found by solving the coated contact at each candidate load: the secant
//! on `ln U(W)` against `ln W` (U the largest utilisation), started at the homogeneous Hertz
//! scaling (`U ∝ W^(1/3)` for a point, `W^(1/2)` for a line), until the solve at the load
//! found gives `|U - 1| < 1e-3`. Each solve keeps the scene's cell size (its grid spans the
//! same number of semi-axes of that load's Hertz contact, with more cells for a larger load).
//!
//! ## The depths of a stack
//! In each layer `2 t / dx` depths (12 to 60) from its top (on the lower side of the interface
//! above it) to its bottom (on its own side), then the substrate's side of the deepest
//! interface and 72 depths to `max(2.5 a, H + 1.5 a)` (`H` the stack's thickness).

use ndarray::Array2;

use super::coated::{CoatedStudy, CoatedStudyError, Located};
use crate::coating::{Layered, Side};
use crate::scene::{ContactKind, Scene};
use crate::stress::Stress;

/// One layer's maxima in the plane of sliding and those of the interface under it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LayerMaxima {
    pub thickness_m: f64,
    pub von_mises: Located,
    /// The largest principal stress (tension positive).
    pub max_tension: Located,
    /// The interface under the layer: its largest shear `sqrt(σxz² + σyz²)` and its most
    /// compressive `σzz` (a value, usually negative).
    pub interface_shear: Located,
    pub interface_normal_min: Located,
}

/// The depths of a stack (module doc).
pub(super) fn stack_depths(layered: &Layered, cell_m: f64, semi_axis_m: f64) -> Vec<(f64, Side)> {
    let mut out = Vec::new();
    let mut top = 0.0;
    for (i, bottom) in layered.interface_depths_m().into_iter().enumerate() {
        let thickness = bottom - top;
        let count = ((2.0 * thickness / cell_m).ceil() as usize).clamp(12, 60);
        for j in 0..=count {
            let z = if j == count {
                bottom
            } else {
                top + thickness * j as f64 / count as f64
            };
            let side = if j == 0 && i > 0 {
                Side::Substrate
            } else {
                Side::Coating
            };
            out.push((z, side));
        }
        top = bottom;
    }
    out.push((top, Side::Substrate));
    let end = (2.5 * semi_axis_m).max(top + 1.5 * semi_axis_m);
    let below = 72;
    for i in 1..=below {
        out.push((top + (end - top) * i as f64 / below as f64, Side::Substrate));
    }
    out
}

/// The maxima of each layer and of the interface under it, from the rows (`[component, x]`
/// at each of `depths`) of the plane of sliding.
pub(super) fn layer_maxima(
    layered: &Layered,
    depths: &[(f64, Side)],
    rows: &[Array2<f64>],
    x_m: &[f64],
) -> Vec<LayerMaxima> {
    let interfaces = layered.interface_depths_m();
    let mut out: Vec<LayerMaxima> = layered
        .layers()
        .iter()
        .map(|layer| LayerMaxima {
            thickness_m: layer.thickness_m,
            von_mises: Located::NONE,
            max_tension: Located::NONE,
            interface_shear: Located::NONE,
            interface_normal_min: Located::NONE,
        })
        .collect();
    for ((z, side), row) in depths.iter().zip(rows) {
        let Some(layer) = layered.layer_at(*z, *side) else {
            continue;
        };
        let on_interface =
            *side == Side::Coating && (z - interfaces[layer]).abs() <= 1e-12 * interfaces[layer];
        let maxima = &mut out[layer];
        for (i, &x) in x_m.iter().enumerate() {
            let s = Stress {
                xx: row[[0, i]],
                yy: row[[1, i]],
                zz: row[[2, i]],
                yz: row[[3, i]],
                xz: row[[4, i]],
                xy: row[[5, i]],
            };
            maxima.von_mises.keep_larger(s.von_mises(), x, *z);
            maxima.max_tension.keep_larger(s.principal()[0], x, *z);
            if on_interface {
                maxima.interface_shear.keep_larger(s.xz.hypot(s.yz), x, *z);
                if maxima.interface_normal_min.value_pa == f64::NEG_INFINITY
                    || s.zz < maxima.interface_normal_min.value_pa
                {
                    maxima.interface_normal_min = Located {
                        value_pa: s.zz,
                        x_m: x,
                        z_m: *z,
                    };
                }
            }
        }
    }
    out
}

/// How a material fails in the strength check.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Yield,
    Fracture,
    Delamination,
}

impl Mode {
    /// The JSON and report word.
    pub fn key(self) -> &'static str {
        match self {
            Mode::Yield => "yield",
            Mode::Fracture => "fracture",
            Mode::Delamination => "delamination",
        }
    }
}

/// One governing stress over its strength (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Utilisation {
    /// `"layer 1"`, `"interface 1"`, ..., `"substrate"`.
    pub place: String,
    pub mode: Mode,
    /// The stress over the strength at the scene's load.
    pub value: f64,
    pub x_m: f64,
    pub z_m: f64,
}

/// Every given strength's utilisation at the study's load, layers top first, then the
/// substrate.
pub fn utilisation(study: &CoatedStudy) -> Vec<Utilisation> {
    let strengths = &study.spec.strengths;
    let mut out = Vec::new();
    let mut push = |place: String, mode: Mode, stress: &Located, strength: Option<f64>| {
        if let Some(strength) = strength {
            out.push(Utilisation {
                place,
                mode,
                value: stress.value_pa / strength,
                x_m: stress.x_m,
                z_m: stress.z_m,
            });
        }
    };
    for (i, layer) in study.layers.iter().enumerate() {
        let [yield_pa, tensile_pa, adhesion_pa] = strengths.layers[i];
        push(
            format!("layer {}", i + 1),
            Mode::Yield,
            &layer.von_mises,
            yield_pa,
        );
        push(
            format!("layer {}", i + 1),
            Mode::Fracture,
            &layer.max_tension,
            tensile_pa,
        );
        push(
            format!("interface {}", i + 1),
            Mode::Delamination,
            &layer.interface_shear,
            adhesion_pa,
        );
    }
    push(
        "substrate".to_string(),
        Mode::Yield,
        &study.maxima.substrate_von_mises,
        strengths.substrate_yield_pa,
    );
    out
}

/// The load at which the first strength is reached, and where.
#[derive(Clone, Debug, PartialEq)]
pub struct FirstFailure {
    pub place: String,
    pub mode: Mode,
    /// N (point, elliptical) or N/m (line).
    pub load_n: f64,
    /// The largest utilisation of the solve at `load_n` (1 to within 1e-3).
    pub check: f64,
    /// The coated solves it took.
    pub solves: usize,
}

/// The largest of the utilisations.
fn governing(list: &[Utilisation]) -> Option<&Utilisation> {
    list.iter().max_by(|a, b| a.value.total_cmp(&b.value))
}

/// The first failure's load (module doc): `None` without strengths or when no stress is
/// tensile where only a tensile strength is given.
pub fn first_failure(
    scene: &Scene,
    study: &CoatedStudy,
) -> Result<Option<FirstFailure>, CoatedStudyError> {
    let list = utilisation(study);
    let Some(first) = governing(&list) else {
        return Ok(None);
    };
    if first.value <= 0.0 {
        return Ok(None);
    }
    let exponent = if study.kind == ContactKind::Line {
        2.0
    } else {
        3.0
    };
    let at = |load: f64| -> Result<(Vec<Utilisation>, f64), CoatedStudyError> {
        let mut stepped = scene.clone();
        stepped.contact = scene
            .contact
            .with_load(load)
            .map_err(|e| CoatedStudyError::Step {
                step: 0,
                message: e.to_string(),
            })?;
        // The grid spans ±extent semi-axes of the load's own Hertz contact: keep the scene's
        // cell size (a larger load needs more cells for the same layer).
        let grown = stepped.contact.half_width_m() / scene.contact.half_width_m();
        let limit = if study.kind == ContactKind::Line {
            super::coated::MAX_LINE_CELLS
        } else {
            super::coated::MAX_CELLS
        };
        stepped.numerical.cells = ((scene.numerical.cells as f64 * grown).ceil() as usize)
            .max(scene.numerical.cells)
            .min(limit);
        let solved = super::coated::solve(&stepped)?;
        let list = utilisation(&solved);
        let value = governing(&list).map_or(0.0, |u| u.value);
        Ok((list, value))
    };
    let (mut w0, mut u0) = (study.load_n, first.value);
    let mut w1 = w0 * u0.powf(-exponent);
    let (mut list, mut u1) = at(w1)?;
    let mut solves = 1;
    while (u1 - 1.0).abs() > 1e-3 && solves < 12 {
        let slope = (u1.ln() - u0.ln()) / (w1.ln() - w0.ln());
        let slope = if slope.is_finite() && slope > 0.05 {
            slope
        } else {
            1.0 / exponent
        };
        let next = (w1.ln() - u1.ln() / slope).exp();
        (w0, u0) = (w1, u1);
        w1 = next;
        (list, u1) = at(w1)?;
        solves += 1;
    }
    let Some(found) = governing(&list) else {
        return Ok(None);
    };
    Ok(Some(FirstFailure {
        place: found.place.clone(),
        mode: found.mode,
        load_n: w1,
        check: u1,
        solves,
    }))
}

#[cfg(test)]
#[path = "coated_layers_tests.rs"]
mod tests;
