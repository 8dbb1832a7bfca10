//! Scenes: `scenes/*.toml`, one figure each. Parsing (serde, unknown keys rejected with their
//! dotted path) and validation into typed values with SI units.
//!
//! See the README for the format reference.

mod raw;
mod sweep;
pub mod traction_csv;
pub mod units;

use std::path::Path;

use crate::contact::elliptic::{CurvedBody, EllipticalContact, PrincipalRadii};
use crate::contact::gear::SpurGearPair;
use crate::contact::material::{self, yield_strength_from_hardness_pa, Material};
use crate::contact::partial_slip::CattaneoMindlin;
use crate::contact::{Body, LineContact, PointContact};
use crate::field::{Axis, Plane, Section};
use crate::render::{ColorMap, Levels, Mark};
use crate::solution::dcfft::TractionGrid;
use crate::solution::point_numerical::{NumericalError, PointTractions};
use crate::solution::Solution;
use crate::stress::{Quantity, QuantityKind};
use raw::{NumberOrText, RawBody, RawContact, RawFigure, RawScene};
use units::Dimension;

pub use sweep::{Sweep, SweepParameter, VolumeSpec, MAX_STEPS};

/// The scene format this build reads.
pub const FORMAT: i64 = 1;

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

/// Contact geometry kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ContactKind {
    /// Two cylinders (or a cylinder on a flat) with parallel axes along y: plane strain.
    Line,
    /// Two spheres, or a sphere on a flat: an axisymmetric Hertz contact of radius a.
    Point,
    /// Bodies with two principal radii each (a ball in a groove, crowned teeth): an elliptical
    /// Hertz contact with semi-axes a along x and b along y. Numerical method only.
    Elliptical,
    /// Surface tractions read from a CSV grid (`[tractions]`). Numerical method only.
    Tractions,
}

/// The Hertz solution of a dimensional contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Hertz {
    Line(LineContact),
    Point(PointContact),
    Elliptical(EllipticalContact),
}

impl Hertz {
    /// Half-width (line) or contact radius (point), in m.
    pub fn half_width_m(&self) -> f64 {
        match self {
            Hertz::Line(line) => line.half_width_m,
            Hertz::Point(point) => point.radius_m,
            Hertz::Elliptical(ellipse) => ellipse.semi_axis_x_m,
        }
    }

    pub fn p0_pa(&self) -> f64 {
        match self {
            Hertz::Line(line) => line.p0_pa,
            Hertz::Point(point) => point.p0_pa,
            Hertz::Elliptical(ellipse) => ellipse.p0_pa,
        }
    }

    /// The load (N/m for a line contact, N for a point contact) at which the peak pressure
    /// would be `p0_pa`.
    pub fn load_for_peak_pressure(&self, p0_pa: f64) -> f64 {
        match self {
            Hertz::Line(line) => line.load_for_peak_pressure(p0_pa),
            Hertz::Point(point) => point.load_for_peak_pressure(p0_pa),
            Hertz::Elliptical(ellipse) => ellipse.load_for_peak_pressure(p0_pa),
        }
    }
}

/// Yield strength of the body whose field is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct YieldStrength {
    pub pa: f64,
    /// The hardness number it was derived from (Tabor, `Y = H/3`), if any.
    pub from_hardness: Option<f64>,
}

/// A dimensional contact: bodies, materials, load and the Hertz solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dimensional {
    pub body1: Body,
    pub body2: Body,
    pub gears: Option<SpurGearPair>,
    pub hertz: Hertz,
}

/// The physical size of a contact: half-width and peak pressure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scale {
    pub half_width_m: f64,
    pub p0_pa: f64,
}

/// The validated contact of a scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact {
    pub kind: ContactKind,
    /// Coefficient of sliding friction: `q = mu p` acts on body 1 in +x.
    pub friction: f64,
    /// Poisson ratio of body 1, the body whose stresses are computed.
    pub poisson: f64,
    /// Half-width and peak pressure in SI; `None` for a normalised scene (a = 1, p0 = 1).
    pub scale: Option<Scale>,
    /// Bodies, materials and load, when the scene gives them (then `scale` follows from them).
    pub dimensional: Option<Dimensional>,
    pub yield_strength: Option<YieldStrength>,
    /// Semi-axis along y over that along x: 1 for a sphere, b/a for an elliptical contact.
    pub aspect: f64,
    /// Cattaneo-Mindlin partial slip of a sphere: the tangential force over mu P, in (0, 1].
    pub tangential: Option<f64>,
}

impl Contact {
    /// Contact half-width in m (1 for a normalised scene, where lengths are in units of a).
    pub fn half_width_m(&self) -> f64 {
        self.scale.map_or(1.0, |s| s.half_width_m)
    }

    /// Peak pressure in Pa (1 for a normalised scene).
    pub fn p0_pa(&self) -> f64 {
        self.scale.map_or(1.0, |s| s.p0_pa)
    }

    /// The closed-form solution, if the contact has one (not an elliptical contact, nor
    /// partial slip).
    pub fn solution(&self, friction: f64, poisson: f64) -> Option<Solution> {
        match (self.kind, self.tangential) {
            (ContactKind::Line, _) => Some(Solution::LineHertz { friction, poisson }),
            (ContactKind::Point, None) => Some(Solution::SphereHertz { friction, poisson }),
            (ContactKind::Point, Some(_))
            | (ContactKind::Elliptical | ContactKind::Tractions, _) => None,
        }
    }
}

/// How a panel's stresses are computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// The exact closed form (McEwen for a line contact, Hamilton for a sphere).
    ClosedForm,
    /// Numerical integration of the tractions discretised on the scene's `[numerical]` grid.
    Numerical,
    /// Numerical minus closed form: where the discretisation error sits.
    Difference,
}

impl Method {
    fn from_key(key: &str) -> Option<Self> {
        match key {
            "closed_form" => Some(Self::ClosedForm),
            "numerical" => Some(Self::Numerical),
            "difference" => Some(Self::Difference),
            _ => None,
        }
    }

    pub fn key(self) -> &'static str {
        match self {
            Self::ClosedForm => "closed_form",
            Self::Numerical => "numerical",
            Self::Difference => "difference",
        }
    }
}

/// The discretisation of the numerical method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Numerical {
    /// Cells per side of the square traction grid (point contact), or uniform strips across
    /// the contact (line contact).
    pub cells: usize,
    /// The traction grid covers `extent` semi-axes each way: `[-e a, e a] x [-e b, e b]`
    /// (point and elliptical contacts; `b = a` for a sphere).
    pub extent_over_a: f64,
}

/// Unit of lengths on a figure (and of `figure.x`, `figure.y`, `figure.z` and `figure.at`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LengthUnit {
    HalfWidth,
    Metre,
    Millimetre,
    Micrometre,
}

impl LengthUnit {
    fn from_key(key: &str) -> Option<Self> {
        match key {
            "a" => Some(Self::HalfWidth),
            "m" => Some(Self::Metre),
            "mm" => Some(Self::Millimetre),
            "um" | "µm" => Some(Self::Micrometre),
            _ => None,
        }
    }

