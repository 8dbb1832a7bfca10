//! Command-line arguments (clap), then validation into typed values.

use std::path::PathBuf;

use clap::{Parser, Subcommand, ValueEnum};

/// The address of a Rerun viewer on this machine (its default port), for `record --connect`.
pub const DEFAULT_VIEWER_URL: &str = "rerun+http://127.0.0.1:9876/proxy";

/// Elastic stress fields under Hertzian contacts: exact closed forms, parallel grids, figures.
#[derive(Debug, Parser)]
#[command(name = "stressfield", version, about, long_about = None)]
pub struct Args {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Render scenes to PNG (and SVG): every scene in scenes/ when none is named, and then
    /// the recording scenes (with a [sweep] or a [volume]) are recorded to out/<scene>.rrd
    /// instead; a named recording scene is drawn (`stressfield record` records it). A scene's
    /// outputs are written all or none.
    Render(RenderArgs),
    /// Record scenes to Rerun .rrd files (out/<scene>.rrd), or stream them to a Rerun viewer
    /// step by step as they are computed: every scene in scenes/ when none is named. Open them
    /// with the Rerun viewer 0.36 (pip install "rerun-sdk==0.36.*"; docs/recordings.md).
    Record {
        /// Scene files (TOML). Default: every *.toml in --scenes-dir.
        scenes: Vec<PathBuf>,
        /// The recording's file, for a single scene (default: <out-dir>/<scene>.rrd); `-`
        /// writes it to standard output, e.g. `stressfield record SCENE -o - | rerun -`.
        #[arg(short = 'o', long, value_name = "FILE.rrd|-")]
        output: Option<PathBuf>,
        /// Start a Rerun viewer (`rerun` on the PATH) and stream the recording to it.
        #[arg(long, conflicts_with_all = ["output", "connect"])]
        spawn: bool,
        /// Stream the recording to a running Rerun viewer, by default the viewer's local
        /// address rerun+http://127.0.0.1:9876/proxy. Put the URL right after the flag, or the
        /// scenes first.
        #[arg(long, value_name = "URL", num_args = 0..=1, default_missing_value = DEFAULT_VIEWER_URL, conflicts_with = "output")]
        connect: Option<String>,
        /// Directory for the recordings.
        #[arg(long, default_value = "out")]
        out_dir: PathBuf,
        /// Directory searched when no scene is named.
        #[arg(long, default_value = "scenes")]
        scenes_dir: PathBuf,
    },
    /// Print the Hertz contact parameters and the yield assessment of a scene.
    Hertz {
        scene: PathBuf,
        /// Print one JSON object (SI units) instead of the table (a rough scene: that of
        /// `contact --json`; a surface scene: that of `surface --json`).
        #[arg(long)]
        json: bool,
    },
    /// Tabulate a scene's [sweep]: one row per step with the swept value and the values its
    /// recording charts (the extremes of each panel and the depth of the maximum; a rough
    /// load sweep's area, spots and peak pressure; a speed sweep's temperatures).
    Sweep {
        scene: PathBuf,
        /// Print one JSON object (units per column, one object per step).
        #[arg(long, conflicts_with = "csv")]
        json: bool,
        /// Print CSV: a header, then one line per step.
        #[arg(long)]
        csv: bool,
    },
    /// Validate scenes without computing anything.
    Check {
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
    },
    /// Print stresses at points read as CSV rows x,y,z (units of a) as CSV (units of p0).
    Probe(ProbeArgs),
    /// Solve a rough contact scene (kind = "rough") and report it: real area, spots, pressures,
    /// approach, gap, the subsurface maxima.
    Contact {
        scene: PathBuf,
        /// Print one JSON object (SI units) instead of the table.
        #[arg(long)]
        json: bool,
        /// Also write the pressure field (Pa, float64, [rows, columns] of the height matrix,
        /// row = y) as a NumPy .npy file.
        #[arg(long, value_name = "FILE.npy")]
        pressure: Option<PathBuf>,
    },
    /// Characterise a rough surface: a height file (ASCII matrix, XYZ, x3p) or a surface/rough
    /// scene. Prints ISO 25178 parameters, spectra, summits and the Greenwood-Williamson values.
    Surface(SurfaceArgs),
    /// Frictional heating of a scene with a [thermal] table: Peclet number, heat partition,
    /// flash temperatures of the bodies, the thermal and total (thermal + contact) stress
    /// maxima of body 1.
    Thermal {
        scene: PathBuf,
        /// Print one JSON object (SI units) instead of the table.
        #[arg(long)]
        json: bool,
        /// Also write body 1's surface temperature rise (K, float64, [rows, columns] of the
        /// thermal grid, row = y) as a NumPy .npy file.
        #[arg(long, value_name = "FILE.npy")]
        temperature: Option<PathBuf>,
        /// Also draw the heating sheet (surface temperature, sections of the temperature and of
        /// the thermal and total von Mises stress, flash temperature against speed) as a PNG
        /// (or SVG, by the extension).
        #[arg(long, value_name = "FILE.png")]
        figure: Option<PathBuf>,
    },
    /// Solve a lubricated line contact (a line or spur-gear scene with [lubricant])
    /// numerically: the elastohydrodynamic pressure and film (Reynolds' equation, the elastic
    /// deflection, the load; Roelands or Barus viscosity), the minimum and central film, the
    /// pressure spike, and the von Mises stress under the pressure beside the dry Hertz one.
    Ehl {
        scene: PathBuf,
        /// Print one JSON object (SI units) instead of the table.
        #[arg(long)]
        json: bool,
        /// Also write the solution as a NumPy .npy file: float64, shape (n, 3), columns x (m),
        /// pressure (Pa), film (m); the entrainment in +x (inlet at -x, outlet at +x).
        #[arg(long, value_name = "FILE.npy")]
        pressure: Option<PathBuf>,
    },
    /// The evolution of a rough contact with sliding distance (a scene with [wear] or
    /// [[series]]): per step the real and plastic area, spots, pressures, worn volume and
    /// depth, the subsurface maxima and, with [thermal], the flash temperature.
    Wear {
        scene: PathBuf,
        /// Print one JSON object (SI units) instead of the table.
        #[arg(long)]
        json: bool,
        /// Also write each step's worn heights (m, float64, [rows, columns], row = y) as
        /// DIR/<scene>_step_NNN.npy, with DIR/<scene>_series.toml listing them as a
        /// [[series]] to read back.
        #[arg(long, value_name = "DIR")]
        heights_out: Option<PathBuf>,
    },
    /// The elastic-plastic contact of a scene with [plasticity] (body 1 J2-plastic): loaded
    /// step by step, then unloaded; the pressure, the plastic zone, the stresses beyond yield
    /// and the residual stress and dent (docs/plasticity.md).
    Plastic {
        scene: PathBuf,
        /// Print one JSON object (SI units) instead of the report.
        #[arg(long)]
        json: bool,
        /// Also write the fields (plastic strain, residual stress, pressure, x, y, z; SI) as a
        /// NumPy .npz archive.
        #[arg(long, value_name = "FILE.npz")]
        fields: Option<PathBuf>,
    },
}

