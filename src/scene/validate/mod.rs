//! Validation of a parsed scene into the typed scene, one file per table; the shared helpers
//! (errors with the key, numbers with units, ranges, friction and Poisson's ratio) are here.

mod bodies;
mod coating;
mod contact;
mod figure;
mod gears;
mod lubricant;
mod numerical;
mod plasticity;
mod rough;
mod rough_scene;
mod surface;
mod sweep;
mod thermal;
mod tractions;
mod volume;
mod wear;

use std::path::Path;

use super::raw::{
    self, CountOrList, NumberOrText, RawBody, RawContact, RawFigure, RawGenerate, RawPlasticity,
    RawScene, RawSurface, RawSweep, RawVolume, RawWear, TextOrList,
};
use super::spec::{
    Contact, ContactKind, Dimensional, FigureSpec, Hertz, LengthUnit, Method, Numerical, PanelSpec,
    PlasticitySpec, RoughSpec, Scale, SectionKind, SeriesEntry, StressUnit, SurfaceSpec, WearSpec,
    YieldStrength, ROUGH_SECTION_MAX_DEPTH_OVER_WIDTH, ROUGH_SECTION_MIN_CELLS,
    ROUGH_SECTION_MIN_DEPTH_OVER_WIDTH,
};
use super::sweep::{Sweep, SweepParameter, VolumeSpec, MAX_STEPS, MIN_PECLET};
use super::traction_csv;
use super::{Scene, SceneError, FORMAT};
use crate::contact::elliptic::{CurvedBody, EllipticalContact, PrincipalRadii};
use crate::contact::gear::SpurGearPair;
use crate::contact::material::{self, yield_strength_from_hardness_pa, Material};
use crate::contact::{Body, LineContact, PointContact};
use crate::io::units::{self, Dimension};
use crate::render::{ColorMap, Levels, Mark};
use crate::solution::dcfft::TractionGrid;
use crate::stress::{Quantity, QuantityKind};

/// The range a dimensional input may take (SI), and why: wide enough for every contact a user
/// could mean (an AFM tip to a rolling mill), narrow enough that every derived Hertz value
/// stays far inside double precision (so no figure or report meets an infinity or a zero).
/// The Python package checks its arguments against the same bounds (issue 50).
#[derive(Clone, Copy, Debug)]
pub struct Bounds {
    pub lo: f64,
    pub hi: f64,
    pub why: &'static str,
}

impl Bounds {
    /// Whether `value` lies within the bounds (a NaN does not).
    pub fn contains(&self, value: f64) -> bool {
        value >= self.lo && value <= self.hi
    }
}

/// Loads, N (point contacts) or N/m (line contacts).
pub const LOAD_BOUNDS: Bounds = Bounds {
    lo: 1e-12,
    hi: 1e12,
    why: "from the piconewtons of an AFM tip to far beyond the largest press",
};
/// Radii of curvature (in size; negative for a concave body), m.
pub const RADIUS_BOUNDS: Bounds = Bounds {
    lo: 1e-9,
    hi: 1e6,
    why: "from a nanometre (an AFM tip) to 1000 km; use \"flat\" for a plane",
};
/// Young's moduli, Pa.
pub const MODULUS_BOUNDS: Bounds = Bounds {
    lo: 1e3,
    hi: 1e13,
    why: "from soft gels (kPa) to ten times diamond (1.2 TPa)",
};
/// Yield strengths and peak pressures given directly, Pa.
pub const STRESS_BOUNDS: Bounds = Bounds {
    lo: 1.0,
    hi: 1e13,
    why: "from a pascal to ten times the modulus of diamond",
};
/// Hardness numbers (kgf/mm²).
pub const HARDNESS_BOUNDS: Bounds = Bounds {
    lo: 0.1,
    hi: 1e5,
    why: "from soft polymers to ten times diamond (about 10000 HV)",
};
/// Contact half-widths given directly, m.
pub const HALF_WIDTH_BOUNDS: Bounds = Bounds {
    lo: 1e-12,
    hi: 1e6,
    why: "from a picometre to 1000 km",
};
/// Gear modules, m.
pub const MODULE_BOUNDS: Bounds = Bounds {
    lo: 1e-6,
    hi: 10.0,
    why: "from micro-gears to the largest mill gears",
};

