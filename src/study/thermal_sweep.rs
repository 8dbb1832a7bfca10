//! The speed sweep of a scene with `[thermal]` (issue 21): body 1's flash temperature as the
//! contact slides faster, from a nearly stationary source (Pe ≪ 1, the temperature centred on
//! the contact and growing like `V`) to a fast one (Pe ≫ 1, the heat swept into a wake behind
//! the contact, the maximum moving back towards the trailing edge and growing like `√V`).
//! Computed once here; the recording (`crate::record`) only draws it.
//!
//! - The Péclet number swept is body 1's, `Pe = V1 a / (2κ1)` (`a` the contact's half-width,
//!   radius or semi-axis along x); every speed of the scene is scaled by the same factor
//!   ([`ThermalSpec::at_body1_peclet`]), so the flux `q = μ p V` grows with it.
//! - One grid serves every step ([`SWEEP_WINDOW`]: `-4a <= x <= 2a`, `|y| <= 2b`, wider than
//!   the study's so that the wake shows), with cells fine enough for the largest Péclet number
//!   (cell Péclet number `u dx <= MAX_CELL_PECLET`, at most [`SWEEP_CELLS`] cells along x,
//!   hence [`peclet_limit`]).
//! - Each step: body 1's share of the heat (the scene's partition; Blok's recomputed at every
//!   speed), its surface temperature under that share, the xz section of its temperature
//!   through the contact's centre (`y = 0`) from the surface to `1.2a`, and the maximum and
//!   mean flash temperature and where the maximum is.
//! - The two asymptotes of body 1's maximum with all the heat in it (as the heating figure
//!   draws them, [`crate::study::thermal_sections`]): the stationary temperature, `∝ Pe`
//!   (Carslaw & Jaeger 1959), and the fast limit of Jaeger (1942) and Blok (1937), `∝ √Pe`.
//!
//! ## References
//! - H. S. Carslaw, J. C. Jaeger, *Conduction of Heat in Solids*, 2nd ed., Oxford (1959).
//! - J. C. Jaeger, Moving sources of heat and the temperature at sliding contacts, *Proc. R.
//!   Soc. N. S. W.* 76 (1942).
//! - H. Blok, Theoretical study of temperature rise at surfaces of actual contact under
//!   oiliness lubricating conditions, *Proc. General Discussion on Lubrication*, IMechE (1937).

use ndarray::Array2;

use super::thermal::{
    body_temperature, heating, hertz_grid, inverse_length, BodyHeating, Gridded, ThermalStudyError,
    Window,
};
use super::thermal_sections::{fast_limit, SECTION_DEPTH_OVER_A};
use crate::scene::{ContactKind, Scene, ThermalSpec};
use crate::thermal::heating::{frictional_flux, Partition};
use crate::thermal::kernel::CellGrid;
use crate::thermal::line::LineTemperature;
use crate::thermal::temperature::{row_temperature, MAX_CELL_PECLET};

/// The most cells along x of the sweep's grid.
pub const SWEEP_CELLS: usize = 320;

/// Depths of the sections: `0..=1.2a` in this many steps (`a/40` apart: at Pe 100 the heated
/// layer is about `a/√Pe = a/10` deep).
pub const SECTION_STEPS: usize = 48;

/// The sweep's grid: `-4a <= x <= 2a` and `|y| <= 2b`, a row on `y = 0`.
pub(super) const SWEEP_WINDOW: Window = Window {
    x_over_a: [-4.0, 2.0],
    y_over_b: 2.0,
    max_cells: SWEEP_CELLS,
    centre_row: true,
    key: "sweep",
    hint: "a Péclet number is beyond what the sweep's grid resolves; lower sweep.to (or the largest of sweep.values)",
};

