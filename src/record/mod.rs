//! Rerun `.rrd` recordings of scenes: each section field as a colour-mapped depth image with its
//! raw values, the surface tractions, contact outlines and the maximum, the scene's parameters
//! and Hertz results as a markdown document, scalar series on a timeline, sweeps (one time
//! point per step) and, for point contacts, the volume as a 3-D point cloud.
//!
//! ## Layout of a recording (entity paths)
//! - `description`: markdown text of the scene, its contact and its `hertz` report (static).
//! - `sections/<k>/field`: panel `k`'s field as a `DepthImage` (values in the figure's stress
//!   unit, so hovering reads them; colour map and an explicit range shared by all steps), placed
//!   in the figure's physical coordinates by a `Transform3D` (static): pixel centres at the grid
//!   samples, horizontal coordinate to the right, the vertical one (depth, or y) downwards.
//! - `sections/<k>/values`: the same values as a `Tensor` with named dimensions.
//! - `sections/<k>/surface`, `sections/<k>/tractions`, `sections/<k>/outline`,
//!   `sections/<k>/maximum`, `sections/<k>/material_points`: line strips and labelled points in
//!   the same coordinates (tractions drawn above the surface, `z < 0`).
//! - `series/<k>/maximum`, `series/<k>/maximum_depth`, `series/<parameter>`: scalars per step.
//! - `history/<k>/point<j>/<component>`: stresses at material points as a load moves.
//! - `volume/points`, `volume/contact` (outline, and `patch`: a mesh shaded by the pressure),
//!   `volume/maximum`: the 3-D point cloud (z downwards).
//! - `log`: one line per step.
//!
//! Steps are time points of a sequence timeline named after the sweep's parameter (`friction`,
//! `load`, `position`), or `step` (a single point) for a scene without a sweep.

mod rough;

use std::path::{Path, PathBuf};

use rerun::RecordingStream;

use crate::field::{self, Axis, FieldError, Volume};
use crate::figure;
use crate::render::colormap::ColorScale;
use crate::render::{ColorMap, Figure};
use crate::scene::{ContactKind, Scene, SectionKind, SweepParameter, VolumeSpec};
use crate::study;

/// The application id of every recording.
pub const APPLICATION_ID: &str = "stressfield";

/// Errors while recording.
#[derive(Debug, thiserror::Error)]
pub enum RecordError {
    #[error(transparent)]
    Field(#[from] FieldError),
    #[error("sweep step {step}: {message}")]
    Step { step: usize, message: String },
    #[error("rerun: {0}")]
    Rerun(String),
    #[error("cannot write {path}: {message}\nhint: check that the directory exists and is writable, or choose another with --out-dir or -o")]
    Output { path: PathBuf, message: String },
}

impl From<rerun::RecordingStreamError> for RecordError {
    fn from(error: rerun::RecordingStreamError) -> Self {
        RecordError::Rerun(error.to_string())
    }
}

/// What was recorded, for the caller's message.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Summary {
    pub steps: usize,
    pub panels: usize,
    /// Points of the 3-D point cloud of the last step (0 without a volume).
    pub volume_points: usize,
}

/// Records `scene` into `path` atomically: into a temporary file in the same directory, renamed
/// once the recording is complete and its stream closed (a failure leaves no file behind).
pub fn record_to_file(
    scene: &Scene,
    path: &Path,
    on_row: &(dyn Fn() + Sync),
) -> Result<Summary, RecordError> {
    let output = |message: String| RecordError::Output {
        path: path.to_path_buf(),
        message,
    };
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let temp = tempfile::Builder::new()
        .prefix(".stressfield-")
        .suffix(".rrd.part")
        .tempfile_in(dir)
        .map_err(|e| output(e.to_string()))?
        .into_temp_path();
    let stream = rerun::RecordingStreamBuilder::new(APPLICATION_ID)
        .recording_name(scene.name.clone())
        .save(&temp)?;
    let summary = record_scene(scene, &stream, on_row).and_then(|summary| {
        stream
            .flush_blocking()
            .map_err(|e| RecordError::Rerun(e.to_string()))?;
        Ok(summary)
    });
    // The footer is written when the last handle of the stream is dropped.
    drop(stream);
    let summary = summary?;
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&temp, std::fs::Permissions::from_mode(0o644))
            .map_err(|e| output(e.to_string()))?;
    }
    temp.persist(path)
        .map_err(|e| output(e.error.to_string()))?;
    Ok(summary)
}

