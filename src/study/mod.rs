//! What a validated scene computes: the stress [`Solution`] of each panel, the grid
//! [`Plane`](crate::field::Plane) it is evaluated on, the display units of the figure, and the
//! scene at each step of a sweep.
//!
//! The pipeline reads off the modules: [`crate::scene`] (what the user wrote) -> `study` (what
//! will be computed) -> [`crate::field`] (evaluated on grids) -> sinks ([`crate::figure`] and
//! [`crate::render`], `crate::record`, [`crate::report`], with the probe's CSV). A new contact
//! kind adds its arm to [`centred_solution`] (its tractions, or the solver that finds them) and,
//! if it is drawn on its own grid, to [`plane`].
//!
//! Uses: [`crate::scene`], [`crate::contact`], [`crate::solution`], [`crate::thermal`],
//! [`crate::operator`], [`crate::field`]; the sinks use it, never the other way.

pub mod admit;
pub mod assess;
pub mod coated;
pub mod coated_layers;
pub mod coated_rough;
pub mod commands;
mod compass;
pub mod coupled;
pub mod drawing;
pub mod ehl;
pub mod gear_heating;
mod grid;
mod heated_search;
pub(crate) mod heated_stress;
pub mod heating_plan;
pub mod lubrication;
pub mod map_roll;
pub mod memory;
pub mod panels;
pub mod plastic;
pub mod rough;
pub mod rough_sheet;
pub mod surface;
pub mod thermal;
pub mod thermal_sections;
pub mod thermal_sweep;
pub mod volume;
pub mod wear;

use crate::contact::partial_slip::CattaneoMindlin;
use crate::contact::ContactError;
use crate::field::Axis;
use crate::scene::{
    Contact, ContactKind, LengthUnit, Method, Numerical, PanelSpec, Scene, StressUnit,
    SweepParameter,
};
use crate::solution::point_numerical::{NumericalError, PointTractions};
use crate::solution::Solution;

pub use admit::{admit, load_scene, parse_scene};
pub use grid::{grid_rows, plane};
pub use panels::panel_fields;

/// The figure's units: lengths in `length` (a, mm, ...), stresses in `stress` (p0, MPa, ...).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DisplayUnits {
    pub length: LengthUnit,
    pub stress: StressUnit,
    /// One a in the figure's length unit.
    pub length_per_a: f64,
    /// One p0 in the figure's stress unit.
    pub stress_per_p0: f64,
}

impl DisplayUnits {
    /// The units of `scene`'s figure.
    pub fn of(scene: &Scene) -> Self {
        let a_m = scene.contact.half_width_m();
        let p0_pa = scene.contact.p0_pa();
        let (length, stress) = (scene.figure.length_unit, scene.figure.stress_unit);
        Self {
            length,
            stress,
            length_per_a: a_m / length.metres(a_m),
            stress_per_p0: p0_pa / stress.pascals(p0_pa),
        }
    }

    /// An axis in units of a, in the figure's length unit.
    pub fn axis(&self, axis: Axis) -> Axis {
        Axis::new(
            axis.min * self.length_per_a,
            axis.max * self.length_per_a,
            axis.count,
        )
    }
}

/// The closed-form solution of a contact with the given friction and Poisson ratio, if it has
/// one ([`Contact::has_closed_form`]): McEwen's line contact, Hamilton's sphere.
pub fn closed_form_solution(contact: &Contact, friction: f64, poisson: f64) -> Option<Solution> {
    if !contact.has_closed_form() {
        return None;
    }
    match contact.kind {
        ContactKind::Line => Some(Solution::LineHertz { friction, poisson }),
        ContactKind::Point => Some(Solution::SphereHertz { friction, poisson }),
        ContactKind::Elliptical
        | ContactKind::Tractions
        | ContactKind::Rough
        | ContactKind::Surface => None,
    }
}

/// The stress solution of a panel (for a difference panel, the numerical one), centred at
/// `load_centre_over_a`.
pub fn solution(scene: &Scene, panel: &PanelSpec) -> Result<Solution, NumericalError> {
    Ok(centred_solution(scene, panel)?.moved_to(scene.load_centre_over_a))
}

fn centred_solution(scene: &Scene, panel: &PanelSpec) -> Result<Solution, NumericalError> {
    let (mu, nu) = (panel.friction, panel.poisson);
    if panel.method == Method::ClosedForm {
        if let Some(solution) = closed_form_solution(&scene.contact, mu, nu) {
            return Ok(solution);
        }
    }
    let Numerical {
        cells,
        extent_over_a: extent,
    } = scene.numerical;
    let tractions = match (scene.contact.kind, scene.contact.tangential) {
        (ContactKind::Line, _) => return Ok(Solution::line_numerical(mu, nu, cells)),
        (ContactKind::Point, None) => PointTractions::hertz_sphere(cells, extent, mu, nu)?,
        (ContactKind::Point, Some(ratio)) => {
            // Validated: 0 < ratio <= 1 and mu > 0.
            let slip = CattaneoMindlin::new(mu, ratio)?;
            PointTractions::mindlin_sphere(cells, extent, &slip, nu)?
        }
        (ContactKind::Elliptical, _) => {
            PointTractions::hertz_ellipse(cells, extent, scene.contact.aspect, mu, nu)?
        }
        (ContactKind::Tractions, _) => match &scene.tractions {
            Some(grid) => PointTractions::new(grid.as_ref().clone(), nu)?,
            None => return Err(NumericalError::MissingTractions),
        },
        // The tractions of a rough contact are solved for (study::rough), once per figure.
        (ContactKind::Rough | ContactKind::Surface, _) => {
            return Err(NumericalError::MissingTractions)
        }
    };
    Ok(Solution::PointNumerical {
        tractions: std::sync::Arc::new(tractions),
        friction: mu,
        poisson: nu,
    })
}

