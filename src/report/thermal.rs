//! The frictional-heating report (`stressfield thermal`, and the thermal block of `hertz` and
//! `contact`): a readable block or one JSON object with SI values.
//!
//! JSON keys (the output contract, SI, body 1 unless named): `peclet`,
//! `sliding_speed_m_per_s`, `heat_partition_body1`, `max_temperature_rise_k`,
//! `mean_temperature_rise_k`, `max_temperature_x_m`, `max_temperature_y_m`,
//! `thermal_von_mises_max_pa`, `total_von_mises_max_pa`, `total_von_mises_max_depth_m`; and
//! also `body1_speed_m_per_s`, `body2_speed_m_per_s`, `body2_peclet`,
//! `body2_max_temperature_rise_k`, `body2_mean_temperature_rise_k` (null without body 2),
//! `thermal_von_mises_max_depth_m`, `contact_von_mises_max_pa`,
//! `contact_von_mises_max_depth_m`, `contact_von_mises_max_x_m`, `total_von_mises_max_x_m`,
//! `total_von_mises_max_y_m`, `thermal_von_mises_max_x_m`, `thermal_von_mises_max_y_m`, the
//! maximum (Tresca) shear `(σ1 − σ3)/2` as everywhere in stressfield:
//! `contact_max_shear_max_pa`, `contact_max_shear_max_depth_m`, `total_max_shear_max_pa`,
//! `total_max_shear_max_depth_m`, `total_max_shear_max_x_m` (these replaced the
//! `*_tresca_max_*` keys, which held σ1 − σ3, twice the shear: renamed rather than kept, so
//! that no reader takes the one for the other); `contact_stress` (`"closed_form"` for line
//! and point contacts: the contact alone is `hertz`'s; `"dcfft"` otherwise),
//! `search_depths`, `search_depth_m`, `depth_tolerance_m` (the search), the properties used:
//! `body1_conductivity_w_per_m_k`, `body1_diffusivity_m2_per_s`, `body1_expansion_per_k`,
//! `body1_modulus_pa`, `body1_poisson`, `body2_conductivity_w_per_m_k`,
//! `body2_diffusivity_m2_per_s`, `body2_expansion_per_k` (null without body 2); `half_width_m`,
//! `rows`, `columns`, `spacing_m`, `traction_on_body1` (`"+x"`, or `"-x"` when body 2's
//! surface is the faster: friction on body 1 acts the way body 2 slides over it, and the
//! contact and total stresses are those of that traction); `coupled` (null unless `coupled = true`): an object with
//! `iterations`, `tolerance`, `pressure_changes`, `isothermal_contact_area_m2`,
//! `contact_area_m2`, `isothermal_spots`, `spots`, `isothermal_max_pressure_pa`,
//! `max_pressure_pa`, `distortion_over_contact_m` (the range of the thermal bulge over the
//! heated contact: what the contact feels); `gear_path` (null unless the scene is a pair of
//! running spur gears: the contract keys are then those of the hottest point of the path of
//! contact): an object with `pinion_speed_rad_per_s`, `friction`, `contact_ratio`,
//! `path_start_m`, `path_end_m`, `hottest_s_m`, and per point of the path the arrays `s_m`,
//! `pairs`, `load_n_per_m`, `pinion_radius_m`, `gear_radius_m`, `half_width_m`,
//! `max_pressure_pa`, `pinion_flank_speed_m_per_s`, `gear_flank_speed_m_per_s`,
//! `sliding_speed_m_per_s`, `peclet`, `heat_partition_body1`, `max_temperature_rise_k`,
//! `body2_max_temperature_rise_k`, `blok_temperature_rise_k`. Positions are measured from the contact's centre (a rough
//! scene: the window's centre); the maxima are searched as [`crate::study::heated_stress`]
//! says.

use std::fmt::Write as _;

use serde::Serialize;

use crate::study::gear_heating::{GearHeating, PathPoint};
use crate::study::thermal::{ContactModel, ThermalStudy};
use crate::thermal::heating::Partition;

