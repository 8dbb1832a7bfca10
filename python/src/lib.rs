//! `stressfield._stressfield`: the Python package's extension, a thin layer over the library's
//! study and report functions (the same ones the command line calls), so that every result is
//! the command line's.
//!
//! Arrays come in as NumPy float64 views of any order (C or Fortran: read through their
//! strides, not copied) and go out as arrays moved into NumPy (not copied). Computation runs
//! with the GIL released (`Python::detach`); the long ones (rough contacts and what contains
//! them) check Python's pending signals between solver iterations ([`Signals`]), so that
//! Ctrl-C stops them. Errors raise `StressfieldError` (a `ValueError`) with the text the
//! command line prints after `error: `; every argument is checked against the bounds the
//! command line keeps for the same quantity in a scene, and named. The Python wrapper
//! (`stressfield/__init__.py`) checks the arguments' kinds, broadcasts, and builds the result
//! objects; the JSON objects are passed as the command line's text and parsed there, so that
//! every number is the command line's to the last digit.

use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use anyhow::{anyhow, bail, Context};
use ndarray::{Array2, Array3, Array4, ArrayView1, ArrayView2, Axis};
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyArray3, PyArray4, PyReadonlyArray1, PyReadonlyArray2,
};
use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use rayon::prelude::*;

use stressfield::contact::rough::{self as rough_contact, Control, RoughContactProblem};
use stressfield::operator::elastic::Periodicity;
use stressfield::report::commands::{contact_json, heating_report, hertz_json};
use stressfield::report::rough::ContactReport;
use stressfield::report::surface::SurfaceReport;
use stressfield::scene::{Bounds, ContactKind, RoughSpec};
use stressfield::solution::dcfft::{DcFft, TractionGrid};
use stressfield::study;
use stressfield::study::commands::{self, Progress};
use stressfield::study::rough::{RoughMaterials, REFERENCE_LENGTH_M, REFERENCE_PRESSURE_PA};
use stressfield::surface::read::{self, Fill, ReadOptions};
use stressfield::surface::stats::{self, FormRemoval, Options};
use stressfield::surface::HeightMap;

create_exception!(
    _stressfield,
    StressfieldError,
    PyValueError,
    "A stressfield input or computation failed; the message is the command line's."
);

/// The error as Python sees it: the command line's text.
fn raise(error: anyhow::Error) -> PyErr {
    StressfieldError::new_err(stressfield::io::text::error_text(&error))
}

type Result<T> = anyhow::Result<T>;

/// A validated scene (`stressfield.Scene`).
#[pyclass(frozen, module = "stressfield._stressfield")]
struct Scene {
    scene: stressfield::scene::Scene,
    /// The file it was read from (or the name given to its text), for messages.
    file: String,
}

/// The contact kind's name as scenes write it.
fn kind_name(kind: ContactKind) -> &'static str {
    match kind {
        ContactKind::Line => "line",
        ContactKind::Point => "point",
        ContactKind::Elliptical => "elliptical",
        ContactKind::Tractions => "tractions",
        ContactKind::Rough => "rough",
        ContactKind::Surface => "surface",
    }
}

/// Reads and validates a scene file, as every command does.
#[pyfunction]
fn load_scene(py: Python<'_>, path: PathBuf) -> PyResult<Scene> {
    let file = path.display().to_string();
    let scene = py
        .detach(|| study::load_scene(&path).map_err(anyhow::Error::from))
        .map_err(raise)?;
    Ok(Scene { scene, file })
}

/// Parses and validates scene text; files it names are read relative to `base_dir`.
#[pyfunction]
fn parse_scene(py: Python<'_>, text: &str, base_dir: PathBuf, name: &str) -> PyResult<Scene> {
    let file = base_dir.join(format!("{name}.toml")).display().to_string();
    let scene = py
        .detach(|| study::parse_scene(text, name, &file).map_err(anyhow::Error::from))
        .map_err(raise)?;
    Ok(Scene { scene, file })
}

/// Python's pending signals (Ctrl-C), checked from a computation running without the GIL.
///
/// Python runs its signal handlers in the main thread between bytecodes; a computation in
/// Rust holds that thread until it returns, so a Ctrl-C would wait for the end of a solve.
/// [`Signals::stop`] takes the GIL briefly and runs the handlers (`PyErr_CheckSignals`): when
/// one raises (`KeyboardInterrupt`), the exception is kept, the computation is asked to stop
/// (between two iterations of a rough contact's solver, or before the next phase of a
/// study), and [`Signals::finish`] raises it instead of any result. Only a call from the
/// main thread checks (Python delivers signals there alone), and at most every
/// [`Signals::EVERY`], so that other Python threads keep the GIL.
struct Signals {
    main_thread: bool,
    last: Instant,
    raised: Option<PyErr>,
}

impl Signals {
    /// The least time between two checks.
    const EVERY: Duration = Duration::from_millis(20);

    /// Signals for a call made by `py`'s current thread.
    fn new(py: Python<'_>) -> Self {
        fn on_main_thread(py: Python<'_>) -> PyResult<bool> {
            let threading = py.import("threading")?;
            let main = threading.call_method0("main_thread")?;
            let current = threading.call_method0("current_thread")?;
            Ok(main.is(&current))
        }
        Self {
            main_thread: on_main_thread(py).unwrap_or(false),
            last: Instant::now(),
            raised: None,
        }
    }

