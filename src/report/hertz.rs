//! The `hertz --json` report: the contact parameters, stress maxima and yield assessment of a
//! Hertz (line, point, elliptical) or traction scene as one JSON object in SI units; the same
//! values as the table of [`super::hertz`].
//!
//! JSON keys (the output contract; `null` where a value is not defined for the scene):
//! `scene`, `kind` (`line`, `point`, `elliptical`, `tractions`), `friction`, `poisson`,
//! `dimensional` (false for a normalised scene, whose SI values are `null` (the contact's
//! size keys stay, as `null`) and whose
//! `*_over_p0` / `*_over_a` values are the figures'); the contact: `half_width_m` (line),
//! `contact_radius_m` (point), `semi_axis_x_m` and `semi_axis_y_m` (elliptical; also
//! `eccentricity`), `max_pressure_pa`, `mean_pressure_pa`, `load_n` (point, elliptical) or
//! `load_n_per_m` (line), `effective_modulus_pa`, `effective_radius_m`, `approach_m` (`null`
//! for a line contact with a flat or concave body); the maxima in body 1 (`null` with
//! `maxima_error` when they could not be computed): `von_mises_max_pa`,
//! `von_mises_max_depth_m`, `max_shear_max_pa` (Tresca, (σ1 − σ3)/2), `max_shear_max_depth_m`,
//! `surface_von_mises_max_pa`, the same over p0 and a (`von_mises_max_over_p0`,
//! `von_mises_max_x_over_a`, `von_mises_max_z_over_a`, `max_shear_max_over_p0`,
//! `max_shear_max_x_over_a`, `max_shear_max_z_over_a`, `surface_von_mises_max_over_p0`;
//! positions within 1e-6 a of zero are zero, as in the table),
//! `tau1_max_over_p0` (line contacts' principal shear τ1, xz), `maxima_grid` (`[nx, ny]` of
//! the DC-FFT grid, `null` for a closed form); the yield assessment: `yield_starts_at_surface`,
//! `p0_at_first_yield_over_y` (von Mises) and `p0_at_first_yield_over_y_tresca` (`null` for
//! tractions), and with a yield strength in a dimensional scene `yield_strength_pa`,
//! `von_mises_over_yield`, `tresca_over_half_yield`, `surface_von_mises_over_yield`,
//! `verdict` (`elastic`, `subsurface`, `surface`), `p0_at_first_yield_pa`,
//! `load_at_first_yield` (N, or N/m for a line contact; for tractions the factor on every
//! traction), `load_factor_at_first_yield`. A scene with `[lubricant]` adds the key
//! `lubrication` (the film and λ, [`super::lubrication`]); a scene with `[thermal]` adds the
//! key `thermal` with the object of `thermal --json`.

use serde::Serialize;

use crate::scene::{ContactKind, Hertz, Scene};
use crate::study::assess::SceneMaxima;

/// What `hertz --json` says (see the module's key list).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct HertzReport {
    pub scene: String,
    pub kind: &'static str,
    pub friction: f64,
    pub poisson: f64,
    pub dimensional: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub half_width_m: Option<Option<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_radius_m: Option<Option<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub semi_axis_x_m: Option<Option<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub semi_axis_y_m: Option<Option<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub eccentricity: Option<Option<f64>>,
    pub max_pressure_pa: Option<f64>,
    pub mean_pressure_pa: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_n: Option<Option<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_n_per_m: Option<Option<f64>>,
    pub effective_modulus_pa: Option<f64>,
    pub effective_radius_m: Option<f64>,
    pub approach_m: Option<f64>,
    pub von_mises_max_pa: Option<f64>,
    pub von_mises_max_depth_m: Option<f64>,
    pub max_shear_max_pa: Option<f64>,
    pub max_shear_max_depth_m: Option<f64>,
    pub surface_von_mises_max_pa: Option<f64>,
    pub von_mises_max_over_p0: Option<f64>,
    pub von_mises_max_x_over_a: Option<f64>,
    pub von_mises_max_z_over_a: Option<f64>,
    pub max_shear_max_over_p0: Option<f64>,
    pub max_shear_max_x_over_a: Option<f64>,
    pub max_shear_max_z_over_a: Option<f64>,
    pub surface_von_mises_max_over_p0: Option<f64>,
    pub tau1_max_over_p0: Option<f64>,
    pub maxima_grid: Option<[usize; 2]>,
    pub maxima_error: Option<String>,
    pub yield_starts_at_surface: Option<bool>,
    pub p0_at_first_yield_over_y: Option<f64>,
    pub p0_at_first_yield_over_y_tresca: Option<f64>,
    pub yield_strength_pa: Option<f64>,
    pub von_mises_over_yield: Option<f64>,
    pub tresca_over_half_yield: Option<f64>,
    pub surface_von_mises_over_yield: Option<f64>,
    pub verdict: Option<&'static str>,
    pub p0_at_first_yield_pa: Option<f64>,
    pub load_at_first_yield: Option<f64>,
    pub load_factor_at_first_yield: Option<f64>,
    /// The film and λ of a scene with `[lubricant]` ([`super::lubrication`]'s keys).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lubrication: Option<super::lubrication::LubricationReport>,
}