/// The name of the timeline of a scene's steps.
pub fn timeline(scene: &Scene) -> &'static str {
    scene.sweep.as_ref().map_or("step", |s| s.parameter.key())
}

/// Grid rows a recording of `scene` evaluates (its sections at every step), for progress.
pub fn rows(scene: &Scene) -> usize {
    if matches!(
        scene.contact.kind,
        ContactKind::Rough | ContactKind::Surface
    ) {
        return 0;
    }
    let steps = scene.sweep.as_ref().map_or(1, |s| s.values.len());
    let rows: usize = scene
        .panels
        .iter()
        .map(|p| study::plane(scene, p).v.count)
        .sum();
    steps * rows
}

/// Records every step of `scene` into `stream`; `on_row` is called once per evaluated grid
/// row ([`rows`] in all).
pub fn record_scene(
    scene: &Scene,
    stream: &RecordingStream,
    on_row: &(dyn Fn() + Sync),
) -> Result<Summary, RecordError> {
    if matches!(
        scene.contact.kind,
        ContactKind::Rough | ContactKind::Surface
    ) {
        return rough::record(scene, stream);
    }
    let steps = scene.sweep.as_ref().map_or(1, |s| s.values.len());
    let timeline = timeline(scene);
    stream.log_static(
        "description",
        &rerun::TextDocument::from_markdown(describe(scene)),
    )?;
    // Every step first, so that each panel keeps one colour range through the sweep.
    let mut step_scenes = Vec::with_capacity(steps);
    let mut figures = Vec::with_capacity(steps);
    for step in 0..steps {
        let step_scene = study::at_step(scene, step).map_err(|e| RecordError::Step {
            step,
            message: e.to_string(),
        })?;
        figures.push(figure::build(&step_scene, on_row)?);
        step_scenes.push(step_scene);
    }
    let panels = scene.panels.len();
    let ranges: Vec<(f64, f64)> = (0..panels)
        .map(|k| {
            let (lo, hi) = figures
                .iter()
                .flat_map(|f| f.panels[k].values.iter().copied())
                .filter(|v| v.is_finite())
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                    (lo.min(v), hi.max(v))
                });
            let map = figures[0].panels[k]
                .scale
                .as_ref()
                .map_or(figures[0].colormap, |s| s.colormap);
            let scale = ColorScale::for_range(map, lo, hi);
            (scale.lo, scale.hi)
        })
        .collect();
    for k in 0..panels {
        log_placement(stream, k, &figures[0])?;
    }
    send_blueprint(scene, stream, &figures[0])?;
    // The point clouds of every step, coloured on one scale.
    let volumes = match &scene.volume {
        Some(spec) => {
            let clouds = step_scenes
                .iter()
                .map(|step_scene| volume_cloud(step_scene, spec))
                .collect::<Result<Vec<_>, _>>()?;
            let (lo, hi) = clouds
                .iter()
                .flat_map(|c| c.values.iter().copied())
                .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), v| {
                    (lo.min(v), hi.max(v))
                });
            let map = match spec.quantity.kind() {
                crate::stress::QuantityKind::Signed => ColorMap::Diverging,
                _ => scene.figure.colormap,
            };
            let scale = ColorScale::for_range(map, f64::from(lo), f64::from(hi));
            stream.log_static("volume", &rerun::ViewCoordinates::RIGHT_HAND_Z_DOWN())?;
            Some((spec, clouds, scale))
        }
        None => None,
    };
    let mut volume_points = 0;
    for (step, (step_scene, figure)) in step_scenes.iter().zip(&figures).enumerate() {
        stream.set_time_sequence(timeline, step as i64);
        if let Some(sweep) = &scene.sweep {
            let text = sweep.describe(step, scene);
            stream.log("log", &rerun::TextLog::new(format!("step {step}: {text}")))?;
            stream.log(
                format!("series/{}", sweep.parameter.key()),
                &rerun::Scalars::new([sweep.values[step]]),
            )?;
        }
        for (k, panel) in figure.panels.iter().enumerate() {
            log_panel(stream, k, figure, panel, ranges[k], scene)?;
        }
        log_material_points(stream, step_scene)?;
        if let Some((spec, clouds, scale)) = &volumes {
            volume_points = log_volume(stream, step_scene, spec, &clouds[step], scale)?;
        }
    }
    Ok(Summary {
        steps,
        panels,
        volume_points,
    })
}

