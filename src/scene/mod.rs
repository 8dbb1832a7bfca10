//! Scenes: `scenes/*.toml`, one figure or recording each. This module is the file format only:
//! parsing (serde, unknown keys rejected with their dotted path, [`raw`]) and validation
//! ([`validate`], one file per table) into the typed scene of [`spec`], plain data in SI
//! units. What a scene computes (solutions, grid planes, display units) is
//! [`crate::study`]'s.
//!
//! See the README for the format reference.
//!
//! Uses: the layers below it for their types and presets (contact, surface, thermal, solution,
//! stress, render's colour maps and levels, io). Whether a valid scene can be computed here
//! (its memory, the speeds a sweep resolves) is the study's second stage,
//! [`crate::study::admit`]; commands read scenes through [`crate::study::load_scene`].

mod display;
mod raw;
mod spec;
mod sweep;
pub mod traction_csv;

mod validate;

pub use validate::{
    Bounds, APPROACH_BOUNDS, LOAD_BOUNDS, MODULUS_BOUNDS, SPACING_BOUNDS, STRESS_BOUNDS,
    WAVELENGTH_BOUNDS,
};

use std::path::Path;

use crate::solution::dcfft::TractionGrid;
use raw::RawScene;

pub use spec::{
    CoatingSpec, Contact, ContactKind, Dimensional, FigureSpec, GearMesh, Hertz, LengthUnit,
    Levelling, LubricantSpec, Method, Numerical, OilSpec, PanelSpec, PlasticitySpec, RoughSpec,
    Scale, SectionKind, SeriesDatum, SeriesEntry, Strengths, StressUnit, SurfaceSpec, ThermalBody,
    ThermalSpec, TractionDirection, WearSpec, YieldStrength, ROUGH_SECTION_MAX_DEPTH_OVER_WIDTH,
    ROUGH_SECTION_MIN_CELLS, ROUGH_SECTION_MIN_DEPTH_OVER_WIDTH,
};
pub use sweep::{compact, Sweep, SweepParameter, VolumeSpec, MAX_STEPS, MIN_PECLET};

/// The scene format this build reads.
pub const FORMAT: i64 = 1;

/// The largest coefficient of friction accepted (scenes, sweeps, `probe --friction`). Dry
/// sliding gives 0.1 to 1 and clean metals in vacuum a few; beyond about 10 surfaces weld
/// rather than slide, and `q = μ p` no longer describes the contact.
pub const MAX_FRICTION: f64 = 10.0;

/// The loosest tolerance a rough contact's solver takes (`numerical.tolerance` lies in `(0,
/// MAX_ROUGH_TOLERANCE)`).
pub const MAX_ROUGH_TOLERANCE: f64 = 1e-2;

/// What a friction coefficient must be, for messages: the range and why.
pub fn friction_requirement(mu: f64) -> Option<String> {
    if (0.0..=MAX_FRICTION).contains(&mu) {
        return None;
    }
    Some(format!(
        "the coefficient of friction must lie in 0..={MAX_FRICTION}, got {}",
        crate::io::text::number(mu)
    ))
}

/// The hint that goes with [`friction_requirement`].
pub const FRICTION_HINT: &str = "dry sliding gives 0.1 to 1, clean metals in vacuum a few; beyond 10 surfaces weld rather than slide (q = μ p no longer holds)";

/// A scene that cannot be used, with the key at fault and how to fix it.
#[derive(Debug, thiserror::Error, PartialEq)]
#[error("{file}{}: {message}{}", location_text(.key, .line_column), hint_text(.hint))]
pub struct SceneError {
    pub file: String,
    /// Dotted key path, e.g. `contact.body1.poisson`.
    pub key: Option<String>,
    pub line_column: Option<(usize, usize)>,
    pub message: String,
    pub hint: Option<String>,
}

fn location_text(key: &Option<String>, line_column: &Option<(usize, usize)>) -> String {
    let mut text = String::new();
    if let Some((line, column)) = line_column {
        text.push_str(&format!(":{line}:{column}"));
    }
    if let Some(key) = key {
        text.push_str(&format!(": key `{key}`"));
    }
    text
}

