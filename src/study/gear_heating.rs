//! The flash temperature of spur gear teeth along the path of contact (a scene with
//! `[contact.gears]` and `[thermal] pinion_speed`).
//!
//! At each point `s` of the path the teeth are two cylinders of the flank radii `ρ1(s)`,
//! `ρ2(s)` in line contact (Hertz), under the normal load per unit face width shared equally by
//! the pairs of teeth in contact (rigid teeth without profile modification: the whole load in
//! the single-pair zone around the pitch point, half of it where two pairs mesh); the contact
//! moves over the pinion's flank at `V1 = ω1 ρ1` and over the gear's at `V2 = ω2 ρ2`, and the
//! flanks slide at `|V1 - V2| = (ω1 + ω2) |s|`, so no heat is made at the pitch point. Each
//! point's flash temperatures are those of the scene's line contact (Jaeger's moving band on
//! each body, the heat parted as `[thermal] partition` says), and the hottest point gets the
//! full study with the thermal stresses.
//!
//! Blok's (1937) flash temperature of the Hertzian band at high Péclet numbers is given beside
//! it: with the heat parted so that the bodies' maximum temperatures agree,
//! `θ_B = 1.11 μ w V_s / (√(2a) (β1 √V1 + β2 √V2))`, `β = K / √κ` each body's thermal
//! effusivity, `w` the load per unit width of the pair (all heat into body 1: without the
//! `β2` term; a fixed fraction `f`: `f` times that).

use crate::contact::gear::SpurGearPair;
use crate::contact::{Body, LineContact};
use crate::scene::{Dimensional, GearMesh, Hertz, Scale, Scene, ThermalSpec, TractionDirection};
use crate::study::thermal::{self, Progress, ThermalStudy, ThermalStudyError};
use crate::thermal::heating::Partition;

/// Points along the path of contact.
pub const PATH_POINTS: usize = 41;

/// The teeth at one point of the path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathPoint {
    /// Distance from the pitch point along the line of action, m (+ towards the pinion's tip).
    pub s_m: f64,
    /// Flank radii `[ρ1, ρ2]`, m.
    pub radii_m: [f64; 2],
    /// Pairs of teeth sharing the load, and this pair's load per unit face width, N/m.
    pub pairs: usize,
    pub load_n_per_m: f64,
    pub half_width_m: f64,
    pub p0_pa: f64,
    /// Speeds of the contact over the pinion's and the gear's flank, m/s.
    pub flank_speeds_m_per_s: [f64; 2],
    pub sliding_speed_m_per_s: f64,
    /// `V a / (2κ)` of each body.
    pub peclet: [f64; 2],
    /// Body 1's (the pinion's) share of the heat.
    pub body1_share: f64,
    /// Each body's maximum flash temperature rise, K.
    pub max_temperature_rise_k: [f64; 2],
    /// Blok's high-Péclet flash temperature of body 1 (module doc), K.
    pub blok_k: f64,
}

/// The heating along the path and the full study at its hottest point.
#[derive(Clone, Debug, PartialEq)]
pub struct GearHeating {
    pub mesh: GearMesh,
    /// Start and end of the path of contact, m from the pitch point.
    pub path_m: [f64; 2],
    pub contact_ratio: f64,
    pub points: Vec<PathPoint>,
    /// Index into `points` of the largest flash temperature of body 1.
    pub hottest: usize,
    /// The full study (temperatures and stresses) at the hottest point.
    pub study: ThermalStudy,
}