/// Approaches of a rough contact, m.
pub const APPROACH_BOUNDS: Bounds = Bounds {
    lo: 1e-12,
    hi: 0.1,
    why: "from a picometre to 10 cm (a surface's heights may reach 1 m)",
};
/// Sample spacings of a surface, m.
pub const SPACING_BOUNDS: Bounds = Bounds {
    lo: crate::surface::MIN_SPACING_M,
    hi: crate::surface::MAX_SPACING_M,
    why: "from an atomic spacing (0.1 nm, an AFM scan) to a metre",
};
/// Wavelengths and lengths of a surface's spectrum (roll-off, cutoff, correlation length, the
/// band of the statistics), m.
pub const WAVELENGTH_BOUNDS: Bounds = Bounds {
    lo: crate::surface::MIN_SPACING_M,
    hi: 1e4,
    why: "from an atomic spacing (0.1 nm) to 10 km (8192 samples a metre apart)",
};
/// The rms height of a generated surface, m.
pub const RMS_HEIGHT_BOUNDS: Bounds = Bounds {
    lo: 1e-12,
    hi: 0.1,
    why: "from a picometre (a polished crystal) to 10 cm (a surface's heights may reach 1 m)",
};

/// The unit after a length a user wrote, for messages: `" a"`, `" mm"`, ...
pub(super) fn unit_after(unit: LengthUnit) -> &'static str {
    match unit {
        LengthUnit::HalfWidth => " a",
        other => other.suffix(),
    }
}

pub(super) struct Validator<'a> {
    pub(super) file: &'a str,
    /// Whether body 2 may be rigid in a contact with Hertz theory (an indenter on the
    /// elastic-plastic body of a `[plasticity]` scene).
    pub(super) rigid_counter: bool,
}