    /// Whether to stop: a signal handler has raised (now or before).
    fn stop(&mut self) -> ControlFlow<()> {
        if self.raised.is_some() {
            return ControlFlow::Break(());
        }
        if !self.main_thread || self.last.elapsed() < Self::EVERY {
            return ControlFlow::Continue(());
        }
        self.last = Instant::now();
        match Python::attach(|py| py.check_signals()) {
            Ok(()) => ControlFlow::Continue(()),
            Err(raised) => {
                self.raised = Some(raised);
                ControlFlow::Break(())
            }
        }
    }

    /// The computation's result as Python sees it: the exception a signal handler raised, if
    /// any (whatever the computation returned), else the result or its error.
    fn finish<T>(self, result: Result<T>) -> PyResult<T> {
        match self.raised {
            Some(raised) => Err(raised),
            None => result.map_err(raise),
        }
    }
}

/// A study of the commands ([`commands`]) with the GIL released and Ctrl-C heard between its
/// steps.
fn interruptible<T: Send>(
    py: Python<'_>,
    run: impl FnOnce(&mut dyn FnMut(Progress) -> ControlFlow<()>) -> Result<T> + Send,
) -> PyResult<T> {
    let mut signals = Signals::new(py);
    let result = py.detach(|| run(&mut |_| signals.stop()));
    signals.finish(result)
}

/// `contact SCENE --json`'s study of a rough scene (the command line's message otherwise).
fn scene_contact(
    scene: &stressfield::scene::Scene,
    file: &str,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
) -> Result<commands::ContactStudy> {
    if scene.contact.kind != ContactKind::Rough {
        bail!(
            "{file} is not a rough contact scene (contact.kind = \"rough\")\nhint: `stressfield hertz {file}` reports Hertz contacts"
        );
    }
    Ok(commands::contact(scene, progress)?)
}

/// `thermal SCENE --json` and body 1's surface temperature rise (K).
fn scene_thermal(
    scene: &stressfield::scene::Scene,
    file: &str,
    progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
) -> Result<(String, Array2<f64>)> {
    if scene.thermal.is_none() {
        bail!(
            "{file} has no [thermal] table\nhint: add [thermal] with speed = \"2 m/s\" and the bodies' thermal properties (material = \"steel\", or conductivity, diffusivity, expansion); see docs/heating.md"
        );
    }
    let heating = commands::thermal(scene, progress)?;
    let json = heating_report(&heating).json();
    let temperature = match heating {
        commands::Heating::Contact(study) => study.body1.temperature_k,
        commands::Heating::Gears(gear) => gear.study.body1.temperature_k,
    };
    Ok((json, temperature))
}

/// The scene's figure (or sheet) as `render` draws it, as PNG or SVG bytes.
fn scene_drawing(scene: &stressfield::scene::Scene, svg: bool) -> Result<Vec<u8>> {
    let drawing = if scene.wear.is_some() {
        let study = study::wear::study(scene, &mut |_| {})?;
        stressfield::figure::Drawing::Sheet(stressfield::figure::wear::wear_sheet(scene, &study))
    } else if scene.draws_plastic_sheet() {
        // A [plasticity] scene draws its elastic-plastic sheet, as `render` does.
        let study = study::plastic::study(scene, &mut |_| {})?;
        let sections = study::plastic::history::sheet_sections(&study);
        let title = scene.title.clone().unwrap_or_else(|| scene.name.clone());
        stressfield::figure::Drawing::Sheet(stressfield::figure::plastic::plastic_sheet(
            &title, &study, &sections,
        ))
    } else {
        let rough = match scene.contact.kind {
            ContactKind::Rough => Some(study::rough::solve(scene, &mut |_, _| {})?),
            _ => None,
        };
        stressfield::figure::compute_and_draw(scene, rough.as_ref(), &|| {})?
    };
    Ok(if svg {
        drawing.svg()?.into_bytes()
    } else {
        stressfield::render::encode_png(&drawing.png()?)?
    })
}

/// Writes `bytes` to `path` atomically (as every command writes its outputs).
fn write_atomically(path: &Path, bytes: &[u8]) -> Result<()> {
    let mut staged = stressfield::io::output::Staged::new();
    staged.add(path, bytes)?;
    staged.commit()?;
    Ok(())
}

/// Records the scene to an `.rrd` file as `record SCENE -o FILE` does.
#[cfg(feature = "rerun")]
fn scene_record(scene: &stressfield::scene::Scene, path: &Path) -> Result<()> {
    if let Some(message) = study::admit::unrecorded_heating(scene) {
        bail!("{message}");
    }
    let destination = stressfield::record::Destination::File(path.to_path_buf());
    if scene.wear.is_some() {
        let study = study::wear::study(scene, &mut |_| {})?;
        let sections = study::wear::sections(&study, &mut |_| {})?;
        stressfield::record::record_wear_to(scene, &destination, &study, &sections)?;
    } else if scene.draws_plastic_sheet() {
        let study = study::plastic::study(scene, &mut |_| {})?;
        stressfield::record::record_plastic_to(scene, &destination, &study)?;
    } else {
        stressfield::record::record_to_with(scene, &destination, &|| {}, None)?;
    }
    Ok(())
}

#[cfg(not(feature = "rerun"))]
fn scene_record(scene: &stressfield::scene::Scene, _path: &Path) -> Result<()> {
    bail!(
        "scene {}: this stressfield package was built without Rerun, so it cannot record\nhint: reinstall it with the feature: pip install ./python --config-settings=build-args=\"--features rerun\" (a long build), or run `stressfield record SCENE -o FILE.rrd`",
        scene.name
    )
}

#[pymethods]
impl Scene {
    /// The scene's name (the file stem; outputs are named after it).
    #[getter]
    fn name(&self) -> String {
        self.scene.name.clone()
    }