/// The viewer layout: one 2-D view per panel (its field, tractions and maximum in physical
/// coordinates), the 3-D volume, and beside them the description, the raw values, the series
/// and the steps.
fn send_blueprint(
    scene: &Scene,
    stream: &RecordingStream,
    figure: &Figure,
) -> Result<(), RecordError> {
    use rerun::blueprint::{
        Blueprint, BlueprintActivation, ContainerLike, Grid, Horizontal, Spatial2DView,
        Spatial3DView, Tabs, TensorView, TextDocumentView, TextLogView, TimeSeriesView, Vertical,
    };
    let mut maps: Vec<ContainerLike> = figure
        .panels
        .iter()
        .enumerate()
        .map(|(k, panel)| {
            let name = if panel.subtitle.is_empty() {
                format!("panel {k}")
            } else {
                panel.subtitle.clone()
            };
            Spatial2DView::new(name)
                .with_origin(format!("sections/{k}"))
                .with_contents(["$origin/**", "- $origin/values"])
                .into()
        })
        .collect();
    if scene.volume.is_some() {
        maps.push(
            Spatial3DView::new("volume (z down)")
                .with_origin("volume")
                .into(),
        );
    }
    let mut tabs: Vec<ContainerLike> = vec![TextDocumentView::new("scene")
        .with_origin("description")
        .into()];
    tabs.extend((0..figure.panels.len()).map(|k| {
        TensorView::new(format!("values {k}"))
            .with_origin(format!("sections/{k}/values"))
            .into()
    }));
    let mut side: Vec<ContainerLike> = vec![Tabs::new(tabs).into()];
    side.push(TimeSeriesView::new("maxima").with_origin("series").into());
    if let Some(sweep) = &scene.sweep {
        if !sweep.material_points.is_empty() {
            side.push(
                TimeSeriesView::new("stress history")
                    .with_origin("history")
                    .into(),
            );
        }
        side.push(TextLogView::new("steps").with_origin("log").into());
    }
    let root = Horizontal::new([Grid::new(maps).into(), Vertical::new(side).into()]);
    Blueprint::new(root).send(
        stream,
        BlueprintActivation {
            make_active: true,
            make_default: true,
        },
    )?;
    Ok(())
}

/// The static transform that places panel `k`'s image pixels at the grid samples.
fn log_placement(stream: &RecordingStream, k: usize, figure: &Figure) -> Result<(), RecordError> {
    log_panel_placement(stream, &format!("sections/{k}/field"), &figure.panels[k])
}

/// The static transform that places a panel's image pixels (entity `path`) at its samples.
fn log_panel_placement(
    stream: &RecordingStream,
    path: &str,
    panel: &crate::render::Panel,
) -> Result<(), RecordError> {
    let (du, dv) = (axis_step(&panel.x), axis_step(&panel.z));
    // Pixel (i, j) covers [i, i + 1) x [j, j + 1): its centre i + 1/2 maps to sample i.
    let translation = [
        (panel.x.min - 0.5 * du) as f32,
        (panel.z.min - 0.5 * dv) as f32,
        0.0,
    ];
    stream.log_static(
        path,
        &rerun::Transform3D::from_translation_scale(translation, [du as f32, dv as f32, 1.0]),
    )?;
    Ok(())
}

fn axis_step(axis: &Axis) -> f64 {
    if axis.count > 1 {
        axis.step()
    } else {
        1.0
    }
}

