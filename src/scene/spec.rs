//! The typed scene: plain data in SI units, as validated from `scenes/*.toml` (the contact,
//! the figure and its panels, the numerical grid, display units).

use std::sync::Arc;

use crate::contact::elliptic::EllipticalContact;
use crate::contact::gear::SpurGearPair;
use crate::contact::material::Material;
use crate::contact::rough::Control;
use crate::contact::{Body, LineContact, PointContact};
use crate::render::{ColorMap, Levels, Mark};
use crate::stress::Quantity;
use crate::surface::stats::{Datum, FormRemoval};
use crate::surface::HeightMap;

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
    /// A rough surface (`[surface]`) pressed on a flat or a second rough surface: the pressure
    /// is solved for (conjugate gradients), then the stresses under it drawn.
    Rough,
    /// A rough surface characterised: topography, statistics, spectra, Greenwood–Williamson.
    Surface,
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
    /// The scale of that number as the scene wrote it (`HV`, `HB`, `HBW`, `BHN`), for reports.
    pub hardness_scale: &'static str,
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

/// One body's share in frictional heating.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThermalBody {
    pub properties: crate::thermal::material::ThermalProperties,
    /// Elastic constants, for the thermal stress.
    pub material: crate::contact::material::Material,
    /// The speed of the contact over this body's surface, m/s (0: the body carries the
    /// contact with it, a pin).
    pub speed_m_per_s: f64,
}

/// Which way friction acts on body 1 in a heated scene: in the direction in which body 2's
/// surface slides over body 1's.
///
/// In the frame of the contact both surfaces move in -x (the contact moves over body `i` at
/// `Vi` in +x), so body 2 slides over body 1 at `V1 - V2` in +x: friction on body 1 acts in
/// +x when body 1's surface is the faster (`V1 > V2`, the usual case of a contact carried by
/// body 2 over body 1) and in -x when body 2's is (a pin on a disc, the approach side of a
/// gear mesh). The isothermal figures of a scene keep `q = μ p` in +x; the heating study
/// (thermal plus contact stress) takes this direction, and its reports say which.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TractionDirection {
    /// `q = μ p` on body 1 in +x (`V1 >= V2`).
    PlusX,
    /// `q = μ p` on body 1 in -x (`V2 > V1`: body 2's surface is the faster).
    MinusX,
}

impl TractionDirection {
    /// The direction for the speeds `V1`, `V2` of the contact over the bodies.
    pub fn of_speeds(body1_m_per_s: f64, body2_m_per_s: f64) -> Self {
        if body2_m_per_s > body1_m_per_s {
            Self::MinusX
        } else {
            Self::PlusX
        }
    }

    /// +1 or -1: the sign of the traction along x.
    pub fn sign(self) -> f64 {
        match self {
            Self::PlusX => 1.0,
            Self::MinusX => -1.0,
        }
    }

    /// `+x` or `-x`, for reports.
    pub fn label(self) -> &'static str {
        match self {
            Self::PlusX => "+x",
            Self::MinusX => "-x",
        }
    }
}

/// `[thermal]`: frictional heating of a sliding contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThermalSpec {
    /// The sliding speed `V = |V1 - V2|`: the frictional flux is `μ p V`.
    pub sliding_speed_m_per_s: f64,
    /// The direction of the friction traction on body 1 (from the bodies' speeds).
    pub traction: TractionDirection,
    /// The scene keys that set the speed of the contact over body 1 and over body 2 (e.g.
    /// `thermal.speed`, `thermal.body2_speed`, `thermal.pinion_speed`): a speed beyond what
    /// the heating can resolve is refused under the key the scene wrote.
    pub speed_keys: [&'static str; 2],
    pub partition: crate::thermal::heating::Partition,
    pub coupled: bool,
    pub body1: ThermalBody,
    /// Body 2, when its properties are known (required unless all heat enters body 1).
    pub body2: Option<ThermalBody>,
    /// Spur gears (`[contact.gears]`): the heating along the path of contact. The speeds
    /// above are then those at the pitch point (no sliding).
    pub gear: Option<GearMesh>,
}

/// The running gears of a scene with `[contact.gears]` and `[thermal]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GearMesh {
    /// The pinion's (body 1's) angular speed, rad/s.
    pub pinion_rad_per_s: f64,
    /// The friction coefficient of the mesh along the path of contact.
    pub friction: f64,
}