    /// The contact kind: line, point, elliptical, tractions, rough or surface.
    #[getter]
    fn kind(&self) -> &'static str {
        kind_name(self.scene.contact.kind)
    }

    /// The file the scene was read from (or stands for).
    #[getter]
    fn file(&self) -> String {
        self.file.clone()
    }

    /// Whether the scene has a `[sweep]` (a recording scene whose steps `sweep` tabulates).
    #[getter]
    fn has_sweep(&self) -> bool {
        self.scene.sweep.is_some()
    }

    /// `hertz SCENE --json` as text: the command line's study ([`commands::hertz`]), so a
    /// coated scene is its coated contact, a rough one its contact, a surface one its
    /// characterisation. Ctrl-C stops it.
    fn hertz_json(&self, py: Python<'_>) -> PyResult<String> {
        interruptible(py, |progress| {
            let study = commands::hertz(&self.scene, progress)?;
            Ok(hertz_json(&self.scene, &study))
        })
    }

    /// `sweep SCENE --json` as text.
    fn sweep_json(&self, py: Python<'_>) -> PyResult<String> {
        py.detach(|| -> Result<String> {
            let table = stressfield::report::sweep::sweep_table(&self.scene, &mut |_, _| {})
                .with_context(|| format!("scene {}", self.scene.name))?;
            Ok(table.json())
        })
        .map_err(raise)
    }

    /// `contact SCENE --json` as text, and the pressure (Pa, `[rows, columns]`). Ctrl-C
    /// stops it.
    fn contact<'py>(&self, py: Python<'py>) -> PyResult<(String, Bound<'py, PyArray2<f64>>)> {
        let (json, pressure) = interruptible(py, |progress| {
            let study = scene_contact(&self.scene, &self.file, progress)?;
            let json = contact_json(&self.scene, &study);
            Ok((json, study.solution.pressure_pa))
        })?;
        Ok((json, pressure.into_pyarray(py)))
    }

    /// `thermal SCENE --json` as text, and body 1's surface temperature rise (K, `[rows,
    /// columns]` of the thermal grid). Ctrl-C stops it.
    fn thermal<'py>(&self, py: Python<'py>) -> PyResult<(String, Bound<'py, PyArray2<f64>>)> {
        let (json, temperature) = interruptible(py, |progress| {
            scene_thermal(&self.scene, &self.file, progress)
        })?;
        Ok((json, temperature.into_pyarray(py)))
    }

    /// `wear SCENE --json` as text: the steps of a scene with `[wear]` or `[[series]]`; with
    /// `arrays`, each step's worn heights (m), pressure (Pa) and wear depth (m), stacked
    /// `(steps, ny, nx)`, the unworn contact first.
    #[allow(clippy::type_complexity)]
    fn wear<'py>(
        &self,
        py: Python<'py>,
        arrays: bool,
    ) -> PyResult<(String, Option<[Bound<'py, PyArray3<f64>>; 3]>)> {
        let (json, stacks) = py
            .detach(|| -> Result<(String, Option<[Array3<f64>; 3]>)> {
                if self.scene.wear.is_none() {
                    bail!(
                        "{} has no [wear] or [[series]]\nhint: add [wear] with coefficient = \"2e-6 mm^3/(N m)\", distance = \"20 m\" and steps = 40 to a rough scene (contact.kind = \"rough\"); see docs/wear.md",
                        self.file
                    );
                }
                let study = study::wear::study(&self.scene, &mut |_| {})
                    .with_context(|| format!("scene {}", self.scene.name))?;
                let json = stressfield::report::wear::WearReport::new(&study).json();
                if !arrays {
                    return Ok((json, None));
                }
                let (ny, nx) = study.steps[0].solution.pressure_pa.dim();
                let count = study.steps.len();
                let mut stacks = [
                    Array3::zeros((count, ny, nx)),
                    Array3::zeros((count, ny, nx)),
                    Array3::zeros((count, ny, nx)),
                ];
                for (k, step) in study.steps.iter().enumerate() {
                    let sources = [
                        step.heights_m.as_ref(),
                        &step.solution.pressure_pa,
                        &step.wear_depth_m,
                    ];
                    for (stack, source) in stacks.iter_mut().zip(sources) {
                        if source.dim() != (ny, nx) {
                            bail!(
                                "scene {}: step {k}'s arrays are {:?}, not the first step's {:?}",
                                self.scene.name,
                                source.dim(),
                                (ny, nx)
                            );
                        }
                        for ((j, i), &value) in source.indexed_iter() {
                            stack[[k, j, i]] = value;
                        }
                    }
                }
                Ok((json, Some(stacks)))
            })
            .map_err(raise)?;
        Ok((json, stacks.map(|s| s.map(|a| a.into_pyarray(py)))))
    }

    /// `plastic SCENE --json` as text: the elastic-plastic contact of a scene with
    /// `[plasticity]`; with `fields`, the arrays of `plastic --fields` (plastic strain,
    /// loaded and residual stress with components last, pressure, x, y, z).
    #[allow(clippy::type_complexity)]
    fn plastic<'py>(
        &self,
        py: Python<'py>,
        fields: bool,
    ) -> PyResult<(String, Option<PlasticArrays<'py>>)> {
        let (json, arrays) = py
            .detach(|| -> Result<(String, Option<PlasticFields>)> {
                if self.scene.plasticity.is_none() {
                    bail!(study::plastic::not_plastic_message(&self.file));
                }
                let study = study::plastic::study(&self.scene, &mut |_| {})
                    .with_context(|| format!("scene {}", self.scene.name))?;
                let json = stressfield::report::plastic::PlasticReport::new(&study).json();
                if !fields {
                    return Ok((json, None));
                }
                let arrays = PlasticFields {
                    plastic_strain: study::plastic::final_plastic_strain(&study).clone(),
                    stress: study::plastic::components_last(&study.loaded_snapshot().stress_pa),
                    residual_stress: study
                        .unloaded_snapshot()
                        .map(|state| study::plastic::components_last(&state.stress_pa)),
                    pressure: study.loaded_snapshot().pressure_pa.clone(),
                    surface_displacement: study::plastic::final_surface_displacement(&study)
                        .clone(),
                    axes: [study.x_m.clone(), study.y_m.clone(), study.z_m.clone()],
                };
                Ok((json, Some(arrays)))
            })
            .map_err(raise)?;
        Ok((
            json,
            arrays.map(|a| {
                let [x, y, z] = a.axes;
                (
                    a.plastic_strain.into_pyarray(py),
                    a.stress.into_pyarray(py),
                    a.residual_stress.map(|r| r.into_pyarray(py)),
                    a.pressure.into_pyarray(py),
                    a.surface_displacement.into_pyarray(py),
                    x.into_pyarray(py),
                    y.into_pyarray(py),
                    z.into_pyarray(py),
                )
            }),
        ))
    }

    /// `ehl SCENE --json` as text, and the solution as `ehl --pressure` writes it (`(n, 3)`:
    /// x m, pressure Pa, film m; entrainment in +x). A solution that does not converge
    /// raises, as the command line fails.
    fn ehl<'py>(&self, py: Python<'py>) -> PyResult<(String, Bound<'py, PyArray2<f64>>)> {
        let (json, array) = py
            .detach(|| -> Result<(String, Array2<f64>)> {
                let study = study::ehl::solve(&self.scene)
                    .with_context(|| format!("scene {}", self.scene.name))?;
                if !study.solution.converged {
                    bail!(
                        "scene {}: the EHL solution did not converge after {} Newton iterations\nhint: the solver is checked for Moes' M from 0.2 to 2000 and L up to 46 (docs/lubrication.md)",
                        self.scene.name,
                        study.solution.iterations
                    );
                }
                let json =
                    stressfield::report::lubrication::EhlReport::new(&self.scene, &study).json();
                Ok((json, study::ehl::solution_array(&study.solution)))
            })
            .map_err(raise)?;
        Ok((json, array.into_pyarray(py)))
    }

    /// Draws the scene's figure to `path` (PNG, or SVG by the extension).
    fn render(&self, py: Python<'_>, path: PathBuf) -> PyResult<()> {
        py.detach(|| -> Result<()> {
            let extension = path
                .extension()
                .map(|e| e.to_string_lossy().to_ascii_lowercase());
            let svg = match extension.as_deref() {
                Some("svg") => true,
                Some("png") => false,
                _ => bail!(
                    "{}: the figure is written as .png or .svg\nhint: give a file name ending in .png or .svg",
                    path.display()
                ),
            };
            let bytes =
                scene_drawing(&self.scene, svg).with_context(|| format!("scene {}", self.scene.name))?;
            write_atomically(&path, &bytes)
        })
        .map_err(raise)
    }

    /// Records the scene to a Rerun `.rrd` file (a package built with the `rerun` feature).
    fn record(&self, py: Python<'_>, path: PathBuf) -> PyResult<()> {
        py.detach(|| {
            scene_record(&self.scene, &path).with_context(|| format!("scene {}", self.scene.name))
        })
        .map_err(raise)
    }

    fn __repr__(&self) -> String {
        format!(
            "Scene(name={:?}, kind={:?}, file={:?})",
            self.scene.name,
            kind_name(self.scene.contact.kind),
            self.file
        )
    }
}