/// The Rerun colour map closest to a figure's.
fn rerun_colormap(map: ColorMap) -> rerun::components::Colormap {
    use rerun::components::Colormap;
    match map {
        ColorMap::Viridis => Colormap::Viridis,
        ColorMap::Inferno => Colormap::Inferno,
        ColorMap::Magma => Colormap::Magma,
        ColorMap::Plasma => Colormap::Plasma,
        // Rerun has no cividis; viridis is its nearest relative.
        ColorMap::Cividis => Colormap::Viridis,
        ColorMap::Turbo => Colormap::Turbo,
        // Rerun's one diverging map (red at the low end, blue at the high end).
        ColorMap::Diverging => Colormap::Spectral,
    }
}

/// One panel at the current step: field, raw values, surface, tractions, outlines, maximum and
/// its series.
fn log_panel(
    stream: &RecordingStream,
    k: usize,
    figure: &Figure,
    panel: &crate::render::Panel,
    range: (f64, f64),
    scene: &Scene,
) -> Result<(), RecordError> {
    let base = format!("sections/{k}");
    let values32 = panel.values.mapv(|v| v as f32);
    let map = panel.scale.as_ref().map_or(figure.colormap, |s| s.colormap);
    let image = rerun::DepthImage::try_from(values32.clone())
        .map_err(|e| RecordError::Rerun(e.to_string()))?
        .with_meter(1.0)
        .with_colormap(rerun_colormap(map))
        .with_depth_range(rerun::components::ValueRange::new(range.0, range.1));
    stream.log(format!("{base}/field"), &image)?;
    let (vertical, horizontal) = (figure.z_label.clone(), figure.x_label.clone());
    let tensor = rerun::Tensor::try_from(values32)
        .map_err(|e| RecordError::Rerun(e.to_string()))?
        .with_dim_names([vertical, horizontal]);
    stream.log(format!("{base}/values"), &tensor)?;
    let depth_section = figure.vertical_is_depth;
    if depth_section {
        let surface = [[panel.x.min as f32, 0.0], [panel.x.max as f32, 0.0]];
        stream.log(
            format!("{base}/surface"),
            &rerun::LineStrips2D::new([surface])
                .with_colors([rerun::Color::from_rgb(90, 90, 90)])
                .with_labels(["surface z = 0"]),
        )?;
        let tractions = traction_strips(panel);
        if !tractions.is_empty() {
            let (strips, labels): (Vec<_>, Vec<_>) = tractions.into_iter().unzip();
            let colors: Vec<rerun::Color> = labels
                .iter()
                .map(|label: &String| {
                    if label.starts_with('p') {
                        rerun::Color::from_rgb(30, 30, 30)
                    } else {
                        rerun::Color::from_rgb(200, 60, 30)
                    }
                })
                .collect();
            stream.log(
                format!("{base}/tractions"),
                &rerun::LineStrips2D::new(strips)
                    .with_colors(colors)
                    .with_labels(labels),
            )?;
        }
    }
    if !panel.outlines.is_empty() {
        let strips: Vec<Vec<[f32; 2]>> = panel
            .outlines
            .iter()
            .map(|line| line.iter().map(|&(u, v)| [u as f32, v as f32]).collect())
            .collect();
        stream.log(
            format!("{base}/outline"),
            &rerun::LineStrips2D::new(strips).with_colors([rerun::Color::from_rgb(255, 255, 255)]),
        )?;
    }
    let unit = figure.value_label.clone();
    if let Some(((iv, iu), value)) = grid_maximum(&panel.values) {
        let (u, v) = (panel.x.value(iu), panel.z.value(iv));
        let label = format!(
            "max {} = {value:.4} at ({u:.3}, {v:.3})",
            unit.split(' ').next().unwrap_or("value")
        );
        stream.log(
            format!("{base}/maximum"),
            &rerun::Points2D::new([[u as f32, v as f32]])
                .with_radii([rerun::Radius::new_ui_points(5.0)])
                .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                .with_labels([label]),
        )?;
        stream.log(format!("series/{k}/maximum"), &rerun::Scalars::new([value]))?;
        if depth_section {
            stream.log(
                format!("series/{k}/maximum_depth"),
                &rerun::Scalars::new([v]),
            )?;
        }
    }
    if let Some(sweep) = &scene.sweep {
        if !sweep.material_points.is_empty() {
            let points: Vec<[f32; 2]> = sweep
                .material_points
                .iter()
                .map(|&(x, z)| [x as f32, z as f32])
                .collect();
            let labels: Vec<String> = (0..points.len()).map(|j| format!("point{j}")).collect();
            stream.log(
                format!("{base}/material_points"),
                &rerun::Points2D::new(points)
                    .with_radii([rerun::Radius::new_ui_points(4.0)])
                    .with_colors([rerun::Color::from_rgb(0, 0, 0)])
                    .with_labels(labels),
            )?;
        }
    }
    Ok(())
}