/// What the report says.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ThermalReport {
    pub peclet: f64,
    pub sliding_speed_m_per_s: f64,
    pub heat_partition_body1: f64,
    pub max_temperature_rise_k: f64,
    pub mean_temperature_rise_k: f64,
    pub max_temperature_x_m: f64,
    pub max_temperature_y_m: f64,
    pub thermal_von_mises_max_pa: f64,
    pub total_von_mises_max_pa: f64,
    pub total_von_mises_max_depth_m: f64,
    pub body1_speed_m_per_s: f64,
    pub body2_speed_m_per_s: Option<f64>,
    pub body2_peclet: Option<f64>,
    pub body2_max_temperature_rise_k: Option<f64>,
    pub body2_mean_temperature_rise_k: Option<f64>,
    pub thermal_von_mises_max_depth_m: f64,
    pub contact_von_mises_max_pa: f64,
    pub contact_von_mises_max_depth_m: f64,
    pub contact_von_mises_max_x_m: f64,
    pub total_von_mises_max_x_m: f64,
    pub thermal_von_mises_max_x_m: f64,
    pub thermal_von_mises_max_y_m: f64,
    pub total_von_mises_max_y_m: f64,
    pub contact_max_shear_max_pa: f64,
    pub contact_max_shear_max_depth_m: f64,
    pub total_max_shear_max_pa: f64,
    pub total_max_shear_max_depth_m: f64,
    pub total_max_shear_max_x_m: f64,
    /// `"closed_form"` (McEwen, Hamilton) or `"dcfft"`: where the contact stress comes from.
    pub contact_stress: &'static str,
    pub search_depths: usize,
    pub search_depth_m: f64,
    pub depth_tolerance_m: f64,
    pub body1_conductivity_w_per_m_k: f64,
    pub body1_diffusivity_m2_per_s: f64,
    pub body1_expansion_per_k: f64,
    pub body1_modulus_pa: f64,
    pub body1_poisson: f64,
    pub body2_conductivity_w_per_m_k: Option<f64>,
    pub body2_diffusivity_m2_per_s: Option<f64>,
    pub body2_expansion_per_k: Option<f64>,
    pub half_width_m: f64,
    pub rows: usize,
    pub columns: usize,
    pub spacing_m: [f64; 2],
    /// `"+x"` or `"-x"`: the direction of `q = μ p` on body 1 in the heating study.
    pub traction_on_body1: &'static str,
    pub coupled: Option<CoupledReport>,
    pub gear_path: Option<GearPathReport>,
}

/// Spur gears: the heating along the path of contact. The contract keys above are those of
/// the hottest point of the path (`hottest_s_m`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct GearPathReport {
    pub pinion_speed_rad_per_s: f64,
    pub friction: f64,
    pub contact_ratio: f64,
    pub path_start_m: f64,
    pub path_end_m: f64,
    pub hottest_s_m: f64,
    /// Per point of the path (m from the pitch point, + towards the pinion's tip).
    pub s_m: Vec<f64>,
    pub pairs: Vec<usize>,
    pub load_n_per_m: Vec<f64>,
    pub pinion_radius_m: Vec<f64>,
    pub gear_radius_m: Vec<f64>,
    pub half_width_m: Vec<f64>,
    pub max_pressure_pa: Vec<f64>,
    pub pinion_flank_speed_m_per_s: Vec<f64>,
    pub gear_flank_speed_m_per_s: Vec<f64>,
    pub sliding_speed_m_per_s: Vec<f64>,
    pub peclet: Vec<f64>,
    pub heat_partition_body1: Vec<f64>,
    pub max_temperature_rise_k: Vec<f64>,
    pub body2_max_temperature_rise_k: Vec<f64>,
    pub blok_temperature_rise_k: Vec<f64>,
}

