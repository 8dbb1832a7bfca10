//! Rough and surface scenes: the `[surface]` and `[counter_surface]` tables (a height map read
//! from a file or generated) and the options of its characterisation.

use std::sync::Arc;

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::scene::{Levelling, SeriesDatum};
use crate::surface::generate::{self, Amplitude, Form, Generator, Spectrum};
use crate::surface::read::{self, Fill, ReadOptions};
use crate::surface::stats::{Datum, FormRemoval, SampleRegion};
use crate::surface::HeightMap;

/// The range of a generated surface's rms slope (a slope of 10 rises 10 m a metre).
const MIN_RMS_SLOPE: f64 = 1e-6;
const MAX_RMS_SLOPE: f64 = 10.0;

/// What is removed from a measured map before its contact is solved (`[surface] level`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum LevelMode {
    /// `"none"`: the heights as measured.
    Keep,
    /// `"mean"`: the mean height only (the default of a periodic contact).
    Mean,
    /// `"plane"` or `"quadratic"`: the least-squares form.
    Form(FormRemoval),
}

impl Validator<'_> {
    /// `[surface]` (and `[counter_surface]`) of a rough or surface scene.
    pub(super) fn surface_spec(
        &self,
        raw: &RawScene,
        kind: ContactKind,
        periodic: bool,
    ) -> Result<SurfaceSpec, SceneError> {
        let default_table = RawSurface::default();
        let table = match (&raw.surface, raw.series.is_empty()) {
            (Some(table), _) => table,
            // A series' files may say their own spacing and units (Gwyddion's header, x3p).
            (None, false) => &default_table,
            (None, true) => return Err(self.error(
                "surface",
                "a rough or surface scene needs its [surface] table",
                Some("add [surface] with file = \"surfaces/worn.asc\" (spacing, height_unit), or [surface.generate]"),
            )),
        };
        let form = self.form_removal(table)?;
        let level = self.level(table, form, kind, periodic)?;
        let series_datum = match (raw.series.is_empty(), level) {
            (false, Some(mode)) if mode != LevelMode::Keep => Some(self.series_datum(table)?),
            _ => {
                for (key, given) in [
                    ("surface.datum", table.datum.is_some()),
                    ("surface.datum_region", table.datum_region.is_some()),
                ] {
                    if given {
                        return Err(self.error(
                            key,
                            "the datum of a levelled series: this scene is not one",
                            Some(if raw.series.is_empty() {
                                "remove it (it applies to the maps of a [[series]])"
                            } else {
                                "remove it: level = \"none\" keeps every map as measured"
                            }),
                        ));
                    }
                }
                None
            }
        };
        let (body1, source, shape) = match raw.series.first() {
            None => self.height_map("surface", table)?,
            Some(first) => {
                if kind != ContactKind::Rough {
                    return Err(self.error(
                        "series",
                        "a series of topographies is solved as a rough contact",
                        Some("use contact.kind = \"rough\""),
                    ));
                }
                for (name, given) in [
                    ("surface.file", table.file.is_some()),
                    ("surface.generate", table.generate.is_some()),
                ] {
                    if given {
                        return Err(self.error(
                            name,
                            "a series names its topographies in [[series]]; [surface] gives only their spacing, units and fill",
                            Some("remove it, and give each topography as a [[series]] table with file and distance"),
                        ));
                    }
                }
                let Some(file) = &first.file else {
                    return Err(self.error(
                        "series[0].file",
                        "each [[series]] entry names its height file",
                        Some("e.g. file = \"surfaces/scar_0m.asc\""),
                    ));
                };
                let map = self.read_map("surface", "series[0].file", file, table)?;
                (map, file.clone(), None)
            }
        };
        let generated = shape.is_some();
        let shape = shape.unwrap_or(Form::None);
        // A measured map of a rough scene is levelled before its contact is solved.
        let (body1, levelling) = match level {
            Some(mode) if !generated => {
                let region = match &series_datum {
                    Some(SeriesDatum::Region { x_m, y_m }) => {
                        Some(self.sample_region(&body1, *x_m, *y_m)?)
                    }
                    _ => None,
                };
                let (map, levelling) =
                    self.levelled("surface.level", body1, mode, region.as_ref())?;
                (map, Some(levelling))
            }
            _ => (body1, None),
        };
        let counter = match (&raw.counter_surface, kind) {
            (None, _) => None,
            (Some(_), ContactKind::Surface) => {
                return Err(self.error(
                    "counter_surface",
                    "a surface scene characterises one surface",
                    Some("remove it, or use kind = \"rough\" to press two rough surfaces together"),
                ))
            }
            (Some(table), _) => {
                let (map, _, counter_shape) = self.height_map("counter_surface", table)?;
                let map = match counter_shape {
                    // A measured counter-surface is levelled as body 1's map would be.
                    None => {
                        let form = self.form_removal(table)?;
                        match self.level(table, form, kind, periodic)? {
                            Some(mode) => {
                                self.levelled("counter_surface.level", map, mode, None)?.0
                            }
                            None => map,
                        }
                    }
                    Some(_) => {
                        if table.level.is_some() {
                            return Err(self.error(
                                "counter_surface.level",
                                "a generated surface has no tilt to level",
                                Some("remove level (it applies to measured maps)"),
                            ));
                        }
                        map
                    }
                };
                if map.shape() != body1.shape()
                    || map
                        .spacing_m()
                        .iter()
                        .zip(body1.spacing_m())
                        .any(|(a, b)| (a - b).abs() > 1e-9 * b)
                {
                    return Err(self.error(
                        "counter_surface",
                        format!(
                            "its {:?} samples spaced {:?} m differ from [surface]'s {:?} spaced {:?} m",
                            map.shape(),
                            map.spacing_m(),
                            body1.shape(),
                            body1.spacing_m()
                        ),
                        Some("give both surfaces on the same grid"),
                    ));
                }
                Some(Arc::new(map))
            }
        };
        let heights = match &counter {
            Some(second) => Arc::new(
                HeightMap::new(body1.heights_m() + second.heights_m(), body1.spacing_m())
                    .map_err(|e| self.error("counter_surface", e.to_string(), None))?,
            ),
            None => Arc::new(body1.clone()),
        };
        if generated && table.level.is_some() {
            return Err(self.error(
                "surface.level",
                "a generated surface has no tilt to level",
                Some("remove level (it applies to measured maps)"),
            ));
        }
        // A generated ball or cylinder: its form is not roughness.
        let form = match table.form {
            None if shape != Form::None => FormRemoval::Quadratic,
            _ => form,
        };
        let band_m = match &table.band {
            None => None,
            Some(values) => match values.as_slice() {
                [a, b] => {
                    let a =
                        self.bounded("surface.band", a, Dimension::Length, WAVELENGTH_BOUNDS)?;
                    let b =
                        self.bounded("surface.band", b, Dimension::Length, WAVELENGTH_BOUNDS)?;
                    if a >= b {
                        return Err(self.error(
                            "surface.band",
                            "give [shortest, longest] wavelength",
                            Some("e.g. band = [\"4 um\", \"100 um\"]"),
                        ));
                    }
                    Some((a, b))
                }
                _ => {
                    return Err(self.error(
                        "surface.band",
                        "needs two wavelengths",
                        Some("e.g. band = [\"4 um\", \"100 um\"]"),
                    ))
                }
            },
        };
        Ok(SurfaceSpec {
            heights,
            body1: Arc::new(body1),
            counter,
            source,
            generated,
            shape,
            form,
            band_m,
            levelling,
            series_datum,
        })
    }

    /// `form` of a `[surface]`-like table: what the statistics remove besides the mean plane.
    pub(super) fn form_removal(&self, table: &RawSurface) -> Result<FormRemoval, SceneError> {
        match table.form.as_deref() {
            None | Some("plane") => Ok(FormRemoval::Plane),
            Some("quadratic") => Ok(FormRemoval::Quadratic),
            Some(other) => Err(self.error(
                "surface.form",
                format!("unknown form `{other}`"),
                Some("use \"plane\" (the mean plane, always removed) or \"quadratic\" (also a second-order form, e.g. a ball's)"),
            )),
        }
    }

    /// `level` of a `[surface]`-like table: `None` where no contact is solved (a surface
    /// scene, whose statistics level their own copy), else what is removed from a measured map
    /// before the solve. By default the form `form` (the least-squares plane) of an isolated
    /// contact's map, and only the mean height of a periodic one: a plane is not periodic
    /// ([`Levelling`]).
    pub(super) fn level(
        &self,
        table: &RawSurface,
        form: FormRemoval,
        kind: ContactKind,
        periodic: bool,
    ) -> Result<Option<LevelMode>, SceneError> {
        if kind != ContactKind::Rough {
            if table.level.is_some() {
                return Err(self.error(
                    "surface.level",
                    "a surface scene's statistics always remove the mean plane; level is for the contact of a rough scene",
                    Some("remove level; form = \"quadratic\" also removes a second-order form"),
                ));
            }
            return Ok(None);
        }
        match table.level.as_deref() {
            None if periodic => Ok(Some(LevelMode::Mean)),
            None => Ok(Some(LevelMode::Form(form))),
            Some("plane") => Ok(Some(LevelMode::Form(FormRemoval::Plane))),
            Some("quadratic") => Ok(Some(LevelMode::Form(FormRemoval::Quadratic))),
            Some("mean") => Ok(Some(LevelMode::Mean)),
            Some("none") => Ok(Some(LevelMode::Keep)),
            Some(other) => Err(self.error(
                "surface.level",
                format!("unknown level `{other}`"),
                Some("use \"plane\" (the least-squares mean plane, the default of an isolated contact), \"mean\" (the mean height only, the default of a periodic one), \"quadratic\" (also a second-order form) or \"none\" (the heights as measured)"),
            )),
        }
    }

    /// `datum` and `datum_region` of a levelled series' `[surface]`.
    fn series_datum(&self, table: &RawSurface) -> Result<SeriesDatum, SceneError> {
        let region = match &table.datum_region {
            None => None,
            Some(values) => {
                let hint = Some("give [\"x from\", \"x to\", \"y from\", \"y to\"] from the map's first sample, over a part that does not wear, e.g. datum_region = [\"0 um\", \"150 um\", \"0 um\", \"670 um\"]");
                let [x0, x1, y0, y1] = values.as_slice() else {
                    return Err(self.error(
                        "surface.datum_region",
                        format!("needs four lengths, got {}", values.len()),
                        hint,
                    ));
                };
                let mut bounds = [0.0; 4];
                for (bound, text) in bounds.iter_mut().zip([x0, x1, y0, y1]) {
                    *bound = units::parse(text, Dimension::Length)
                        .map_err(|m| self.error("surface.datum_region", m, hint))?;
                    if !(bound.is_finite() && *bound >= 0.0) {
                        return Err(self.error(
                            "surface.datum_region",
                            format!(
                                "`{}` must be a length of at least 0 from the map's first sample",
                                crate::io::text::cut(text, 40)
                            ),
                            hint,
                        ));
                    }
                }
                if bounds[0] >= bounds[1] || bounds[2] >= bounds[3] {
                    return Err(self.error(
                        "surface.datum_region",
                        "each range runs from the smaller length to the larger",
                        hint,
                    ));
                }
                Some(SeriesDatum::Region {
                    x_m: [bounds[0], bounds[1]],
                    y_m: [bounds[2], bounds[3]],
                })
            }
        };
        match (table.datum.as_deref(), region) {
            (None, Some(region)) => Ok(region),
            (Some(_), Some(_)) => Err(self.error(
                "surface.datum",
                "give either datum or datum_region, not both",
                Some("datum_region alone fits each map's form on that region"),
            )),
            (None | Some("first"), None) => Ok(SeriesDatum::First),
            (Some("each"), None) => Ok(SeriesDatum::Each),
            (Some(other), None) => Err(self.error(
                "surface.datum",
                format!("unknown datum `{}`", crate::io::text::cut(other, 40)),
                Some("use \"first\" (the first map's form removed from every map, the default) or \"each\" (each map its own), or give datum_region"),
            )),
        }
    }

    /// The samples of `map` within `x_m` x `y_m` (from its first sample), for a datum fitted
    /// there: at least three by three samples, or the key is refused.
    pub(super) fn sample_region(
        &self,
        map: &HeightMap,
        x_m: [f64; 2],
        y_m: [f64; 2],
    ) -> Result<SampleRegion, SceneError> {
        let [ny, nx] = map.shape();
        let [dx, dy] = map.spacing_m();
        let range = |[from, to]: [f64; 2], step: f64, count: usize| {
            // The samples at from..=to, to a thousandth of a step (rounded coordinates).
            let first = ((from / step) - 1e-3).ceil().max(0.0) as usize;
            let last = ((to / step) + 1e-3).floor().min((count - 1) as f64) as usize;
            first..(last + 1).max(first)
        };
        let region = SampleRegion {
            columns: range(x_m, dx, nx),
            rows: range(y_m, dy, ny),
        };
        if region.columns.len() < 3 || region.rows.len() < 3 {
            return Err(self.error(
                "surface.datum_region",
                format!(
                    "holds {} x {} samples of the {} x {} map (spaced {} x {} m): a datum is fitted on at least 3 x 3",
                    region.columns.len(),
                    region.rows.len(),
                    nx,
                    ny,
                    crate::io::text::approx(dx),
                    crate::io::text::approx(dy)
                ),
                Some("widen the region, within the map's extent"),
            ));
        }
        Ok(region)
    }

    /// A measured map levelled as `mode` says, the form fitted on `region`'s samples when
    /// given ([`Datum`]), and what was done.
    pub(super) fn levelled(
        &self,
        key: &str,
        map: HeightMap,
        mode: LevelMode,
        region: Option<&SampleRegion>,
    ) -> Result<(HeightMap, Levelling), SceneError> {
        let (heights, levelling) = match mode {
            LevelMode::Keep => return Ok((map, Levelling::Raw)),
            LevelMode::Mean => {
                let plane = Datum::fitted(&map, FormRemoval::Plane, region).plane_m;
                // The mean over the region when given (a series' datum), else the map's.
                let mean_m = match region {
                    Some(region) => {
                        let heights = map.heights_m();
                        let values: Vec<f64> = region
                            .rows
                            .clone()
                            .flat_map(|j| region.columns.clone().map(move |i| heights[[j, i]]))
                            .collect();
                        values.iter().sum::<f64>() / values.len().max(1) as f64
                    }
                    None => map.heights_m().mean().unwrap_or(0.0),
                };
                (map.heights_m() - mean_m, Levelling::Mean { mean_m, plane })
            }
            LevelMode::Form(form) => {
                let datum = Datum::fitted(&map, form, region);
                (
                    datum.remove_from(map.heights_m()),
                    Levelling::Removed(datum),
                )
            }
        };
        let map = HeightMap::new(heights, map.spacing_m())
            .map_err(|e| self.error(key, e.to_string(), None))?;
        Ok((map, levelling))
    }

    /// One `[surface]`-like table: the map, a description of its source, and for a generated
    /// surface the form superposed on it.
    fn height_map(
        &self,
        key: &str,
        table: &RawSurface,
    ) -> Result<(HeightMap, String, Option<Form>), SceneError> {
        match (&table.file, &table.generate) {
            (Some(_), Some(_)) | (None, None) => Err(self.error(
                key,
                "give either file (a measured surface) or [generate] (a random one)",
                Some("e.g. file = \"surfaces/worn.asc\", or a [surface.generate] table"),
            )),
            (Some(file), None) => Ok((
                self.read_map(key, &format!("{key}.file"), file, table)?,
                file.clone(),
                None,
            )),
            (None, Some(generate)) => {
                for (name, given) in [
                    ("spacing", table.spacing.is_some()),
                    ("height_unit", table.height_unit.is_some()),
                    ("fill", table.fill.is_some()),
                    ("length_unit", table.length_unit.is_some()),
                ] {
                    if given {
                        return Err(self.error(
                            &format!("{key}.{name}"),
                            "a generated surface takes its grid from [generate]",
                            Some("move spacing into the [generate] table; remove the others"),
                        ));
                    }
                }
                let (generator, description) =
                    self.generator(&format!("{key}.generate"), generate)?;
                let map = generate::generate(&generator)
                    .map_err(|e| self.error(&format!("{key}.generate"), e.to_string(), None))?;
                Ok((map, description, Some(generator.form)))
            }
        }
    }

    /// The height file `file` (named at `file_key`, relative to the scene) read with the
    /// options of the `[surface]`-like table `table` at `key` (spacing, units, fill).
    pub(super) fn read_map(
        &self,
        key: &str,
        file_key: &str,
        file: &str,
        table: &RawSurface,
    ) -> Result<HeightMap, SceneError> {
        let spacing_m = table
            .spacing
            .as_ref()
            .map(|s| self.spacing(&format!("{key}.spacing"), s))
            .transpose()?;
        let unit = |name: &str, value: &Option<String>| -> Result<Option<f64>, SceneError> {
            value
                .as_deref()
                .map(|text| {
                    read::length_unit_m(text).ok_or_else(|| {
                        self.error(
                            &format!("{key}.{name}"),
                            format!("unknown unit `{text}`"),
                            Some("use m, mm, µm (or um), nm or pm"),
                        )
                    })
                })
                .transpose()
        };
        let fill = match table.fill.as_deref() {
            None | Some("refuse") => Fill::Refuse,
            Some("interpolate") => Fill::Interpolate,
            Some(other) => {
                return Err(self.error(
                    &format!("{key}.fill"),
                    format!("unknown fill `{other}`"),
                    Some("use \"refuse\" (the default) or \"interpolate\""),
                ))
            }
        };
        let options = ReadOptions {
            spacing_m,
            height_unit_m: unit("height_unit", &table.height_unit)?,
            xyz_length_unit_m: unit("length_unit", &table.length_unit)?,
            fill,
        };
        let path = Path::new(self.file)
            .parent()
            .unwrap_or_else(|| Path::new(""))
            .join(file);
        let map = read::read_surface(&path, &options).map_err(|e| {
            let hint = match e {
                read::ReadError::Io { .. } => "the path is relative to the scene file",
                _ => "check the file and its height_unit and spacing",
            };
            self.error(file_key, e.to_string(), Some(hint))
        })?;
        Ok(map)
    }

    fn spacing(&self, key: &str, value: &TextOrList) -> Result<[f64; 2], SceneError> {
        match value {
            TextOrList::Text(text) => {
                let d = self.bounded(key, text, Dimension::Length, SPACING_BOUNDS)?;
                Ok([d, d])
            }
            TextOrList::List(list) => match list.as_slice() {
                [x, y] => Ok([
                    self.bounded(key, x, Dimension::Length, SPACING_BOUNDS)?,
                    self.bounded(key, y, Dimension::Length, SPACING_BOUNDS)?,
                ]),
                _ => Err(self.error(
                    key,
                    "give one spacing or [dx, dy]",
                    Some("e.g. spacing = \"1 um\""),
                )),
            },
        }
    }

    /// `[surface.generate]` into a generator and a description.
    fn generator(&self, key: &str, raw: &RawGenerate) -> Result<(Generator, String), SceneError> {
        let samples = match &raw.samples {
            None => {
                return Err(self.error(
                    &format!("{key}.samples"),
                    "how many samples?",
                    Some("e.g. samples = 256, or [nx, ny]"),
                ))
            }
            Some(CountOrList::Count(n)) => [*n, *n],
            Some(CountOrList::List(list)) => match list.as_slice() {
                [nx, ny] => [*nx, *ny],
                _ => {
                    return Err(self.error(
                        &format!("{key}.samples"),
                        "give one count or [nx, ny]",
                        None,
                    ))
                }
            },
        };
        if samples.iter().any(|&n| !(8..=8192).contains(&n)) {
            return Err(self.error(
                &format!("{key}.samples"),
                format!("each count must lie in 8..=8192, got {samples:?}"),
                Some("256 to 1024 is usual"),
            ));
        }
        let spacing_m = match &raw.spacing {
            Some(s) => self.spacing(&format!("{key}.spacing"), s)?,
            None => {
                return Err(self.error(
                    &format!("{key}.spacing"),
                    "the sample spacing is needed",
                    Some("e.g. spacing = \"1 um\""),
                ))
            }
        };
        let length = |name: &str, value: &Option<String>| {
            let bounds = match name {
                "sphere_radius" | "cylinder_radius" => RADIUS_BOUNDS,
                _ => WAVELENGTH_BOUNDS,
            };
            value
                .as_deref()
                .map(|text| self.bounded(&format!("{key}.{name}"), text, Dimension::Length, bounds))
                .transpose()
        };
        let (nx, ny) = (samples[0] as usize, samples[1] as usize);
        let size = (nx as f64 * spacing_m[0]).min(ny as f64 * spacing_m[1]);
        let (spectrum, description) = match (raw.hurst, length("correlation_length", &raw.correlation_length)?) {
            (Some(hurst), None) => {
                if !(hurst > 0.0 && hurst <= 1.0) {
                    return Err(self.error(
                        &format!("{key}.hurst"),
                        format!("must lie in (0, 1], got {}", crate::io::text::number(hurst)),
                        Some("measured surfaces have Hurst exponents of 0.5 to 1; 0.8 is common"),
                    ));
                }
                let (rolloff, cutoff) = self.self_affine_band(
                    key,
                    length("rolloff", &raw.rolloff)?,
                    length("cutoff", &raw.cutoff)?,
                    size,
                    spacing_m[0].max(spacing_m[1]),
                )?;
                (
                    Spectrum::SelfAffine {
                        hurst,
                        rolloff_wavelength_m: rolloff,
                        cutoff_wavelength_m: cutoff,
                    },
                    format!("self-affine, H = {}, roll-off {:.4} µm, cutoff {:.4} µm", crate::io::text::number(hurst), rolloff * 1e6, cutoff * 1e6),
                )
            }
            (None, Some(length)) => {
                if raw.rolloff.is_some() || raw.cutoff.is_some() {
                    return Err(self.error(&format!("{key}.rolloff"), "roll-off and cutoff belong to a self-affine spectrum (hurst)", Some("remove them")));
                }
                (
                    Spectrum::Gaussian {
                        correlation_length_m: length,
                    },
                    format!("Gaussian autocorrelation, correlation length {:.4} µm", length * 1e6),
                )
            }
            (Some(_), Some(_)) => {
                return Err(self.error(
                    &format!("{key}.correlation_length"),
                    "give hurst (a self-affine spectrum) or correlation_length (a Gaussian autocorrelation), not both",
                    None,
                ))
            }
            (None, None) => {
                return Err(self.error(
                    &format!("{key}.hurst"),
                    "which spectrum?",
                    Some("give hurst = 0.8 (self-affine; rolloff and cutoff wavelengths optional) or correlation_length = \"10 um\""),
                ))
            }
        };
        let amplitude = match (&raw.rms_height, raw.rms_slope) {
            (Some(text), None) => Amplitude::RmsHeight(self.bounded(
                &format!("{key}.rms_height"),
                text,
                Dimension::Length,
                RMS_HEIGHT_BOUNDS,
            )?),
            (None, Some(slope)) if (MIN_RMS_SLOPE..=MAX_RMS_SLOPE).contains(&slope) => {
                Amplitude::RmsSlope(slope)
            }
            (None, Some(slope)) => {
                return Err(self.error(
                    &format!("{key}.rms_slope"),
                    format!(
                        "must lie between {} and {MAX_RMS_SLOPE}, got {}",
                        crate::io::text::compact(MIN_RMS_SLOPE),
                        crate::io::text::number(slope)
                    ),
                    Some("machined and worn surfaces have rms slopes of 0.01 to 0.5"),
                ))
            }
            _ => {
                return Err(self.error(
                    &format!("{key}.rms_height"),
                    "give one of rms_height and rms_slope",
                    Some("e.g. rms_height = \"0.2 um\" or rms_slope = 0.1"),
                ))
            }
        };
        let form = match (
            length("sphere_radius", &raw.sphere_radius)?,
            length("cylinder_radius", &raw.cylinder_radius)?,
        ) {
            (None, None) => Form::None,
            (Some(radius_m), None) => Form::Sphere { radius_m },
            (None, Some(radius_m)) => Form::Cylinder { radius_m },
            (Some(_), Some(_)) => {
                return Err(self.error(
                    &format!("{key}.cylinder_radius"),
                    "give a sphere or a cylinder, not both",
                    None,
                ))
            }
        };
        let seed = match raw.seed {
            None => 1,
            Some(s) if s >= 0 => s as u64,
            Some(s) => {
                return Err(self.error(
                    &format!("{key}.seed"),
                    format!("must be >= 0, got {s}"),
                    None,
                ))
            }
        };
        Ok((
            Generator {
                shape: [ny, nx],
                spacing_m,
                spectrum,
                amplitude,
                form,
                seed,
            },
            format!("generated ({description}, seed {seed})"),
        ))
    }

    /// The roll-off and cutoff wavelengths of a self-affine spectrum: each as given, or a
    /// default that fits the map and the other one: the roll-off a quarter of the shorter side
    /// (at least the cutoff given, at most the side), the cutoff four spacings (at most the roll-off, at least
    /// two spacings, the shortest wavelength the grid resolves). A conflict names the key to
    /// give and the default it came from.
    fn self_affine_band(
        &self,
        key: &str,
        rolloff: Option<f64>,
        cutoff: Option<f64>,
        size_m: f64,
        spacing_m: f64,
    ) -> Result<(f64, f64), SceneError> {
        let rolloff_m =
            rolloff.unwrap_or_else(|| (size_m / 4.0).max(cutoff.unwrap_or(0.0)).min(size_m));
        let cutoff_m =
            cutoff.unwrap_or_else(|| (4.0 * spacing_m).min(rolloff_m).max(2.0 * spacing_m));
        if cutoff_m > rolloff_m {
            let um = |m: f64| crate::io::text::approx(m * 1e6);
            let (at, message, hint) = match (rolloff.is_some(), cutoff.is_some()) {
                (true, true) => (
                    "cutoff",
                    format!("the cutoff wavelength ({} um) must not exceed the roll-off wavelength ({} um)", um(cutoff_m), um(rolloff_m)),
                    "give a cutoff at most the roll-off (the cutoff is the shortest wavelength of the spectrum)".to_string(),
                ),
                (true, false) => (
                    "rolloff",
                    format!("the roll-off wavelength ({} um) is shorter than two sample spacings ({} um), the shortest wavelength the grid resolves, and so shorter than the default cutoff", um(rolloff_m), um(cutoff_m)),
                    "give a longer rolloff, or a finer spacing".to_string(),
                ),
                (false, true) => (
                    "cutoff",
                    format!("the cutoff wavelength ({} um) exceeds the map's shorter side ({} um), so it exceeds the default roll-off", um(cutoff_m), um(size_m)),
                    "give a shorter cutoff, or more samples".to_string(),
                ),
                // Neither given: equal spacings always fit (at least 8 samples a side), so the
                // spacings are the cause (issue 42: this named `cutoff`, a key not written).
                (false, false) => (
                    "spacing",
                    format!("the spacings differ too much: the shortest wavelength the coarser one resolves (two spacings, {} um) is longer than a quarter of the map's shorter side ({} um of {} um), the default roll-off", um(cutoff_m), um(rolloff_m), um(size_m)),
                    "give closer (or equal) spacings, or more samples along the shorter side; or give rolloff and cutoff".to_string(),
                ),
            };
            return Err(self.error(&format!("{key}.{at}"), message, Some(&hint)));
        }
        Ok((rolloff_m, cutoff_m))
    }
}