/// The largest finite value of a map and its `(row, column)`.
fn grid_maximum(values: &ndarray::Array2<f64>) -> Option<((usize, usize), f64)> {
    values
        .indexed_iter()
        .filter(|(_, v)| v.is_finite())
        .max_by(|a, b| a.1.total_cmp(b.1))
        .map(|(index, &v)| (index, v))
}

/// The traction profiles drawn above the surface (`z < 0`): `p` and, where any, `q`, scaled
/// so that the larger peak rises a fifth of the panel's depth range.
fn traction_strips(panel: &crate::render::Panel) -> Vec<(Vec<[f32; 2]>, String)> {
    let peak = panel
        .traction
        .iter()
        .map(|s| s.p.abs().max(s.q.abs()))
        .fold(0.0f64, f64::max);
    if peak <= 0.0 {
        return Vec::new();
    }
    let height = 0.2 * (panel.z.max - panel.z.min);
    let scale = height / peak;
    let strip = |f: &dyn Fn(&crate::render::TractionSample) -> f64| -> Vec<[f32; 2]> {
        panel
            .traction
            .iter()
            .map(|s| [s.x as f32, (-scale * f(s)) as f32])
            .collect()
    };
    let mut strips = vec![(strip(&|s| s.p), format!("p (peak {peak:.4})"))];
    if panel.traction.iter().any(|s| s.q != 0.0) {
        strips.push((strip(&|s| s.q), "q".to_string()));
    }
    strips
}

/// Stresses at the sweep's material points (body frame) as a moving load passes: `σxx`,
/// `σzz`, `τxz` and the figure's quantity, in the figure's stress unit.
fn log_material_points(stream: &RecordingStream, scene: &Scene) -> Result<(), RecordError> {
    let Some(sweep) = &scene.sweep else {
        return Ok(());
    };
    if sweep.material_points.is_empty() {
        return Ok(());
    }
    let unit_over_a = study::length_unit_over_a(scene);
    let stress_per_p0 = study::DisplayUnits::of(scene).stress_per_p0;
    for (k, panel) in scene.panels.iter().enumerate() {
        let solution = study::solution(scene, panel)
            .map_err(|e| RecordError::Field(FieldError::Numerical(e.to_string())))?;
        let y = match scene.figure.section {
            SectionKind::Xz => panel.at * unit_over_a,
            _ => 0.0,
        };
        for (j, &(x, z)) in sweep.material_points.iter().enumerate() {
            // Finite on the surface on a strip or cell edge too (the mean of the neighbours).
            let s = solution.finite_stress_over_p0(x * unit_over_a, y, z * unit_over_a);
            let base = format!("history/{k}/point{j}");
            let quantity = scene.figure.quantity;
            let mut components = vec![("sxx", s.xx), ("szz", s.zz), ("sxz", s.xz)];
            if !components.iter().any(|(name, _)| *name == quantity.key()) {
                components.push((quantity.key(), quantity.of(&s)));
            }
            for (name, value) in components {
                stream.log(
                    format!("{base}/{name}"),
                    &rerun::Scalars::new([value * stress_per_p0]),
                )?;
            }
        }
    }
    Ok(())
}

/// A step's point cloud: positions (figure length unit) and values (figure stress unit).
struct Cloud {
    positions: Vec<[f32; 3]>,
    values: Vec<f32>,
    spacing: f64,
    maximum: Option<([f32; 3], f32)>,
}