impl GearPathReport {
    fn new(gear: &GearHeating) -> Self {
        let of = |f: &dyn Fn(&PathPoint) -> f64| gear.points.iter().map(f).collect::<Vec<f64>>();
        Self {
            pinion_speed_rad_per_s: gear.mesh.pinion_rad_per_s,
            friction: gear.mesh.friction,
            contact_ratio: gear.contact_ratio,
            path_start_m: gear.path_m[0],
            path_end_m: gear.path_m[1],
            hottest_s_m: gear.points[gear.hottest].s_m,
            s_m: of(&|p| p.s_m),
            pairs: gear.points.iter().map(|p| p.pairs).collect(),
            load_n_per_m: of(&|p| p.load_n_per_m),
            pinion_radius_m: of(&|p| p.radii_m[0]),
            gear_radius_m: of(&|p| p.radii_m[1]),
            half_width_m: of(&|p| p.half_width_m),
            max_pressure_pa: of(&|p| p.p0_pa),
            pinion_flank_speed_m_per_s: of(&|p| p.flank_speeds_m_per_s[0]),
            gear_flank_speed_m_per_s: of(&|p| p.flank_speeds_m_per_s[1]),
            sliding_speed_m_per_s: of(&|p| p.sliding_speed_m_per_s),
            peclet: of(&|p| p.peclet[0]),
            heat_partition_body1: of(&|p| p.body1_share),
            max_temperature_rise_k: of(&|p| p.max_temperature_rise_k[0]),
            body2_max_temperature_rise_k: of(&|p| p.max_temperature_rise_k[1]),
            blok_temperature_rise_k: of(&|p| p.blok_k),
        }
    }

    fn write_text(&self, out: &mut String, partition: Partition) -> std::fmt::Result {
        writeln!(
            out,
            "spur gears running: pinion at {:.1} rpm, mesh friction {}; path of contact from {:.3} to {:.3} mm about the pitch point, contact ratio {:.4}",
            self.pinion_speed_rad_per_s * 30.0 / std::f64::consts::PI,
            self.friction,
            self.path_start_m * 1e3,
            self.path_end_m * 1e3,
            self.contact_ratio
        )?;
        writeln!(
            out,
            "  (load shared equally by the pairs in contact; s from the pitch point, + towards the pinion's tip; Blok: {})",
            match partition {
                Partition::Blok => "1.11 mu w Vs / (sqrt(2a) (b1 sqrt V1 + b2 sqrt V2))",
                Partition::Fraction(_) => "f 1.11 mu w Vs / (sqrt(2a) b1 sqrt V1), f the given fraction",
                Partition::Body1 => "1.11 mu w Vs / (sqrt(2a) b1 sqrt V1), all heat into the pinion",
            }
        )?;
        writeln!(
            out,
            "  {:>8} {:>5} {:>8} {:>7} {:>8} {:>7} {:>7} {:>7} {:>7} {:>9} {:>9} {:>9}",
            "s (mm)",
            "pairs",
            "w (N/mm)",
            "a (µm)",
            "p0 (MPa)",
            "V1",
            "V2",
            "Vs",
            "Pe1",
            "T1 (K)",
            "T2 (K)",
            "Blok (K)"
        )?;
        let n = self.s_m.len();
        let step = (n - 1).div_ceil(10).max(1);
        let hottest = self
            .s_m
            .iter()
            .position(|&s| s == self.hottest_s_m)
            .unwrap_or(0);
        let pitch = self
            .s_m
            .iter()
            .enumerate()
            .fold((0, f64::INFINITY), |b, (k, s)| {
                if s.abs() < b.1 {
                    (k, s.abs())
                } else {
                    b
                }
            })
            .0;
        for k in 0..n {
            if k % step != 0 && k != n - 1 && k != hottest && k != pitch {
                continue;
            }
            writeln!(
                out,
                "  {:>8.3} {:>5} {:>8.2} {:>7.2} {:>8.1} {:>7.3} {:>7.3} {:>7.3} {:>7.2} {:>9.2} {:>9.2} {:>9.2}{}",
                self.s_m[k] * 1e3,
                self.pairs[k],
                self.load_n_per_m[k] * 1e-3,
                self.half_width_m[k] * 1e6,
                self.max_pressure_pa[k] * 1e-6,
                self.pinion_flank_speed_m_per_s[k],
                self.gear_flank_speed_m_per_s[k],
                self.sliding_speed_m_per_s[k],
                self.peclet[k],
                self.max_temperature_rise_k[k],
                self.body2_max_temperature_rise_k[k],
                self.blok_temperature_rise_k[k],
                if k == hottest { "  <- hottest" } else if k == pitch { "  <- pitch point" } else { "" }
            )?;
        }
        writeln!(
            out,
            "the hottest point of the path, s = {:.3} mm, in full:",
            self.hottest_s_m * 1e3
        )
    }
}

