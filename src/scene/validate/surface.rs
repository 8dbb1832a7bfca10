//! Rough and surface scenes: the `[surface]` and `[counter_surface]` tables (a height map read
//! from a file or generated) and the options of its characterisation.

use std::sync::Arc;

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::contact::rough::Control;
use crate::surface::generate::{self, Amplitude, Form, Generator, Spectrum};
use crate::surface::read::{self, Fill, ReadOptions};
use crate::surface::stats::FormRemoval;
use crate::surface::HeightMap;

/// The range of a generated surface's rms slope (a slope of 10 rises 10 m a metre).
const MIN_RMS_SLOPE: f64 = 1e-6;
const MAX_RMS_SLOPE: f64 = 10.0;

impl Validator<'_> {
    /// `[surface]` (and `[counter_surface]`) of a rough or surface scene.
    pub(super) fn surface_spec(
        &self,
        raw: &RawScene,
        kind: ContactKind,
    ) -> Result<SurfaceSpec, SceneError> {
        let Some(table) = &raw.surface else {
            return Err(self.error(
                "surface",
                "a rough or surface scene needs its [surface] table",
                Some("add [surface] with file = \"surfaces/worn.asc\" (spacing, height_unit), or [surface.generate]"),
            ));
        };
        let (body1, source, shape) = self.height_map("surface", table)?;
        let generated = shape.is_some();
        let shape = shape.unwrap_or(Form::None);
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
                let (map, _, _) = self.height_map("counter_surface", table)?;
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
        let form = match table.form.as_deref() {
            // A generated ball or cylinder: its form is not roughness.
            None if shape != Form::None => FormRemoval::Quadratic,
            None | Some("plane") => FormRemoval::Plane,
            Some("quadratic") => FormRemoval::Quadratic,
            Some(other) => {
                return Err(self.error(
                    "surface.form",
                    format!("unknown form `{other}`"),
                    Some("use \"plane\" (the mean plane, always removed) or \"quadratic\" (also a second-order form, e.g. a ball's)"),
                ))
            }
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
        })
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
            (Some(file), None) => {
                let spacing_m = table
                    .spacing
                    .as_ref()
                    .map(|s| self.spacing(&format!("{key}.spacing"), s))
                    .transpose()?;
                let unit =
                    |name: &str, value: &Option<String>| -> Result<Option<f64>, SceneError> {
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
                    self.error(&format!("{key}.file"), e.to_string(), Some(hint))
                })?;
                Ok((map, file.clone(), None))
            }
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

    /// What presses a rough contact, against its surface: a mean pressure over the map below
    /// the combined modulus E* (beyond it the strains would be of order one, far outside
    /// elasticity, and the surfaces flattened), an approach below the surface's peak-to-valley
    /// height (beyond it the surfaces overlap everywhere). With a hardness `H` (the pressure
    /// cap) the load must also stay below `H` times the nominal area: the most the fully
    /// plastic surface carries. `hardness_key` is the key the hardness came from.
    ///
    /// Periodic and without a hardness, an approach must also stay below the highest point's
    /// height above the mean plane (Sp): a periodic surface's mean displacement is zero, so the
    /// mean gap is that height less the approach, and at it the gap closes everywhere (beyond
    /// it there is no elastic solution).
    ///
    /// `key` names the load, mean pressure or approach (`contact.load`, or a sweep's
    /// `sweep.values[i]` for each of its loads).
    fn rough_control(
        &self,
        rough: &RoughSpec,
        key: &str,
        heights: &HeightMap,
        hardness_key: &str,
    ) -> Result<(), SceneError> {
        let [width_m, length_m] = heights.size_m();
        let area_m2 = width_m * length_m;
        let aspect = width_m.max(length_m) / width_m.min(length_m);
        if rough.periodic && aspect > crate::operator::elastic::MAX_PERIODIC_ASPECT {
            return Err(self.error(
                "contact.periodic",
                format!(
                    "the map is {} times longer than wide ({} x {} m): a periodic contact's kernel sums the images out to 1.5 times the longer side, so its time grows with the square of the longer side; at most {} here",
                    crate::io::text::approx(aspect),
                    crate::io::text::approx(width_m),
                    crate::io::text::approx(length_m),
                    crate::operator::elastic::MAX_PERIODIC_ASPECT
                ),
                Some("solve it as an isolated contact (periodic = false), or use a map closer to square"),
            ));
        }
        let mean_pa = match rough.control {
            Some(Control::Load { newtons }) => Some((key, newtons / area_m2)),
            Some(Control::MeanPressure { pa }) => Some((key, pa)),
            _ => None,
        };
        if let (Some((key, mean_pa)), Some(hardness_pa)) = (mean_pa, rough.hardness_pa) {
            if mean_pa >= hardness_pa {
                return Err(self.error(
                    key,
                    format!(
                        "a mean pressure of {} Pa over the map's {} m² is more than the fully plastic surface carries: the hardness ({hardness_key}) caps the pressure at {} Pa, so at most {} N",
                        crate::io::text::approx(mean_pa),
                        crate::io::text::approx(area_m2),
                        crate::io::text::approx(hardness_pa),
                        crate::io::text::approx(hardness_pa * area_m2)
                    ),
                    Some(&format!("lower {key}, give a larger map, or check {hardness_key} (a pressure capped at H carries at most H times the nominal area)")),
                ));
            }
        }
        match (rough.control, rough.e_star_pa) {
            (Some(Control::Load { newtons }), Some(e_star)) if newtons / area_m2 > e_star => {
                Err(self.error(
                    key,
                    format!(
                        "{} N over the map's {} m² is a mean pressure of {} Pa, more than the combined modulus E* = {} Pa",
                        crate::io::text::approx(newtons),
                        crate::io::text::approx(area_m2),
                        crate::io::text::approx(newtons / area_m2),
                        crate::io::text::approx(e_star)
                    ),
                    Some("rough contact is elastic (up to a hardness cap): give a load whose mean pressure over the map is a small fraction of E*, or a larger map"),
                ))
            }
            (Some(Control::MeanPressure { pa }), Some(e_star)) if pa > e_star => Err(self.error(
                key,
                format!(
                    "{} Pa is more than the combined modulus E* = {} Pa",
                    crate::io::text::approx(pa),
                    crate::io::text::approx(e_star)
                ),
                Some("rough contact is elastic (up to a hardness cap): give a small fraction of E*"),
            )),
            (Some(Control::Approach { m }), _) => {
                let map = heights.heights_m();
                let (low, high) = map
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &h| {
                        (lo.min(h), hi.max(h))
                    });
                let mean = map.sum() / map.len() as f64;
                if m > high - low {
                    Err(self.error(
                        key,
                        format!(
                            "{} m is more than the surface's peak-to-valley height {} m: the surfaces would overlap everywhere",
                            crate::io::text::approx(m),
                            crate::io::text::approx(high - low)
                        ),
                        Some("the approach is counted from first contact: give a fraction of the peak-to-valley height"),
                    ))
                } else if rough.periodic
                    && rough.hardness_pa.is_none()
                    && m >= (high - mean) * (1.0 - crate::contact::rough::FULL_CONTACT_MARGIN)
                {
                    Err(self.error(
                        key,
                        format!(
                            "{} m closes the gap everywhere (full contact): a periodic surface's mean displacement is zero, so its mean gap is the highest point's height above the mean plane, {} m, less the approach",
                            crate::io::text::approx(m),
                            crate::io::text::approx(high - mean)
                        ),
                        Some("give an approach below that height, or press it by a load (contact.load or contact.mean_pressure), which never closes the gap completely"),
                    ))
                } else {
                    Ok(())
                }
            }
            _ => Ok(()),
        }
    }

    /// A rough or surface scene: its tables beyond `[contact]`.
    pub(super) fn rough_scene(
        &self,
        raw: RawScene,
        name: &str,
        mut contact: Contact,
    ) -> Result<Scene, SceneError> {
        let surface = self.surface_spec(&raw, contact.kind)?;
        if let Some(i) = raw.panels.iter().position(|p| p.section.is_some()) {
            return Err(self.error(
                &format!("panel[{i}].section"),
                "a rough or surface scene chooses its own sections: the xz section through the report's maximum and the plane at its depth (or, for a surface, none)",
                Some("remove the [[panel]] table; to cut a smooth contact in several planes use kind = \"point\" or \"elliptical\""),
            ));
        }
        for (key, given) in [
            ("panel", !raw.panels.is_empty()),
            ("tractions", raw.tractions.is_some()),
            (
                "sweep",
                raw.sweep.is_some() && contact.kind == ContactKind::Surface,
            ),
            ("volume", raw.volume.is_some()),
            ("figure.section", raw.figure.section.is_some()),
            ("figure.at", raw.figure.at.is_some()),
            ("figure.x", raw.figure.x.is_some()),
            ("figure.y", raw.figure.y.is_some()),
            (
                "figure.z",
                raw.figure.z.is_some() && contact.kind == ContactKind::Surface,
            ),
            ("figure.resolution", raw.figure.resolution.is_some()),
        ] {
            if given {
                return Err(self.error(
                    key,
                    "a rough or surface scene draws its own set of panels (topography, pressure, sections through the peak; or the surface's statistics)",
                    Some("remove it; see the README's rough contact section"),
                ));
            }
        }
        if let (Some(numerical), Some(rough)) = (&raw.numerical, contact.rough.as_mut()) {
            if numerical.cells.is_some() || numerical.extent.is_some() {
                let key = if numerical.cells.is_some() {
                    "numerical.cells"
                } else {
                    "numerical.extent"
                };
                return Err(self.error(
                    key,
                    "the grid of a rough contact is the surface's",
                    Some("remove it; numerical takes tolerance and max_iterations here"),
                ));
            }
            if let Some(t) = numerical.tolerance {
                if !(t > 0.0 && t < 1e-2) {
                    return Err(self.error(
                        "numerical.tolerance",
                        format!("must lie in (0, 0.01), got {}", crate::io::text::number(t)),
                        Some("the default is 1e-8"),
                    ));
                }
                rough.tolerance = t;
            }
            if let Some(n) = numerical.max_iterations {
                if !(10..=1_000_000).contains(&n) {
                    return Err(self.error(
                        "numerical.max_iterations",
                        format!("must lie in 10..=1000000, got {n}"),
                        None,
                    ));
                }
                rough.max_iterations = n as usize;
            }
        }
        let hardness_key = if raw.contact.hardness.is_some() {
            "contact.hardness"
        } else {
            "contact.yield_strength"
        };
        if let Some(rough) = &contact.rough {
            let key = match rough.control {
                Some(Control::Load { .. }) => "contact.load",
                Some(Control::MeanPressure { .. }) => "contact.mean_pressure",
                _ => "contact.approach",
            };
            self.rough_control(rough, key, &surface.heights, hardness_key)?;
        }
        let figure = self.figure(&raw.figure, &contact, &[])?;
        if figure.depth_given {
            self.rough_section_depth(&figure, &surface.heights)?;
        }
        let thermal = self.thermal(&raw, &contact)?;
        let [ny, nx] = surface.heights.shape();
        let mut scene = Scene {
            name: name.into(),
            title: raw.title,
            contact,
            figure,
            panels: Vec::new(),
            numerical: Numerical {
                cells: nx.max(ny),
                extent_over_a: 1.0,
            },
            tractions: None,
            sweep: None,
            volume: None,
            load_centre_over_a: 0.0,
            thermal,
            surface: Some(surface),
        };
        if let Some(sweep) = &raw.sweep {
            let sweep = self.sweep(sweep, &scene)?;
            // Each load of a rough sweep is held to the limits of the scene's own load.
            if let (Some(rough), Some(surface)) = (&scene.contact.rough, &scene.surface) {
                for (k, &newtons) in sweep.values.iter().enumerate() {
                    let stepped = RoughSpec {
                        control: Some(Control::Load { newtons }),
                        ..*rough
                    };
                    self.rough_control(
                        &stepped,
                        &sweep.value_key(k),
                        &surface.heights,
                        hardness_key,
                    )?;
                }
            }
            scene.sweep = Some(sweep);
        }
        Ok(scene)
    }
}
impl Validator<'_> {
    /// A rough scene's `[figure] z`: the depth range of its xz section, which is drawn over
    /// at least [`ROUGH_SECTION_MIN_CELLS`] of the map's cells along x (the whole row when the
    /// range is deep) at equal scale and at least
    /// [`ROUGH_SECTION_MIN_DEPTH_OVER_WIDTH`] as deep as wide: the range spans at least that
    /// fraction of those cells, and at most [`ROUGH_SECTION_MAX_DEPTH_OVER_WIDTH`] times the
    /// map's width.
    fn rough_section_depth(
        &self,
        figure: &FigureSpec,
        heights: &crate::surface::HeightMap,
    ) -> Result<(), SceneError> {
        let per_um = figure.length_unit.metres(1e-6) / 1e-6;
        let (z0, z1) = figure.z;
        let span_um = (z1 - z0) * per_um;
        let [_, nx] = heights.shape();
        let cell_um = heights.spacing_m()[0] * 1e6;
        let width_um = nx as f64 * cell_um;
        let suffix = unit_after(figure.length_unit);
        let shallowest_um =
            ROUGH_SECTION_MIN_DEPTH_OVER_WIDTH * ROUGH_SECTION_MIN_CELLS.min(nx) as f64 * cell_um;
        let in_unit = |um: f64| crate::io::text::approx(um / per_um);
        if span_um < shallowest_um * (1.0 - 1e-9) {
            return Err(self.error(
                "figure.z",
                format!(
                    "the depth range [{}, {}] spans {}{suffix}, less than a quarter of the {} cells ({}{suffix}) a section shows at least",
                    crate::io::text::number(z0),
                    crate::io::text::number(z1),
                    in_unit(span_um),
                    ROUGH_SECTION_MIN_CELLS.min(nx),
                    in_unit(ROUGH_SECTION_MIN_CELLS.min(nx) as f64 * cell_um),
                ),
                Some(&format!(
                    "give a range at least {}{suffix} deep, or a surface with finer samples",
                    in_unit(shallowest_um)
                )),
            ));
        }
        if span_um > ROUGH_SECTION_MAX_DEPTH_OVER_WIDTH * width_um {
            return Err(self.error(
                "figure.z",
                format!(
                    "the depth range [{}, {}] is more than {} times as deep as the map is wide ({}{suffix}): the section would be a tower",
                    crate::io::text::number(z0),
                    crate::io::text::number(z1),
                    crate::io::text::compact(ROUGH_SECTION_MAX_DEPTH_OVER_WIDTH),
                    in_unit(width_um),
                ),
                Some(&format!(
                    "give a range at most {}{suffix} deep",
                    in_unit(ROUGH_SECTION_MAX_DEPTH_OVER_WIDTH * width_um)
                )),
            ));
        }
        Ok(())
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
                _ => (
                    "cutoff",
                    format!("the cutoff wavelength ({} um) exceeds the map's shorter side ({} um), so it exceeds the default roll-off", um(cutoff_m), um(size_m)),
                    "give a shorter cutoff, or more samples".to_string(),
                ),
            };
            return Err(self.error(&format!("{key}.{at}"), message, Some(&hint)));
        }
        Ok((rolloff_m, cutoff_m))
    }
}