/// A spacing pair (m) within `bounds`, named as the Python argument.
fn spacing_pair(dx: f64, dy: f64, bounds: Bounds) -> Result<[f64; 2]> {
    for (name, value) in [("dx", dx), ("dy", dy)] {
        if !bounds.contains(value) {
            bail!(
                "spacing: {name} must lie between {} m and {} m, got {}\nhint: {}",
                stressfield::io::text::compact(bounds.lo),
                stressfield::io::text::compact(bounds.hi),
                stressfield::io::text::number(value),
                bounds.why
            );
        }
    }
    Ok([dx, dy])
}

/// The spacing of a traction grid (`stress`): from an atomic spacing to 10 km.
const TRACTION_SPACING: Bounds = stressfield::scene::WAVELENGTH_BOUNDS;

/// `value` (SI, in `unit`) within a scene's `bounds` for the same quantity, named `name` as
/// the Python argument, the scene's reason as the hint.
fn check_bounds(name: &str, value: f64, bounds: Bounds, unit: &str) -> Result<()> {
    if !bounds.contains(value) {
        bail!(
            "{name} must lie between {} {unit} and {} {unit}, got {}\nhint: {}",
            stressfield::io::text::compact(bounds.lo),
            stressfield::io::text::compact(bounds.hi),
            stressfield::io::text::number(value),
            bounds.why
        );
    }
    Ok(())
}

/// Body 1's friction coefficient, as scenes and `probe --friction` take it.
fn check_friction(friction: f64) -> Result<()> {
    if let Some(message) = stressfield::scene::friction_requirement(friction) {
        bail!(
            "friction: {message}\nhint: {}",
            stressfield::scene::FRICTION_HINT
        );
    }
    Ok(())
}

/// Poisson's ratio, as scenes take it.
fn check_poisson(poisson: f64) -> Result<()> {
    if !(-1.0 < poisson && poisson <= 0.5) {
        bail!(
            "poisson must lie in (-1, 0.5], got {}\nhint: steel is about 0.3",
            stressfield::io::text::number(poisson)
        );
    }
    Ok(())
}

