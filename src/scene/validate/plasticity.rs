//! `[plasticity]`: body 1 elastic-plastic (issue 51). The yield strength given once (here, or
//! `contact.yield_strength` / `contact.hardness`), the hardening, the load steps and the
//! volume grid, each bounded with the key and the fix named.

#[allow(clippy::wildcard_imports)]
use super::*;

/// The most load (or unload) increments: each is a few elastic solves over the volume.
pub const MAX_PLASTIC_STEPS: usize = 200;
/// The default load increments (the peak pressure at 2.5 Y moves by less than 1 % from 8 to
/// 16 increments, docs/plasticity.md).
pub const DEFAULT_PLASTIC_STEPS: usize = 8;
/// Cells along x and y: the contact radius needs about 8 cells across its radius for the
/// first yield within 0.5 %, and the grid at most 512 (the operator's memory).
pub const GRID_CELLS_RANGE: (usize, usize) = (16, 512);
/// Cell layers in depth.
pub const DEPTH_CELLS_RANGE: (usize, usize) = (4, 256);
/// The fewest cells across the Hertz contact radius.
pub const MIN_CELLS_PER_RADIUS: f64 = 6.0;

impl Validator<'_> {
    /// What a rough scene's `[plasticity]` may not have: the lateral grid is the map's, the
    /// contact is pressed by a load (or a mean pressure), and the map is one surface.
    fn rough_plasticity(
        &self,
        table: &RawPlasticity,
        raw: &RawScene,
        scene: &Scene,
    ) -> Result<(), SceneError> {
        for (key, given) in [
            ("plasticity.grid_cells", table.grid_cells.is_some()),
            ("plasticity.extent_over_a", table.extent_over_a.is_some()),
        ] {
            if given {
                return Err(self.error(
                    key,
                    "the lateral grid of a rough contact's volume is the map's own cells",
                    Some("remove it; depth_cells and depth_over_a (in radii of the largest contact spot) set the depth"),
                ));
            }
        }
        if !raw.series.is_empty() {
            return Err(self.error(
                "series",
                "a series of measured maps is not computed with [plasticity]",
                Some("remove one of the two: `stressfield plastic` presses one map"),
            ));
        }
        if raw.contact.approach.is_some() {
            return Err(self.error(
                "contact.approach",
                "[plasticity] loads the contact in load steps: an approach is not a load",
                Some("give contact.load (or contact.mean_pressure)"),
            ));
        }
        if let Some(surface) = &scene.surface {
            let [ny, nx] = surface.heights.shape();
            let largest = GRID_CELLS_RANGE.1;
            if nx > largest || ny > largest {
                return Err(self.error(
                    "surface",
                    format!(
                        "the map's {nx} x {ny} samples are more than the {largest} x {largest} cells a plastic volume takes"
                    ),
                    Some("crop or resample the map (e.g. [surface.generate] samples = 128)"),
                ));
            }
        }
        Ok(())
    }

    /// `[plasticity]` of a scene validated but for this.
    pub(super) fn plasticity(
        &self,
        table: &RawPlasticity,
        raw: &RawScene,
        scene: &Scene,
    ) -> Result<PlasticitySpec, SceneError> {
        for (key, given, what) in [
            ("thermal", raw.thermal.is_some(), "frictional heating"),
            ("wear", raw.wear.is_some(), "wear"),
            ("sweep", raw.sweep.is_some(), "a sweep"),
            ("volume", raw.volume.is_some(), "a volume recording"),
            (
                "tractions",
                raw.tractions.is_some(),
                "tractions from a file",
            ),
        ] {
            if given {
                return Err(self.error(
                    key,
                    format!("{what} is not computed with [plasticity]"),
                    Some("remove one of the two tables: `stressfield plastic` solves the elastic-plastic contact alone"),
                ));
            }
        }
        if scene.contact.coating.is_some() {
            return Err(self.error(
                "contact.body1.coating",
                "an elastic-plastic body 1 with a coating is not computed",
                Some("remove the coating or [plasticity]"),
            ));
        }
        let rough = scene.contact.kind == ContactKind::Rough;
        if !matches!(
            scene.contact.kind,
            ContactKind::Point | ContactKind::Elliptical | ContactKind::Rough | ContactKind::Line
        ) {
            return Err(self.error(
                "contact.kind",
                format!(
                    "[plasticity] is computed under point, elliptical, line and rough contacts so far, not `{}`",
                    raw.contact.kind.trim()
                ),
                Some("use contact.kind = \"point\" (a ball on a flat), \"elliptical\", \"line\" (a roller, plane strain) or \"rough\""),
            ));
        }
        if rough {
            self.rough_plasticity(table, raw, scene)?;
        }
        if scene.contact.tangential.is_some() {
            return Err(self.error(
                "contact.tangential",
                "partial slip is not computed with [plasticity]",
                Some("remove it; contact.friction slides the contact with q = mu p"),
            ));
        }
        // Body 1's elastic constants, and whether body 2 is rigid.
        let (body1, counter_rigid) = match (scene.contact.dimensional, rough) {
            (Some(dimensional), false) => (
                dimensional.body1.material,
                dimensional.body2.material.modulus_pa.is_infinite(),
            ),
            (_, true) => {
                let empty = RawBody::default();
                let raw1 = raw.contact.body1.as_ref().unwrap_or(&empty);
                let raw2 = raw.contact.body2.as_ref().unwrap_or(&empty);
                let body1 = self.rough_body("contact.body1", raw1)?;
                if body1.modulus_pa.is_infinite() {
                    return Err(self.error(
                        "contact.body1.material",
                        "the elastic-plastic body 1 cannot be rigid",
                        Some("give body 1 its material (e.g. material = \"steel\"); body 2 may be rigid"),
                    ));
                }
                let body2 = self.rough_body("contact.body2", raw2)?;
                (body1, body2.modulus_pa.is_infinite())
            }
            (None, false) => {
                return Err(self.error(
                    "contact.load",
                    "[plasticity] needs the bodies and the load, not a normalised contact",
                    Some("give [contact.body1], [contact.body2] and contact.load"),
                ))
            }
        };
        let yield_strength_pa = match (&table.yield_strength, scene.contact.yield_strength) {
            (Some(_), Some(_)) => {
                let key = if raw.contact.hardness.is_some() {
                    "contact.hardness"
                } else {
                    "contact.yield_strength"
                };
                return Err(self.error(
                    "plasticity.yield_strength",
                    format!("the yield strength is given twice: here and as {key}"),
                    Some(&format!("give it once: remove {key} or plasticity.yield_strength")),
                ));
            }
            (Some(text), None) => {
                let value = units::parse(text, Dimension::Pressure)
                    .map_err(|m| self.error("plasticity.yield_strength", m, None))?;
                if value.is_nan() || value <= 0.0 {
                    return Err(self.error(
                        "plasticity.yield_strength",
                        format!("the yield strength must be positive, got `{}`", text.trim()),
                        Some("e.g. yield_strength = \"1 GPa\""),
                    ));
                }
                self.within(
                    "plasticity.yield_strength",
                    value,
                    text,
                    Dimension::Pressure,
                    STRESS_BOUNDS,
                )?
            }
            (None, Some(y)) => y.pa,
            (None, None) => {
                return Err(self.error(
                    "plasticity.yield_strength",
                    "missing yield strength",
                    Some("add yield_strength = \"1 GPa\" (or contact.yield_strength, or contact.hardness)"),
                ))
            }
        };
        let hardening_modulus_pa = match &table.hardening_modulus {
            None => 0.0,
            Some(text) => {
                let value = units::parse(text, Dimension::Pressure)
                    .map_err(|m| self.error("plasticity.hardening_modulus", m, None))?;
                if !(0.0..=MODULUS_BOUNDS.hi).contains(&value) {
                    return Err(self.error(
                        "plasticity.hardening_modulus",
                        format!(
                            "the plastic modulus must be zero (perfectly plastic) or positive, got `{}`",
                            text.trim()
                        ),
                        Some("e.g. hardening_modulus = \"10 GPa\", or 0 for a perfectly plastic body"),
                    ));
                }
                value
            }
        };
        let count = |key: &str, value: Option<i64>, default: usize, range: (usize, usize)| {
            let Some(value) = value else {
                return Ok(default);
            };
            if value < range.0 as i64 || value > range.1 as i64 {
                return Err(self.error(
                    key,
                    format!("must lie between {} and {}, got {value}", range.0, range.1),
                    None,
                ));
            }
            Ok(value as usize)
        };
        let steps = count(
            "plasticity.steps",
            table.steps,
            DEFAULT_PLASTIC_STEPS,
            (1, MAX_PLASTIC_STEPS),
        )?;
        let unload = table.unload.unwrap_or(true);
        if table.unload_steps.is_some() && !unload {
            return Err(self.error(
                "plasticity.unload_steps",
                "given with unload = false",
                Some("remove it, or set unload = true"),
            ));
        }
        let unload_steps = count(
            "plasticity.unload_steps",
            table.unload_steps,
            DEFAULT_PLASTIC_STEPS / 2,
            (1, MAX_PLASTIC_STEPS),
        )?;
        let grid_cells = count(
            "plasticity.grid_cells",
            table.grid_cells,
            64,
            GRID_CELLS_RANGE,
        )?;
        let depth_cells = count(
            "plasticity.depth_cells",
            table.depth_cells,
            32,
            DEPTH_CELLS_RANGE,
        )?;
        if grid_cells % 2 != 0 {
            return Err(self.error(
                "plasticity.grid_cells",
                format!("must be even (a cell centred on the axis), got {grid_cells}"),
                Some(&format!("use {}", grid_cells + 1)),
            ));
        }
        let ratio = |key: &str, value: Option<f64>, default: f64, lo: f64, hi: f64| {
            let value = value.unwrap_or(default);
            if !(value >= lo && value <= hi) {
                return Err(self.error(
                    key,
                    format!("must lie between {lo} and {hi}, got {value}"),
                    None,
                ));
            }
            Ok(value)
        };
        let extent_over_a = ratio(
            "plasticity.extent_over_a",
            table.extent_over_a,
            2.0,
            1.2,
            20.0,
        )?;
        let depth_over_a = ratio(
            "plasticity.depth_over_a",
            table.depth_over_a,
            2.0,
            0.5,
            20.0,
        )?;
        let tolerance = ratio("plasticity.tolerance", table.tolerance, 1e-6, 1e-12, 1e-2)?;
        let cells_per_radius = grid_cells as f64 / (2.0 * extent_over_a);
        if !rough && cells_per_radius < MIN_CELLS_PER_RADIUS {
            let needed = (MIN_CELLS_PER_RADIUS * 2.0 * extent_over_a / 2.0).ceil() as usize * 2;
            return Err(self.error(
                "plasticity.grid_cells",
                format!(
                    "{grid_cells} cells over {extent_over_a} a each side put {cells_per_radius:.1} cells across the contact radius: too coarse for the plastic zone under it"
                ),
                Some(&format!(
                    "use grid_cells >= {needed}, or a smaller extent_over_a"
                )),
            ));
        }
        if scene.contact.poisson >= 0.5 {
            return Err(self.error(
                "contact.body1.poisson",
                "an incompressible body 1 (Poisson's ratio 0.5) is not computed with [plasticity]",
                Some("use a Poisson's ratio below 0.5, e.g. 0.3 for steel"),
            ));
        }
        Ok(PlasticitySpec {
            yield_strength_pa,
            hardening_modulus_pa,
            unload,
            steps,
            unload_steps,
            grid_cells,
            depth_cells,
            extent_over_a,
            depth_over_a,
            tolerance,
            body1,
            counter_rigid,
        })
    }
}
