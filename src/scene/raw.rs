//! Serde structures mirroring `scenes/*.toml` one to one. Unknown keys are errors.

use serde::Deserialize;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawScene {
    pub format: i64,
    pub title: Option<String>,
    pub contact: RawContact,
    #[serde(default)]
    pub figure: RawFigure,
    pub numerical: Option<RawNumerical>,
    pub tractions: Option<RawTractions>,
    #[serde(default, rename = "panel")]
    pub panels: Vec<RawPanel>,
    pub sweep: Option<RawSweep>,
    pub volume: Option<RawVolume>,
    /// The roughness of body 1 (rough and surface scenes).
    pub surface: Option<RawSurface>,
    /// The roughness of body 2, added to body 1's (rough scenes).
    pub counter_surface: Option<RawSurface>,
    /// Frictional heating (line, point, elliptical and rough scenes).
    pub thermal: Option<RawThermal>,
    /// Archard wear of a rough scene's surface along the sliding distance.
    pub wear: Option<RawWear>,
    /// A rough scene's measured topographies at increasing sliding distances.
    #[serde(default)]
    pub series: Vec<RawSeriesEntry>,
    /// Body 1 elastic-plastic (issue 51): `stressfield plastic`.
    pub plasticity: Option<RawPlasticity>,
    /// The lubricant: film thickness and λ (line, point, elliptical and gear scenes).
    pub lubricant: Option<RawLubricant>,
}

/// `[plasticity]`: J2 plasticity of body 1 with linear hardening, the load steps and the
/// volume grid of the plastic strain.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPlasticity {
    pub yield_strength: Option<String>,
    /// The plastic modulus h of σY(εp) = Y + h εp.
    pub hardening_modulus: Option<String>,
    pub unload: Option<bool>,
    /// Load increments up to the load.
    pub steps: Option<i64>,
    /// Increments down to zero.
    pub unload_steps: Option<i64>,
    /// Cells along x and y of the volume grid.
    pub grid_cells: Option<i64>,
    /// Cell layers in depth.
    pub depth_cells: Option<i64>,
    /// The grid's half-width over the Hertz contact radius.
    pub extent_over_a: Option<f64>,
    /// The grid's depth over the Hertz contact radius.
    pub depth_over_a: Option<f64>,
    /// Relative tolerance of the fixed point in each step.
    pub tolerance: Option<f64>,
}

/// `[lubricant]`: the oil, how fast the surfaces entrain it, and their roughness.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLubricant {
    /// Dynamic viscosity at the inlet temperature, e.g. "0.05 Pa s".
    pub viscosity: Option<String>,
    /// An ISO viscosity grade, "ISO VG 220" or 220: the kinematic viscosity at 40 °C.
    pub grade: Option<NumberOrText>,
    /// Kinematic viscosities at 40 °C and 100 °C, e.g. "220 mm^2/s" (Walther, ASTM D341).
    pub viscosity_40c: Option<String>,
    pub viscosity_100c: Option<String>,
    /// The inlet (oil) temperature, e.g. "70 C".
    pub temperature: Option<String>,
    /// The oil's density at the inlet temperature, e.g. "870 kg/m^3".
    pub density: Option<String>,
    /// The pressure-viscosity coefficient α, e.g. "20 GPa^-1".
    pub pressure_viscosity: Option<String>,
    /// Roelands' pressure-viscosity index Z.
    pub roelands_z: Option<f64>,
    /// The numerical solution's viscosity law: "roelands" (default) or "barus".
    pub pressure_viscosity_law: Option<String>,
    /// The numerical solution's density: "dowson_higginson" (default) or "constant".
    pub compressibility: Option<String>,
    /// The mean entrainment speed u = (u1 + u2)/2, e.g. "2 m/s".
    pub entrainment_speed: Option<String>,
    /// Spur gears: the pinion's speed, when [thermal] does not give it.
    pub pinion_speed: Option<String>,
    /// The composite rms roughness, or the two surfaces' rms roughness.
    pub roughness: Option<TextOrList>,
}

/// `[wear]`: Archard's law stepped over the sliding distance.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawWear {
    /// Dimensional wear coefficient, e.g. "2e-6 mm^3/(N m)".
    pub coefficient: Option<String>,
    /// Total sliding distance, e.g. "20 m".
    pub distance: Option<String>,
    pub steps: Option<i64>,
}

/// `[[series]]`: one measured topography and the sliding distance it was measured at.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSeriesEntry {
    pub file: Option<String>,
    pub distance: Option<String>,
}

/// `[thermal]`: sliding speed, the bodies' speeds, the heat partition.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawThermal {
    pub speed: Option<String>,
    /// Spur gears: the pinion's rotational speed (the speeds follow along the path of contact)
    /// and the mesh's friction coefficient when it differs from `contact.friction`.
    pub pinion_speed: Option<String>,
    pub friction: Option<f64>,
    pub body1_speed: Option<String>,
    pub body2_speed: Option<String>,
    /// "body1", "blok", or body 1's fraction.
    pub partition: Option<NumberOrText>,
    pub coupled: Option<bool>,
}