/// The closed-form solution of a panel's contact, if it has one (validated for every panel
/// drawn in closed form or as a difference).
pub fn closed_form(scene: &Scene, panel: &PanelSpec) -> Option<Solution> {
    let solution = closed_form_solution(&scene.contact, panel.friction, panel.poisson)?;
    Some(solution.moved_to(scene.load_centre_over_a))
}

/// The scene at step `k` of its sweep (the scene itself when it has none): the friction of
/// every panel, the load (Hertz recomputed at fixed geometry), the load's position, the
/// speeds of `[thermal]` (scaled together to body 1's Péclet number), the coating's
/// thickness, or the lubricant's entrainment speed.
pub fn at_step(scene: &Scene, k: usize) -> Result<Scene, ContactError> {
    let Some(sweep) = &scene.sweep else {
        return Ok(scene.clone());
    };
    let value = sweep.values[k];
    let mut stepped = scene.clone();
    match sweep.parameter {
        SweepParameter::Friction => {
            stepped.contact.friction = value;
            for panel in &mut stepped.panels {
                panel.friction = value;
            }
        }
        SweepParameter::Load => stepped.contact = scene.contact.with_load(value)?,
        SweepParameter::Position => {
            stepped.load_centre_over_a = value * scene.length_unit_over_a();
        }
        SweepParameter::Peclet => {
            let a = scene.contact.half_width_m();
            stepped.thermal = scene.thermal.map(|t| t.at_body1_peclet(value, a));
        }
        SweepParameter::CoatingThickness => {
            if let Some(coating) = &mut stepped.contact.coating {
                coating.thickness_m = value;
            }
        }
        SweepParameter::EntrainmentSpeed => {
            if let Some(lubricant) = &mut stepped.lubricant {
                lubricant.entrainment_m_per_s = value;
            }
        }
    }
    Ok(stepped)
}

#[cfg(test)]
mod tests {
    use super::{at_step, solution};
    use crate::contact::PointContact;
    use crate::scene::Scene;

    #[test]
    fn a_load_step_recomputes_hertz_at_fixed_geometry() {
        let text = "format = 1\n[contact]\nkind = \"point\"\nload = \"100 N\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"6.35 mm\"\nmaterial = \"steel\"\n[figure]\nlength_unit = \"mm\"\n[sweep]\nparameter = \"load\"\nvalues = [\"100 N\", \"800 N\"]\n";
        let scene = Scene::parse(text, "t", "t.toml").expect("valid");
        let (first, second) = (
            at_step(&scene, 0).expect("ok"),
            at_step(&scene, 1).expect("ok"),
        );
        assert_eq!(first.contact, scene.contact);
        // Hertz (Johnson 1985, §4.2(a)): a and p0 grow as W^(1/3); 8 times the load, twice.
        let ratio = |f: fn(&crate::scene::Contact) -> f64| f(&second.contact) / f(&first.contact);
        assert!((ratio(|c| c.p0_pa()) - 2.0).abs() < 1e-12);
        assert!((ratio(|c| c.half_width_m()) - 2.0).abs() < 1e-12);
        let direct = PointContact::new(
            &scene.contact.dimensional.expect("dimensional").body1,
            &scene.contact.dimensional.expect("dimensional").body2,
            800.0,
        )
        .expect("valid");
        assert!((second.contact.p0_pa() - direct.p0_pa).abs() < 1e-6 * direct.p0_pa);
    }

    #[test]
    fn a_position_step_moves_the_solution() {
        let text = "format = 1\n[contact]\nkind = \"line\"\n[sweep]\nparameter = \"position\"\nvalues = [0.0, 1.5]\n";
        let scene = Scene::parse(text, "t", "t.toml").expect("valid");
        let moved = at_step(&scene, 1).expect("ok");
        let solution = solution(&moved, &moved.panels[0]).expect("closed form");
        let centred = super::solution(&scene, &scene.panels[0]).expect("closed form");
        let (a, b) = (
            solution.stress_over_p0(1.25, 0.0, 0.4),
            centred.stress_over_p0(-0.25, 0.0, 0.4),
        );
        assert_eq!(a, b);
        assert_eq!(solution.surface_traction_over_p0(1.5, 0.0), (1.0, 0.0));
    }
}
