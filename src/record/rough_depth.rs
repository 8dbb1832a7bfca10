//! A rough scene's stress through depth ([`crate::study::rough_sheet::depth_layers`]): the map
//! view `depth` stepping down on the timeline `depth` (layers numbered from 1 at the surface,
//! closer near the surface, the depth of the report's maximum among them), and the chart
//! `charts/depth_maxima` of the largest σvM and Tresca stress against depth.

use rerun::RecordingStream;

use super::rough::{load_text, log_map_static, log_map_step, rerun_error};
use super::section::When;
use super::{step_time, RecordError};
use crate::contact::rough::RoughSolution;
use crate::render::chart::{Chart, Series, Style, PALETTE};
use crate::render::{Figure, Mark, Panel};
use crate::scene::Scene;
use crate::study::rough::REFERENCE_LENGTH_M;
use crate::study::rough_sheet::DepthLayer;

/// The report's maximum (`contact`): its von Mises value (Pa) and depth (reference length).
#[derive(Clone, Copy, Debug)]
pub(super) struct Reported {
    pub value_pa: f64,
    pub z: f64,
    /// How the maps are rolled (a periodic contact's, centred on the report's maximum).
    pub roll: crate::study::map_roll::Roll,
}

/// The scene's stress quantity in planes parallel to the surface, stepping down on the
/// `depth` timeline, in the view framed by `frame`, with the chart of the largest stresses
/// against depth; with `on_load`, the layer of the report's maximum on the timeline `load`
/// too (at its first step, so that it shows at every load).
#[allow(clippy::too_many_arguments)]
pub(super) fn log_depth_steps(
    stream: &RecordingStream,
    scene: &Scene,
    solution: &RoughSolution,
    reported: Reported,
    frame: &super::section::Frame,
    on_load: bool,
    on_row: &(dyn Fn() + Sync),
    flush: &dyn Fn() -> Result<(), RecordError>,
) -> Result<(), RecordError> {
    let [dx, dy] = solution.spacing_m;
    let (ny, nx) = solution.pressure_pa.dim();
    let quantity = scene.figure.quantity;
    let per_pa = 1.0 / scene.figure.stress_unit.pascals(1.0);
    let layers = crate::study::rough_sheet::depth_layers(scene, solution, reported.z, on_row)
        .map_err(rerun_error)?;
    // Each layer's finite extremes: the colour range of all.
    let (lo, hi) = layers
        .iter()
        .flat_map(|layer| layer.values_pa.iter().copied())
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    // A non-negative quantity's colours to the 99.5 % quantile of all layers' values (one
    // cell's spike at the surface would leave the deeper layers one dark colour); values
    // beyond take the top colour, each layer's labelled maximum keeps its value.
    let hi = if lo >= 0.0 {
        let all: Vec<f64> = layers
            .iter()
            .flat_map(|layer| layer.values_pa.iter().copied())
            .collect();
        crate::render::robust_top(&all).0.max(f64::MIN_POSITIVE)
    } else {
        hi
    };
    let (lo, hi) = (lo * per_pa, hi * per_pa);
    let count = layers.len();
    // The layer of the report's maximum (its depth is one of the layers').
    let reported_layer = layers
        .iter()
        .enumerate()
        .min_by(|(_, a), (_, b)| {
            (a.z - reported.z)
                .abs()
                .total_cmp(&(b.z - reported.z).abs())
        })
        .map_or(0, |(k, _)| k);
    let (x_axis, y_axis) = reported.roll.axes([ny, nx], [dx * 1e6, dy * 1e6]);
    let mut preview = None;
    for (k, layer) in layers.iter().enumerate() {
        stream.set_time_sequence("depth", step_time(k));
        let depth_um = layer.z * REFERENCE_LENGTH_M * 1e6;
        let figure = Figure {
            title: quantity.description().into(),
            panels: vec![Panel {
                subtitle: String::new(),
                x: x_axis,
                z: y_axis,
                values: reported
                    .roll
                    .apply(layer.values_pa.view())
                    .mapv(|v| v * per_pa),
                traction: Vec::new(),
                half_width: 0.0,
                outlines: Vec::new(),
                scale: None,
                peak: None,
                axes: None,
            }],
            value_label: scene.figure.stress_unit.label(quantity.symbol()),
            x_label: "x (µm)".into(),
            z_label: "y (µm)".into(),
            vertical_is_depth: false,
            traction_label: String::new(),
            colormap: scene.figure.colormap,
            levels: crate::render::Levels::Count(0),
            mark: Mark::Max,
            panel_width_px: 400,
        };
        let range = super::rough::map_range(&figure, &figure.panels[0], Some((lo, hi)));
        let shown = super::section::displayed(&figure, &figure.panels[0]);
        if k == 0 {
            log_map_static(stream, "depth", frame, &figure, &shown, Some(range))?;
        }
        let mut title = format!(
            "layer {} of {count}: z = {} µm deep, {}",
            step_time(k),
            crate::scene::compact(depth_um),
            load_text(scene, solution)
        );
        if k == reported_layer {
            title.push_str(": the report's largest σvM");
        }
        log_map_step(
            stream,
            When::Step,
            "depth",
            frame,
            &figure,
            &shown,
            range,
            &title,
        )?;
        stream.log("series/depth_um", &rerun::Scalars::new([depth_um]))?;
        if on_load {
            // The charts against W have values on this timeline too, the scene's load's
            // (flat through depth: the layers are all under that load), so that they are
            // not left empty with a missing-component error when the time panel is on `depth`.
            for (path, value) in [
                ("series/contact_fraction", solution.contact_fraction),
                ("series/spots", solution.spots as f64),
                ("series/max_pressure_mpa", solution.max_pressure_pa * 1e-6),
            ] {
                stream.log(path, &rerun::Scalars::new([value]))?;
            }
        }
        let chart = depth_chart(&layers, k, reported)?;
        stream.log(
            "charts/depth_maxima",
            &rerun::EncodedImage::from_file_contents(chart),
        )?;
        flush()?;
        if k == reported_layer {
            preview = Some((figure, shown, range, title));
        }
    }
    if let Some((figure, shown, range, title)) = preview.filter(|_| on_load) {
        stream.disable_timeline("depth");
        stream.set_time_sequence("load", step_time(0));
        if let Some(values) = super::value_timeline(scene) {
            stream.set_time_sequence(values.timeline()?, values.values[0]);
        }
        let title = format!("{title} (the timeline \"depth\" steps down)");
        log_map_step(
            stream,
            When::Step,
            "depth",
            frame,
            &figure,
            &shown,
            range,
            &title,
        )?;
        stream.log(
            "charts/depth_maxima",
            &rerun::EncodedImage::from_file_contents(depth_chart(
                &layers,
                reported_layer,
                reported,
            )?),
        )?;
        super::rough::disable_load_timelines(stream, scene);
        flush()?;
    }
    Ok(())
}