/// `[lubricant]`: the oil, its entrainment and the surfaces' roughness (film thickness, λ and
/// the numerical EHL solution of a line contact).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LubricantSpec {
    /// Dynamic viscosity at the inlet temperature and ambient pressure, Pa s.
    pub viscosity_pa_s: f64,
    /// The oil's kinematic viscosities and temperature, when the viscosity follows from them.
    pub oil: Option<OilSpec>,
    /// The pressure-viscosity coefficient α (the slope of `ln η` at zero pressure), 1/Pa: the
    /// film formulas'.
    pub alpha_per_pa: f64,
    /// The numerical solution's pressure-viscosity law (Roelands by default).
    pub pressure_viscosity: crate::lubrication::viscosity::PressureViscosity,
    /// The numerical solution's density law (Dowson–Higginson by default).
    pub compressibility: crate::lubrication::density::Compressibility,
    /// The mean entrainment speed `u = (u1 + u2)/2`, m/s (gears: at the pitch point).
    pub entrainment_m_per_s: f64,
    /// Where the entrainment speed comes from, for reports (`lubricant.entrainment_speed`,
    /// the bodies' speeds of `[thermal]`, the pinion's speed).
    pub entrainment_source: &'static str,
    /// Spur gears: the pinion's speed, rad/s (the film along the path of contact).
    pub pinion_rad_per_s: Option<f64>,
    /// The composite rms roughness `√(σ1² + σ2²)`, m, when given.
    pub roughness_m: Option<f64>,
}

/// An oil given by its kinematic viscosities (Walther, ASTM D341) at a temperature.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OilSpec {
    /// The ISO VG grade, when the scene names one.
    pub grade: Option<u32>,
    pub kinematic_40c_m2_per_s: f64,
    pub kinematic_100c_m2_per_s: f64,
    pub temperature_k: f64,
    pub density_kg_per_m3: f64,
    /// The kinematic viscosity at the temperature.
    pub kinematic_m2_per_s: f64,
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
    /// Rough and surface scenes: control, materials and solver settings.
    pub rough: Option<RoughSpec>,
    /// A layer bonded to body 1 (`[contact.body1.coating]`).
    pub coating: Option<CoatingSpec>,
}

/// A coating on body 1: the layer, the body under it (the substrate) and the counter-body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoatingSpec {
    pub thickness_m: f64,
    /// The layer's elastic constants.
    pub material: Material,
    /// Body 1's own material, under the layer.
    pub substrate: Material,
    /// The counter-body's `(1 - ν²)/E`, Pa⁻¹: 0 when it is rigid.
    pub counter_per_pa: f64,
    /// Whether the counter-body is rigid (`material = "rigid"`).
    pub counter_rigid: bool,
    /// The layers under the top one (`[[contact.body1.layers]]` after the first).
    pub under: crate::coating::Interlayers,
    /// Whether the scene gave its layers as `[[contact.body1.layers]]` (its report lists
    /// them) rather than `[contact.body1.coating]`.
    pub stacked: bool,
    /// The strengths given with the layers.
    pub strengths: Strengths,
}

/// The strengths of a stack's materials (`[[contact.body1.layers]]` and
/// `contact.body1.yield_strength`), Pa; `None` where not given.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Strengths {
    /// Per layer, top first: `[yield, tensile, adhesion of the interface under it]`.
    pub layers: [[Option<f64>; 3]; crate::coating::MAX_LAYERS],
    pub substrate_yield_pa: Option<f64>,
}

impl Strengths {
    /// Whether any strength is given.
    pub fn any(&self) -> bool {
        self.substrate_yield_pa.is_some() || self.layers.iter().flatten().any(Option::is_some)
    }
}

impl CoatingSpec {
    /// The layered half-space of body 1.
    pub fn layered(&self) -> crate::coating::Layered {
        crate::coating::Layered {
            coating: self.material,
            substrate: self.substrate,
            thickness_m: self.thickness_m,
            under: self.under,
        }
    }
}

/// The contact of a rough or surface scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughSpec {
    /// Load, mean pressure or approach (rough scenes; `None` for a surface scene).
    pub control: Option<Control>,
    pub periodic: bool,
    /// Combined modulus of the two bodies (a rigid body adds nothing), when bodies are given.
    pub e_star_pa: Option<f64>,
    /// Indentation hardness of the rough surface (Pa): the pressure cap, and the plasticity
    /// index. From `hardness` (HB/HV number times 9.80665 MPa) or `yield_strength` (3 Y).
    pub hardness_pa: Option<f64>,
    pub tolerance: f64,
    pub max_iterations: usize,
}

