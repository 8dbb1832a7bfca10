//! `[wear]` and `[[series]]` of a rough scene: Archard wear simulated over a sliding distance,
//! or measured topographies of the worn surface at increasing distances.

use std::sync::Arc;

use super::surface::LevelMode;
#[allow(clippy::wildcard_imports)]
use super::*;
use crate::contact::rough::Control;
use crate::scene::{Levelling, SeriesDatum};
use crate::surface::HeightMap;

/// Archard's dimensional wear coefficient, m²/N (= m³/(N m)).
const WEAR_COEFFICIENT_BOUNDS: Bounds = Bounds {
    lo: 1e-22,
    hi: 1e-9,
    why: "from far below the mildest sliding wear measured to far above severe abrasion (measured values span roughly 1e-9 to 1e-2 mm^3/(N m))",
};

/// A sliding distance, m.
const DISTANCE_BOUNDS: Bounds = Bounds {
    lo: 1e-9,
    hi: 1e9,
    why: "from a nanometre of fretting to a million kilometres",
};

/// The most steps of a simulated wear evolution (each a contact solve).
pub const MAX_WEAR_STEPS: usize = 1000;
/// The default number of steps.
pub const DEFAULT_WEAR_STEPS: usize = 40;
/// The most topographies of a measured series.
pub const MAX_SERIES: usize = 200;