/// `[surface]`: a height map read from a file or generated.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSurface {
    /// ASCII matrix, XYZ or x3p file, relative to the scene file.
    pub file: Option<String>,
    /// Sample spacing: one length, or [dx, dy].
    pub spacing: Option<TextOrList>,
    /// Unit of the heights (ASCII, XYZ): "m", "mm", "um", "nm".
    pub height_unit: Option<String>,
    /// Unit of x and y of an XYZ file.
    pub length_unit: Option<String>,
    /// Missing points: "refuse" (default) or "interpolate".
    pub fill: Option<String>,
    /// Form removed before the statistics: "plane" (default) or "quadratic".
    pub form: Option<String>,
    /// What is removed from a measured map before a rough contact is solved: "plane",
    /// "quadratic", "mean" or "none" (default: as `form` for an isolated contact, "mean" for a
    /// periodic one).
    pub level: Option<String>,
    /// A series: how its maps share one datum: "first" (the first map's fitted form removed
    /// from every map, the default) or "each" (each map its own).
    pub datum: Option<String>,
    /// A series: the region each map's form is fitted on (a part that does not wear):
    /// ["x from", "x to", "y from", "y to"], lengths from the map's first sample.
    pub datum_region: Option<Vec<String>>,
    /// Wavelength band of the Hurst fit: ["4 um", "100 um"].
    pub band: Option<Vec<String>>,
    pub generate: Option<RawGenerate>,
}

/// `[surface.generate]`: a Gaussian random surface.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawGenerate {
    /// Samples along x and y: one count, or [nx, ny].
    pub samples: Option<CountOrList>,
    pub spacing: Option<TextOrList>,
    pub hurst: Option<f64>,
    pub rolloff: Option<String>,
    pub cutoff: Option<String>,
    pub correlation_length: Option<String>,
    pub rms_height: Option<String>,
    pub rms_slope: Option<f64>,
    pub seed: Option<i64>,
    pub sphere_radius: Option<String>,
    pub cylinder_radius: Option<String>,
}

/// One text, or a list of texts.
#[derive(Debug, Clone)]
pub enum TextOrList {
    Text(String),
    List(Vec<String>),
}

/// One count, or a list of counts.
#[derive(Debug, Clone)]
pub enum CountOrList {
    Count(i64),
    List(Vec<i64>),
}

/// `[sweep]`: one time point of a recording per value.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSweep {
    /// "friction", "load" or "position".
    pub parameter: String,
    pub values: Option<Vec<NumberOrText>>,
    pub from: Option<f64>,
    pub to: Option<f64>,
    pub steps: Option<i64>,
    /// `[[x, z], ...]` in the figure's length unit (position sweeps).
    pub material_points: Option<Vec<Vec<f64>>>,
}