/// How a rough scene's surface evolves with sliding distance.
#[derive(Clone, Debug, PartialEq)]
pub enum WearSpec {
    /// `[wear]`: Archard's law on body 1's surface, stepped uniformly (a rough body 2 slides
    /// over it without wearing).
    Archard {
        /// `k`, m²/N.
        coefficient_m2_per_n: f64,
        /// Total sliding distance, m.
        distance_m: f64,
        steps: usize,
    },
    /// `[[series]]`: measured topographies; the scene's `[surface]` is the first of them.
    Series(Vec<SeriesEntry>),
}

/// One measured topography of a series.
#[derive(Clone, Debug, PartialEq)]
pub struct SeriesEntry {
    pub distance_m: f64,
    /// The file as the scene names it.
    pub source: String,
    /// The worn body's heights (body 1's), as read. A rough counter-surface slides over them:
    /// the contact sees them plus the counter shifted by the distance ([`crate::wear::slid`]).
    pub heights: Arc<HeightMap>,
}

/// The height map of a rough or surface scene.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceSpec {
    /// The heights acting on the contact: body 1's, plus body 2's when it is rough.
    pub heights: Arc<HeightMap>,
    /// Body 1's heights alone.
    pub body1: Arc<HeightMap>,
    /// Body 2's, when rough.
    pub counter: Option<Arc<HeightMap>>,
    /// Where the heights come from, e.g. "worn.asc" or "generated (self-affine, H = 0.8, seed 1)".
    pub source: String,
    /// Generated (periodic by construction): spectra need no window.
    pub generated: bool,
    /// The form a generated surface was superposed on (a ball or a cylinder), else `None`.
    pub shape: crate::surface::generate::Form,
    /// What the statistics remove besides the mean plane (default: nothing, or a quadratic
    /// for a generated ball or cylinder).
    pub form: FormRemoval,
    /// The Hurst fit's band of wavelengths (m).
    pub band_m: Option<(f64, f64)>,
    /// How a measured map of a rough scene was levelled before its contact is solved; `None`
    /// for a generated map (nothing to level) and for a surface scene (its statistics level
    /// their own copy).
    pub levelling: Option<Levelling>,
    /// A measured series' datum (`None` unless the scene is a levelled series).
    pub series_datum: Option<SeriesDatum>,
}

/// How a measured height map is levelled before its contact is solved (`[surface] level`).
/// A measured map's tilt is the instrument's mounting, not the contact's geometry: instrument
/// software (Gwyddion's plane levelling, ISO 25178-2's F-operator) removes it before anything
/// else, and so does an isolated contact solve unless told otherwise. A periodic map is
/// different: it is one period of a surface that repeats, and a plane is not periodic (it
/// puts a step at the seam and tilts every period), so a periodic solve removes only the
/// mean height unless a plane is asked for (issue 50).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Levelling {
    /// `level = "none"`: the heights as measured, deliberately.
    Raw,
    /// Only the mean height `mean_m` removed (the default of a periodic contact, or
    /// `level = "mean"`); `plane` is body 1's least-squares plane, kept (as in
    /// [`Levelling::Removed`]).
    Mean { mean_m: f64, plane: [f64; 3] },
    /// The least-squares form of body 1's map removed from it (and likewise a measured
    /// counter-surface's from that, and from every map of a series by the series' datum,
    /// [`SeriesDatum`]); its `plane_m` is body 1's least-squares plane `c0 + c1 x + c2 y` (m,
    /// and m/m for the slopes, x and y from the map's first sample; a series: fitted where its
    /// datum says).
    Removed(Datum),
}

/// How the maps of a measured series share one datum (`[surface] datum`, `datum_region`): a
/// series is one specimen measured again, so the wear between two maps is their difference,
/// and a levelling of its own per map would tilt the worn region differently in each
/// (issue 50).
#[derive(Clone, Debug, PartialEq)]
pub enum SeriesDatum {
    /// The first map's fitted form removed from every map (the default).
    First,
    /// Each map its own fitted form (`datum = "each"`: each map mounted anew and its tilt
    /// not the specimen's).
    Each,
    /// Each map's form fitted on the samples of a region that does not wear (`datum_region`,
    /// x and y ranges from the map's first sample, m), then removed from the whole map.
    Region { x_m: [f64; 2], y_m: [f64; 2] },
}

impl Levelling {
    /// The map's least-squares plane `[c0, c1, c2]` (m, m/m, m/m), removed or kept; `None`
    /// for heights solved as measured.
    pub fn plane_m(&self) -> Option<[f64; 3]> {
        match self {
            Levelling::Raw => None,
            Levelling::Mean { plane, .. } => Some(*plane),
            Levelling::Removed(datum) => Some(datum.plane_m),
        }
    }