/// Options of `render`.
#[derive(Debug, clap::Args)]
pub struct RenderArgs {
    /// Scene files (TOML). Default: every *.toml in --scenes-dir.
    pub scenes: Vec<PathBuf>,
    /// Directory for the images.
    #[arg(long, default_value = "out")]
    pub out_dir: PathBuf,
    /// Directory searched when no scene is named.
    #[arg(long, default_value = "scenes")]
    pub scenes_dir: PathBuf,
    /// Also write SVG (in addition to scenes that ask for it).
    #[arg(long)]
    pub svg: bool,
    /// Also write each figure's values next to its PNG: <scene>.npz with, per panel k,
    /// values_k [rows, columns] in the figure's stress unit and its axes horizontal_k and
    /// vertical_k in its length unit (float64; numpy.load reads it).
    #[arg(long)]
    pub save_field: bool,
    /// Also record the (single) scene to this Rerun .rrd file.
    #[arg(long, value_name = "FILE")]
    pub rrd: Option<PathBuf>,
    #[command(flatten)]
    pub compare: CompareArgs,
}

/// Options of `render --compare`.
#[derive(Debug, clap::Args)]
#[command(next_help_heading = "Regression comparison")]
pub struct CompareArgs {
    /// Compare each drawn figure with the references DIR/<scene>.png (and the fields
    /// DIR/<scene>.npz where they exist); print one line per scene, a summary, and exit
    /// non-zero if any differs. Differing images get <scene>.diff.png in --out-dir.
    /// Recording scenes recorded rather than drawn (no scene named) are not compared.
    #[arg(long, value_name = "DIR")]
    pub compare: Option<PathBuf>,
    /// How images are judged: per-channel tolerance and a budget of differing pixels
    /// (--tolerance, --max-differing-pixels), or the root mean square difference of all
    /// channels over the image (--rms-tolerance; matplotlib's and pytest-mpl's measure).
    #[arg(long, value_enum, default_value_t = MeasureArg::Pixels, requires = "compare")]
    pub measure: MeasureArg,
    /// --measure pixels: largest per-channel difference (0-255) that still counts as equal
    /// [default: 16].
    #[arg(long, requires = "compare")]
    pub tolerance: Option<u8>,
    /// --measure pixels: pixels allowed to differ beyond --tolerance [default: 0].
    #[arg(long, requires = "compare")]
    pub max_differing_pixels: Option<usize>,
    /// --measure rms: largest RMS difference, in levels of 255 [default: 2, pytest-mpl's].
    #[arg(long, requires = "compare")]
    pub rms_tolerance: Option<f64>,
    /// Largest absolute difference of a field value from its reference DIR/<scene>.npz, in
    /// the figure's stress unit (p0, MPa, ...) [default: 1e-6].
    #[arg(long, requires = "compare")]
    pub field_tolerance: Option<f64>,
    /// Write an HTML report of the comparison to DIR/index.html: one self-contained page,
    /// reference | actual | difference for every scene, failures first.
    #[arg(long, value_name = "DIR", requires = "compare")]
    pub report: Option<PathBuf>,
    /// Rewrite the references of the scenes that differ, and write missing ones (PNG, and the
    /// field where the reference had one or --save-field is given); scenes within tolerance are
    /// left untouched. Updated scenes do not fail the run.
    #[arg(long, requires = "compare")]
    pub update: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MeasureArg {
    /// Per-channel tolerance and a pixel budget.
    Pixels,
    /// Root mean square difference over the image.
    Rms,
}

/// Options of `probe`.
#[derive(Debug, clap::Args)]
pub struct ProbeArgs {
    /// Scene whose contact (friction, Poisson ratio) is used; default: a normalised contact.
    pub scene: Option<PathBuf>,
    /// Contact geometry: line (cylinders, plane strain) or point (sphere; y is used).
    /// Default: the scene's, else line.
    #[arg(long, value_enum)]
    pub contact: Option<ContactArg>,
    /// Coefficient of sliding friction (overrides the scene's).
    #[arg(long, allow_negative_numbers = true)]
    pub friction: Option<f64>,
    /// Poisson's ratio of the body (overrides the scene's).
    #[arg(long, allow_negative_numbers = true)]
    pub poisson: Option<f64>,
    /// Stress solution: the exact closed form, or numerical integration of the tractions
    /// discretised into --strips uniform strips (line) or --cells² uniform cells (point),
    /// an independent check of the closed form.
    #[arg(long, value_enum, default_value_t = MethodArg::ClosedForm)]
    pub method: MethodArg,
    /// Number of strips of the numerical method (error about 0.1/strips p0 at z >= 0.1a).
    #[arg(long, default_value_t = 2000)]
    pub strips: usize,
    /// Point contact, numerical method: cells per side of the square traction grid.
    #[arg(long, default_value_t = 255)]
    pub cells: usize,
    /// Point contact, numerical method: the grid covers [-extent, extent]² (units of a).
    #[arg(long, default_value_t = 2.0)]
    pub extent: f64,
    /// CSV file of points, or - for standard input.
    #[arg(long, value_name = "FILE|-")]
    pub points: PathBuf,
}

/// Options of `surface`.
#[derive(Debug, clap::Args)]
pub struct SurfaceArgs {
    /// A height file (.asc/.txt/.csv matrix, .xyz, .x3p) or a scene (.toml).
    pub input: PathBuf,
    /// Sample spacing of a file that does not say it, e.g. 1um, or 1um,2um for dx,dy.
    #[arg(long)]
    pub spacing: Option<String>,
    /// Unit of the heights of a file that does not say it: m, mm, um, nm.
    #[arg(long)]
    pub height_unit: Option<String>,
    /// Unit of x and y of an XYZ file (default m).
    #[arg(long)]
    pub length_unit: Option<String>,
    /// Missing points: refuse (default) or interpolate.
    #[arg(long, default_value = "refuse")]
    pub fill: String,
    /// Form removed besides the mean plane: plane (none more) or quadratic.
    #[arg(long, default_value = "plane")]
    pub form: String,
    /// Wavelength band of the Hurst fit, e.g. 4um,100um.
    #[arg(long)]
    pub band: Option<String>,
    /// Combined modulus E* for the Greenwood-Williamson load and the highest asperity's Hertz
    /// pressure, e.g. 115GPa (a scene takes it from its bodies).
    #[arg(long)]
    pub e_star: Option<String>,
    /// Hardness for the plasticity index, e.g. 3GPa or 300HV.
    #[arg(long)]
    pub hardness: Option<String>,
    /// Print one JSON object (SI units) instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Also write the heights as read or generated (before levelling; m, float64,
    /// [rows, columns], row = y) as a NumPy .npy file.
    #[arg(long, value_name = "FILE.npy")]
    pub heights: Option<PathBuf>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ContactArg {
    Line,
    Point,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    ClosedForm,
    Numerical,
}

#[cfg(test)]
mod tests {
    /// The address `--connect` uses alone is the one Rerun's SDK connects to by default (this
    /// copy exists for builds without Rerun).
    #[cfg(feature = "rerun")]
    #[test]
    fn the_default_viewer_address_is_rerun_s() {
        assert_eq!(
            super::DEFAULT_VIEWER_URL,
            stressfield::record::DEFAULT_VIEWER_URL
        );
    }
}