fn hint_text(hint: &Option<String>) -> String {
    hint.as_ref()
        .map(|h| format!("\nhint: {h}"))
        .unwrap_or_default()
}

/// A validated scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The file stem; outputs are `out/<name>.png`.
    pub name: String,
    pub title: Option<String>,
    pub contact: Contact,
    pub figure: FigureSpec,
    pub panels: Vec<PanelSpec>,
    pub numerical: Numerical,
    /// The user's tractions (kind = "tractions") on their grid, in units of a and p0.
    pub tractions: Option<std::sync::Arc<TractionGrid>>,
    /// A recording scene's sweep: one time point per value.
    pub sweep: Option<Sweep>,
    /// A recording scene's 3-D volume, recorded as iso-surfaces (point contacts).
    pub volume: Option<VolumeSpec>,
    /// The x position of the contact's centre on the body (units of a; a moving load's step).
    pub load_centre_over_a: f64,
    /// The heights of a rough or surface scene.
    pub surface: Option<SurfaceSpec>,
    /// Frictional heating, when the scene has a `[thermal]` table.
    pub thermal: Option<ThermalSpec>,
    /// A rough scene's evolution with sliding distance (`[wear]` or `[[series]]`).
    pub wear: Option<WearSpec>,
    /// Body 1 elastic-plastic (`[plasticity]`, `stressfield plastic`).
    pub plasticity: Option<PlasticitySpec>,
    /// The lubricant (`[lubricant]`): film thickness, λ, the line contact's EHL solution.
    pub lubricant: Option<LubricantSpec>,
}

impl Scene {
    /// Whether `render` and `record` draw the elastic-plastic sheet and load steps of this
    /// scene: a `[plasticity]` point or line contact. A rough map's is not this one (its
    /// sections are a few cells deep under a map many contacts wide, its curves Hertz's), nor
    /// an ellipse's (the sheet's Hertz pressure, approach and mean-pressure curves are the
    /// circle's of radius √(ab), and its x axis is in √(ab), not in the ellipse's own a): their
    /// elastic figure is drawn.
    pub fn draws_plastic_sheet(&self) -> bool {
        self.plasticity.is_some()
            && matches!(self.contact.kind, ContactKind::Point | ContactKind::Line)
    }

    /// The yield strength of body 1: `contact.yield_strength` (or `hardness`), else
    /// `plasticity.yield_strength` (a scene gives it once; validation refuses both). The
    /// `hertz` report's yield assessment and the figure's yield line read it here, so that a
    /// `[plasticity]` scene's own yield strength is assessed too.
    pub fn yield_strength(&self) -> Option<YieldStrength> {
        self.contact.yield_strength.or_else(|| {
            self.plasticity.map(|p| YieldStrength {
                pa: p.yield_strength_pa,
                from_hardness: None,
                hardness_scale: "",
            })
        })
    }

    /// Size of one figure length unit in units of a.
    pub fn length_unit_over_a(&self) -> f64 {
        let a_m = self.contact.half_width_m();
        self.figure.length_unit.metres(a_m) / a_m
    }

    /// Reads and validates a scene file.
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let file = path.display().to_string();
        let text = crate::io::input::read_to_string(path, crate::io::input::SCENE_FILE_LIMIT)
            .map_err(|e| SceneError {
                file: file.clone(),
                key: None,
                line_column: None,
                message: format!("cannot read the scene: {e}"),
                hint: Some(
                    "check the path; scenes are TOML files such as scenes/line_tau1.toml".into(),
                ),
            })?;
        let name = path
            .file_stem()
            .map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
        Self::parse(&text, &name, &file)
    }

    /// Parses and validates scene text; `name` names the outputs, `file` the error messages.
    pub fn parse(text: &str, name: &str, file: &str) -> Result<Self, SceneError> {
        let deserializer = toml::Deserializer::parse(text).map_err(|e| {
            let mut error = toml_error(text, file, None, &e);
            error.message = format!("invalid TOML: {}", error.message);
            error
        })?;
        let raw: RawScene = serde_path_to_error::deserialize(deserializer).map_err(|e| {
            let path = e.path().to_string();
            let key = (path != "." && !path.is_empty()).then_some(path);
            toml_error(text, file, key, e.inner())
        })?;
        validate::Validator {
            file,
            rigid_counter: raw.plasticity.is_some(),
        }
        .scene(raw, name)
    }
}