    /// Size of one unit in m, given the half-width.
    pub fn metres(self, half_width_m: f64) -> f64 {
        match self {
            Self::HalfWidth => half_width_m,
            Self::Metre => 1.0,
            Self::Millimetre => 1e-3,
            Self::Micrometre => 1e-6,
        }
    }

    /// The unit after a number: `a`, ` m`, ` mm`, ` µm`.
    pub fn suffix(self) -> &'static str {
        match self {
            Self::HalfWidth => "a",
            Self::Metre => " m",
            Self::Millimetre => " mm",
            Self::Micrometre => " µm",
        }
    }

    /// Axis label for a coordinate, e.g. `x/a` or `x (mm)`.
    pub fn axis_label(self, coordinate: &str) -> String {
        match self {
            Self::HalfWidth => format!("{coordinate}/a"),
            Self::Metre => format!("{coordinate} (m)"),
            Self::Millimetre => format!("{coordinate} (mm)"),
            Self::Micrometre => format!("{coordinate} (µm)"),
        }
    }
}

/// Unit of stresses on a figure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StressUnit {
    PeakPressure,
    Pascal,
    MegaPascal,
    GigaPascal,
}

impl StressUnit {
    fn from_key(key: &str) -> Option<Self> {
        match key {
            "p0" => Some(Self::PeakPressure),
            "Pa" => Some(Self::Pascal),
            "MPa" => Some(Self::MegaPascal),
            "GPa" => Some(Self::GigaPascal),
            _ => None,
        }
    }

    /// Size of one unit in Pa, given the peak pressure.
    pub fn pascals(self, p0_pa: f64) -> f64 {
        match self {
            Self::PeakPressure => p0_pa,
            Self::Pascal => 1.0,
            Self::MegaPascal => 1e6,
            Self::GigaPascal => 1e9,
        }
    }

    /// Label of a value with this unit, e.g. `τ1 / p0` or `τ1 (MPa)`.
    pub fn label(self, symbol: &str) -> String {
        match self {
            Self::PeakPressure => format!("{symbol} / p0"),
            Self::Pascal => format!("{symbol} (Pa)"),
            Self::MegaPascal => format!("{symbol} (MPa)"),
            Self::GigaPascal => format!("{symbol} (GPa)"),
        }
    }
}

/// Which plane a figure cuts through the body.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SectionKind {
    /// x horizontal, depth z downwards, at a given y.
    Xz,
    /// y horizontal, depth z downwards, at a given x.
    Yz,
    /// x horizontal, y upwards, at a given depth z (the surface at z = 0).
    Xy,
}

impl SectionKind {
    fn from_key(key: &str) -> Option<Self> {
        match key {
            "xz" => Some(Self::Xz),
            "yz" => Some(Self::Yz),
            "xy" => Some(Self::Xy),
            _ => None,
        }
    }

    /// Names of the horizontal, vertical and normal coordinates.
    pub fn coordinates(self) -> (&'static str, &'static str, &'static str) {
        match self {
            Self::Xz => ("x", "z", "y"),
            Self::Yz => ("y", "z", "x"),
            Self::Xy => ("x", "y", "z"),
        }
    }

    /// Whether the vertical axis is the depth (drawn downwards).
    pub fn vertical_is_depth(self) -> bool {
        self != Self::Xy
    }

    pub fn key(self) -> &'static str {
        match self {
            Self::Xz => "xz",
            Self::Yz => "yz",
            Self::Xy => "xy",
        }
    }
}

/// What the figure shows and how.
#[derive(Clone, Debug, PartialEq)]
pub struct FigureSpec {
    pub quantity: Quantity,
    pub section: SectionKind,
    /// Range along the horizontal axis (x, or y for a yz section), in `length_unit`.
    pub horizontal: (f64, f64),
    /// Range along the vertical axis (depth z, or y for an xy section), in `length_unit`.
    pub vertical: (f64, f64),
    pub length_unit: LengthUnit,
    pub stress_unit: StressUnit,
    /// Samples along the horizontal axis; the vertical one follows with the same spacing.
    pub resolution: usize,
    pub levels: Levels,
    pub colormap: ColorMap,
    /// Which extremes to mark; `None` chooses from the data (see `figure::auto_mark`).
    pub mark: Option<Mark>,
    pub width_px: u32,
    pub svg: bool,
}

/// One panel: the contact with its own friction and Poisson ratio, cut at its own position.
#[derive(Clone, Debug, PartialEq)]
pub struct PanelSpec {
    pub method: Method,
    pub friction: f64,
    pub poisson: f64,
    /// Position of the section along its normal (y for xz, x for yz, depth z for xy), in the
    /// figure's `length_unit`.
    pub at: f64,
    pub subtitle: Option<String>,
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
    /// A recording scene's 3-D point cloud (point contacts).
    pub volume: Option<VolumeSpec>,
    /// The x position of the contact's centre on the body (units of a; a moving load's step).
    pub load_centre_over_a: f64,
}

impl Scene {
    /// Reads and validates a scene file.
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| SceneError {
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
        Validator { file }.scene(raw, name)
    }

    /// Size of one figure length unit in units of a.
    pub fn length_unit_over_a(&self) -> f64 {
        self.figure.length_unit.metres(self.contact.half_width_m()) / self.contact.half_width_m()
    }

    /// The grid of a panel, in units of a. A numerical (or difference) panel of a point contact
    /// is sampled at the cell centres of the traction grid within the figure's range (and its
    /// depths at the cell spacing), so that whole layers come from one DC-FFT each; an xz or
    /// yz section then lies on the nearest row or column of centres.
    pub fn plane(&self, panel: &PanelSpec) -> Plane {
        let numerical = panel.method != Method::ClosedForm
            || self
                .contact
                .solution(panel.friction, panel.poisson)
                .is_none();
        if self.contact.kind != ContactKind::Line && numerical {
            return self.grid_plane(panel);
        }
        let unit_over_a = self.length_unit_over_a();
        let (u0, u1) = self.figure.horizontal;
        let (v0, v1) = self.figure.vertical;
        let nu = self.figure.resolution;
        let nv = grid_rows(nu, u1 - u0, v1 - v0);
        let u = Axis::new(u0 * unit_over_a, u1 * unit_over_a, nu);
        let v = Axis::new(v0 * unit_over_a, v1 * unit_over_a, nv);
        let at = panel.at * unit_over_a;
        let section = match self.figure.section {
            SectionKind::Xz => Section::Xz { y: at },
            SectionKind::Yz => Section::Yz { x: at },
            SectionKind::Xy => Section::Xy { z: at },
        };
        Plane { section, u, v }
    }