/// A height array and its spacing, checked as a height map's (finite heights at most 1 m in
/// size, spacings of 0.1 nm to 1 m, at least 2 x 2), named as the Python arguments.
fn check_heights(heights: ArrayView2<f64>, spacing_m: [f64; 2]) -> Result<()> {
    use stressfield::surface::SurfaceError;
    stressfield::surface::check_samples(heights, spacing_m).map_err(|error| match error {
        SurfaceError::Spacing { .. } => anyhow!("spacing: {error}"),
        other => anyhow!("heights: {other}"),
    })
}

/// `stressfield.contact`: the rough contact of a height array, solved and reported as
/// `contact --json` reports a scene's; every argument within the bounds of the scene key it
/// stands for. Ctrl-C stops it between iterations.
#[pyfunction]
#[pyo3(signature = (heights, dx, dy, e_star, control, value, periodic, hardness, friction, poisson, tolerance))]
#[allow(clippy::too_many_arguments)]
fn contact<'py>(
    py: Python<'py>,
    heights: PyReadonlyArray2<'py, f64>,
    dx: f64,
    dy: f64,
    e_star: f64,
    control: &str,
    value: f64,
    periodic: bool,
    hardness: Option<f64>,
    friction: f64,
    poisson: f64,
    tolerance: f64,
) -> PyResult<(String, Bound<'py, PyArray2<f64>>)> {
    let heights = heights.as_array();
    let mut signals = Signals::new(py);
    let result = py.detach(|| -> Result<(String, Array2<f64>)> {
        let spacing_m = [dx, dy];
        check_heights(heights, spacing_m)?;
        check_range("e_star", e_star, 1.0, 1e13, "Pa")?;
        if let Some(h) = hardness {
            check_range("hardness", h, 1.0, 1e13, "Pa")?;
        }
        check_poisson(poisson)?;
        check_friction(friction)?;
        let loosest = stressfield::scene::MAX_ROUGH_TOLERANCE;
        if !(tolerance > 0.0 && tolerance < loosest) {
            bail!(
                "tolerance must lie in (0, {}), as a scene's numerical.tolerance, got {}\nhint: the default is 1e-8",
                stressfield::io::text::number(loosest),
                stressfield::io::text::number(tolerance)
            );
        }
        let control = match control {
            "load" => {
                check_bounds("load", value, stressfield::scene::LOAD_BOUNDS, "N")?;
                Control::Load { newtons: value }
            }
            "mean_pressure" => {
                check_bounds("mean_pressure", value, stressfield::scene::STRESS_BOUNDS, "Pa")?;
                Control::MeanPressure { pa: value }
            }
            "approach" => {
                check_bounds("approach", value, stressfield::scene::APPROACH_BOUNDS, "m")?;
                Control::Approach { m: value }
            }
            other => bail!("unknown control {other}: use load, mean_pressure or approach"),
        };
        // As a rough scene is admitted: the solve and the subsurface search within the memory
        // allowed, estimated before anything is allocated.
        let (ny, nx) = heights.dim();
        let (bytes, seconds) = study::heating_plan::contact_cost([ny, nx]);
        let limit = stressfield::field::memory_limit_bytes();
        if bytes > limit {
            bail!(
                "heights: the contact of a {nx} x {ny} map needs about {} of CPU and {} ({} bytes a cell), more than the {} this machine allows\nhint: use a coarser map (half the samples a side takes a quarter of the memory)",
                study::heating_plan::duration(seconds),
                stressfield::io::text::bytes(bytes as u64),
                study::heating_plan::CONTACT_BYTES_PER_CELL,
                stressfield::io::text::bytes(limit as u64)
            );
        }
        let problem = RoughContactProblem {
            heights_m: heights,
            spacing_m,
            e_star_pa: e_star,
            periodicity: if periodic {
                Periodicity::Periodic
            } else {
                Periodicity::NonPeriodic
            },
            control,
            hardness_pa: hardness,
            tolerance,
            max_iterations: rough_contact::DEFAULT_MAX_ITERATIONS,
            memory_limit_bytes: stressfield::field::memory_limit_bytes(),
        };
        let solution = rough_contact::solve_interruptible(
            &problem,
            &rough_contact::Warm::default(),
            &mut rough_contact::OperatorCache::default(),
            &mut |_, _| signals.stop(),
        )?;
        if signals.stop().is_break() {
            bail!("interrupted before the subsurface maxima: no result");
        }
        let materials = RoughMaterials {
            friction,
            poisson,
            e_star_pa: Some(e_star),
            hardness_pa: hardness,
        };
        // The plasticity index reads the summits of the surface (a copy of the heights,
        // made only with a hardness).
        let surface = match hardness {
            Some(_) => Some(HeightMap::new(heights.to_owned(), spacing_m)?),
            None => None,
        };
        let findings = study::rough::findings_of(
            &solution,
            &materials,
            surface.as_ref().map(|s| (s, false)),
        )?;
        let spec = RoughSpec {
            control: Some(control),
            periodic,
            e_star_pa: Some(e_star),
            hardness_pa: hardness,
            tolerance,
            max_iterations: rough_contact::DEFAULT_MAX_ITERATIONS,
        };
        let mut report = ContactReport::of(&spec, friction, poisson, &solution, &findings);
        // As the command line warns of a scene's map: a periodic contact on a seam where
        // the heights' opposite edges do not meet.
        if periodic {
            report
                .warnings
                .extend(study::rough::seam_warning(heights, &solution.pressure_pa));
        }
        Ok((report.json(), solution.pressure_pa))
    });
    let (json, pressure) = signals.finish(result)?;
    Ok((json, pressure.into_pyarray(py)))
}