fn toml_error(text: &str, file: &str, key: Option<String>, error: &toml::de::Error) -> SceneError {
    let line_column = error.span().map(|span| line_column(text, span.start));
    let mut message = error.message().trim().to_string();
    let leaf = key
        .as_deref()
        .and_then(|k| k.rsplit('.').next())
        .unwrap_or("key");
    let hint = if message.starts_with("unknown field") {
        Some("remove or correct the key; docs/reference.md lists every scene key".into())
    } else if message.starts_with("invalid type: integer")
        || message.starts_with("invalid type: floating point")
    {
        (message.ends_with("expected a string") || message.contains("a text with its unit such as"))
            .then(|| {
                format!(
                    "a dimensional value is text with its unit, in quotes, e.g. {leaf} = {}",
                    unit_example(leaf)
                )
            })
    } else if message.starts_with("invalid type: string") {
        let number = message
            .split('"')
            .nth(1)
            .filter(|n| n.trim().parse::<f64>().is_ok());
        let written = number.map_or_else(|| "0.2".to_string(), |n| n.trim().to_string());
        ["expected f64", "expected i64", "expected a number"]
            .iter()
            .any(|e| message.ends_with(e))
            .then(|| {
                format!(
                    "this key takes a plain number without quotes or unit, e.g. {leaf} = {written}"
                )
            })
    } else if message == "duplicate key" {
        let line = error
            .span()
            .and_then(|span| text.get(span.start..))
            .and_then(|rest| rest.lines().next())
            .unwrap_or("");
        let name = line.split('=').next().unwrap_or("").trim();
        if !name.is_empty() {
            message = format!("duplicate key `{}`", crate::io::text::cut(name, 40));
        }
        Some("give each key once in its table; remove one of the two".into())
    } else {
        None
    };
    SceneError {
        file: file.into(),
        message: in_user_words(&message, key.as_deref()),
        key,
        line_column,
        hint,
    }
}

/// A serde message in the user's words: no Rust type names (`struct RawThermal`, `f64`), and
/// the value a key takes as the reference describes it (issue 42, class 10).
fn in_user_words(message: &str, key: Option<&str>) -> String {
    let Some((given, expected)) = message.split_once(", expected ") else {
        return message.to_string();
    };
    let leaf = key.and_then(|k| k.rsplit('.').next()).unwrap_or("");
    let expected = if leaf == "partition" {
        "body 1's share of the heat: a fraction from 0 to 1, \"body1\" or \"blok\"".to_string()
    } else if expected.starts_with("struct Raw") {
        match key {
            Some(key) => {
                format!("a table: [{key}] on a line of its own, its keys on the lines below")
            }
            None => "a table".to_string(),
        }
    } else {
        match expected {
            "f64" | "f32" => "a number".to_string(),
            "i64" | "i32" | "u64" | "u32" | "usize" => "a whole number".to_string(),
            "a string" => "a text in quotes".to_string(),
            "a sequence" => "a list in brackets, e.g. [1.0, 2.0]".to_string(),
            "a boolean" => "true or false".to_string(),
            other => other.to_string(),
        }
    };
    format!("{given}, expected {expected}")
}

/// An example of a dimensional value for the key named `leaf`, for messages.
fn unit_example(leaf: &str) -> &'static str {
    match leaf {
        "load" => "\"1000 N\" (a line contact: per unit length, \"40 kN/m\")",
        "radius" | "radius_x" | "radius_y" | "sphere_radius" | "cylinder_radius" => "\"20 mm\"",
        "modulus" | "yield_strength" | "p0" | "mean_pressure" => "\"210 GPa\"",
        "hardness" => "\"700 HV\"",
        "a" | "approach" | "spacing" | "rms_height" | "rolloff" | "cutoff"
        | "correlation_length" => "\"1 um\"",
        "speed" | "body1_speed" | "body2_speed" | "entrainment_speed" => "\"2 m/s\"",
        "viscosity" => "\"0.05 Pa s\"",
        "viscosity_40c" | "viscosity_100c" => "\"220 mm^2/s\"",
        "pressure_viscosity" => "\"20 GPa^-1\"",
        "temperature" => "\"70 C\"",
        "roughness" => "\"0.1 um\"",
        "pinion_speed" => "\"1500 rpm\"",
        _ => "\"20 mm\" (docs/reference.md gives each key's unit)",
    }
}

fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stress::Quantity;

    fn parse(text: &str) -> Result<Scene, SceneError> {
        Scene::parse(text, "test", "test.toml")
    }

    #[test]
    fn minimal_normalised_scene() {
        let scene = parse("format = 1\n[contact]\nkind = \"line\"\n").expect("valid");
        assert_eq!(scene.contact.poisson, 0.3);
        assert_eq!(scene.panels.len(), 1);
        assert_eq!(scene.figure.quantity, Quantity::VonMises);
    }

    #[test]
    fn contact_given_by_size_is_drawn_in_mm_and_mpa() {
        let text = "format = 1\n[contact]\nkind = \"line\"\na = \"0.25 mm\"\np0 = \"1.5 GPa\"\n";
        let scene = parse(text).expect("valid");
        assert_eq!(scene.contact.half_width_m(), 0.25e-3);
        assert_eq!(scene.contact.p0_pa(), 1.5e9);
        assert_eq!(scene.figure.length_unit, LengthUnit::Millimetre);
        assert_eq!(scene.figure.stress_unit, StressUnit::MegaPascal);
        // Default range ±2.5a, given in mm.
        assert!((scene.figure.x.1 - 0.625).abs() < 1e-12);
        let explicit =
            parse("format = 1\n[contact]\nkind = \"line\"\na = 1\np0 = 1\n").expect("valid");
        assert_eq!(explicit.contact.scale, None);
    }

    #[test]
    fn unknown_key_reports_dotted_path_and_line() {
        let err =
            parse("format = 1\n[contact]\nkind = \"line\"\npoison = 0.3\n").expect_err("typo");
        assert_eq!(err.key.as_deref(), Some("contact.poison"), "{err}");
        assert_eq!(err.line_column.map(|(l, _)| l), Some(4), "{err}");
    }

    /// Issue 24, class 18: what a new user writes gets an example of the right form.
    #[test]
    fn a_new_users_mistakes_get_an_example() {
        let message = |text: &str| parse(text).expect_err("refused").to_string();
        let load = message("format = 1\n[contact]\nkind = \"point\"\nload = 1000\n");
        assert!(load.contains("load = \"1000 N\""), "{load}");
        let friction = message("format = 1\n[contact]\nkind = \"line\"\nfriction = \"0.2\"\n");
        assert!(friction.contains("friction = 0.2"), "{friction}");
        let twice =
            message("format = 1\n[contact]\nkind = \"line\"\nfriction = 0.2\nfriction = 0.3\n");
        assert!(
            twice.contains("duplicate key `friction`") && twice.contains(":5:"),
            "{twice}"
        );
        let line = message("format = 1\n[contact]\nkind = \"line\"\nload = \"1000 N\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"10 mm\"\nmaterial = \"steel\"\n");
        assert!(
            line.contains("per unit length") && line.contains("contact.load"),
            "{line}"
        );
        let rockwell = message("format = 1\n[contact]\nkind = \"line\"\nhardness = \"60 HRC\"\n");
        assert!(
            rockwell.contains("ASTM E140") && rockwell.contains("contact.hardness"),
            "{rockwell}"
        );
        let rigid = message("format = 1\n[contact]\nkind = \"point\"\nload = \"300 N\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"rigid\"\n[contact.body2]\nradius = \"6 mm\"\nmaterial = \"steel\"\n");
        assert!(
            rigid.contains("rough contacts only") && rigid.contains("contact.body1.material"),
            "{rigid}"
        );
    }

    #[test]
    fn poisson_out_of_range_names_the_key() {
        let err = parse("format = 1\n[contact]\nkind = \"line\"\npoisson = 0.7\n").expect_err("nu");
        assert_eq!(err.key.as_deref(), Some("contact.poisson"));
        assert!(err.to_string().contains("(-1, 0.5]"), "{err}");
    }
}