/// Body 1's largest Péclet number the sweep's grid resolves for `spec`'s bodies: the cell
/// Péclet number of the fastest heated body (body 2 too under Blok's partition) at most
/// [`MAX_CELL_PECLET`] with [`SWEEP_CELLS`] cells across the window's `6a` (106.7 when body 1
/// is the fastest). 0 when body 1 carries the contact.
pub fn peclet_limit(spec: &ThermalSpec) -> f64 {
    let heated = heated_bodies(spec);
    let u1 = inverse_length(&heated.body1);
    let fastest = heated
        .body2
        .as_ref()
        .map_or(u1, |b2| u1.max(inverse_length(b2)));
    if fastest <= 0.0 {
        return 0.0;
    }
    let width_over_a = SWEEP_WINDOW.x_over_a[1] - SWEEP_WINDOW.x_over_a[0];
    MAX_CELL_PECLET * SWEEP_CELLS as f64 / width_over_a * u1 / fastest
}

/// The bodies whose temperatures the sweep computes: body 2 only for Blok's partition (the
/// others do not read its temperature).
fn heated_bodies(spec: &ThermalSpec) -> ThermalSpec {
    let mut heated = *spec;
    if spec.partition != Partition::Blok {
        heated.body2 = None;
    }
    heated
}

/// Why `scene` cannot be swept in speed (`sweep.parameter = "peclet"`): the message and the
/// fix, or `None`.
pub fn refusal(scene: &Scene) -> Option<(&'static str, &'static str)> {
    let Some(spec) = &scene.thermal else {
        return Some((
            "a Péclet sweep varies the sliding speed of [thermal], and the scene has none",
            "add [thermal] with speed = \"1 m/s\" (and the bodies' materials), or sweep \"friction\", \"load\" or \"position\"",
        ));
    };
    if scene.contact.kind == ContactKind::Rough {
        return Some((
            "a Péclet sweep is recorded for line, point and elliptical contacts, not for a rough contact",
            "`stressfield thermal SCENE` reports a rough scene's heating (and --figure FILE.png charts its maximum against Pe); sweep the load of a rough scene",
        ));
    }
    if spec.gear.is_some() {
        return Some((
            "running gears are heated along their path of contact at the pinion's speed; their speeds are not swept",
            "`stressfield thermal SCENE` reports the path (and --figure FILE.png draws it); sweep the pinion's speed by copying the scene",
        ));
    }
    if spec.coupled {
        return Some((
            "a Péclet sweep heats the Hertz pressure; the coupled solution (thermal.coupled = true) solves the pressure again at every speed and is not swept",
            "set thermal.coupled = false",
        ));
    }
    if spec.body1.speed_m_per_s <= 0.0 {
        return Some((
            "the Péclet number swept is body 1's, V1 a / (2κ1), and body 1 carries the contact (thermal.body1_speed = 0)",
            "give thermal.body1_speed > 0 (the speed of the contact over body 1), or make the body the contact moves over body 1",
        ));
    }
    None
}

/// One speed of the sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct SpeedStep {
    /// Body 1's Péclet number and the sliding speed (m/s).
    pub peclet: f64,
    pub sliding_speed_m_per_s: f64,
    /// Body 1's heating under its share: the surface map `[ny, nx]` (K), the maximum, the mean
    /// over the contact, where the maximum is.
    pub body1: BodyHeating,
    /// Body 1's maximum rise (K) with all the heat in it (the asymptotes' quantity).
    pub whole_max_k: f64,
    /// `[depths, nx]`: body 1's temperature rise (K) under its share in the xz section through
    /// [`SpeedSweep::row`].
    pub section_k: Array2<f64>,
}

/// The speed sweep of a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct SpeedSweep {
    /// The length `a` of the Péclet number, m.
    pub half_width_m: f64,
    /// The grid: `[ny, nx]`, `[dx, dy]` (m), and the centre of cell `[0, 0]` relative to the
    /// contact's centre (m).
    pub shape: [usize; 2],
    pub spacing_m: [f64; 2],
    pub origin_m: [f64; 2],
    /// `μ p` on the grid: the flux per unit sliding speed (W/m² per m/s), the contact where it
    /// is positive.
    pub flux_per_speed: Array2<f64>,
    /// The row of the sections (through the contact's centre) and its y (m).
    pub row: usize,
    pub y_m: f64,
    /// Section depths (m), evenly spaced from 0.
    pub depths_m: Vec<f64>,
    /// A line contact (plane problem): every row is the same.
    pub line: bool,
    /// Body 1's maximum with all the heat in it: the stationary asymptote's `θ / Pe` (None for
    /// a line contact, which has no steady stationary temperature) and the fast one's
    /// `θ / √Pe` (K).
    pub slow_per_peclet: Option<f64>,
    pub fast_per_root_peclet: f64,
    pub steps: Vec<SpeedStep>,
}