    /// The plane of a numerical point-contact panel on the traction grid's cell centres.
    fn grid_plane(&self, panel: &PanelSpec) -> Plane {
        let unit_over_a = self.length_unit_over_a();
        let (x_axis, y_axis) = match &self.tractions {
            // The user's grid as it is.
            Some(grid) => {
                let ([x0, y0], [dx, dy], [ny, nx]) = (grid.origin(), grid.cell(), grid.shape());
                (
                    GridAxis {
                        origin: x0,
                        cell: dx,
                        cells: nx,
                    },
                    GridAxis {
                        origin: y0,
                        cell: dy,
                        cells: ny,
                    },
                )
            }
            // The Hertz grid covers `extent` semi-axes each way: [-e, e] x [-e b/a, e b/a].
            None => {
                let Numerical {
                    cells,
                    extent_over_a: extent,
                } = self.numerical;
                let stretch = if self.contact.kind == ContactKind::Elliptical {
                    self.contact.aspect
                } else {
                    1.0
                };
                (
                    GridAxis::centred(extent, cells),
                    GridAxis::centred(extent * stretch, cells),
                )
            }
        };
        // Centres within the figure range [lo, hi] (figure units; at least one).
        let centres = |axis: &GridAxis, (lo, hi): (f64, f64)| {
            let (first, last) = axis.within(lo * unit_over_a, hi * unit_over_a);
            Axis::new(axis.centre(first), axis.centre(last), last - first + 1)
        };
        // Depths at the smaller cell side: square map cells in an xz section of a sphere, and
        // rows as fine as the x cells across a long ellipse (whose y cells are b/a times
        // longer).
        let dz = x_axis.cell.min(y_axis.cell);
        let depths = |(lo, hi): (f64, f64), h: f64| {
            let (lo, hi) = (lo * unit_over_a, hi * unit_over_a);
            let count = ((hi - lo) / h + 1e-9).floor() as usize + 1;
            Axis::new(lo, lo + (count - 1) as f64 * h, count.max(1))
        };
        let at = panel.at * unit_over_a;
        let (section, u, v) = match self.figure.section {
            SectionKind::Xz => (
                Section::Xz {
                    y: y_axis.nearest_centre(at),
                },
                centres(&x_axis, self.figure.horizontal),
                depths(self.figure.vertical, dz),
            ),
            SectionKind::Yz => (
                Section::Yz {
                    x: x_axis.nearest_centre(at),
                },
                centres(&y_axis, self.figure.horizontal),
                depths(self.figure.vertical, dz),
            ),
            SectionKind::Xy => (
                Section::Xy { z: at },
                centres(&x_axis, self.figure.horizontal),
                centres(&y_axis, self.figure.vertical),
            ),
        };
        Plane { section, u, v }
    }

    /// The stress solution of a panel (for a difference panel, the numerical one), centred at
    /// `load_centre_over_a`.
    pub fn solution(&self, panel: &PanelSpec) -> Result<Solution, NumericalError> {
        Ok(self
            .centred_solution(panel)?
            .moved_to(self.load_centre_over_a))
    }

    fn centred_solution(&self, panel: &PanelSpec) -> Result<Solution, NumericalError> {
        let (mu, nu) = (panel.friction, panel.poisson);
        if panel.method == Method::ClosedForm {
            if let Some(solution) = self.contact.solution(mu, nu) {
                return Ok(solution);
            }
        }
        let Numerical {
            cells,
            extent_over_a: extent,
        } = self.numerical;
        let tractions = match (self.contact.kind, self.contact.tangential) {
            (ContactKind::Line, _) => return Ok(Solution::line_numerical(mu, nu, cells)),
            (ContactKind::Point, None) => PointTractions::hertz_sphere(cells, extent, mu, nu)?,
            (ContactKind::Point, Some(ratio)) => {
                // Validated: 0 < ratio <= 1 and mu > 0.
                let slip = CattaneoMindlin::new(mu, ratio)?;
                PointTractions::mindlin_sphere(cells, extent, &slip, nu)?
            }
            (ContactKind::Elliptical, _) => {
                PointTractions::hertz_ellipse(cells, extent, self.contact.aspect, mu, nu)?
            }
            (ContactKind::Tractions, _) => match &self.tractions {
                Some(grid) => PointTractions::new(grid.as_ref().clone(), nu)?,
                None => return Err(NumericalError::MissingTractions),
            },
        };
        Ok(Solution::PointNumerical {
            tractions: std::sync::Arc::new(tractions),
            friction: mu,
            poisson: nu,
        })
    }

    /// The closed-form solution of a panel's contact, if it has one (validated for every panel
    /// drawn in closed form or as a difference).
    pub fn closed_form(&self, panel: &PanelSpec) -> Option<Solution> {
        let solution = self.contact.solution(panel.friction, panel.poisson)?;
        Some(solution.moved_to(self.load_centre_over_a))
    }
}

/// One axis of a numerical traction grid: `cells` cells over `[-extent, extent]` (units of a).
struct GridAxis {
    /// Edge of the first cell.
    origin: f64,
    cell: f64,
    cells: usize,
}

impl GridAxis {
    /// `cells` cells over `[-extent, extent]`.
    fn centred(extent: f64, cells: usize) -> Self {
        Self {
            origin: -extent,
            cell: 2.0 * extent / cells as f64,
            cells,
        }
    }

    fn centre(&self, index: usize) -> f64 {
        self.origin + (index as f64 + 0.5) * self.cell
    }

    /// Index of the first and last cell centre within `[lo, hi]` (at least one).
    fn within(&self, lo: f64, hi: f64) -> (usize, usize) {
        let last_cell = (self.cells - 1) as f64;
        let first = ((lo - self.origin) / self.cell - 0.5 - 1e-9)
            .ceil()
            .clamp(0.0, last_cell) as usize;
        let last = ((hi - self.origin) / self.cell - 0.5 + 1e-9)
            .floor()
            .clamp(first as f64, last_cell) as usize;
        (first, last)
    }

    fn nearest_centre(&self, u: f64) -> f64 {
        let index = ((u - self.origin) / self.cell - 0.5)
            .round()
            .clamp(0.0, (self.cells - 1) as f64);
        self.centre(index as usize)
    }
}

/// Rows of a grid with square cells: `nx` samples over `width`, as many as fit over `height`.
fn grid_rows(nx: usize, width: f64, height: f64) -> usize {
    let rows = (height / width * (nx - 1) as f64).round() as usize + 1;
    rows.max(2)
}

fn toml_error(text: &str, file: &str, key: Option<String>, error: &toml::de::Error) -> SceneError {
    let line_column = error.span().map(|span| line_column(text, span.start));
    let message = error.message().trim().to_string();
    let hint = if message.starts_with("unknown field") {
        Some("remove or correct the key; the README lists every scene key".into())
    } else {
        None
    };
    SceneError {
        file: file.into(),
        key,
        line_column,
        message,
        hint,
    }
}

fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