/// The line-contact scene of the teeth at `s`: flank radii, shared load, the mesh's friction,
/// and `[thermal]` with the speeds there and the sliding speed `sliding`.
pub(crate) fn scene_at(
    scene: &Scene,
    mesh: &GearMesh,
    s: f64,
    sliding: f64,
) -> Option<(Scene, PathPoint)> {
    let dimensional = scene.contact.dimensional?;
    let pair = dimensional.gears?;
    let spec = scene.thermal?;
    let radii = pair.flank_radii_m(s);
    let pairs = pair.pairs_in_contact(s);
    let load = match dimensional.hertz {
        Hertz::Line(line) => line.load_n_per_m / pairs as f64,
        _ => return None,
    };
    let body1 = Body {
        radius_m: radii[0],
        ..dimensional.body1
    };
    let body2 = Body {
        radius_m: radii[1],
        ..dimensional.body2
    };
    let line = LineContact::new(&body1, &body2, load).ok()?;
    let speeds = pair.flank_speeds_m_per_s(s, mesh.pinion_rad_per_s);
    let mut at = scene.clone();
    at.contact.friction = mesh.friction;
    at.contact.scale = Some(Scale {
        half_width_m: line.half_width_m,
        p0_pa: line.p0_pa,
    });
    at.contact.dimensional = Some(Dimensional {
        body1,
        body2,
        gears: None,
        hertz: Hertz::Line(line),
    });
    let mut thermal_spec: ThermalSpec = spec;
    thermal_spec.gear = None;
    thermal_spec.sliding_speed_m_per_s = sliding;
    thermal_spec.body1.speed_m_per_s = speeds[0];
    // On the approach side (s < 0) the gear's flank is the faster: friction on the pinion
    // acts in -x there.
    thermal_spec.traction = TractionDirection::of_speeds(speeds[0], speeds[1]);
    if let Some(b2) = &mut thermal_spec.body2 {
        b2.speed_m_per_s = speeds[1];
    }
    at.thermal = Some(thermal_spec);
    let a = line.half_width_m;
    let peclet = |speed: f64, diffusivity: f64| speed * a / (2.0 * diffusivity);
    let point = PathPoint {
        s_m: s,
        radii_m: radii,
        pairs,
        load_n_per_m: load,
        half_width_m: a,
        p0_pa: line.p0_pa,
        flank_speeds_m_per_s: speeds,
        sliding_speed_m_per_s: (speeds[0] - speeds[1]).abs(),
        peclet: [
            peclet(speeds[0], spec.body1.properties.diffusivity_m2_per_s),
            spec.body2.map_or(f64::NAN, |b| {
                peclet(speeds[1], b.properties.diffusivity_m2_per_s)
            }),
        ],
        body1_share: f64::NAN,
        max_temperature_rise_k: [0.0; 2],
        blok_k: 0.0,
    };
    Some((at, point))
}

/// Blok's flash temperature of body 1 (module doc).
fn blok(point: &PathPoint, spec: &ThermalSpec, friction: f64) -> f64 {
    let effusivity = |p: &crate::thermal::material::ThermalProperties| {
        p.conductivity_w_per_m_k / p.diffusivity_m2_per_s.sqrt()
    };
    let [v1, v2] = point.flank_speeds_m_per_s;
    let heat = 1.11 * friction * point.load_n_per_m * point.sliding_speed_m_per_s
        / (2.0 * point.half_width_m).sqrt();
    let one = effusivity(&spec.body1.properties) * v1.sqrt();
    match (spec.partition, &spec.body2) {
        (Partition::Blok, Some(b2)) => heat / (one + effusivity(&b2.properties) * v2.sqrt()),
        (Partition::Fraction(f), _) => f * heat / one,
        _ => heat / one,
    }
}

/// The positions along the path: [`PATH_POINTS`] evenly spaced, the pitch point, and both
/// sides of each change in the number of pairs in contact (so the load's steps show).
pub fn path_positions(pair: &SpurGearPair) -> Vec<f64> {
    let [start, end] = pair.path_of_contact_m();
    let mut positions: Vec<f64> = (0..PATH_POINTS)
        .map(|k| start + (end - start) * k as f64 / (PATH_POINTS - 1) as f64)
        .collect();
    if start < 0.0 && end > 0.0 {
        positions.push(0.0);
    }
    let pitch = pair.base_pitch_m();
    let nudge = 1e-9 * (end - start);
    for boundary in [end - pitch, start + pitch] {
        if boundary > start && boundary < end {
            positions.push(boundary - nudge);
            positions.push(boundary + nudge);
        }
    }
    positions.sort_by(f64::total_cmp);
    positions.dedup();
    positions
}