/// Evaluates the scene's `[volume]` for its first panel's contact and keeps the points whose
/// |value| is at least `threshold` of the largest.
fn volume_cloud(scene: &Scene, spec: &VolumeSpec) -> Result<Cloud, RecordError> {
    let unit_over_a = study::length_unit_over_a(scene);
    let longest = (spec.x.1 - spec.x.0)
        .max(spec.y.1 - spec.y.0)
        .max(spec.z.1 - spec.z.0);
    let spacing = longest / (spec.points - 1) as f64;
    let axis = |(lo, hi): (f64, f64)| {
        let count = (((hi - lo) / spacing).round() as usize + 1).max(2);
        Axis::new(lo * unit_over_a, hi * unit_over_a, count)
    };
    let volume = Volume {
        x: axis(spec.x),
        y: axis(spec.y),
        z: axis(spec.z),
    };
    // The closed form where there is one (a numerical volume would take direct summation at
    // every point).
    let panel = &scene.panels[0];
    let solution = match study::closed_form(scene, panel) {
        Some(solution) => solution,
        None => study::solution(scene, panel)
            .map_err(|e| RecordError::Field(FieldError::Numerical(e.to_string())))?,
    };
    let field = field::evaluate_volume::<f32>(&solution, &volume, &[spec.quantity], &|| {})?;
    let block = field
        .block(spec.quantity)
        .ok_or_else(|| RecordError::Rerun("volume quantity missing".into()))?;
    let stress_per_p0 = study::DisplayUnits::of(scene).stress_per_p0;
    let largest = block
        .iter()
        .filter(|v| v.is_finite())
        .fold(0.0f32, |m, v| m.max(v.abs()));
    let cut = spec.threshold as f32 * largest;
    let mut cloud = Cloud {
        positions: Vec::new(),
        values: Vec::new(),
        spacing,
        maximum: None,
    };
    let to_unit = |value: f64| (value / unit_over_a) as f32;
    for ((iz, iy, ix), &value) in block.indexed_iter() {
        if !(value.is_finite() && value.abs() >= cut) {
            continue;
        }
        let position = [
            to_unit(volume.x.value(ix)),
            to_unit(volume.y.value(iy)),
            to_unit(volume.z.value(iz)),
        ];
        let shown = value * stress_per_p0 as f32;
        if cloud.maximum.is_none_or(|(_, m)| shown > m) {
            cloud.maximum = Some((position, shown));
        }
        cloud.positions.push(position);
        cloud.values.push(shown);
    }
    Ok(cloud)
}

/// Logs a step's point cloud, coloured on `scale` (one for all steps), with the contact outline on
/// the surface and the maximum labelled. Returns the number of points.
fn log_volume(
    stream: &RecordingStream,
    scene: &Scene,
    spec: &VolumeSpec,
    cloud: &Cloud,
    scale: &ColorScale,
) -> Result<usize, RecordError> {
    let colors: Vec<rerun::Color> = cloud
        .values
        .iter()
        .map(|&v| {
            let [r, g, b] = scale.rgb(f64::from(v));
            rerun::Color::from_rgb(r, g, b)
        })
        .collect();
    stream.log(
        "volume/points",
        &rerun::Points3D::new(cloud.positions.iter().copied())
            .with_colors(colors)
            .with_radii([(0.35 * cloud.spacing) as f32]),
    )?;
    let unit_over_a = study::length_unit_over_a(scene);
    let aspect = scene.contact.aspect;
    let centre = scene.load_centre_over_a;
    if matches!(
        scene.contact.kind,
        ContactKind::Point | ContactKind::Elliptical
    ) {
        let outline: Vec<[f32; 3]> = (0..=256)
            .map(|i| {
                let angle = std::f64::consts::TAU * f64::from(i) / 256.0;
                [
                    ((centre + angle.cos()) / unit_over_a) as f32,
                    (aspect * angle.sin() / unit_over_a) as f32,
                    0.0,
                ]
            })
            .collect();
        stream.log(
            "volume/contact",
            &rerun::LineStrips3D::new([outline])
                .with_colors([rerun::Color::from_rgb(20, 20, 20)])
                .with_labels(["contact"]),
        )?;
        stream.log("volume/contact/patch", &contact_patch(scene))?;
    }
    if let Some((position, value)) = cloud.maximum {
        stream.log(
            "volume/maximum",
            &rerun::Points3D::new([position])
                .with_radii([cloud.spacing as f32])
                .with_colors([rerun::Color::from_rgb(255, 255, 255)])
                .with_labels([format!(
                    "max {} = {value:.4} at ({:.3}, {:.3}, {:.3})",
                    spec.quantity.symbol(),
                    position[0],
                    position[1],
                    position[2]
                )]),
        )?;
    }
    Ok(cloud.positions.len())
}