/// The coupled solution against the isothermal one.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CoupledReport {
    pub iterations: usize,
    pub tolerance: f64,
    pub pressure_changes: Vec<f64>,
    pub isothermal_contact_area_m2: f64,
    pub contact_area_m2: f64,
    pub isothermal_spots: usize,
    pub spots: usize,
    pub isothermal_max_pressure_pa: f64,
    pub max_pressure_pa: f64,
    pub distortion_over_contact_m: f64,
}

impl CoupledReport {
    fn new(coupled: &crate::study::coupled::CoupledContact) -> Self {
        let area = |s: &crate::contact::rough::RoughSolution| {
            let (ny, nx) = s.pressure_pa.dim();
            s.contact_fraction * (nx as f64 * s.spacing_m[0]) * (ny as f64 * s.spacing_m[1])
        };
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for (&w, &p) in coupled.distortion_m.iter().zip(&coupled.heated.pressure_pa) {
            if p > 0.0 {
                lo = lo.min(w);
                hi = hi.max(w);
            }
        }
        Self {
            iterations: coupled.iterations,
            tolerance: crate::study::coupled::TOLERANCE,
            pressure_changes: coupled.changes.clone(),
            isothermal_contact_area_m2: area(&coupled.isothermal),
            contact_area_m2: area(&coupled.heated),
            isothermal_spots: coupled.isothermal.spots,
            spots: coupled.heated.spots,
            isothermal_max_pressure_pa: coupled.isothermal.max_pressure_pa,
            max_pressure_pa: coupled.heated.max_pressure_pa,
            distortion_over_contact_m: if hi >= lo { hi - lo } else { 0.0 },
        }
    }
}

impl ThermalReport {
    pub fn new(study: &ThermalStudy) -> Self {
        let body2 = study.body2.as_ref();
        Self {
            peclet: study.body1.peclet,
            sliding_speed_m_per_s: study.spec.sliding_speed_m_per_s,
            heat_partition_body1: study.body1.share,
            max_temperature_rise_k: study.body1.max_temperature_rise_k,
            mean_temperature_rise_k: study.body1.mean_temperature_rise_k,
            max_temperature_x_m: study.body1.max_at_m[0],
            max_temperature_y_m: study.body1.max_at_m[1],
            thermal_von_mises_max_pa: study.thermal_von_mises.value_pa,
            total_von_mises_max_pa: study.total_von_mises.value_pa,
            total_von_mises_max_depth_m: study.total_von_mises.depth_m,
            body1_speed_m_per_s: study.spec.body1.speed_m_per_s,
            body2_speed_m_per_s: study.spec.body2.map(|b| b.speed_m_per_s),
            body2_peclet: body2.map(|b| b.peclet),
            body2_max_temperature_rise_k: body2.map(|b| b.max_temperature_rise_k),
            body2_mean_temperature_rise_k: body2.map(|b| b.mean_temperature_rise_k),
            thermal_von_mises_max_depth_m: study.thermal_von_mises.depth_m,
            contact_von_mises_max_pa: study.contact_von_mises.value_pa,
            contact_von_mises_max_depth_m: study.contact_von_mises.depth_m,
            contact_von_mises_max_x_m: study.contact_von_mises.x_m,
            total_von_mises_max_x_m: study.total_von_mises.x_m,
            thermal_von_mises_max_x_m: study.thermal_von_mises.x_m,
            thermal_von_mises_max_y_m: study.thermal_von_mises.y_m,
            total_von_mises_max_y_m: study.total_von_mises.y_m,
            contact_max_shear_max_pa: study.contact_max_shear.value_pa,
            contact_max_shear_max_depth_m: study.contact_max_shear.depth_m,
            total_max_shear_max_pa: study.total_max_shear.value_pa,
            total_max_shear_max_depth_m: study.total_max_shear.depth_m,
            total_max_shear_max_x_m: study.total_max_shear.x_m,
            contact_stress: match study.contact_model {
                ContactModel::ClosedForm { .. } => "closed_form",
                ContactModel::Gridded | ContactModel::Rough { .. } => "dcfft",
            },
            search_depths: study.search.coarse_depths,
            search_depth_m: study.search.depth_m,
            depth_tolerance_m: study.search.tolerance_m,
            body1_conductivity_w_per_m_k: study.spec.body1.properties.conductivity_w_per_m_k,
            body1_diffusivity_m2_per_s: study.spec.body1.properties.diffusivity_m2_per_s,
            body1_expansion_per_k: study.spec.body1.properties.expansion_per_k,
            body1_modulus_pa: study.spec.body1.material.modulus_pa,
            body1_poisson: study.spec.body1.material.poisson,
            body2_conductivity_w_per_m_k: study
                .spec
                .body2
                .map(|b| b.properties.conductivity_w_per_m_k),
            body2_diffusivity_m2_per_s: study.spec.body2.map(|b| b.properties.diffusivity_m2_per_s),
            body2_expansion_per_k: study.spec.body2.map(|b| b.properties.expansion_per_k),
            half_width_m: study.half_width_m,
            rows: study.shape[0],
            columns: study.shape[1],
            spacing_m: study.spacing_m,
            traction_on_body1: study.spec.traction.label(),
            coupled: study.coupled.as_ref().map(CoupledReport::new),
            gear_path: None,
        }
    }