impl Validator<'_> {
    /// The evolution of a rough scene (`scene`, validated but for this) with sliding distance:
    /// `[wear]`, `[[series]]`, or neither.
    pub(super) fn wear(
        &self,
        raw: &RawScene,
        scene: &Scene,
    ) -> Result<Option<WearSpec>, SceneError> {
        let key = match (&raw.wear, raw.series.is_empty()) {
            (None, true) => return Ok(None),
            (Some(_), false) => {
                return Err(self.error(
                    "wear",
                    "give either [wear] (Archard wear simulated on the surface) or [[series]] (measured topographies), not both",
                    Some("remove one of them"),
                ))
            }
            (Some(_), true) => "wear",
            (None, false) => "series",
        };
        let (Some(rough), Some(surface)) = (&scene.contact.rough, &scene.surface) else {
            return Err(self.error(key, "wear needs a rough contact", None));
        };
        if scene.contact.kind != ContactKind::Rough {
            return Err(self.error(
                key,
                "a surface scene characterises its surface; wear is solved on a rough contact",
                Some("use contact.kind = \"rough\" with a load and the bodies"),
            ));
        }
        let load_n = match rough.control {
            Some(Control::Load { newtons }) => newtons,
            Some(Control::MeanPressure { pa }) => {
                let [width, length] = surface.heights.size_m();
                pa * width * length
            }
            _ => {
                return Err(self.error(
                    "contact.approach",
                    "a worn surface is pressed by a load: under a fixed approach it would wear out of contact",
                    Some("give contact.load (or contact.mean_pressure) instead"),
                ))
            }
        };
        if raw
            .counter_surface
            .as_ref()
            .is_some_and(|c| c.generate.is_none())
        {
            return Err(self.error(
                "counter_surface.file",
                "in a wear scene the counter-surface slides over the worn body, shifted by the sliding distance at each step, so it must be periodic: a measured map's opposite edges do not meet",
                Some("generate it ([counter_surface.generate], periodic by construction), or leave body 2 smooth"),
            ));
        }
        if surface.counter.is_some() && scene.thermal.is_some_and(|t| t.coupled) {
            return Err(self.error(
                "thermal.coupled",
                "a coupled worn contact under a rough sliding counter-surface is not modelled: the body wears under the counter's mean plane while its contact is through the asperities, and their bulges would differ",
                Some("set coupled = false (the flash temperature of every step is still reported), or leave body 2 smooth"),
            ));
        }
        match &raw.wear {
            Some(table) => self.archard(table, &surface.body1, load_n).map(Some),
            None => self.series(raw, surface).map(Some),
        }
    }

    /// `[wear]`: coefficient, distance and steps, refused where the wear `k W s` is more
    /// than the map holds above its lowest point.
    fn archard(
        &self,
        table: &RawWear,
        heights: &HeightMap,
        load_n: f64,
    ) -> Result<WearSpec, SceneError> {
        let Some(text) = &table.coefficient else {
            return Err(self.error(
                "wear.coefficient",
                "Archard wear needs its dimensional wear coefficient k (volume per load and sliding distance)",
                Some("e.g. coefficient = \"2e-6 mm^3/(N m)\" (or in m^2/N)"),
            ));
        };
        let coefficient_m2_per_n = self.bounded(
            "wear.coefficient",
            text,
            Dimension::WearCoefficient,
            WEAR_COEFFICIENT_BOUNDS,
        )?;
        let Some(text) = &table.distance else {
            return Err(self.error(
                "wear.distance",
                "Archard wear needs the total sliding distance",
                Some("e.g. distance = \"20 m\""),
            ));
        };
        let distance_m = self.bounded("wear.distance", text, Dimension::Length, DISTANCE_BOUNDS)?;
        let steps = match table.steps {
            None => DEFAULT_WEAR_STEPS,
            Some(n) if (1..=MAX_WEAR_STEPS as i64).contains(&n) => n as usize,
            Some(n) => {
                return Err(self.error(
                    "wear.steps",
                    format!("must lie in 1..={MAX_WEAR_STEPS}, got {n}"),
                    Some(&format!(
                        "each step is a contact solve; the default is {DEFAULT_WEAR_STEPS} (backward Euler is stable at any step)"
                    )),
                ))
            }
        };
        let wear_m3 = coefficient_m2_per_n * load_n * distance_m;
        let capacity_m3 = crate::wear::capacity_m3(heights.heights_m(), heights.spacing_m());
        if wear_m3 > capacity_m3 {
            return Err(self.error(
                "wear.distance",
                format!(
                    "the wear k W s = {} m³ is more than the map holds above its lowest point ({} m³): the surface would be worn through",
                    crate::io::text::approx(wear_m3),
                    crate::io::text::approx(capacity_m3)
                ),
                Some("lower wear.distance or wear.coefficient, or give a surface with a larger height range (a ball's form, a deeper map)"),
            ));
        }
        Ok(WearSpec::Archard {
            coefficient_m2_per_n,
            distance_m,
            steps,
        })
    }

    /// `[[series]]`: every topography read with `[surface]`'s options, on the first one's grid,
    /// at strictly increasing distances.
    fn series(&self, raw: &RawScene, surface: &SurfaceSpec) -> Result<WearSpec, SceneError> {
        let entries = &raw.series;
        if entries.len() < 2 {
            return Err(self.error(
                "series",
                "a series needs at least two topographies (one is a plain rough contact)",
                Some("add [[series]] tables, or give the one file as [surface] file"),
            ));
        }
        if entries.len() > MAX_SERIES {
            return Err(self.error(
                "series",
                format!("{} topographies is more than {MAX_SERIES}", entries.len()),
                Some("keep every second one, or split the series"),
            ));
        }
        let default_table = RawSurface::default();
        let table = raw.surface.as_ref().unwrap_or(&default_table);
        let first = &surface.body1;
        // Every map levelled by the series' one datum (issue 50): the first map's fitted form,
        // or each map's fitted on the region that does not wear, or (on request) each map's
        // own.
        let periodic = raw.contact.periodic.unwrap_or(false);
        let level = self.level(
            table,
            self.form_removal(table)?,
            ContactKind::Rough,
            periodic,
        )?;
        let mut result = Vec::with_capacity(entries.len());
        let mut previous: Option<(f64, String)> = None;
        for (i, entry) in entries.iter().enumerate() {
            let key = format!("series[{i}]");
            let Some(file) = &entry.file else {
                return Err(self.error(
                    &format!("{key}.file"),
                    "each [[series]] entry names its height file",
                    Some("e.g. file = \"surfaces/scar_5m.asc\""),
                ));
            };
            let Some(text) = &entry.distance else {
                return Err(self.error(
                    &format!("{key}.distance"),
                    "each [[series]] entry gives the sliding distance it was measured at",
                    Some("e.g. distance = \"5 m\" (\"0 m\" for the unworn surface)"),
                ));
            };
            let distance_m = units::parse(text, Dimension::Length)
                .map_err(|m| self.error(&format!("{key}.distance"), m, None))?;
            if !(0.0..=DISTANCE_BOUNDS.hi).contains(&distance_m) {
                return Err(self.error(
                    &format!("{key}.distance"),
                    format!(
                        "must lie between 0 m and {} m, got `{}`",
                        crate::io::text::compact(DISTANCE_BOUNDS.hi),
                        crate::io::text::cut(text, 40)
                    ),
                    Some(DISTANCE_BOUNDS.why),
                ));
            }
            if let Some((before, before_text)) = &previous {
                if distance_m <= *before {
                    return Err(self.error(
                        &format!("{key}.distance"),
                        format!(
                            "the distances must increase from entry to entry: `{}` follows `{}`",
                            crate::io::text::cut(text, 40),
                            crate::io::text::cut(before_text, 40)
                        ),
                        Some("list the topographies in the order they were measured"),
                    ));
                }
            }
            previous = Some((distance_m, text.clone()));
            let body1 = if i == 0 {
                Arc::clone(first)
            } else {
                let map = self.read_map("surface", &format!("{key}.file"), file, table)?;
                let spacing_differs = map
                    .spacing_m()
                    .iter()
                    .zip(first.spacing_m())
                    .any(|(a, b)| (a - b).abs() > 1e-9 * b);
                if map.shape() != first.shape() || spacing_differs {
                    let [ny, nx] = map.shape();
                    let [fy, fx] = first.shape();
                    let [dx, dy] = map.spacing_m();
                    let [fdx, fdy] = first.spacing_m();
                    return Err(self.error(
                        &format!("{key}.file"),
                        format!(
                            "{file}: its {nx} x {ny} samples spaced {} x {} m differ from the first topography's ({}: {fx} x {fy} spaced {} x {} m)",
                            crate::io::text::approx(dx),
                            crate::io::text::approx(dy),
                            surface.source,
                            crate::io::text::approx(fdx),
                            crate::io::text::approx(fdy),
                        ),
                        Some("a series is one surface measured again: give every topography on the same grid, with one spacing and height unit (crop or resample them alike)"),
                    ));
                }
                let key = format!("{key}.file");
                let heights = match (level, &surface.levelling, &surface.series_datum) {
                    (None | Some(LevelMode::Keep), ..) | (_, None, _) => map,
                    // The first map's datum, removed from this one.
                    (_, Some(Levelling::Mean { mean_m, .. }), Some(SeriesDatum::First)) => {
                        HeightMap::new(map.heights_m() - *mean_m, map.spacing_m())
                            .map_err(|e| self.error(&key, e.to_string(), None))?
                    }
                    (_, Some(Levelling::Removed(datum)), Some(SeriesDatum::First)) => {
                        HeightMap::new(datum.remove_from(map.heights_m()), map.spacing_m())
                            .map_err(|e| self.error(&key, e.to_string(), None))?
                    }
                    (Some(mode), _, Some(SeriesDatum::Region { x_m, y_m })) => {
                        let region = self.sample_region(&map, *x_m, *y_m)?;
                        self.levelled(&key, map, mode, Some(&region))?.0
                    }
                    (Some(mode), ..) => self.levelled(&key, map, mode, None)?.0,
                };
                Arc::new(heights)
            };
            result.push(SeriesEntry {
                distance_m,
                source: file.clone(),
                heights: body1,
            });
        }
        Ok(WearSpec::Series(result))
    }
}