/// `value` positive, finite and within `[low, high]` (`unit` for the message).
fn check_range(name: &str, value: f64, low: f64, high: f64, unit: &str) -> Result<()> {
    if !(value.is_finite() && value > 0.0 && value >= low && value <= high) {
        if low > 0.0 {
            bail!(
                "{name} must lie between {} {unit} and {} {unit}, got {}",
                stressfield::io::text::number(low),
                stressfield::io::text::number(high),
                stressfield::io::text::number(value)
            );
        }
        bail!(
            "{name} must be positive and finite ({unit}), got {}",
            stressfield::io::text::number(value)
        );
    }
    Ok(())
}

/// The tractions of `stress` (Pa) within the bounds of a pressure given in a scene (in size:
/// a traction may pull or push), named by their argument and cell.
fn check_traction(name: &str, array: ArrayView2<f64>) -> Result<()> {
    let bound = stressfield::scene::STRESS_BOUNDS;
    if let Some(((row, column), &value)) = array
        .indexed_iter()
        .find(|(_, t)| !(t.is_finite() && t.abs() <= bound.hi))
    {
        bail!(
            "{name}[{row}, {column}] is {} Pa: a traction must be finite and at most {} Pa in size\nhint: {}",
            stressfield::io::text::number(value),
            stressfield::io::text::compact(bound.hi),
            bound.why
        );
    }
    Ok(())
}

/// `stressfield.stress`: the stresses under uniform tractions on the cells of a grid, by
/// DC-FFT, at the cell centres of each depth: `[depth, row, column, component]` in Pa. The
/// memory the layers take is estimated and refused beyond what the machine allows before
/// anything is allocated ([`stressfield::field::kept_layers_bytes`]).
#[pyfunction]
#[pyo3(signature = (pressure, dx, dy, depths, shear_x, shear_y, poisson, periodic))]
#[allow(clippy::too_many_arguments)]
fn stress<'py>(
    py: Python<'py>,
    pressure: Option<PyReadonlyArray2<'py, f64>>,
    dx: f64,
    dy: f64,
    depths: PyReadonlyArray1<'py, f64>,
    shear_x: Option<PyReadonlyArray2<'py, f64>>,
    shear_y: Option<PyReadonlyArray2<'py, f64>>,
    poisson: f64,
    periodic: bool,
) -> PyResult<Bound<'py, PyArray4<f64>>> {
    let named = [
        ("pressure", pressure.as_ref().map(|a| a.as_array())),
        ("shear_x", shear_x.as_ref().map(|a| a.as_array())),
        ("shear_y", shear_y.as_ref().map(|a| a.as_array())),
    ];
    let depths = depths.as_array();
    let layers = py
        .detach(|| -> Result<Array4<f64>> {
            let [dx, dy] = spacing_pair(dx, dy, TRACTION_SPACING)?;
            check_poisson(poisson)?;
            if let Some(&z) = depths.iter().find(|z| !(z.is_finite() && **z >= 0.0)) {
                bail!(
                    "depths must be non-negative and finite (m, into the body), got {}",
                    stressfield::io::text::number(z)
                );
            }
            let present: Vec<(&str, ArrayView2<f64>)> = named
                .iter()
                .filter_map(|(name, array)| array.map(|a| (*name, a)))
                .collect();
            // Shapes and values before the memory (a mismatch is said as such).
            if let Some((first, array)) = present.first() {
                for (name, other) in &present[1..] {
                    if other.dim() != array.dim() {
                        let ((ny, nx), (my, mx)) = (other.dim(), array.dim());
                        bail!("{name} has shape [{ny}, {nx}] but {first} has [{my}, {mx}]; give every traction as [rows = y, columns = x]");
                    }
                }
                let (ny, nx) = array.dim();
                let bytes = stressfield::field::kept_layers_bytes(
                    [ny, nx],
                    present.len(),
                    depths.len(),
                    rayon::current_num_threads(),
                );
                let limit = stressfield::field::memory_limit_bytes();
                if bytes > limit {
                    bail!(
                        "stress: {} depths of a {nx} x {ny} grid need about {} (the layers returned, 48 bytes a cell each, and the DC-FFT's working memory), more than the {} this machine allows (at most 4 GiB, and 3/4 of the memory available)\nhint: ask for fewer depths at a time (each depth's layer is computed on its own), or use a coarser grid",
                        depths.len(),
                        stressfield::io::text::bytes(bytes as u64),
                        stressfield::io::text::bytes(limit as u64)
                    );
                }
            }
            for (name, array) in &present {
                check_traction(name, *array)?;
            }
            // The grid in the rough study's reference units (1 µm, 1 MPa), as its layers are.
            let scaled = |k: usize| {
                named[k]
                    .1
                    .map(|a| a.mapv(|t| t / REFERENCE_PRESSURE_PA))
            };
            let grid = TractionGrid::new(
                [0.0, 0.0],
                [dx / REFERENCE_LENGTH_M, dy / REFERENCE_LENGTH_M],
                scaled(0),
                scaled(1),
                scaled(2),
            )?;
            let fft = if periodic {
                DcFft::periodic(&grid, poisson)?
            } else {
                DcFft::new(&grid, poisson)?
            };
            drop(grid);
            layers_of(&fft, depths)
        })
        .map_err(raise)?;
    Ok(layers.into_pyarray(py))
}