struct Validator<'a> {
    file: &'a str,
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

    fn scene(&self, raw: RawScene, name: &str) -> Result<Scene, SceneError> {
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
        let contact = self.contact(&raw.contact)?;
        let figure = self.figure(&raw.figure, &contact)?;
        let method = self.method("contact.method", raw.contact.method.as_deref())?;
        let numerical = self.numerical(raw.numerical.as_ref(), &contact)?;
        let tractions = self.tractions(&raw, &contact)?;
        let at = self.section_position("figure.at", raw.figure.at, &contact, &figure)?;
        let mut panels = Vec::new();
        for (i, panel) in raw.panels.iter().enumerate() {
            let key = format!("panel[{i}]");
            let method = match panel.method.as_deref() {
                Some(text) => self.method(&format!("{key}.method"), Some(text))?,
                None => method,
            };
            let at = match panel.at {
                Some(value) => {
                    self.section_position(&format!("{key}.at"), Some(value), &contact, &figure)?
                }
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
                at,
                subtitle: panel.subtitle.clone(),
            });
        }
        if panels.is_empty() {
            panels.push(PanelSpec {
                method,
                friction: contact.friction,
                poisson: contact.poisson,
                at,
                subtitle: None,
            });
        }
        if contact.solution(0.0, contact.poisson).is_none() {
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
        if panels.len() > 6 {
            return Err(self.error(
                "panel",
                format!("{} panels is too many for one figure", panels.len()),
                Some("use at most 6 [[panel]] tables; split the rest into another scene"),
            ));
        }
        let plane_points = figure.resolution
            * grid_rows(
                figure.resolution,
                figure.horizontal.1 - figure.horizontal.0,
                figure.vertical.1 - figure.vertical.0,
            );
        let bytes = plane_points.saturating_mul(panels.len()).saturating_mul(8);
        if bytes > crate::field::MAX_FIELD_BYTES {
            return Err(self.error(
                "figure.resolution",
                format!(
                    "{} points per panel x {} panels need about {} MiB, more than the {} MiB allowed",
                    plane_points,
                    panels.len(),
                    bytes >> 20,
                    crate::field::MAX_FIELD_BYTES >> 20
                ),
                Some("lower figure.resolution (600 to 1200 is plenty for a figure)"),
            ));
        }
        let mut scene = Scene {
            name: name.into(),
            title: raw.title,
            contact,
            figure,
            panels,
            numerical,
            tractions,
            sweep: None,
            volume: None,
            load_centre_over_a: 0.0,
        };
        if let Some(sweep) = &raw.sweep {
            scene.sweep = Some(self.sweep(sweep, &scene)?);
        }
        if let Some(volume) = &raw.volume {
            scene.volume = Some(self.volume(volume, &scene.contact, &scene.figure)?);
        }
        Ok(scene)
    }

    /// The `[tractions]` table of a `kind = "tractions"` scene: the CSV grid read and converted
    /// to units of a and p0 (the contact's `a` and `p0`, or the file's own units `a`, `p0`).
    fn tractions(
        &self,
        raw: &RawScene,
        contact: &Contact,
    ) -> Result<Option<std::sync::Arc<TractionGrid>>, SceneError> {
        let table = match (&raw.tractions, contact.kind) {
            (None, ContactKind::Tractions) => {
                return Err(self.error(
                    "tractions",
                    "a traction scene needs its [tractions] table",
                    Some("add [tractions] with file = \"my_tractions.csv\" (rows x,y,p[,qx][,qy]), length_unit and stress_unit"),
                ))
            }
            (None, _) => return Ok(None),
            (Some(_), kind) if kind != ContactKind::Tractions => {
                return Err(self.error(
                    "tractions",
                    "tractions from a file need kind = \"tractions\"",
                    Some("set contact.kind = \"tractions\", or remove [tractions]"),
                ))
            }
            (Some(table), _) => table,
        };
        if raw.numerical.is_some() {
            return Err(self.error(
                "numerical",
                "the grid of a traction scene is the file's",
                Some("remove [numerical]"),
            ));
        }
        let length_unit = match table.length_unit.as_deref() {
            None => LengthUnit::HalfWidth,
            Some(key) => LengthUnit::from_key(key).ok_or_else(|| {
                self.error(
                    "tractions.length_unit",
                    format!("unknown length unit `{key}`"),
                    Some("use \"a\", \"mm\", \"um\" or \"m\""),
                )
            })?,
        };
        let stress_unit = match table.stress_unit.as_deref() {
            None => StressUnit::PeakPressure,
            Some(key) => StressUnit::from_key(key).ok_or_else(|| {
                self.error(
                    "tractions.stress_unit",
                    format!("unknown stress unit `{key}`"),
                    Some("use \"p0\", \"MPa\", \"GPa\" or \"Pa\""),
                )
            })?,
        };
        let dimensional_units =
            length_unit != LengthUnit::HalfWidth || stress_unit != StressUnit::PeakPressure;
        if dimensional_units && contact.scale.is_none() {
            return Err(self.error(
                "tractions.length_unit",
                "tractions in physical units need the reference length a and pressure p0 of the figures",
                Some("add contact.a (e.g. \"0.1 mm\") and contact.p0 (e.g. \"1 GPa\"), or give the file in units of a and p0"),
            ));
        }
        let path = std::path::Path::new(self.file)
            .parent()
            .unwrap_or_else(|| std::path::Path::new(""))
            .join(&table.file);
        let text = std::fs::read_to_string(&path).map_err(|e| {
            self.error(
                "tractions.file",
                format!("cannot read {}: {e}", path.display()),
                Some("the path is relative to the scene file"),
            )
        })?;
        let read = traction_csv::read(&text)
            .map_err(|m| self.error("tractions.file", format!("{}: {m}", path.display()), None))?;
        let a_m = contact.half_width_m();
        let p0_pa = contact.p0_pa();
        let length = length_unit.metres(a_m) / a_m;
        let stress = stress_unit.pascals(p0_pa) / p0_pa;
        let cell = [read.cell[0] * length, read.cell[1] * length];
        let origin = [
            read.first_centre[0] * length - 0.5 * cell[0],
            read.first_centre[1] * length - 0.5 * cell[1],
        ];
        let scaled = |a: ndarray::Array2<f64>| a.mapv(|v| v * stress);
        let grid = TractionGrid::new(
            origin,
            cell,
            Some(scaled(read.pressure)),
            read.shear_x.map(scaled),
            read.shear_y.map(scaled),
        )
        .map_err(|e| self.error("tractions.file", e.to_string(), None))?;
        let [ny, nx] = grid.shape();
        if nx > 4096 || ny > 4096 {
            return Err(self.error(
                "tractions.file",
                format!("a {nx} x {ny} grid is larger than 4096 x 4096"),
                Some("resample the tractions more coarsely"),
            ));
        }
        Ok(Some(std::sync::Arc::new(grid)))
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

    fn numerical(
        &self,
        raw: Option<&raw::RawNumerical>,
        contact: &Contact,
    ) -> Result<Numerical, SceneError> {
        let empty = raw::RawNumerical::default();
        let raw = raw.unwrap_or(&empty);
        let (default_cells, range, hint) = match contact.kind {
            ContactKind::Line => (
                400,
                8..=100_000,
                "strips across the contact: 400 is accurate to about 1e-4 p0 at z >= 0.1a",
            ),
            ContactKind::Point | ContactKind::Elliptical | ContactKind::Tractions => (
                255,
                8..=2048,
                "cells per side of the traction grid: 255 over ±2a is accurate to about 0.2 % p0",
            ),
        };
        let cells = match raw.cells {
            None => default_cells,
            Some(n) if range.contains(&n) => n as usize,
            Some(n) => {
                return Err(self.error(
                    "numerical.cells",
                    format!("must lie in {}..={}, got {n}", range.start(), range.end()),
                    Some(hint),
                ))
            }
        };
        let extent_over_a = match (raw.extent, contact.kind) {
            (Some(_), ContactKind::Line) => {
                return Err(self.error(
                    "numerical.extent",
                    "a line contact's strips always span the contact -a..a",
                    Some("remove it; set the number of strips with numerical.cells"),
                ))
            }
            (None, _) => 2.0,
            (Some(e), _) if (1.0..=20.0).contains(&e) => e,
            (Some(e), _) => {
                return Err(self.error(
                    "numerical.extent",
                    format!("must lie in 1..=20 semi-axes, got {e}"),
                    Some("the grid must cover the contact, -a..a (and -b..b across); 2 leaves room around it"),
                ))
            }
        };
        Ok(Numerical {
            cells,
            extent_over_a,
        })
    }

    /// The position of a section along its normal: any y or x, a depth z >= 0; only 0 for a
    /// line contact (its field does not depend on y).
    fn section_position(
        &self,
        key: &str,
        value: Option<f64>,
        contact: &Contact,
        figure: &FigureSpec,
    ) -> Result<f64, SceneError> {
        let Some(at) = value else {
            return Ok(0.0);
        };
        let (_, _, normal) = figure.section.coordinates();
        if !at.is_finite() {
            return Err(self.error(key, format!("must be a finite {normal}, got {at}"), None));
        }
        if contact.kind == ContactKind::Line && at != 0.0 {
            return Err(self.error(
                key,
                "a line contact is the same in every xz plane (plane strain)",
                Some("remove it; sections at other y are for point contacts"),
            ));
        }
        if figure.section == SectionKind::Xy && at < 0.0 {
            return Err(self.error(
                key,
                format!(
                    "the depth of an xy section must be >= 0 (z points into the body), got {at}"
                ),
                Some("0 is the surface"),
            ));
        }
        Ok(at)
    }

    fn friction(&self, key: &str, mu: f64) -> Result<f64, SceneError> {
        if !(mu.is_finite() && mu >= 0.0) {
            return Err(self.error(
                key,
                format!("friction coefficient must be >= 0 and finite, got {mu}"),
                Some("typical values are 0 to 0.5"),
            ));
        }
        Ok(mu)
    }

    fn poisson(&self, key: &str, nu: f64) -> Result<f64, SceneError> {
        if !(nu > -1.0 && nu <= 0.5) {
            return Err(self.error(
                key,
                format!("Poisson's ratio must lie in (-1, 0.5], got {nu}"),
                Some("steel is about 0.3"),
            ));
        }
        Ok(nu)
    }

    fn positive(&self, key: &str, text: &str, dimension: Dimension) -> Result<f64, SceneError> {
        let value = units::parse(text, dimension).map_err(|m| self.error(key, m, None))?;
        if !(value.is_finite() && value > 0.0) {
            return Err(self.error(
                key,
                format!("must be positive and finite, got `{text}`"),
                None,
            ));
        }
        Ok(value)
    }

    fn contact(&self, raw: &RawContact) -> Result<Contact, SceneError> {
        let kind = match raw.kind.as_str() {
            "line" => ContactKind::Line,
            "point" => ContactKind::Point,
            "elliptical" => ContactKind::Elliptical,
            "tractions" => ContactKind::Tractions,
            other => {
                return Err(self.error(
                    "contact.kind",
                    format!("unknown contact kind `{other}`"),
                    Some("use \"line\" (cylinders, plane strain), \"point\" (spheres) or \"elliptical\" (two principal radii per body)"),
                ))
            }
        };
        let tangential = match (raw.tangential, kind) {
            (None, _) => None,
            (Some(_), ContactKind::Line | ContactKind::Elliptical | ContactKind::Tractions) => {
                return Err(self.error(
                    "contact.tangential",
                    "partial slip (Cattaneo-Mindlin) is available for a sphere only",
                    Some("use kind = \"point\", or remove it for full sliding (q = mu p)"),
                ))
            }
            (Some(ratio), ContactKind::Point) if ratio > 0.0 && ratio <= 1.0 => Some(ratio),
            (Some(ratio), ContactKind::Point) => {
                return Err(self.error(
                    "contact.tangential",
                    format!("the tangential force over mu P must lie in (0, 1], got {ratio}"),
                    Some("1 is full sliding; 0.5 leaves a stick circle of radius 0.79a"),
                ))
            }
        };
        if tangential.is_some() && raw.friction.is_none_or(|mu| mu <= 0.0) {
            return Err(self.error(
                "contact.friction",
                "partial slip needs a friction coefficient > 0",
                Some("add e.g. friction = 0.5"),
            ));
        }
        if kind == ContactKind::Tractions {
            if raw.friction.is_some() {
                return Err(self.error(
                    "contact.friction",
                    "the tangential tractions of a traction scene come from the file",
                    Some("remove it; give qx (and qy) columns in the CSV file instead"),
                ));
            }
            let key = [
                ("contact.load", raw.load.is_some()),
                ("contact.body1", raw.body1.is_some()),
                ("contact.body2", raw.body2.is_some()),
                ("contact.gears", raw.gears.is_some()),
            ]
            .into_iter()
            .find_map(|(key, given)| given.then_some(key));
            if let Some(key) = key {
                return Err(self.error(
                    key,
                    "a traction scene has no bodies or load: the file gives the tractions",
                    Some("remove it; contact.a and contact.p0 set the figures' units"),
                ));
            }
        }
        if kind != ContactKind::Line && raw.gears.is_some() {
            return Err(self.error(
                "contact.gears",
                "spur gears make a line contact",
                Some("use kind = \"line\" with [contact.gears], or give sphere radii in [contact.body1] and [contact.body2]"),
            ));
        }
        let friction = self.friction("contact.friction", raw.friction.unwrap_or(0.0))?;
        let mut aspect = match (raw.aspect, kind) {
            (None, _) => 1.0,
            (Some(_), ContactKind::Line | ContactKind::Point | ContactKind::Tractions) => {
                return Err(self.error(
                    "contact.aspect",
                    "the aspect ratio b/a is for an elliptical contact",
                    Some("use kind = \"elliptical\", or remove it"),
                ))
            }
            (Some(ratio), ContactKind::Elliptical) if (0.01..=100.0).contains(&ratio) => ratio,
            (Some(ratio), ContactKind::Elliptical) => {
                return Err(self.error(
                    "contact.aspect",
                    format!("the semi-axis ratio b/a must lie in 0.01..=100, got {ratio}"),
                    Some("b is the semi-axis along y, a along x (the sliding direction)"),
                ))
            }
        };
        let dimensional_keys =
            raw.load.is_some() || raw.body1.is_some() || raw.body2.is_some() || raw.gears.is_some();
        let yield_strength = self.yield_strength(raw)?;
        let scale = self.scale(raw)?;
        if !dimensional_keys && scale.is_none() && yield_strength.is_some() {
            let key = if raw.hardness.is_some() {
                "contact.hardness"
            } else {
                "contact.yield_strength"
            };
            return Err(self.error(
                key,
                "a yield check needs a dimensional contact; this scene is normalised (a = 1, p0 = 1)",
                Some("give a and p0 with units, or load and bodies; `stressfield hertz` reports p0 at first yield in units of Y anyway"),
            ));
        }
        if !dimensional_keys {
            if kind == ContactKind::Elliptical && raw.aspect.is_none() {
                return Err(self.error(
                    "contact.aspect",
                    "a normalised elliptical contact needs its semi-axis ratio b/a",
                    Some("add e.g. aspect = 0.3 (b along y over a along x), or give load and bodies with radius_x and radius_y"),
                ));
            }
            let poisson = self.poisson("contact.poisson", raw.poisson.unwrap_or(0.3))?;
            return Ok(Contact {
                kind,
                friction,
                poisson,
                scale,
                dimensional: None,
                yield_strength,
                aspect,
                tangential,
            });
        }
        if raw.aspect.is_some() {
            return Err(self.error(
                "contact.aspect",
                "the semi-axis ratio follows from the load and the bodies",
                Some("remove it, or remove the load and bodies for a normalised scene"),
            ));
        }
        if raw.a.is_some() || raw.p0.is_some() {
            let key = if raw.a.is_some() {
                "contact.a"
            } else {
                "contact.p0"
            };
            return Err(self.error(
                key,
                "a and p0 follow from the load and the bodies",
                Some("give either a and p0, or load with [contact.body1] and [contact.body2]"),
            ));
        }
        if raw.poisson.is_some() {
            return Err(self.error(
                "contact.poisson",
                "a dimensional scene takes Poisson's ratio from each body",
                Some("move it to [contact.body1] and [contact.body2] (or use a material preset)"),
            ));
        }
        let (load_dimension, load_hint) = match kind {
            ContactKind::Line => (
                Dimension::ForcePerLength,
                "add e.g. load = \"40 kN/m\" (force per unit length for a line contact)",
            ),
            ContactKind::Point | ContactKind::Elliptical | ContactKind::Tractions => (
                Dimension::Force,
                "add e.g. load = \"500 N\" (the total force for a point contact)",
            ),
        };
        let load_text = raw.load.as_deref().ok_or_else(|| {
            self.error(
                "contact.load",
                "a dimensional scene needs the load",
                Some(load_hint),
            )
        })?;
        let load = self.positive("contact.load", load_text, load_dimension)?;
        let gears = raw.gears.as_ref().map(|g| self.gears(g)).transpose()?;
        let empty = RawBody::default();
        let elliptical = kind == ContactKind::Elliptical;
        let raw1 = raw.body1.as_ref().unwrap_or(&empty);
        let raw2 = raw.body2.as_ref().unwrap_or(&empty);
        let mut body1 = self.body("contact.body1", raw1, gears.is_some(), elliptical)?;
        let mut body2 = self.body("contact.body2", raw2, gears.is_some(), elliptical)?;
        if let Some(pair) = gears {
            body1.radius_m = pair.curvature_radius_at_pitch_point_m(0);
            body2.radius_m = pair.curvature_radius_at_pitch_point_m(1);
        }
        let radius_error = |e: crate::contact::ContactError| {
            self.error("contact.body2.radius", e.to_string(), Some("a flat is radius = \"flat\"; a concave body has a negative radius larger in size than the convex one's"))
        };
        let hertz = match kind {
            ContactKind::Line => {
                Hertz::Line(LineContact::new(&body1, &body2, load).map_err(radius_error)?)
            }
            ContactKind::Point => {
                Hertz::Point(PointContact::new(&body1, &body2, load).map_err(radius_error)?)
            }
            ContactKind::Elliptical => {
                let curved = |radii, body: &Body| CurvedBody {
                    radii,
                    material: body.material,
                };
                let first = curved(self.principal_radii("contact.body1", raw1)?, &body1);
                let second = curved(self.principal_radii("contact.body2", raw2)?, &body2);
                let ellipse = EllipticalContact::new(&first, &second, 0.0, load).map_err(|e| {
                    self.error("contact.body2.radius_y", e.to_string(), Some("each principal relative curvature must be positive: a concave radius must be larger in size than the convex one's in the same plane"))
                })?;
                aspect = ellipse.semi_axis_y_m / ellipse.semi_axis_x_m;
                Hertz::Elliptical(ellipse)
            }
            ContactKind::Tractions => {
                return Err(self.error(
                    "contact.load",
                    "a traction scene has no bodies or load",
                    None,
                ))
            }
        };
        Ok(Contact {
            kind,
            friction,
            poisson: body1.material.poisson,
            scale: Some(Scale {
                half_width_m: hertz.half_width_m(),
                p0_pa: hertz.p0_pa(),
            }),
            dimensional: Some(Dimensional {
                body1,
                body2,
                gears,
                hertz,
            }),
            yield_strength,
            aspect,
            tangential,
        })
    }

    /// `a` and `p0` given directly: both bare 1 (normalised, the default) or both with units.
    fn scale(&self, raw: &RawContact) -> Result<Option<Scale>, SceneError> {
        let value = |key: &str, value: &NumberOrText, dimension: Dimension| match value {
            NumberOrText::Number(n) if *n == 1.0 => Ok(None),
            NumberOrText::Number(n) => Err(self.error(
                key,
                format!("a bare number means normalised units and must be 1, got {n}"),
                Some(&format!(
                    "write it with a unit for a dimensional scale, e.g. {}",
                    dimension.example()
                )),
            )),
            NumberOrText::Text(text) => self.positive(key, text, dimension).map(Some),
        };
        let a = raw
            .a
            .as_ref()
            .map(|v| value("contact.a", v, Dimension::Length))
            .transpose()?
            .flatten();
        let p0 = raw
            .p0
            .as_ref()
            .map(|v| value("contact.p0", v, Dimension::Pressure))
            .transpose()?
            .flatten();
        match (a, p0) {
            (Some(half_width_m), Some(p0_pa)) => Ok(Some(Scale {
                half_width_m,
                p0_pa,
            })),
            (None, None) => Ok(None),
            (Some(_), None) => Err(self.error(
                "contact.p0",
                "a dimensional half-width needs a dimensional peak pressure",
                Some("add e.g. p0 = \"1.2 GPa\""),
            )),
            (None, Some(_)) => Err(self.error(
                "contact.a",
                "a dimensional peak pressure needs a dimensional half-width",
                Some("add e.g. a = \"0.2 mm\""),
            )),
        }
    }

    fn yield_strength(&self, raw: &RawContact) -> Result<Option<YieldStrength>, SceneError> {
        match (&raw.yield_strength, &raw.hardness) {
            (Some(_), Some(_)) => Err(self.error(
                "contact.hardness",
                "give either yield_strength or hardness, not both",
                None,
            )),
            (Some(text), None) => Ok(Some(YieldStrength {
                pa: self.positive("contact.yield_strength", text, Dimension::Pressure)?,
                from_hardness: None,
            })),
            (None, Some(text)) => {
                let number = self.positive("contact.hardness", text, Dimension::Hardness)?;
                Ok(Some(YieldStrength {
                    pa: yield_strength_from_hardness_pa(number),
                    from_hardness: Some(number),
                }))
            }
            (None, None) => Ok(None),
        }
    }

    fn gears(&self, raw: &raw::RawGears) -> Result<SpurGearPair, SceneError> {
        let module_m = self.positive("contact.gears.module", &raw.module, Dimension::Length)?;
        let angle = units::parse(&raw.pressure_angle, Dimension::Angle)
            .map_err(|m| self.error("contact.gears.pressure_angle", m, None))?;
        if !(angle > 0.0 && angle < std::f64::consts::FRAC_PI_2) {
            return Err(self.error(
                "contact.gears.pressure_angle",
                format!(
                    "must lie between 0 and 90 deg, got `{}`",
                    raw.pressure_angle
                ),
                Some("20 deg is standard"),
            ));
        }
        let teeth: [u32; 2] = match raw.teeth.as_slice() {
            [a, b] if *a >= 6 && *b >= 6 && *a <= 100_000 && *b <= 100_000 => {
                [*a as u32, *b as u32]
            }
            _ => {
                return Err(self.error(
                    "contact.gears.teeth",
                    format!("needs two tooth counts of at least 6, got {:?}", raw.teeth),
                    Some("e.g. teeth = [20, 40] (pinion = body1, gear = body2)"),
                ))
            }
        };
        Ok(SpurGearPair {
            module_m,
            teeth,
            pressure_angle_rad: angle,
        })
    }

    /// A radius: `"flat"` or a non-zero length.
    fn radius(&self, key: &str, text: &str) -> Result<f64, SceneError> {
        match text.trim() {
            "flat" | "inf" | "infinite" => Ok(f64::INFINITY),
            _ => {
                let r =
                    units::parse(text, Dimension::Length).map_err(|m| self.error(key, m, None))?;
                if !r.is_finite() || r == 0.0 {
                    return Err(self.error(
                        key,
                        format!("must be non-zero and finite, got `{text}`"),
                        Some("use \"flat\" for a plane"),
                    ));
                }
                Ok(r)
            }
        }
    }

    /// The principal radii of a body in the xz and yz planes (elliptical contact): `radius_x`
    /// and `radius_y`, each defaulting to `radius`.
    fn principal_radii(&self, key: &str, raw: &RawBody) -> Result<PrincipalRadii, SceneError> {
        let one = |name: &str, own: &Option<String>| {
            match (own, &raw.radius) {
            (Some(text), _) => self.radius(&format!("{key}.{name}"), text),
            (None, Some(text)) => self.radius(&format!("{key}.radius"), text),
            (None, None) => Err(self.error(&format!("{key}.{name}"), "missing radius", Some("give radius_x (in the xz plane, along the sliding direction) and radius_y (in the yz plane), or radius for both; \"flat\" for a plane, negative for a concave surface"))),
        }
        };
        Ok(PrincipalRadii {
            first_m: one("radius_x", &raw.radius_x)?,
            second_m: one("radius_y", &raw.radius_y)?,
        })
    }

    fn body(
        &self,
        key: &str,
        raw: &RawBody,
        radius_from_gears: bool,
        elliptical: bool,
    ) -> Result<Body, SceneError> {
        if !elliptical {
            if let Some(name) = [("radius_x", &raw.radius_x), ("radius_y", &raw.radius_y)]
                .iter()
                .find_map(|(n, v)| v.is_some().then_some(*n))
            {
                return Err(self.error(
                    &format!("{key}.{name}"),
                    "two principal radii make an elliptical contact",
                    Some("use kind = \"elliptical\", or give one radius"),
                ));
            }
        }
        let radius_m = match (&raw.radius, radius_from_gears || elliptical) {
            (_, true) if elliptical => f64::NAN,
            (Some(_), true) => {
                return Err(self.error(&format!("{key}.radius"), "the radius follows from [contact.gears]", Some("remove it, or remove [contact.gears]")))
            }
            (None, true) => f64::NAN,
            (None, false) => {
                return Err(self.error(&format!("{key}.radius"), "missing radius", Some("e.g. radius = \"20 mm\", radius = \"flat\", or a negative radius for a concave body")))
            }
            (Some(text), false) => self.radius(&format!("{key}.radius"), text)?,
        };
        let preset = match &raw.material {
            Some(name) => Some(material::preset(name).ok_or_else(|| {
                let names: Vec<_> = material::PRESETS.iter().map(|p| p.name).collect();
                self.error(
                    &format!("{key}.material"),
                    format!("unknown material `{name}`"),
                    Some(&format!(
                        "use one of: {}; or give modulus and poisson",
                        names.join(", ")
                    )),
                )
            })?),
            None => None,
        };
        let modulus_pa = match (&raw.modulus, preset) {
            (Some(text), _) => {
                self.positive(&format!("{key}.modulus"), text, Dimension::Pressure)?
            }
            (None, Some(p)) => p.material.modulus_pa,
            (None, None) => {
                return Err(self.error(
                    &format!("{key}.modulus"),
                    "missing elastic modulus",
                    Some("add modulus = \"210 GPa\" or material = \"steel\""),
                ))
            }
        };
        let poisson = match (raw.poisson, preset) {
            (Some(nu), _) => self.poisson(&format!("{key}.poisson"), nu)?,
            (None, Some(p)) => p.material.poisson,
            (None, None) => {
                return Err(self.error(
                    &format!("{key}.poisson"),
                    "missing Poisson's ratio",
                    Some("add poisson = 0.3 or material = \"steel\""),
                ))
            }
        };
        Ok(Body {
            radius_m,
            material: Material {
                modulus_pa,
                poisson,
            },
        })
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

    fn figure(&self, raw: &RawFigure, contact: &Contact) -> Result<FigureSpec, SceneError> {
        let quantity = match &raw.quantity {
            Some(key) => Quantity::from_key(key).ok_or_else(|| {
                let keys: Vec<_> = Quantity::ALL.iter().map(|q| q.key()).collect();
                self.error(
                    "figure.quantity",
                    format!("unknown quantity `{key}`"),
                    Some(&format!("use one of: {}", keys.join(", "))),
                )
            })?,
            None => Quantity::VonMises,
        };
        let dimensional = contact.scale.is_some();
        let length_unit = match &raw.length_unit {
            Some(key) => LengthUnit::from_key(key).ok_or_else(|| {
                self.error(
                    "figure.length_unit",
                    format!("unknown length unit `{key}`"),
                    Some("use \"a\", \"mm\", \"um\" or \"m\""),
                )
            })?,
            None if dimensional => LengthUnit::Millimetre,
            None => LengthUnit::HalfWidth,
        };
        let stress_unit = match &raw.stress_unit {
            Some(key) => StressUnit::from_key(key).ok_or_else(|| {
                self.error(
                    "figure.stress_unit",
                    format!("unknown stress unit `{key}`"),
                    Some("use \"p0\", \"MPa\", \"GPa\" or \"Pa\""),
                )
            })?,
            None if dimensional => StressUnit::MegaPascal,
            None => StressUnit::PeakPressure,
        };
        if !dimensional && length_unit != LengthUnit::HalfWidth {
            return Err(self.error(
                "figure.length_unit",
                "a normalised scene (no load or bodies) is drawn in units of a",
                Some("use length_unit = \"a\", or give contact.load and the bodies"),
            ));
        }
        if !dimensional && stress_unit != StressUnit::PeakPressure {
            return Err(self.error(
                "figure.stress_unit",
                "a normalised scene (no load or bodies) is drawn in units of p0",
                Some("use stress_unit = \"p0\", or give contact.load and the bodies"),
            ));
        }
        let section = match &raw.section {
            Some(key) => SectionKind::from_key(key).ok_or_else(|| {
                self.error(
                    "figure.section",
                    format!("unknown section `{key}`"),
                    Some("use \"xz\" (depth below the sliding direction), \"yz\" (depth across it) or \"xy\" (a plane at a depth, 0 for the surface)"),
                )
            })?,
            None => SectionKind::Xz,
        };
        if contact.kind == ContactKind::Line && section != SectionKind::Xz {
            return Err(self.error(
                "figure.section",
                format!(
                    "a line contact is plane strain: its {} sections only repeat the xz field",
                    section.key()
                ),
                Some("use section = \"xz\" (the default), or kind = \"point\""),
            ));
        }
        let (horizontal_name, vertical_name, normal_name) = section.coordinates();
        let ranges = [
            ("x", raw.x.as_ref()),
            ("y", raw.y.as_ref()),
            ("z", raw.z.as_ref()),
        ];
        for (name, range) in ranges {
            if range.is_some() && name == normal_name {
                return Err(self.error(
                    &format!("figure.{name}"),
                    format!("an {} section has no {name} range: {name} is fixed by figure.at", section.key()),
                    Some(&format!("give figure.{horizontal_name} and figure.{vertical_name}, and the section's {normal_name} as figure.at")),
                ));
            }
        }
        let range_of = |name: &str| {
            ranges
                .iter()
                .find(|(n, _)| *n == name)
                .and_then(|(_, range)| *range)
        };
        let a_in_unit = contact.half_width_m() / length_unit.metres(contact.half_width_m());
        let default_horizontal = match (contact.kind, section) {
            (ContactKind::Line, _) => 2.5,
            (ContactKind::Point | ContactKind::Tractions, _) => 2.0,
            // Twice the semi-axis along the horizontal axis (b = aspect a along y).
            (ContactKind::Elliptical, SectionKind::Yz) => 2.0 * contact.aspect,
            (ContactKind::Elliptical, _) => 2.0,
        };
        let horizontal = self.range(
            &format!("figure.{horizontal_name}"),
            range_of(horizontal_name),
            (
                -default_horizontal * a_in_unit,
                default_horizontal * a_in_unit,
            ),
        )?;
        let default_vertical = if section.vertical_is_depth() {
            (0.0, 2.0 * a_in_unit * contact.aspect.min(1.0))
        } else {
            let b = 2.0 * a_in_unit * contact.aspect;
            (-b, b)
        };
        let vertical = self.range(
            &format!("figure.{vertical_name}"),
            range_of(vertical_name),
            default_vertical,
        )?;
        if section.vertical_is_depth() && vertical.0 < 0.0 {
            return Err(self.error(
                "figure.z",
                format!(
                    "depth must be >= 0 (z points into the body), got {}",
                    vertical.0
                ),
                Some("start the range at 0 for the surface"),
            ));
        }
        let resolution = match raw.resolution {
            None => 801,
            Some(n) if (16..=20_000).contains(&n) => n as usize,
            Some(n) => {
                return Err(self.error(
                    "figure.resolution",
                    format!("must lie in 16..=20000 samples along x, got {n}"),
                    Some("600 to 1200 is plenty for a figure"),
                ))
            }
        };
        let levels = match (raw.contours, &raw.levels) {
            (Some(_), Some(_)) => {
                return Err(self.error(
                    "figure.levels",
                    "give either contours (a count) or levels (values), not both",
                    None,
                ))
            }
            (Some(n), None) if (0..=100).contains(&n) => Levels::Count(n as usize),
            (Some(n), None) => {
                return Err(self.error(
                    "figure.contours",
                    format!("must lie in 0..=100, got {n}"),
                    None,
                ))
            }
            (None, Some(values)) if values.iter().all(|v| v.is_finite()) => {
                Levels::Values(values.clone())
            }
            (None, Some(_)) => {
                return Err(self.error("figure.levels", "levels must be finite numbers", None))
            }
            (None, None) => Levels::Count(10),
        };
        let colormap = match &raw.colormap {
            Some(key) => ColorMap::from_key(key).ok_or_else(|| {
                let keys: Vec<_> = ColorMap::ALL.iter().map(|c| c.key()).collect();
                self.error(
                    "figure.colormap",
                    format!("unknown colour map `{key}`"),
                    Some(&format!("use one of: {}", keys.join(", "))),
                )
            })?,
            None => match quantity.kind() {
                QuantityKind::NonNegative => ColorMap::Viridis,
                QuantityKind::Signed => ColorMap::Diverging,
            },
        };
        let mark = match raw.mark.as_deref() {
            None | Some("auto") => None,
            Some("max") => Some(Mark::Max),
            Some("min") => Some(Mark::Min),
            Some("both") => Some(Mark::Both),
            Some("none") => Some(Mark::None),
            Some(other) => {
                return Err(self.error(
                    "figure.mark",
                    format!("unknown mark `{other}`"),
                    Some("use \"auto\", \"max\", \"min\", \"both\" or \"none\""),
                ))
            }
        };
        let width_px = match raw.width {
            None => 560,
            Some(w) if (200..=4000).contains(&w) => w as u32,
            Some(w) => {
                return Err(self.error(
                    "figure.width",
                    format!("panel width must lie in 200..=4000 px, got {w}"),
                    None,
                ))
            }
        };
        Ok(FigureSpec {
            quantity,
            section,
            horizontal,
            vertical,
            length_unit,
            stress_unit,
            resolution,
            levels,
            colormap,
            mark,
            width_px,
            svg: raw.svg.unwrap_or(false),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        assert!((scene.figure.horizontal.1 - 0.625).abs() < 1e-12);
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

    #[test]
    fn poisson_out_of_range_names_the_key() {
        let err = parse("format = 1\n[contact]\nkind = \"line\"\npoisson = 0.7\n").expect_err("nu");
        assert_eq!(err.key.as_deref(), Some("contact.poisson"));
        assert!(err.to_string().contains("(-1, 0.5]"), "{err}");
    }
}