/// The heating of a gear scene along its path of contact ([`path_positions`]); `progress`
/// gets the points done, then the hottest point's study.
pub fn gear_heating(
    scene: &Scene,
    progress: &mut dyn FnMut(Progress),
) -> Result<GearHeating, ThermalStudyError> {
    let spec = scene.thermal.ok_or(ThermalStudyError::NoThermal)?;
    let mesh = spec.gear.ok_or(ThermalStudyError::NotGears)?;
    let pair = scene
        .contact
        .dimensional
        .and_then(|d| d.gears)
        .ok_or(ThermalStudyError::NotGears)?;
    let path_m = pair.path_of_contact_m();
    let positions = path_positions(&pair);
    let total = positions.len();
    let mut points = Vec::with_capacity(total);
    for (k, &s) in positions.iter().enumerate() {
        // The heating at unit sliding speed, scaled: the shares do not depend on it, and the
        // pitch point (no sliding) gets them too.
        let (at, mut point) = scene_at(scene, &mesh, s, 1.0).ok_or(ThermalStudyError::NotGears)?;
        let at_spec = at.thermal.ok_or(ThermalStudyError::NoThermal)?;
        let (_, body1, body2) = thermal::hertz_flash(&at, &at_spec)?;
        let sliding = point.sliding_speed_m_per_s;
        point.body1_share = body1.share;
        point.max_temperature_rise_k = [
            body1.max_temperature_rise_k * sliding,
            body2.map_or(0.0, |b| b.max_temperature_rise_k * sliding),
        ];
        point.blok_k = blok(&point, &spec, mesh.friction);
        points.push(point);
        progress(Progress::Path { done: k + 1, total });
    }
    let hottest = points
        .iter()
        .enumerate()
        .fold((0, f64::NEG_INFINITY), |best, (k, p)| {
            if p.max_temperature_rise_k[0] > best.1 {
                (k, p.max_temperature_rise_k[0])
            } else {
                best
            }
        })
        .0;
    let s = points[hottest].s_m;
    let sliding = points[hottest].sliding_speed_m_per_s;
    let (at, _) = scene_at(scene, &mesh, s, sliding).ok_or(ThermalStudyError::NotGears)?;
    let study = thermal::study(&at, None, progress)?;
    Ok(GearHeating {
        mesh,
        path_m,
        contact_ratio: pair.contact_ratio(),
        points,
        hottest,
        study,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gears(speed: &str, partition: &str) -> Scene {
        let text = format!(
            r#"
format = 1
[contact]
kind = "line"
load = "40 kN/m"
[contact.gears]
module = "5 mm"
teeth = [20, 40]
pressure_angle = "20 deg"
[contact.body1]
material = "steel"
[contact.body2]
material = "steel"
[thermal]
pinion_speed = "{speed}"
friction = 0.05
partition = {partition}
"#
        );
        Scene::parse(&text, "gears", "gears.toml").expect("valid gear scene")
    }

    #[test]
    fn no_heat_at_the_pitch_point_and_the_load_steps_with_the_pairs() {
        let scene = gears("1500 rpm", "\"blok\"");
        let heating = gear_heating(&scene, &mut |_| {}).expect("heating");
        let pitch = heating
            .points
            .iter()
            .find(|p| p.s_m == 0.0)
            .expect("the pitch point is on the path");
        assert_eq!(pitch.sliding_speed_m_per_s, 0.0);
        assert_eq!(pitch.max_temperature_rise_k, [0.0, 0.0]);
        // Rolling speeds agree there: ω1 r1 sin φ = ω2 r2 sin φ.
        let [v1, v2] = pitch.flank_speeds_m_per_s;
        assert!((v1 - v2).abs() < 1e-12 * v1);
        // The single-pair zone carries the whole load, the double-pair zones half of it.
        for p in &heating.points {
            assert!((p.load_n_per_m * p.pairs as f64 - 40e3).abs() < 1e-9);
        }
        assert!(heating.points.iter().any(|p| p.pairs == 1));
        assert!(heating.points.iter().any(|p| p.pairs == 2));
        // The flash temperature grows away from the pitch point on either side.
        let hottest = &heating.points[heating.hottest];
        assert!(hottest.s_m.abs() > 0.5 * (heating.path_m[1] - heating.path_m[0]) / 2.0);
        // The full study is that of the hottest point.
        assert!(
            (heating.study.body1.max_temperature_rise_k - hottest.max_temperature_rise_k[0]).abs()
                < 1e-9 * hottest.max_temperature_rise_k[0]
        );
    }

    /// Blok's flash temperature (Blok 1937; the 1.11 factor of the Hertzian band) is the
    /// high-Péclet limit: with all heat into the pinion at 20000 rpm (Pe1 from 11 to 127), the
    /// path's temperatures against it.
    #[test]
    fn fast_gears_follow_bloks_flash_temperature() {
        let scene = gears("20000 rpm", "\"body1\"");
        let heating = gear_heating(&scene, &mut |_| {}).expect("heating");
        let mut worst: f64 = 0.0;
        for p in heating
            .points
            .iter()
            .filter(|p| p.sliding_speed_m_per_s > 0.0)
        {
            let error = (p.max_temperature_rise_k[0] - p.blok_k) / p.blok_k;
            worst = worst.max(error.abs());
        }
        // Measured: 1.4e-3 at most (4e-4 at Pe1 = 11), the rounding of Blok's 1.11.
        eprintln!("measured: gear path vs Blok: {worst:.2e}");
        assert!(worst < 5e-3, "{worst}");
    }
}