impl SpeedSweep {
    /// The x of cell column `column`, m from the contact's centre.
    pub fn x_m(&self, column: usize) -> f64 {
        self.origin_m[0] + column as f64 * self.spacing_m[0]
    }
}

/// Sweeps `scene` (with `[thermal]`, see [`refusal`]) over body 1's Péclet numbers `peclets`
/// (each at most [`peclet_limit`]); `progress(done, total)` after each step.
pub fn speed_sweep(
    scene: &Scene,
    peclets: &[f64],
    progress: &mut dyn FnMut(usize, usize),
) -> Result<SpeedSweep, ThermalStudyError> {
    sweep_on(scene, peclets, &SWEEP_WINDOW, progress)
}

/// [`speed_sweep`] on `window`.
fn sweep_on(
    scene: &Scene,
    peclets: &[f64],
    window: &Window,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<SpeedSweep, ThermalStudyError> {
    let spec = scene.thermal.ok_or(ThermalStudyError::NoThermal)?;
    if let Some((message, hint)) = refusal(scene) {
        return Err(ThermalStudyError::PecletSweep { message, hint });
    }
    let a = scene.contact.half_width_m();
    let largest = peclets.iter().copied().fold(0.0, f64::max);
    if largest <= 0.0 {
        return Err(ThermalStudyError::PecletSweep {
            message: "a Péclet sweep needs positive Péclet numbers",
            hint: "give sweep.values > 0, or from and to > 0",
        });
    }
    let spec = heated_bodies(&spec);
    let gridded = hertz_grid(scene, &spec.at_body1_peclet(largest, a), window)?;
    let friction = scene.contact.friction;
    let flux_per_speed = gridded
        .pressure_pa
        .mapv(|p| frictional_flux(friction, p, 1.0));
    let row = gridded.shape[0] / 2;
    let depths_m: Vec<f64> = (0..=SECTION_STEPS)
        .map(|k| SECTION_DEPTH_OVER_A * a * k as f64 / SECTION_STEPS as f64)
        .collect();
    let k1 = spec.body1.properties.conductivity_w_per_m_k;
    // Body 2's temperature per unit sliding speed, kept while its u = V/(2κ) stays (a body
    // that carries the contact, u = 0, at every step).
    let mut body2_cache: Option<(f64, Array2<f64>)> = None;
    let mut steps = Vec::with_capacity(peclets.len());
    for (done, &peclet) in peclets.iter().enumerate() {
        let stepped = spec.at_body1_peclet(peclet, a);
        let speed = stepped.sliding_speed_m_per_s;
        let flux = flux_per_speed.mapv(|q| q * speed);
        let t1 = body_temperature(&gridded, &stepped.body1, &flux)?;
        let whole1 = heating(&gridded, &t1, 1.0, peclet);
        let share = match &stepped.body2 {
            Some(b2) => {
                let u2 = inverse_length(b2);
                let per_speed = match body2_cache.take() {
                    Some((u, t)) if u == u2 => t,
                    _ => body_temperature(&gridded, b2, &flux_per_speed)?,
                };
                let t2 = per_speed.mapv(|t| t * speed);
                body2_cache = Some((u2, per_speed));
                let mean2 =
                    heating(&gridded, &t2, 1.0, inverse_length(b2) * a).mean_temperature_rise_k;
                stepped
                    .partition
                    .body1_share(whole1.mean_temperature_rise_k, mean2)
            }
            None => stepped.partition.body1_share(1.0, 0.0),
        };
        let body1 = heating(&gridded, &t1, share, peclet);
        let section_k = section(&gridded, &stepped, &flux, row, &depths_m, &body1)?;
        steps.push(SpeedStep {
            peclet,
            sliding_speed_m_per_s: speed,
            whole_max_k: whole1.max_temperature_rise_k,
            body1,
            section_k,
        });
        progress(done + 1, peclets.len());
    }
    // The asymptotes with the flux at body 1's Pe: V = c Pe, c the scene's V / Pe.
    let per_peclet = spec.sliding_speed_m_per_s / spec.body1_peclet(a);
    let slow_per_peclet = if gridded.line {
        None
    } else {
        let mut resting = spec.body1;
        resting.speed_m_per_s = 0.0;
        let t = body_temperature(&gridded, &resting, &flux_per_speed)?;
        Some(t.iter().copied().fold(0.0, f64::max) * per_peclet)
    };
    // θ_fast = fast_limit(q) / √u with u = Pe / a: per √Pe, fast_limit(μ p) c √a.
    let fast_per_root_peclet =
        fast_limit(&flux_per_speed, gridded.spacing_m[0], k1) * per_peclet * a.sqrt();
    Ok(SpeedSweep {
        half_width_m: a,
        shape: gridded.shape,
        spacing_m: gridded.spacing_m,
        origin_m: gridded.origin_m,
        y_m: gridded.origin_m[1] + row as f64 * gridded.spacing_m[1],
        row,
        flux_per_speed,
        depths_m,
        line: gridded.line,
        slow_per_peclet,
        fast_per_root_peclet,
        steps,
    })
}

/// Body 1's temperature rise under its share along `row` at each depth: the surface row of
/// its map at `z = 0`, below it the row summed directly ([`row_temperature`]), or a line
/// contact's band at that depth ([`LineTemperature`]).
fn section(
    gridded: &Gridded,
    stepped: &ThermalSpec,
    flux: &Array2<f64>,
    row: usize,
    depths_m: &[f64],
    body1: &BodyHeating,
) -> Result<Array2<f64>, ThermalStudyError> {
    let [_, nx] = gridded.shape;
    let u = inverse_length(&stepped.body1);
    let k = stepped.body1.properties.conductivity_w_per_m_k;
    let grid = CellGrid {
        shape: gridded.shape,
        spacing_m: gridded.spacing_m,
    };
    let mut out = Array2::zeros((depths_m.len(), nx));
    for (d, &z) in depths_m.iter().enumerate() {
        let values: Vec<f64> = if z == 0.0 {
            body1.temperature_k.row(row).to_vec()
        } else if gridded.line {
            let band: Vec<f64> = flux.row(row).to_vec();
            LineTemperature::new(nx, gridded.spacing_m[0], z, u, k)
                .apply(&band)
                .iter()
                .map(|t| t * body1.share)
                .collect()
        } else {
            row_temperature(&grid, flux.view(), row, z, u, k)
                .iter()
                .map(|t| t * body1.share)
                .collect()
        };
        out.row_mut(d).assign(&ndarray::ArrayView1::from(&values));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use super::*;
    use crate::study::thermal::{study, STUDY_WINDOW};
    use crate::thermal::special::integrate;

    /// A steel ball (radius 10 mm) sliding on a steel flat under 50 N, μ = 0.1, the contact
    /// moving over the flat (body 1) at 1 m/s (Pe about 6), with `partition`.
    fn ball_on_flat(partition: &str) -> Scene {
        let text = format!(
            "format = 1\n[contact]\nkind = \"point\"\nload = \"50 N\"\nfriction = 0.1\n\
             [contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n\
             [contact.body2]\nradius = \"10 mm\"\nmaterial = \"steel\"\n\
             [thermal]\nspeed = \"1 m/s\"\npartition = \"{partition}\"\n"
        );
        Scene::parse(&text, "t", "t.toml").expect("a valid scene")
    }

    /// `μ p0 V a / K` of body 1 at body 1's Péclet number `pe` (K): the scale of the
    /// temperatures.
    fn scale_k(scene: &Scene, pe: f64) -> f64 {
        let spec = scene.thermal.expect("[thermal]");
        let a = scene.contact.half_width_m();
        let v = spec.at_body1_peclet(pe, a).sliding_speed_m_per_s;
        scene.contact.friction * scene.contact.p0_pa() * v * a
            / spec.body1.properties.conductivity_w_per_m_k
    }

    #[test]
    fn the_hottest_point_follows_the_fast_limit_of_jaeger_and_blok() {
        // All heat into the flat. At high Pe each streamline is heated like a semi-infinite
        // body for its time under the contact (Jaeger 1942; Blok 1937): along the centre row
        // q = μ p0 V √(1 - x²/a²) and θ(x) = (1/K) √(κ/(πV)) ∫_x^a q(s)/√(s - x) ds, whose
        // largest value, with √(κ/(πV)) = a/√(2π Pe), is μ p0 V a / (K √(2π Pe)) max_x I(x),
        // I(x) = ∫_0^√(1-x) 2 √(1 - (x + t²)²) dt (s = x + t², x in units of a), integrated
        // here independently of the grid. The computed maximum approaches it from below
        // (heat also spreads sideways); tolerance 1.5 % at Pe 100, and closer at 100 than at
        // 10.
        let scene = ball_on_flat("body1");
        let integral = |x: f64| {
            integrate(
                |t| 2.0 * (1.0 - (x + t * t).powi(2)).max(0.0).sqrt(),
                0.0,
                (1.0 - x).sqrt(),
                1e-12,
            )
        };
        let largest = (0..=2000)
            .map(|k| integral(-1.0 + 2.0 * k as f64 / 2000.0))
            .fold(0.0, f64::max);
        let peclets = [10.0, 100.0];
        let sweep = speed_sweep(&scene, &peclets, &mut |_, _| {}).expect("swept");
        let errors: Vec<f64> = sweep
            .steps
            .iter()
            .map(|step| {
                let limit =
                    scale_k(&scene, step.peclet) * largest / (2.0 * PI * step.peclet).sqrt();
                step.whole_max_k / limit - 1.0
            })
            .collect();
        eprintln!("measured: max vs 1-D fast limit at Pe {peclets:?}: {errors:?}");
        assert!(errors[1].abs() < 0.015, "{errors:?}");
        assert!(errors[1].abs() < errors[0].abs(), "{errors:?}");
        // The grid's own fast limit (the heating figure's asymptote) is the same integral.
        let fast = sweep.fast_per_root_peclet * 100f64.sqrt();
        let limit = scale_k(&scene, 100.0) * largest / (2.0 * PI * 100.0).sqrt();
        eprintln!(
            "measured: grid fast limit vs quadrature: {:.2e}",
            fast / limit - 1.0
        );
        assert!((fast / limit - 1.0).abs() < 1e-3, "{fast} vs {limit}");
    }

    #[test]
    fn a_slow_source_tends_to_the_stationary_centre_temperature() {
        // A stationary Hertzian flux q0 √(1 - r²/a²) raises the centre by π q0 a / (4K)
        // (Carslaw & Jaeger 1959; 3π q_mean a / (8K) with q_mean = 2 q0 / 3): the maximum
        // tends to it as Pe -> 0, linear in V (tolerance 1 % at Pe 0.01), from below.
        let scene = ball_on_flat("body1");
        let peclets = [0.01, 0.1];
        let sweep = speed_sweep(&scene, &peclets, &mut |_, _| {}).expect("swept");
        let ratios: Vec<f64> = sweep
            .steps
            .iter()
            .map(|step| step.whole_max_k / (PI / 4.0 * scale_k(&scene, step.peclet)))
            .collect();
        eprintln!("measured: max / stationary centre at Pe {peclets:?}: {ratios:.4?}");
        assert!((ratios[0] - 1.0).abs() < 0.01, "{ratios:?}");
        assert!(ratios[1] < ratios[0], "{ratios:?}");
        // The slow asymptote is that stationary maximum per unit Pe.
        let slow = sweep.slow_per_peclet.expect("a point contact") * 0.01;
        let stationary = PI / 4.0 * scale_k(&scene, 0.01);
        eprintln!(
            "measured: slow asymptote vs π q0 a / (4K): {:.2e}",
            slow / stationary - 1.0
        );
        assert!(
            (slow / stationary - 1.0).abs() < 5e-3,
            "{slow} vs {stationary}"
        );
    }

    #[test]
    fn the_hottest_point_moves_behind_the_centre_as_the_speed_rises() {
        // At rest the hottest point is the centre; moving, the wake carries it back towards
        // the trailing edge x = -a, further the faster (monotone over three decades), on the
        // axis y = 0.
        let scene = ball_on_flat("body1");
        let peclets: Vec<f64> = (0..=6).map(|k| 0.1 * 10f64.powf(0.5 * k as f64)).collect();
        let sweep = speed_sweep(&scene, &peclets, &mut |_, _| {}).expect("swept");
        let a = sweep.half_width_m;
        let x: Vec<f64> = sweep
            .steps
            .iter()
            .map(|s| s.body1.max_at_m[0] / a)
            .collect();
        eprintln!("measured: max x/a at Pe {peclets:.3?}: {x:.3?}");
        assert!(x[0].abs() <= 0.1, "{x:?}");
        assert!(x.windows(2).all(|w| w[1] <= w[0]), "{x:?}");
        assert!(x[6] < -0.5 && x[6] > -1.0, "{x:?}");
        for step in &sweep.steps {
            assert!(step.body1.max_at_m[1].abs() < 1e-12 * a);
        }
        // The section's surface row is the map's row through the centre.
        assert!(sweep.y_m.abs() < 1e-12 * a);
        let last = &sweep.steps[6];
        assert_eq!(
            last.section_k.row(0),
            last.body1.temperature_k.row(sweep.row)
        );
        // Below the surface it cools.
        let deepest = last
            .section_k
            .row(SECTION_STEPS)
            .iter()
            .copied()
            .fold(0.0, f64::max);
        assert!(deepest < 0.5 * last.body1.max_temperature_rise_k);
    }

    #[test]
    fn on_the_studys_grid_the_maps_are_the_studys() {
        // A second path: the thermal study of the scene at each step (`at_step` scales the
        // speeds) on its own grid against the sweep on that window, with Blok's partition
        // recomputed per step; the same arithmetic, so equal to rounding.
        let mut scene = ball_on_flat("blok");
        let own = scene
            .thermal
            .expect("[thermal]")
            .body1_peclet(scene.contact.half_width_m());
        scene.sweep = Some(crate::scene::Sweep {
            parameter: crate::scene::SweepParameter::Peclet,
            values: vec![own, 0.3, 20.0],
            material_points: Vec::new(),
            generated: false,
        });
        for (k, &peclet) in [own, 0.3, 20.0].iter().enumerate() {
            let stepped = crate::study::at_step(&scene, k).expect("a step");
            let reference = study(&stepped, None, &mut |_| {}).expect("studied");
            let sweep = sweep_on(&scene, &[peclet], &STUDY_WINDOW, &mut |_, _| {}).expect("swept");
            let step = &sweep.steps[0];
            assert_eq!(sweep.shape, reference.shape);
            assert!((step.body1.peclet / reference.body1.peclet - 1.0).abs() < 1e-12);
            assert!((step.body1.share - reference.body1.share).abs() < 1e-12);
            let largest = reference.body1.max_temperature_rise_k;
            for (got, want) in step
                .body1
                .temperature_k
                .iter()
                .zip(&reference.body1.temperature_k)
            {
                assert!((got - want).abs() < 1e-12 * largest, "{got} vs {want}");
            }
            assert!(
                (step.body1.mean_temperature_rise_k / reference.body1.mean_temperature_rise_k
                    - 1.0)
                    .abs()
                    < 1e-12
            );
            assert_eq!(step.body1.max_at_m, reference.body1.max_at_m);
        }
    }

    #[test]
    fn the_grid_resolves_the_limit_and_no_more() {
        // Body 1 the fastest: 2 x 320 cells / 6a = 106.7.
        let scene = ball_on_flat("blok");
        let spec = scene.thermal.expect("[thermal]");
        let limit = peclet_limit(&spec);
        assert!((limit - 320.0 / 3.0).abs() < 1e-12, "{limit}");
        assert!(speed_sweep(&scene, &[0.999 * limit], &mut |_, _| {}).is_ok());
        let error = speed_sweep(&scene, &[1.01 * limit], &mut |_, _| {}).expect_err("too fast");
        assert!(
            error
                .to_string()
                .starts_with("sweep: the cell Péclet number"),
            "{error}"
        );
    }
}