/// The DC-FFT layers at `depths_m` by the library's driver of depth layers (in parallel over
/// the depths, or layer after layer with each split over the threads where the working sets
/// would not fit), `[depth, row, column, component]` in Pa.
fn layers_of(fft: &DcFft, depths_m: ArrayView1<f64>) -> Result<Array4<f64>> {
    let [ny, nx] = fft.shape();
    let depths: Vec<f64> = depths_m.iter().map(|z| z / REFERENCE_LENGTH_M).collect();
    let mut out = Array4::<f64>::zeros((depths.len(), ny, nx, 6));
    // Each depth's slot, written by whichever worker computes it.
    let slots: Vec<Mutex<_>> = out.axis_iter_mut(Axis(0)).map(Mutex::new).collect();
    stressfield::field::for_each_dcfft_layer(fft, &depths, |index, _, layer| {
        if let Ok(mut slot) = slots[index].lock() {
            for (c, component) in layer.axis_iter(Axis(0)).enumerate() {
                slot.index_axis_mut(Axis(2), c)
                    .zip_mut_with(&component, |o, &v| *o = v * REFERENCE_PRESSURE_PA);
            }
        }
    })?;
    drop(slots);
    Ok(out)
}

/// Friction and Poisson ratio of a closed form, checked as scenes and `probe` check them.
fn closed_form_parameters(friction: f64, poisson: f64) -> Result<()> {
    check_friction(friction)?;
    check_poisson(poisson)
}

/// `stressfield.line_stress` on flat arrays of points (the wrapper broadcasts): `[point,
/// component]` over p0.
#[pyfunction]
fn line_stress<'py>(
    py: Python<'py>,
    x: PyReadonlyArray1<'py, f64>,
    z: PyReadonlyArray1<'py, f64>,
    friction: f64,
    poisson: f64,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let (x, z) = (x.as_array(), z.as_array());
    closed_form_rows(py, friction, poisson, [("x", x), ("z", z)], |i| {
        stressfield::solution::line_hertz::stress_over_p0(x[i], z[i], friction, poisson)
    })
}