impl HertzReport {
    /// The report of `scene` (a Hertz or traction scene) with its maxima as the study found
    /// them ([`crate::study::assess::scene_maxima`]).
    pub fn new(scene: &Scene, found: &SceneMaxima) -> Self {
        let contact = &scene.contact;
        let dimensional = contact.scale.is_some();
        let si = |value: f64| dimensional.then_some(value);
        let (a_m, p0_pa) = (contact.half_width_m(), contact.p0_pa());
        let point = contact.kind != ContactKind::Line;
        let kind = match contact.kind {
            ContactKind::Line => "line",
            ContactKind::Point => "point",
            ContactKind::Elliptical => "elliptical",
            ContactKind::Tractions => "tractions",
            ContactKind::Rough => "rough",
            ContactKind::Surface => "surface",
        };
        let mut report = Self {
            scene: scene.name.clone(),
            kind,
            friction: contact.friction,
            poisson: contact.poisson,
            dimensional,
            half_width_m: None,
            contact_radius_m: None,
            semi_axis_x_m: None,
            semi_axis_y_m: None,
            eccentricity: None,
            max_pressure_pa: None,
            mean_pressure_pa: None,
            load_n: None,
            load_n_per_m: None,
            effective_modulus_pa: None,
            effective_radius_m: None,
            approach_m: None,
            von_mises_max_pa: None,
            von_mises_max_depth_m: None,
            max_shear_max_pa: None,
            max_shear_max_depth_m: None,
            surface_von_mises_max_pa: None,
            von_mises_max_over_p0: None,
            von_mises_max_x_over_a: None,
            von_mises_max_z_over_a: None,
            max_shear_max_over_p0: None,
            max_shear_max_x_over_a: None,
            max_shear_max_z_over_a: None,
            surface_von_mises_max_over_p0: None,
            tau1_max_over_p0: found.tau1.map(|t| t.value_over_p0),
            maxima_grid: found.grid,
            maxima_error: None,
            yield_starts_at_surface: None,
            p0_at_first_yield_over_y: None,
            p0_at_first_yield_over_y_tresca: None,
            yield_strength_pa: None,
            von_mises_over_yield: None,
            tresca_over_half_yield: None,
            surface_von_mises_over_yield: None,
            verdict: None,
            p0_at_first_yield_pa: None,
            load_at_first_yield: None,
            load_factor_at_first_yield: None,
            lubrication: crate::study::lubrication::films(scene)
                .as_ref()
                .map(super::lubrication::LubricationReport::new),
        };
        let tractions = contact.kind == ContactKind::Tractions;
        // The contact's size: from the Hertz solution of the bodies, else from the scale.
        match contact.dimensional.map(|d| d.hertz) {
            Some(Hertz::Line(line)) => {
                report.half_width_m = Some(Some(line.half_width_m));
                report.load_n_per_m = Some(Some(line.load_n_per_m));
                report.effective_modulus_pa = Some(line.effective_modulus_pa);
                report.effective_radius_m = Some(line.effective_radius_m);
                report.max_pressure_pa = Some(line.p0_pa);
                report.mean_pressure_pa = Some(line.mean_pressure_pa);
                report.approach_m = contact
                    .dimensional
                    .and_then(|d| line.approach_of_axes_m(&d.body1, &d.body2));
            }
            Some(Hertz::Point(point)) => {
                report.contact_radius_m = Some(Some(point.radius_m));
                report.load_n = Some(Some(point.load_n));
                report.effective_modulus_pa = Some(point.effective_modulus_pa);
                report.effective_radius_m = Some(point.effective_radius_m);
                report.max_pressure_pa = Some(point.p0_pa);
                report.mean_pressure_pa = Some(point.mean_pressure_pa);
                report.approach_m = Some(point.approach_m);
            }
            Some(Hertz::Elliptical(ellipse)) => {
                report.semi_axis_x_m = Some(Some(ellipse.semi_axis_x_m));
                report.semi_axis_y_m = Some(Some(ellipse.semi_axis_y_m));
                report.eccentricity = Some(Some(ellipse.eccentricity));
                report.load_n = Some(Some(ellipse.load_n));
                report.effective_modulus_pa = Some(ellipse.effective_modulus_pa);
                report.max_pressure_pa = Some(ellipse.p0_pa);
                report.mean_pressure_pa = Some(ellipse.mean_pressure_pa);
                report.approach_m = Some(ellipse.approach_m);
            }
            None if tractions => {}
            None => {
                // The contact given by its size (or normalised: a = p0 = 1, no SI values).
                let size = si(a_m);
                match contact.kind {
                    ContactKind::Line => {
                        report.half_width_m = Some(size);
                        report.mean_pressure_pa = si(std::f64::consts::FRAC_PI_4 * p0_pa);
                        report.load_n_per_m = Some(si(std::f64::consts::FRAC_PI_2 * a_m * p0_pa));
                    }
                    ContactKind::Elliptical => {
                        report.semi_axis_x_m = Some(size);
                        report.semi_axis_y_m = Some(si(a_m * contact.aspect));
                    }
                    _ => {
                        report.contact_radius_m = Some(size);
                        report.mean_pressure_pa = si(2.0 / 3.0 * p0_pa);
                        report.load_n =
                            Some(si(2.0 / 3.0 * std::f64::consts::PI * a_m * a_m * p0_pa));
                    }
                }
                report.max_pressure_pa = si(p0_pa);
            }
        }
        let maxima = match &found.maxima {
            Ok(maxima) => *maxima,
            Err(e) => {
                report.maxima_error = Some(e.clone());
                return report;
            }
        };
        let (vm, tresca) = (&maxima.von_mises, &maxima.max_shear);
        report.von_mises_max_pa = si(vm.value_over_p0 * p0_pa);
        report.von_mises_max_depth_m = si(vm.z_over_a * a_m);
        report.max_shear_max_pa = si(tresca.value_over_p0 * p0_pa);
        report.max_shear_max_depth_m = si(tresca.z_over_a * a_m);
        report.surface_von_mises_max_pa = si(maxima.von_mises_surface.value_over_p0 * p0_pa);
        report.von_mises_max_over_p0 = Some(vm.value_over_p0);
        report.von_mises_max_x_over_a = Some(super::snap_position(vm.x_over_a));
        report.von_mises_max_z_over_a = Some(super::snap_position(vm.z_over_a));
        report.max_shear_max_over_p0 = Some(tresca.value_over_p0);
        report.max_shear_max_x_over_a = Some(super::snap_position(tresca.x_over_a));
        report.max_shear_max_z_over_a = Some(super::snap_position(tresca.z_over_a));
        report.surface_von_mises_max_over_p0 = Some(maxima.von_mises_surface.value_over_p0);
        report.yield_starts_at_surface = Some(maxima.yield_starts_at_surface());
        if !tractions {
            report.p0_at_first_yield_over_y = Some(1.0 / vm.value_over_p0);
            report.p0_at_first_yield_over_y_tresca = Some(0.5 / tresca.value_over_p0);
        }
        let (Some(y), true) = (scene.yield_strength(), dimensional) else {
            return report;
        };
        let ratio_vm = vm.value_over_p0 * p0_pa / y.pa;
        let surface_ratio = maxima.von_mises_surface.value_over_p0 * p0_pa / y.pa;
        report.yield_strength_pa = Some(y.pa);
        report.von_mises_over_yield = Some(ratio_vm);
        report.tresca_over_half_yield = Some(tresca.value_over_p0 * p0_pa / (0.5 * y.pa));
        report.surface_von_mises_over_yield = Some(surface_ratio);
        report.verdict = Some(if ratio_vm < 1.0 {
            "elastic"
        } else if surface_ratio < 1.0 {
            "subsurface"
        } else {
            "surface"
        });
        let p0_yield = y.pa / vm.value_over_p0;
        report.p0_at_first_yield_pa = Some(p0_yield);
        if tractions {
            // Stresses are linear in the tractions: the factor on every traction.
            report.load_factor_at_first_yield = Some(p0_yield / p0_pa);
            return report;
        }
        report.load_factor_at_first_yield =
            Some((p0_yield / p0_pa).powi(if point { 3 } else { 2 }));
        report.load_at_first_yield = contact
            .dimensional
            .map(|d| d.hertz.load_for_peak_pressure(p0_yield));
        report
    }

    /// One JSON object; `thermal` (the object of `thermal --json`) is added as the key
    /// `thermal` when given.
    pub fn json(&self, thermal: Option<&super::thermal::ThermalReport>) -> String {
        let text = serde_json::to_string_pretty(self)
            .unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"));
        super::with_thermal(text, thermal)
    }
}