impl Validator<'_> {
    fn error(&self, key: &str, message: impl Into<String>, hint: Option<&str>) -> SceneError {
        SceneError {
            file: self.file.into(),
            key: Some(key.into()),
            line_column: None,
            message: message.into(),
            hint: hint.map(Into::into),
        }
    }

    pub(super) fn scene(&self, raw: RawScene, name: &str) -> Result<Scene, SceneError> {
        if raw.format != FORMAT {
            return Err(self.error(
                "format",
                format!(
                    "this build reads scene format {FORMAT}, the scene says {}",
                    raw.format
                ),
                Some("set `format = 1`"),
            ));
        }
        self.heated_contact_keys(&raw)?;
        self.lubricated_bodies(&raw)?;
        let contact = self.contact(&raw.contact)?;
        if matches!(contact.kind, ContactKind::Rough | ContactKind::Surface) {
            if raw.plasticity.is_some() && contact.kind == ContactKind::Surface {
                return Err(self.error(
                    "plasticity",
                    "a surface scene characterises the surface; it presses no contact to yield",
                    Some(
                        "use contact.kind = \"rough\" to press the map on a flat with [plasticity]",
                    ),
                ));
            }
            if raw.lubricant.is_some() {
                // The same refusal as the table's own (one message for one requirement).
                self.lubricant(&raw, &contact, None)?;
            }
            return self.rough_scene(raw, name, contact);
        }
        for (key, given) in [
            ("surface", raw.surface.is_some()),
            ("counter_surface", raw.counter_surface.is_some()),
            ("wear", raw.wear.is_some()),
            ("series", !raw.series.is_empty()),
        ] {
            if given {
                return Err(self.error(
                    key,
                    "a height map (and its wear) belongs to a rough or surface scene",
                    Some("use contact.kind = \"rough\" (press it on a flat) or \"surface\" (characterise it)"),
                ));
            }
        }
        let thermal = self.thermal(&raw, &contact)?;
        let lubricant = self.lubricant(&raw, &contact, thermal.as_ref())?;
        let own_sections = self.panel_sections(&raw)?;
        let figure = self.figure(&raw.figure, &contact, &own_sections)?;
        let method = self.method("contact.method", raw.contact.method.as_deref())?;
        let numerical = self.numerical(raw.numerical.as_ref(), &contact)?;
        let tractions = self.tractions(&raw, &contact)?;
        let at = self.section_position(
            "figure.at",
            raw.figure.at,
            &contact,
            &figure,
            figure.section,
        )?;
        let mut panels = Vec::new();
        for (i, (panel, own)) in raw.panels.iter().zip(&own_sections).enumerate() {
            let key = format!("panel[{i}]");
            let method = match panel.method.as_deref() {
                Some(text) => self.method(&format!("{key}.method"), Some(text))?,
                None => method,
            };
            let section = own.unwrap_or(figure.section);
            let at = match panel.at {
                Some(value) => self.section_position(
                    &format!("{key}.at"),
                    Some(value),
                    &contact,
                    &figure,
                    section,
                )?,
                // figure.at is a position along another axis: no default for this plane.
                None if section != figure.section && raw.figure.at.is_some() => {
                    let (_, _, figure_normal) = figure.section.coordinates();
                    let position = match section {
                        SectionKind::Xz => {
                            "the y of the xz section (0 through the contact's centre)"
                        }
                        SectionKind::Yz => {
                            "the x of the yz section (0 through the contact's centre)"
                        }
                        SectionKind::Xy => "the depth z of the xy section (0 for the surface)",
                    };
                    return Err(self.error(
                        &format!("{key}.at"),
                        format!(
                            "this panel's {} section needs its own position: figure.at is the {figure_normal} of the figure's {} sections",
                            section.key(),
                            figure.section.key()
                        ),
                        Some(&format!("give {key}.at, {position}")),
                    ));
                }
                None if section != figure.section => 0.0,
                None => at,
            };
            let friction = match panel.friction {
                Some(mu) => self.friction(&format!("{key}.friction"), mu)?,
                None => contact.friction,
            };
            let poisson = match panel.poisson {
                Some(nu) => self.poisson(&format!("{key}.poisson"), nu)?,
                None => contact.poisson,
            };
            panels.push(PanelSpec {
                method,
                friction,
                poisson,
                section,
                at,
                subtitle: panel.subtitle.clone(),
            });
        }
        if panels.is_empty() {
            panels.push(PanelSpec {
                method,
                friction: contact.friction,
                poisson: contact.poisson,
                section: figure.section,
                at,
                subtitle: None,
            });
        }
        if !contact.has_closed_form() {
            let key = raw
                .panels
                .iter()
                .position(|p| p.method.is_some())
                .map_or_else(
                    || "contact.method".to_string(),
                    |i| format!("panel[{i}].method"),
                );
            if let Some(panel) = panels.iter().find(|p| p.method != Method::Numerical) {
                let what = match contact.kind {
                    ContactKind::Elliptical => "an elliptical contact",
                    ContactKind::Tractions => "a traction grid from a file",
                    _ => "partial slip",
                };
                return Err(self.error(
                    &key,
                    format!(
                        "{what} has no closed form here, so `{}` cannot be drawn",
                        panel.method.key()
                    ),
                    Some("use method = \"numerical\""),
                ));
            }
        }
        let moving = raw
            .sweep
            .as_ref()
            .is_some_and(|sweep| sweep.parameter == "position");
        if !moving {
            self.numerical_ranges(
                &contact,
                &figure,
                &numerical,
                tractions.as_deref(),
                &raw.panels,
                &panels,
            )?;
        }
        if panels.len() > 6 {
            return Err(self.error(
                "panel",
                format!("{} panels is too many for one figure", panels.len()),
                Some("use at most 6 [[panel]] tables; split the rest into another scene"),
            ));
        }
        if contact.coating.is_some() {
            // What a coated scene does not compute is refused, never drawn homogeneous.
            for (key, given, what) in [
                (
                    "thermal",
                    raw.thermal.is_some(),
                    "frictional heating of a coated body",
                ),
                (
                    "volume",
                    raw.volume.is_some(),
                    "a volume recording of a coated body",
                ),
                (
                    "panel",
                    !raw.panels.is_empty(),
                    "panels of a coated body (its figure draws its own sections)",
                ),
            ] {
                if given {
                    return Err(self.error(
                        key,
                        format!("{what} is not computed"),
                        Some("remove the table; `hertz` reports the coated contact and its stresses, `render` draws its sheet"),
                    ));
                }
            }
            if let Some(sweep) = &raw.sweep {
                if sweep.parameter.trim() != "coating_thickness" {
                    return Err(self.error(
                        "sweep.parameter",
                        format!("a coated scene records a sweep of its coating's thickness, not `{}`", sweep.parameter.trim()),
                        Some("use parameter = \"coating_thickness\" (from/to in the figure's length unit, spaced geometrically), or run `hertz` on scenes with other loads or friction"),
                    ));
                }
            }
        }
        let mut scene = Scene {
            name: name.into(),
            title: raw.title.clone(),
            contact,
            figure,
            panels,
            numerical,
            tractions,
            sweep: None,
            volume: None,
            load_centre_over_a: 0.0,
            thermal,
            surface: None,
            wear: None,
            plasticity: None,
            lubricant,
        };
        if let Some(sweep) = &raw.sweep {
            scene.sweep = Some(self.sweep(sweep, &scene)?);
        }
        if let Some(volume) = &raw.volume {
            scene.volume = Some(self.volume(volume, &scene.contact, &scene.figure)?);
        }
        if let Some(table) = &raw.plasticity {
            scene.plasticity = Some(self.plasticity(table, &raw, &scene)?);
        }
        Ok(scene)
    }

    /// Each `[[panel]]`'s own section (`None`: the figure's). A speed (Péclet) sweep records
    /// its own temperature sections, so a panel's section there is refused, not ignored.
    fn panel_sections(&self, raw: &RawScene) -> Result<Vec<Option<SectionKind>>, SceneError> {
        let speed_sweep = raw.sweep.as_ref().is_some_and(|s| s.parameter == "peclet");
        let mut sections = Vec::with_capacity(raw.panels.len());
        for (i, panel) in raw.panels.iter().enumerate() {
            let key = format!("panel[{i}].section");
            let Some(text) = &panel.section else {
                if speed_sweep {
                    // Not drawn by a recording of the speed: refused, not ignored (issue 42,
                    // class 9).
                    return Err(self.error(
                        &format!("panel[{i}]"),
                        "a Péclet sweep records its own views (body 1's surface temperature, its xz section and the charts against Pe), not panels: this [[panel]] would be ignored",
                        Some("remove the [[panel]] tables; draw the stress panels in a scene without [sweep] (`stressfield thermal SCENE --figure` draws the heating's stress sections)"),
                    ));
                }
                sections.push(None);
                continue;
            };
            let kind = self.section_kind(&key, text)?;
            if speed_sweep {
                return Err(self.error(
                    &key,
                    "a Péclet sweep records its own sections of the temperature (the surface and the xz section through the contact's centre), not the panels'",
                    Some("remove it; draw the stress sections in a scene without [sweep]"),
                ));
            }
            sections.push(Some(kind));
        }
        Ok(sections)
    }

    fn method(&self, key: &str, value: Option<&str>) -> Result<Method, SceneError> {
        match value {
            None => Ok(Method::ClosedForm),
            Some(text) => Method::from_key(text).ok_or_else(|| {
                self.error(
                    key,
                    format!("unknown method `{text}`"),
                    Some("use \"closed_form\" (exact), \"numerical\" (integrated tractions) or \"difference\" (numerical minus closed form)"),
                )
            }),
        }
    }

    fn friction(&self, key: &str, mu: f64) -> Result<f64, SceneError> {
        match super::friction_requirement(mu) {
            Some(message) => Err(self.error(key, message, Some(super::FRICTION_HINT))),
            None => Ok(mu),
        }
    }

    fn poisson(&self, key: &str, nu: f64) -> Result<f64, SceneError> {
        if !(nu > -1.0 && nu <= 0.5) {
            return Err(self.error(
                key,
                format!(
                    "Poisson's ratio must lie in (-1, 0.5], got {}",
                    crate::io::text::number(nu)
                ),
                Some("steel is about 0.3"),
            ));
        }
        Ok(nu)
    }

    /// A value with its unit within `bounds` (in SI units), named by `key` with the value
    /// the user wrote.
    fn bounded(
        &self,
        key: &str,
        text: &str,
        dimension: Dimension,
        bounds: Bounds,
    ) -> Result<f64, SceneError> {
        let value = units::parse(text, dimension).map_err(|m| self.error(key, m, None))?;
        self.within(key, value, text, dimension, bounds)
    }

    /// `value` (SI, as the user wrote `text`) within `bounds`.
    fn within(
        &self,
        key: &str,
        value: f64,
        text: &str,
        dimension: Dimension,
        bounds: Bounds,
    ) -> Result<f64, SceneError> {
        if !(value >= bounds.lo && value <= bounds.hi) {
            let unit = dimension.si_unit();
            return Err(self.error(
                key,
                format!(
                    "must lie between {} {unit} and {} {unit}, got `{}`",
                    crate::io::text::compact(bounds.lo),
                    crate::io::text::compact(bounds.hi),
                    crate::io::text::cut(text, 40)
                ),
                Some(bounds.why),
            ));
        }
        Ok(value)
    }

    fn range(
        &self,
        key: &str,
        values: Option<&Vec<f64>>,
        default: (f64, f64),
    ) -> Result<(f64, f64), SceneError> {
        let Some(values) = values else {
            return Ok(default);
        };
        match values.as_slice() {
            [lo, hi] if lo.is_finite() && hi.is_finite() && lo < hi => Ok((*lo, *hi)),
            [lo, hi] if lo >= hi => Err(self.error(
                key,
                format!("range [{lo}, {hi}] is empty or inverted"),
                Some("write [min, max] with min < max"),
            )),
            _ => Err(self.error(key, format!("needs [min, max], got {values:?}"), None)),
        }
    }
}