    /// The report of running spur gears: the path, and the contract keys at its hottest point.
    pub fn for_gears(gear: &GearHeating) -> Self {
        Self {
            gear_path: Some(GearPathReport::new(gear)),
            ..Self::new(&gear.study)
        }
    }

    /// One JSON object.
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// The readable block.
    pub fn text(&self, study: &ThermalStudy) -> String {
        let mut out = String::new();
        let _ = self.write_text(&mut out, study);
        out
    }

    fn write_text(&self, out: &mut String, study: &ThermalStudy) -> std::fmt::Result {
        let um = |m: f64| m * 1e6;
        let mpa = |pa: f64| pa * 1e-6;
        let speed = |v: f64| crate::io::text::significant(v, 5, 1e6, true);
        let partition = match study.spec.partition {
            Partition::Body1 => "all into body 1 (counter-face adiabatic)".to_string(),
            Partition::Fraction(f) => format!("fraction {f} into body 1, as given"),
            Partition::Blok => "Blok's (equal mean flash temperatures)".to_string(),
        };
        writeln!(out, "frictional heating")?;
        if let Some(gear) = &self.gear_path {
            gear.write_text(out, study.spec.partition)?;
        }
        if let Some(c) = &self.coupled {
            let percent = |new: f64, old: f64| 100.0 * (new - old) / old;
            writeln!(
                out,
                "  coupled thermo-mechanical contact: converged in {} iterations (pressure change {:.1e} < {:.0e}); thermal bulge over the contact {:.3} µm",
                c.iterations,
                c.pressure_changes.last().copied().unwrap_or(0.0),
                c.tolerance,
                um(c.distortion_over_contact_m)
            )?;
            writeln!(
                out,
                "    heating changes the contact: area {:.4e} -> {:.4e} m^2 ({:+.2} %), spots {} -> {}, peak pressure {:.1} -> {:.1} MPa ({:+.2} %)",
                c.isothermal_contact_area_m2,
                c.contact_area_m2,
                percent(c.contact_area_m2, c.isothermal_contact_area_m2),
                c.isothermal_spots,
                c.spots,
                mpa(c.isothermal_max_pressure_pa),
                mpa(c.max_pressure_pa),
                percent(c.max_pressure_pa, c.isothermal_max_pressure_pa)
            )?;
        }
        writeln!(
            out,
            "  sliding speed {} m/s; contact over body 1 at {} m/s (Peclet V a/(2 kappa) = {:.4}){}",
            speed(self.sliding_speed_m_per_s),
            speed(self.body1_speed_m_per_s),
            self.peclet,
            match (self.body2_speed_m_per_s, self.body2_peclet) {
                (Some(v), Some(pe)) => format!(", over body 2 at {} m/s (Peclet {pe:.4})", speed(v)),
                _ => String::new(),
            }
        )?;
        writeln!(
            out,
            "  heat partition: {partition}: {:.4} of q = mu p V into body 1",
            self.heat_partition_body1
        )?;
        if study.spec.traction == crate::scene::TractionDirection::MinusX {
            writeln!(
                out,
                "  friction on body 1 acts in -x: body 2's surface is the faster and slides over body 1 towards -x (the contact and total stresses below are those of q = mu p in -x)"
            )?;
        }
        writeln!(
            out,
            "  body 1 flash temperature: max {:.2} K at x = {:.2} µm, y = {:.2} µm; mean over the contact {:.2} K",
            self.max_temperature_rise_k,
            um(self.max_temperature_x_m),
            um(self.max_temperature_y_m),
            self.mean_temperature_rise_k
        )?;
        let hottest = self
            .max_temperature_rise_k
            .max(self.body2_max_temperature_rise_k.unwrap_or(0.0));
        if hottest > crate::study::coupled::MAX_FLASH_TEMPERATURE_RISE_K {
            writeln!(
                out,
                "  note: a flash temperature rise of {hottest:.0} K is beyond any solid (more than {:.0} K): the surfaces would melt, and the linear heating with constant properties does not hold there",
                crate::study::coupled::MAX_FLASH_TEMPERATURE_RISE_K
            )?;
        }
        if let (Some(max), Some(mean), true) = (
            self.body2_max_temperature_rise_k,
            self.body2_mean_temperature_rise_k,
            self.heat_partition_body1 < 1.0,
        ) {
            writeln!(
                out,
                "  body 2 flash temperature: max {max:.2} K; mean over the contact {mean:.2} K"
            )?;
        }
        let properties = |k: f64, kappa: f64, alpha: f64| {
            format!(
                "K = {} W/(m K), kappa = {} m^2/s, alpha = {} 1/K",
                crate::io::text::significant(k, 4, 1e6, true),
                crate::io::text::significant(kappa, 4, 1e6, true),
                crate::io::text::significant(alpha, 4, 1e6, true)
            )
        };
        writeln!(
            out,
            "  thermal properties used: body 1 {}, E = {:.1} GPa, nu = {}{}",
            properties(
                self.body1_conductivity_w_per_m_k,
                self.body1_diffusivity_m2_per_s,
                self.body1_expansion_per_k
            ),
            self.body1_modulus_pa * 1e-9,
            self.body1_poisson,
            match (
                self.body2_conductivity_w_per_m_k,
                self.body2_diffusivity_m2_per_s,
                self.body2_expansion_per_k
            ) {
                (Some(k), Some(kappa), Some(alpha)) =>
                    format!("; body 2 {}", properties(k, kappa, alpha)),
                _ => String::new(),
            }
        )?;
        let a = self.half_width_m;
        writeln!(
            out,
            "  von Mises maxima (body 1): thermal {:.1} MPa at depth {:.2} µm, x = {:.2} µm ({:.3} a), y = {:.2} µm; contact alone {:.1} MPa at depth {:.2} µm, x = {:.2} µm; total {:.1} MPa at depth {:.2} µm, x = {:.2} µm, y = {:.2} µm",
            mpa(self.thermal_von_mises_max_pa),
            um(self.thermal_von_mises_max_depth_m),
            um(self.thermal_von_mises_max_x_m),
            self.thermal_von_mises_max_x_m / a,
            um(self.thermal_von_mises_max_y_m),
            mpa(self.contact_von_mises_max_pa),
            um(self.contact_von_mises_max_depth_m),
            um(self.contact_von_mises_max_x_m),
            mpa(self.total_von_mises_max_pa),
            um(self.total_von_mises_max_depth_m),
            um(self.total_von_mises_max_x_m),
            um(self.total_von_mises_max_y_m)
        )?;
        writeln!(
            out,
            "  maximum shear (s1 - s3)/2 (Tresca) maxima: contact alone {:.1} MPa at depth {:.2} µm; total {:.1} MPa at depth {:.2} µm, x = {:.2} µm",
            mpa(self.contact_max_shear_max_pa),
            um(self.contact_max_shear_max_depth_m),
            mpa(self.total_max_shear_max_pa),
            um(self.total_max_shear_max_depth_m),
            um(self.total_max_shear_max_x_m)
        )?;
        writeln!(
            out,
            "  grid: {} x {} cells of {:.3} x {:.3} µm; contact stress {}; maxima searched at the cell centres of {} depths to {:.2} µm, refined in depth to {:.3} µm{}",
            self.columns,
            self.rows,
            um(self.spacing_m[0]),
            um(self.spacing_m[1]),
            if self.contact_stress == "closed_form" {
                "from the closed form (contact alone as hertz)"
            } else {
                "by DC-FFT on the grid"
            },
            self.search_depths,
            um(self.search_depth_m),
            um(self.depth_tolerance_m),
            if self.contact_stress == "closed_form" {
                " and the totals in x between the centres"
            } else {
                ""
            }
        )
    }
}