/// The contact patch on the surface `z = 0` as a mesh of rings, shaded by the Hertz pressure
/// `p/p0 = sqrt(1 - r²)` (white at the edge, dark red at the centre), in the figure's length
/// unit and at the load's current position.
fn contact_patch(scene: &Scene) -> rerun::Mesh3D {
    const RINGS: usize = 12;
    const SEGMENTS: usize = 96;
    let unit_over_a = study::length_unit_over_a(scene);
    let (aspect, centre) = (scene.contact.aspect, scene.load_centre_over_a);
    let shade = |r: f64| {
        let p = (1.0 - r * r).max(0.0).sqrt();
        let mix = |white: f64, dark: f64| (white + (dark - white) * p).round() as u8;
        rerun::Color::from_rgb(mix(255.0, 150.0), mix(255.0, 20.0), mix(255.0, 20.0))
    };
    let mut positions = vec![[(centre / unit_over_a) as f32, 0.0, 0.0]];
    let mut colors = vec![shade(0.0)];
    for ring in 1..=RINGS {
        let r = ring as f64 / RINGS as f64;
        for k in 0..SEGMENTS {
            let angle = std::f64::consts::TAU * k as f64 / SEGMENTS as f64;
            positions.push([
                ((centre + r * angle.cos()) / unit_over_a) as f32,
                (aspect * r * angle.sin() / unit_over_a) as f32,
                0.0,
            ]);
            colors.push(shade(r));
        }
    }
    // Vertex of ring `ring` (1-based), segment `k`.
    let index = |ring: usize, k: usize| (1 + (ring - 1) * SEGMENTS + k % SEGMENTS) as u32;
    let mut triangles = Vec::new();
    for k in 0..SEGMENTS {
        triangles.push([0, index(1, k), index(1, k + 1)]);
    }
    for ring in 1..RINGS {
        for k in 0..SEGMENTS {
            let (a, b) = (index(ring, k), index(ring, k + 1));
            let (c, d) = (index(ring + 1, k), index(ring + 1, k + 1));
            triangles.push([a, c, d]);
            triangles.push([a, d, b]);
        }
    }
    rerun::Mesh3D::new(positions)
        .with_triangle_indices(triangles)
        .with_vertex_colors(colors)
}

/// The markdown description of a scene: title, contact, sweep and the `hertz` report.
pub fn describe(scene: &Scene) -> String {
    let mut text = format!(
        "# {}\n\n",
        scene.title.clone().unwrap_or_else(|| scene.name.clone())
    );
    text.push_str(&format!(
        "Scene `{}`: {} panel(s) of {} ({}), {} section.\n\n",
        scene.name,
        scene.panels.len(),
        scene.figure.quantity.description(),
        scene
            .figure
            .stress_unit
            .label(scene.figure.quantity.symbol()),
        scene.figure.section.key(),
    ));
    if let Some(sweep) = &scene.sweep {
        let first = sweep.describe(0, scene);
        let last = sweep.describe(sweep.values.len() - 1, scene);
        text.push_str(&format!(
            "**Sweep** over {}: {} steps, from {first} to {last}, on the timeline `{}`.\n\n",
            sweep.parameter.key(),
            sweep.values.len(),
            sweep.parameter.key()
        ));
        if sweep.parameter == SweepParameter::Position {
            text.push_str("The field is drawn in a fixed body frame as the contact's centre moves to x0: the stress history of each material point.\n\n");
        }
    }
    text.push_str("Conventions: z points into the body (depth drawn downwards), tension positive, q = μp acts in +x on the body (trailing edge x = −a).\n\n");
    text.push_str("## Contact (`stressfield hertz`)\n\n```text\n");
    text.push_str(&crate::report::hertz(scene));
    text.push_str("```\n");
    text
}