/// The largest von Mises and Tresca stresses of every layer against depth (MPa against µm),
/// the current layer marked and the report's maximum ringed, as a PNG.
fn depth_chart(
    layers: &[DepthLayer],
    current: usize,
    reported: Reported,
) -> Result<Vec<u8>, RecordError> {
    let um = |z: f64| z * REFERENCE_LENGTH_M * 1e6;
    let mut chart = Chart::new(
        "largest stresses against depth",
        "depth z (µm)",
        "largest stress (MPa)",
    );
    let deepest = layers.last().map_or(1.0, |l| um(l.z));
    let highest = layers
        .iter()
        .map(|l| l.max_von_mises_pa)
        .fold(reported.value_pa, f64::max)
        * 1e-6;
    chart.x_range = Some((0.0, deepest.max(1e-9)));
    chart.y_range = Some((0.0, (1.25 * highest).max(1e-9)));
    // The shape of its panel in the default window (a third of its width, a third of its
    // height), so that the viewer fits the image without black bands.
    chart.width_px = 560;
    chart.height_px = 340;
    for (label, colour, of) in [
        (
            "max σvM",
            PALETTE[1],
            &(|l: &DepthLayer| l.max_von_mises_pa) as &dyn Fn(&DepthLayer) -> f64,
        ),
        ("max τ Tresca", PALETTE[0], &|l: &DepthLayer| {
            l.max_tresca_pa
        }),
    ] {
        chart.series.push(Series {
            label: label.into(),
            points: layers.iter().map(|l| (um(l.z), of(l) * 1e-6)).collect(),
            style: Style::Line,
            colour,
        });
        if let Some(layer) = layers.get(current) {
            chart.series.push(Series {
                label: String::new(),
                points: vec![(um(layer.z), of(layer) * 1e-6)],
                style: Style::Markers,
                colour,
            });
        }
    }
    chart.series.push(Series {
        label: "report's max σvM".into(),
        points: vec![(um(reported.z), reported.value_pa * 1e-6)],
        style: Style::Markers,
        colour: PALETTE[3],
    });
    super::chart_png_bytes(&chart)
}
