//! `stressfield._stressfield`: the Python package's extension, a thin layer over the library's
//! study and report functions (the same ones the command line calls), so that every result is
//! the command line's.
//!
//! Arrays come in as NumPy float64 views of any order (C or Fortran: read through their
//! strides, not copied) and go out as arrays moved into NumPy (not copied). Computation runs
//! with the GIL released (`Python::detach`). Errors raise `StressfieldError` (a `ValueError`)
//! with the text the command line prints after `error: `. The Python wrapper
//! (`stressfield/__init__.py`) checks the arguments' kinds, broadcasts, and builds the result
//! objects; the JSON objects are passed as the command line's text and parsed there, so that
//! every number is the command line's to the last digit.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context};
use ndarray::{Array2, Array4, ArrayView1, Axis};
use numpy::{IntoPyArray, PyArray2, PyArray4, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use rayon::prelude::*;

use stressfield::contact::rough::{self as rough_contact, Control, RoughContactProblem};
use stressfield::operator::elastic::Periodicity;
use stressfield::report::rough::ContactReport;
use stressfield::report::surface::SurfaceReport;
use stressfield::report::thermal::ThermalReport;
use stressfield::scene::{ContactKind, RoughSpec};
use stressfield::solution::dcfft::{DcFft, TractionGrid};
use stressfield::study;
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

/// `contact SCENE`'s computation: the solved contact, its report and, with `[thermal]`, the
/// heating on it.
fn scene_contact(scene: &stressfield::scene::Scene, file: &str) -> Result<(String, Array2<f64>)> {
    if scene.contact.kind != ContactKind::Rough {
        bail!(
            "{file} is not a rough contact scene (contact.kind = \"rough\")\nhint: `stressfield hertz {file}` reports Hertz contacts"
        );
    }
    let solution = study::rough::solve(scene, &mut |_, _| {})
        .with_context(|| format!("scene {}", scene.name))?;
    let findings = study::rough::findings(scene, &solution)?;
    let report = ContactReport::new(scene, &solution, &findings);
    let thermal = match scene.thermal {
        // The heating reuses the maxima just found (its contact alone's).
        Some(_) => Some(ThermalReport::new(
            &study::thermal::study_with(
                scene,
                Some(&solution),
                Some(study::thermal::ContactMaxima {
                    maxima: &findings.maxima,
                    friction: scene.contact.friction,
                    poisson: scene.contact.poisson,
                }),
                &mut |_| {},
            )
            .context("frictional heating")
            .with_context(|| format!("scene {}", scene.name))?,
        )),
        None => None,
    };
    Ok((report.json_with(thermal.as_ref()), solution.pressure_pa))
}

/// The heating of a Hertz or gear scene (the gears' along their path), as `hertz` and
/// `thermal` compute it.
fn hertz_heating(
    scene: &stressfield::scene::Scene,
) -> Result<(ThermalReport, study::thermal::ThermalStudy)> {
    let gears = scene.thermal.and_then(|t| t.gear).is_some();
    Ok(if gears {
        let gear = study::gear_heating::gear_heating(scene, &mut |_| {})
            .context("frictional heating of the gears")?;
        (ThermalReport::for_gears(&gear), gear.study.clone())
    } else {
        let study =
            study::thermal::study(scene, None, &mut |_| {}).context("frictional heating")?;
        (ThermalReport::new(&study), study)
    })
}

/// `surface SCENE --json` of a surface scene.
fn scene_surface_json(scene: &stressfield::scene::Scene, file: &str) -> Result<String> {
    let Some(surface) = &scene.surface else {
        bail!("{file} has no [surface]: characterise a surface scene (kind = \"surface\" or \"rough\") or a height file");
    };
    let rough = scene.contact.rough;
    let options = Options {
        form: surface.form,
        band_m: surface.band_m,
        window: !surface.generated,
    };
    let characterisation = stats::characterise(&surface.heights, &options)
        .with_context(|| format!("characterising {}", surface.source))?;
    Ok(SurfaceReport::new(
        &characterisation,
        rough.and_then(|r| r.e_star_pa),
        rough.and_then(|r| r.hardness_pa),
    )
    .json())
}

/// `hertz SCENE --json`.
fn scene_hertz_json(scene: &stressfield::scene::Scene, file: &str) -> Result<String> {
    match scene.contact.kind {
        ContactKind::Rough => Ok(scene_contact(scene, file)?.0),
        ContactKind::Surface => scene_surface_json(scene, file),
        _ => {
            let maxima = study::assess::scene_maxima(scene);
            let heating = match scene.thermal {
                Some(_) => {
                    Some(hertz_heating(scene).with_context(|| format!("scene {}", scene.name))?)
                }
                None => None,
            };
            let report = stressfield::report::hertz::HertzReport::new(scene, &maxima);
            Ok(report.json(heating.as_ref().map(|(report, _)| report)))
        }
    }
}

/// `thermal SCENE --json` and body 1's surface temperature rise (K).
fn scene_thermal(scene: &stressfield::scene::Scene, file: &str) -> Result<(String, Array2<f64>)> {
    if scene.thermal.is_none() {
        bail!(
            "{file} has no [thermal] table\nhint: add [thermal] with speed = \"2 m/s\" and the bodies' thermal properties (material = \"steel\", or conductivity, diffusivity, expansion); see docs/heating.md"
        );
    }
    let computed = || -> Result<(ThermalReport, study::thermal::ThermalStudy)> {
        if scene.contact.kind == ContactKind::Rough {
            let solution = study::rough::solve(scene, &mut |_, _| {})?;
            let study = study::thermal::study(scene, Some(&solution), &mut |_| {})
                .context("frictional heating")?;
            Ok((ThermalReport::new(&study), study))
        } else {
            hertz_heating(scene)
        }
    };
    let (report, study) = computed().with_context(|| format!("scene {}", scene.name))?;
    Ok((report.json(), study.body1.temperature_k))
}

/// The scene's figure (or sheet) as `render` draws it, as PNG or SVG bytes.
fn scene_drawing(scene: &stressfield::scene::Scene, svg: bool) -> Result<Vec<u8>> {
    let drawing = if scene.wear.is_some() {
        let study = study::wear::study(scene, &mut |_| {})?;
        stressfield::figure::Drawing::Sheet(stressfield::figure::wear::wear_sheet(scene, &study))
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

    /// `hertz SCENE --json` as text.
    fn hertz_json(&self, py: Python<'_>) -> PyResult<String> {
        py.detach(|| scene_hertz_json(&self.scene, &self.file))
            .map_err(raise)
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

    /// `contact SCENE --json` as text, and the pressure (Pa, `[rows, columns]`).
    fn contact<'py>(&self, py: Python<'py>) -> PyResult<(String, Bound<'py, PyArray2<f64>>)> {
        let (json, pressure) = py
            .detach(|| scene_contact(&self.scene, &self.file))
            .map_err(raise)?;
        Ok((json, pressure.into_pyarray(py)))
    }

    /// `thermal SCENE --json` as text, and body 1's surface temperature rise (K, `[rows,
    /// columns]` of the thermal grid).
    fn thermal<'py>(&self, py: Python<'py>) -> PyResult<(String, Bound<'py, PyArray2<f64>>)> {
        let (json, temperature) = py
            .detach(|| scene_thermal(&self.scene, &self.file))
            .map_err(raise)?;
        Ok((json, temperature.into_pyarray(py)))
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

/// A positive, finite spacing pair (m), named as the Python argument.
fn spacing_pair(dx: f64, dy: f64) -> Result<[f64; 2]> {
    for (name, value) in [("dx", dx), ("dy", dy)] {
        if !(value.is_finite() && (stressfield::surface::MIN_SPACING_M..=1e4).contains(&value)) {
            bail!(
                "spacing: {name} must lie between 1e-10 m and 10000 m, got {}",
                stressfield::io::text::number(value)
            );
        }
    }
    Ok([dx, dy])
}

/// `stressfield.contact`: the rough contact of a height array, solved and reported as
/// `contact --json` reports a scene's.
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
    let (json, pressure) = py
        .detach(|| -> Result<(String, Array2<f64>)> {
            let spacing_m = spacing_pair(dx, dy)?;
            check_range("e_star", e_star, 1.0, 1e13, "Pa")?;
            if let Some(h) = hardness {
                check_range("hardness", h, 1.0, 1e13, "Pa")?;
            }
            if !(-1.0 < poisson && poisson <= 0.5) {
                bail!(
                    "poisson must lie in (-1, 0.5], got {}",
                    stressfield::io::text::number(poisson)
                );
            }
            if !(friction.is_finite() && friction >= 0.0) {
                bail!(
                    "friction must be a non-negative number, got {}",
                    stressfield::io::text::number(friction)
                );
            }
            let control = match control {
                "load" => {
                    check_range("load", value, 0.0, f64::MAX, "N")?;
                    Control::Load { newtons: value }
                }
                "mean_pressure" => {
                    check_range("mean_pressure", value, 0.0, f64::MAX, "Pa")?;
                    Control::MeanPressure { pa: value }
                }
                "approach" => Control::Approach { m: value },
                other => bail!("unknown control {other}: use load, mean_pressure or approach"),
            };
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
            let solution = rough_contact::solve(&problem, &mut |_, _| {})?;
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
        })
        .map_err(raise)?;
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

/// An optional traction array: copied into the grid (scaled to the reference pressure).
fn traction(array: &Option<PyReadonlyArray2<'_, f64>>) -> Option<Array2<f64>> {
    array
        .as_ref()
        .map(|a| a.as_array().mapv(|p| p / REFERENCE_PRESSURE_PA))
}

/// `stressfield.stress`: the stresses under uniform tractions on the cells of a grid, by
/// DC-FFT, at the cell centres of each depth: `[depth, row, column, component]` in Pa.
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
    // The grid in the rough study's reference units (1 µm, 1 MPa), as its layers are.
    let (p, qx, qy) = (traction(&pressure), traction(&shear_x), traction(&shear_y));
    let depths = depths.as_array();
    let layers = py
        .detach(|| -> Result<Array4<f64>> {
            let [dx, dy] = spacing_pair(dx, dy)?;
            if !(-1.0 < poisson && poisson <= 0.5) {
                bail!(
                    "poisson must lie in (-1, 0.5], got {}",
                    stressfield::io::text::number(poisson)
                );
            }
            if let Some(&z) = depths.iter().find(|z| !(z.is_finite() && **z >= 0.0)) {
                bail!(
                    "depths must be non-negative and finite (m, into the body), got {}",
                    stressfield::io::text::number(z)
                );
            }
            let grid = TractionGrid::new(
                [0.0, 0.0],
                [dx / REFERENCE_LENGTH_M, dy / REFERENCE_LENGTH_M],
                p,
                qx,
                qy,
            )?;
            let fft = if periodic {
                DcFft::periodic(&grid, poisson)?
            } else {
                DcFft::new(&grid, poisson)?
            };
            layers_of(&fft, depths)
        })
        .map_err(raise)?;
    Ok(layers.into_pyarray(py))
}

/// The DC-FFT layers at `depths_m`, in parallel over the depths, `[depth, row, column,
/// component]` in Pa.
fn layers_of(fft: &DcFft, depths_m: ArrayView1<f64>) -> Result<Array4<f64>> {
    let [ny, nx] = fft.shape();
    let depths: Vec<f64> = depths_m.iter().copied().collect();
    let mut out = Array4::<f64>::zeros((depths.len(), ny, nx, 6));
    out.axis_iter_mut(Axis(0))
        .into_par_iter()
        .zip(depths.par_iter())
        .try_for_each(|(mut slot, &z)| -> Result<()> {
            let layer = fft.layer(z / REFERENCE_LENGTH_M)?;
            for (c, component) in layer.axis_iter(Axis(0)).enumerate() {
                slot.index_axis_mut(Axis(2), c)
                    .zip_mut_with(&component, |o, &v| *o = v * REFERENCE_PRESSURE_PA);
            }
            Ok(())
        })?;
    Ok(out)
}

/// Friction and Poisson ratio of a closed form, checked as scenes check them.
fn closed_form_parameters(friction: f64, poisson: f64) -> Result<()> {
    if !(friction.is_finite() && friction >= 0.0) {
        bail!(
            "friction must be a non-negative number, got {}",
            stressfield::io::text::number(friction)
        );
    }
    if !(-1.0 < poisson && poisson <= 0.5) {
        bail!(
            "poisson must lie in (-1, 0.5], got {}",
            stressfield::io::text::number(poisson)
        );
    }
    Ok(())
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
    closed_form_rows(py, friction, poisson, z, |i| {
        stressfield::solution::line_hertz::stress_over_p0(x[i], z[i], friction, poisson)
    })
}

/// Depths of the closed forms: z >= 0 (into the body), finite.
fn check_depths<'a>(mut z: impl Iterator<Item = &'a f64>) -> Result<()> {
    if let Some(&bad) = z.find(|z| !(z.is_finite() && **z >= 0.0)) {
        bail!(
            "z must be non-negative and finite (into the body, units of a), got {}",
            stressfield::io::text::number(bad)
        );
    }
    Ok(())
}

/// A closed form's stresses at the points `0..z.len()` (the Python side broadcast the
/// coordinates to one length), in parallel and without the GIL: `[point, component]`, the
/// components in `Stress` order (xx, yy, zz, yz, xz, xy), after the parameters and depths
/// are checked.
fn closed_form_rows<'py>(
    py: Python<'py>,
    friction: f64,
    poisson: f64,
    z: ArrayView1<'_, f64>,
    stress: impl Fn(usize) -> stressfield::stress::Stress + Sync,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let out = py
        .detach(|| -> Result<Array2<f64>> {
            closed_form_parameters(friction, poisson)?;
            check_depths(z.iter())?;
            let mut out = Array2::zeros((z.len(), 6));
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
    closed_form_rows(py, friction, poisson, z, |i| {
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
                spacing_m: spacing.map(|(dx, dy)| spacing_pair(dx, dy)).transpose()?,
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
                let [a, b] = spacing_pair(a, b).map_err(|e| anyhow!("band: {e}"))?;
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
        // The statistics need the map as the library holds it: one copy.
        let map = HeightMap::new(heights.to_owned(), spacing_pair(dx, dy)?)?;
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