/// `[volume]`: a box under a point contact, recorded as nested iso-surfaces.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawVolume {
    pub quantity: Option<String>,
    pub x: Option<Vec<f64>>,
    pub y: Option<Vec<f64>>,
    pub z: Option<Vec<f64>>,
    pub points: Option<i64>,
    pub threshold: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawContact {
    pub kind: String,
    /// "closed_form" (default), "numerical" or "difference".
    pub method: Option<String>,
    pub friction: Option<f64>,
    /// Poisson ratio of the body whose field is drawn, for normalised scenes.
    pub poisson: Option<f64>,
    /// Contact half-width and peak pressure, given directly instead of load and bodies.
    pub a: Option<NumberOrText>,
    pub p0: Option<NumberOrText>,
    pub load: Option<String>,
    pub body1: Option<RawBody>,
    pub body2: Option<RawBody>,
    pub gears: Option<RawGears>,
    pub yield_strength: Option<String>,
    pub hardness: Option<String>,
    /// Elliptical contact given normalised: semi-axis along y over that along x.
    pub aspect: Option<f64>,
    /// Partial slip of a sphere: the tangential force as a fraction of mu P.
    pub tangential: Option<f64>,
    /// Rough contact: the load over the nominal area, or the rigid approach, instead of load.
    pub mean_pressure: Option<String>,
    pub approach: Option<String>,
    /// Rough contact: the surface is periodic.
    pub periodic: Option<bool>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBody {
    pub radius: Option<String>,
    /// Principal radii in the xz and yz planes (elliptical contact).
    pub radius_x: Option<String>,
    pub radius_y: Option<String>,
    pub material: Option<String>,
    pub modulus: Option<String>,
    pub poisson: Option<f64>,
    /// Thermal properties (scenes with `[thermal]`).
    pub conductivity: Option<String>,
    pub diffusivity: Option<String>,
    pub density: Option<String>,
    pub specific_heat: Option<String>,
    pub expansion: Option<String>,
    /// A layer bonded to the body (`[contact.body1.coating]`).
    pub coating: Option<RawCoating>,
    /// Several layers (`[[contact.body1.layers]]`, top first).
    pub layers: Option<Vec<RawLayer>>,
    /// The substrate's yield strength under `[[contact.body1.layers]]`.
    pub yield_strength: Option<String>,
}

/// `[[contact.body1.layers]]`: one layer of a stack, top first, with its optional strengths
/// (`adhesion_strength`: of the interface under the layer).
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLayer {
    pub thickness: Option<String>,
    pub material: Option<String>,
    pub modulus: Option<String>,
    pub poisson: Option<f64>,
    pub tensile_strength: Option<String>,
    pub yield_strength: Option<String>,
    pub adhesion_strength: Option<String>,
}

/// `[contact.body1.coating]`: the layer's thickness and elastic constants.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCoating {
    pub thickness: Option<String>,
    pub material: Option<String>,
    pub modulus: Option<String>,
    pub poisson: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawGears {
    pub module: String,
    pub teeth: Vec<i64>,
    pub pressure_angle: String,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFigure {
    pub quantity: Option<String>,
    /// "xz" (default), "yz" or "xy".
    pub section: Option<String>,
    /// Position of the section along its normal (y, x or depth z), in `length_unit`.
    pub at: Option<f64>,
    pub x: Option<Vec<f64>>,
    pub y: Option<Vec<f64>>,
    pub z: Option<Vec<f64>>,
    pub length_unit: Option<String>,
    pub stress_unit: Option<String>,
    pub resolution: Option<i64>,
    pub contours: Option<i64>,
    pub levels: Option<Vec<f64>>,
    pub colormap: Option<String>,
    pub mark: Option<String>,
    pub width: Option<i64>,
    pub svg: Option<bool>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPanel {
    pub method: Option<String>,
    /// "xz", "yz" or "xy": this panel's section plane (default: the figure's).
    pub section: Option<String>,
    pub at: Option<f64>,
    pub friction: Option<f64>,
    pub poisson: Option<f64>,
    pub subtitle: Option<String>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawNumerical {
    /// Cells per side of the square traction grid (point contact) or strips (line contact).
    pub cells: Option<i64>,
    /// Half-size of the traction grid in semi-axes (point and elliptical contacts).
    pub extent: Option<f64>,
    /// Rough contact: relative tolerance and iteration cap of the solver.
    pub tolerance: Option<f64>,
    pub max_iterations: Option<i64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawTractions {
    /// CSV file of `x,y,p[,qx][,qy]` rows, relative to the scene file.
    pub file: String,
    /// Unit of x and y: "a" (default), "m", "mm", "um".
    pub length_unit: Option<String>,
    /// Unit of p, qx, qy: "p0" (default), "Pa", "MPa", "GPa".
    pub stress_unit: Option<String>,
}

/// A value written either as a bare number or as a string with a unit.
#[derive(Debug, Clone)]
pub enum NumberOrText {
    Number(f64),
    Text(String),
}

// The three either-or values are read by hand rather than as untagged enums, so that a value
// of the wrong kind is refused in the user's words ("expected a number, or a text with its
// unit") instead of "data did not match any variant of untagged enum NumberOrText" (issue 42,
// class 10). `toml::from_str` reads them through `deserialize_any`.

impl<'de> Deserialize<'de> for NumberOrText {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor;
        impl serde::de::Visitor<'_> for Visitor {
            type Value = NumberOrText;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a number, or a text with its unit such as \"2 mm\"")
            }
            fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<Self::Value, E> {
                Ok(NumberOrText::Number(v))
            }
            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<Self::Value, E> {
                Ok(NumberOrText::Number(v as f64))
            }
            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<Self::Value, E> {
                Ok(NumberOrText::Number(v as f64))
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<Self::Value, E> {
                Ok(NumberOrText::Text(v.to_string()))
            }
        }
        deserializer.deserialize_any(Visitor)
    }
}

impl<'de> Deserialize<'de> for TextOrList {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor;
        impl<'de> serde::de::Visitor<'de> for Visitor {
            type Value = TextOrList;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a text with its unit such as \"1 um\", or a list of two such as [\"1 um\", \"2 um\"]")
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<Self::Value, E> {
                Ok(TextOrList::Text(v.to_string()))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<Self::Value, A::Error> {
                let mut list = Vec::new();
                while let Some(text) = seq.next_element::<String>()? {
                    list.push(text);
                }
                Ok(TextOrList::List(list))
            }
        }
        deserializer.deserialize_any(Visitor)
    }
}

impl<'de> Deserialize<'de> for CountOrList {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor;
        impl<'de> serde::de::Visitor<'de> for Visitor {
            type Value = CountOrList;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a whole number such as 256, or a list of two such as [256, 128]")
            }
            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<Self::Value, E> {
                Ok(CountOrList::Count(v))
            }
            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<Self::Value, E> {
                i64::try_from(v)
                    .map(CountOrList::Count)
                    .map_err(|_| E::invalid_value(serde::de::Unexpected::Unsigned(v), &self))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<Self::Value, A::Error> {
                let mut list = Vec::new();
                while let Some(count) = seq.next_element::<i64>()? {
                    list.push(count);
                }
                Ok(CountOrList::List(list))
            }
        }
        deserializer.deserialize_any(Visitor)
    }
}