/// The points of the closed forms (coordinates `named`, the last one z, broadcast to one
/// length), as `probe` reads its points: finite, z >= 0 (into the body), and within
/// [`stressfield::io::points::MAX_DISTANCE_OVER_A`] of the contact.
fn check_points(named: &[(&str, ArrayView1<'_, f64>)]) -> Result<()> {
    use stressfield::io::points::MAX_DISTANCE_OVER_A;
    for (name, values) in named {
        if let Some((i, &bad)) = values.indexed_iter().find(|(_, v)| !v.is_finite()) {
            bail!(
                "{name} must be finite (units of a), got {} at point {i} (of the coordinates broadcast together, in C order)",
                stressfield::io::text::number(bad)
            );
        }
    }
    if let Some((_, z)) = named.last() {
        if let Some(&bad) = z.iter().find(|z| **z < 0.0) {
            bail!(
                "z must be non-negative and finite (into the body, units of a), got {}",
                stressfield::io::text::number(bad)
            );
        }
    }
    let points = named.first().map_or(0, |(_, v)| v.len());
    for i in 0..points {
        let distance = named.iter().map(|(_, v)| v[i].abs()).fold(0.0, f64::max);
        if distance > MAX_DISTANCE_OVER_A {
            let coordinates: Vec<String> = named
                .iter()
                .map(|(name, v)| format!("{name} = {}", stressfield::io::text::number(v[i])))
                .collect();
            bail!(
                "point {i} ({}) lies {} a from the contact, farther than the {} a a probe reaches\nhint: beyond it every stress is below 1e-9 p0 (they fall as a/r for a line contact, (a/r)² for a point contact); probe nearer",
                coordinates.join(", "),
                stressfield::io::text::number(distance),
                stressfield::io::text::compact(MAX_DISTANCE_OVER_A)
            );
        }
    }
    Ok(())
}

/// A closed form's stresses at the points `0..n` (the Python side broadcast the coordinates
/// to one length `n`), in parallel and without the GIL: `[point, component]`, the
/// components in `Stress` order (xx, yy, zz, yz, xz, xy), after the parameters and points are
/// checked.
fn closed_form_rows<'py, const N: usize>(
    py: Python<'py>,
    friction: f64,
    poisson: f64,
    named: [(&str, ArrayView1<'_, f64>); N],
    stress: impl Fn(usize) -> stressfield::stress::Stress + Sync,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let out = py
        .detach(|| -> Result<Array2<f64>> {
            closed_form_parameters(friction, poisson)?;
            check_points(&named)?;
            let points = named.first().map_or(0, |(_, v)| v.len());
            let mut out = Array2::zeros((points, 6));
            out.axis_iter_mut(Axis(0))
                .into_par_iter()
                .enumerate()
                .for_each(|(i, mut row)| {
                    let s = stress(i);
                    row.assign(&ndarray::arr1(&[s.xx, s.yy, s.zz, s.yz, s.xz, s.xy]));
                });
            Ok(out)
        })
        .map_err(raise)?;
    Ok(out.into_pyarray(py))
}

/// `stressfield.sphere_stress` on flat arrays of points: `[point, component]` over p0.
#[pyfunction]
fn sphere_stress<'py>(
    py: Python<'py>,
    x: PyReadonlyArray1<'py, f64>,
    y: PyReadonlyArray1<'py, f64>,
    z: PyReadonlyArray1<'py, f64>,
    friction: f64,
    poisson: f64,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let (x, y, z) = (x.as_array(), y.as_array(), z.as_array());
    closed_form_rows(py, friction, poisson, [("x", x), ("y", y), ("z", z)], |i| {
        stressfield::solution::sphere_hertz::stress_over_p0(x[i], y[i], z[i], friction, poisson)
    })
}

/// A length unit's size in m (`height_unit`, `length_unit`), with the command line's list.
fn unit_m(name: &str, unit: Option<&str>) -> Result<Option<f64>> {
    unit.map(|text| {
        read::length_unit_m(text).ok_or_else(|| {
            anyhow!(
                "{name} {}: use one of {}",
                stressfield::io::text::cut(text, 40),
                stressfield::io::units::Dimension::Length.unit_list()
            )
        })
    })
    .transpose()
}

/// `stressfield.read_surface`: a height file read as `surface FILE` reads it.
#[pyfunction]
#[pyo3(signature = (path, spacing, height_unit, length_unit, fill))]
#[allow(clippy::type_complexity)]
fn read_surface<'py>(
    py: Python<'py>,
    path: PathBuf,
    spacing: Option<(f64, f64)>,
    height_unit: Option<String>,
    length_unit: Option<String>,
    fill: &str,
) -> PyResult<(Bound<'py, PyArray2<f64>>, (f64, f64))> {
    let map = py
        .detach(|| -> Result<HeightMap> {
            let fill = match fill {
                "refuse" => Fill::Refuse,
                "interpolate" => Fill::Interpolate,
                other => bail!("fill {other}: use refuse or interpolate"),
            };
            let options = ReadOptions {
                spacing_m: spacing
                    .map(|(dx, dy)| spacing_pair(dx, dy, stressfield::scene::SPACING_BOUNDS))
                    .transpose()?,
                height_unit_m: unit_m("height_unit", height_unit.as_deref())?,
                xyz_length_unit_m: unit_m("length_unit", length_unit.as_deref())?,
                fill,
            };
            Ok(read::read_surface(&path, &options)?)
        })
        .map_err(raise)?;
    let [dx, dy] = map.spacing_m();
    Ok((map.into_heights_m().into_pyarray(py), (dx, dy)))
}

/// `stressfield.surface_stats`: `surface --json` of a height array.
#[pyfunction]
#[pyo3(signature = (heights, dx, dy, form, band, e_star, hardness, window))]
#[allow(clippy::too_many_arguments)]
fn surface_stats(
    py: Python<'_>,
    heights: PyReadonlyArray2<'_, f64>,
    dx: f64,
    dy: f64,
    form: &str,
    band: Option<(f64, f64)>,
    e_star: Option<f64>,
    hardness: Option<f64>,
    window: bool,
) -> PyResult<String> {
    let heights = heights.as_array();
    py.detach(|| -> Result<String> {
        let form = match form {
            "plane" => FormRemoval::Plane,
            "quadratic" => FormRemoval::Quadratic,
            other => bail!("form {other}: use plane or quadratic"),
        };
        let band_m = match band {
            Some((a, b)) => {
                let bounds = stressfield::scene::WAVELENGTH_BOUNDS;
                for (which, value) in [("shorter", a), ("longer", b)] {
                    if !bounds.contains(value) {
                        bail!(
                            "band: the {which} wavelength must lie between {} m and {} m, got {}\nhint: {}",
                            stressfield::io::text::compact(bounds.lo),
                            stressfield::io::text::compact(bounds.hi),
                            stressfield::io::text::number(value),
                            bounds.why
                        );
                    }
                }
                if a >= b {
                    bail!(
                        "band: give the shorter wavelength first, got {},{}",
                        stressfield::io::text::number(a),
                        stressfield::io::text::number(b)
                    );
                }
                Some((a, b))
            }
            None => None,
        };
        if let Some(e) = e_star {
            check_range("e_star", e, 1.0, 1e13, "Pa")?;
        }
        if let Some(h) = hardness {
            check_range("hardness", h, 1.0, 1e13, "Pa")?;
        }
        check_heights(heights, [dx, dy])?;
        // The statistics need the map as the library holds it: one copy.
        let map = HeightMap::new(heights.to_owned(), [dx, dy])?;
        let options = Options {
            form,
            band_m,
            window,
        };
        let characterisation =
            stats::characterise(&map, &options).context("characterising the heights")?;
        Ok(SurfaceReport::new(&characterisation, e_star, hardness).json())
    })
    .map_err(raise)
}

/// Whether the extension was built with Rerun (`Scene.record`).
#[pyfunction]
fn has_rerun() -> bool {
    cfg!(feature = "rerun")
}

#[pymodule]
fn _stressfield(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("StressfieldError", m.py().get_type::<StressfieldError>())?;
    m.add_class::<Scene>()?;
    m.add_function(wrap_pyfunction!(load_scene, m)?)?;
    m.add_function(wrap_pyfunction!(parse_scene, m)?)?;
    m.add_function(wrap_pyfunction!(contact, m)?)?;
    m.add_function(wrap_pyfunction!(stress, m)?)?;
    m.add_function(wrap_pyfunction!(line_stress, m)?)?;
    m.add_function(wrap_pyfunction!(sphere_stress, m)?)?;
    m.add_function(wrap_pyfunction!(read_surface, m)?)?;
    m.add_function(wrap_pyfunction!(surface_stats, m)?)?;
    m.add_function(wrap_pyfunction!(has_rerun, m)?)?;
    Ok(())
}

/// The arrays of a plastic study, computed without the GIL.
struct PlasticFields {
    plastic_strain: Array3<f64>,
    stress: Array4<f64>,
    residual_stress: Option<Array4<f64>>,
    pressure: Array2<f64>,
    surface_displacement: Array2<f64>,
    axes: [Vec<f64>; 3],
}

/// [`PlasticFields`] handed to Python: plastic strain, stress, residual stress (unloaded
/// only), pressure, surface displacement, x, y, z.
type PlasticArrays<'py> = (
    Bound<'py, PyArray3<f64>>,
    Bound<'py, PyArray4<f64>>,
    Option<Bound<'py, PyArray4<f64>>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
);