    /// The JSON name of what was removed: "plane", "quadratic", "mean" or "none".
    pub fn removed(&self) -> &'static str {
        match self {
            Levelling::Raw => "none",
            Levelling::Mean { .. } => "mean",
            Levelling::Removed(datum) => match datum.form() {
                FormRemoval::Plane => "plane",
                FormRemoval::Quadratic => "quadratic",
            },
        }
    }
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
    /// Whether the contact has a closed-form solution (not an elliptical contact, partial
    /// slip, or tractions from a file).
    pub fn has_closed_form(&self) -> bool {
        match self.kind {
            ContactKind::Line => true,
            ContactKind::Point => self.tangential.is_none(),
            ContactKind::Elliptical
            | ContactKind::Tractions
            | ContactKind::Rough
            | ContactKind::Surface => false,
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
    pub(crate) fn from_key(key: &str) -> Option<Self> {
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

pub use super::display::{LengthUnit, StressUnit};

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
    pub(crate) fn from_key(key: &str) -> Option<Self> {
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
    /// The section of the panels that do not choose their own (`[[panel]] section`).
    pub section: SectionKind,
    /// Ranges along x, y and the depth z (given or defaulted), in `length_unit`: each panel's
    /// section draws the two in its plane ([`FigureSpec::ranges`]).
    pub x: (f64, f64),
    pub y: (f64, f64),
    pub z: (f64, f64),
    /// Whether the scene gave the depth range (`[figure] z`): a rough scene's section
    /// otherwise takes its depth from the solved contact.
    pub depth_given: bool,
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

impl FigureSpec {
    /// The horizontal and vertical ranges of a `section` of this figure (x and z, y and z, or
    /// x and y), in `length_unit`.
    pub fn ranges(&self, section: SectionKind) -> ((f64, f64), (f64, f64)) {
        match section {
            SectionKind::Xz => (self.x, self.z),
            SectionKind::Yz => (self.y, self.z),
            SectionKind::Xy => (self.x, self.y),
        }
    }
}

/// A rough scene's xz section shows at least this many of its map's cells along x (or the
/// whole row, if shorter).
pub const ROUGH_SECTION_MIN_CELLS: usize = 8;

/// A rough scene's xz section is drawn at least this fraction of its width deep (at equal
/// scale): a quarter, so that the sheet's 840 px wide section is at least 210 px tall, room
/// for its colour bar's ticks and caption. A shallower depth range narrows the section.
pub const ROUGH_SECTION_MIN_DEPTH_OVER_WIDTH: f64 = 0.25;

/// A rough scene's `[figure] z` reaches at most this many times the map's width in depth.
pub const ROUGH_SECTION_MAX_DEPTH_OVER_WIDTH: f64 = 10.0;

/// One panel: the contact with its own friction and Poisson ratio, cut in its own plane at its
/// own position.
#[derive(Clone, Debug, PartialEq)]
pub struct PanelSpec {
    pub method: Method,
    pub friction: f64,
    pub poisson: f64,
    /// The plane the panel cuts: its own (`[[panel]] section`) or the figure's. Panels of one
    /// figure may cut different planes (an xz and a yz section side by side), on one colour
    /// scale, each with its own axes.
    pub section: SectionKind,
    /// Position of the section along its normal (y for xz, x for yz, depth z for xy), in the
    /// figure's `length_unit`.
    pub at: f64,
    pub subtitle: Option<String>,
}

/// `[plasticity]`: body 1 elastic-plastic (J2, linear isotropic hardening), loaded to the
/// scene's load in `steps` increments and, with `unload`, unloaded in `unload_steps`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlasticitySpec {
    pub yield_strength_pa: f64,
    /// The plastic modulus `h` of `σY(εp) = Y + h εp` (0: perfectly plastic).
    pub hardening_modulus_pa: f64,
    pub unload: bool,
    pub steps: usize,
    pub unload_steps: usize,
    /// Cells along x and along y of the volume grid (and of the contact's grid).
    pub grid_cells: usize,
    /// Uniform cell layers in depth.
    pub depth_cells: usize,
    /// The grid's half-width over the Hertz contact radius `a`.
    pub extent_over_a: f64,
    /// The grid's depth over `a`.
    pub depth_over_a: f64,
    pub tolerance: f64,
    /// Body 1's elastic constants (the elastic-plastic body).
    pub body1: Material,
    /// Whether body 2 is rigid (`material = "rigid"`).
    pub counter_rigid: bool,
}
