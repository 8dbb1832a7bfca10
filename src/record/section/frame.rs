//! Where a map view's parts go: the panel as displayed (depth down), and the frame of a map
//! in its view (margins, strip, colour bar) in the viewer's pixels.

use super::*;

/// The panel as drawn in a view, whose vertical axis points down: a depth as it is; a map
/// seen from above (y up in the figure) with its rows reversed and its vertical coordinate
/// negated, so that it reads as the PNG figure does. Labels undo the negation
/// ([`Notation::position`]).
pub fn displayed(figure: &Figure, panel: &Panel) -> Panel {
    let mut shown = panel.clone();
    if !figure.axes_of(panel).vertical_is_depth {
        let rows = panel.values.nrows();
        shown.values = ndarray::Array2::from_shape_fn(panel.values.dim(), |(row, column)| {
            panel.values[[rows - 1 - row, column]]
        });
        shown.z = crate::field::Axis::new(-panel.z.max, -panel.z.min, panel.z.count);
        for line in &mut shown.outlines {
            for point in line.iter_mut() {
                point.1 = -point.1;
            }
        }
    }
    shown
}

/// Whether a row is logged once for the whole recording or at the current step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum When {
    Static,
    Step,
}

/// Logs `archetype` at `path`, statically or at the current step.
pub fn put(
    stream: &RecordingStream,
    when: When,
    path: impl Into<rerun::EntityPath>,
    archetype: &impl rerun::AsComponents,
) -> Result<(), RecordError> {
    match when {
        When::Static => stream.log_static(path, archetype)?,
        When::Step => stream.log(path, archetype)?,
    }
    Ok(())
}

/// The geometry of a panel's view, in its coordinates.
#[derive(Clone, Debug)]
pub struct Frame {
    /// The field's extent (pixel edges).
    pub u: (f64, f64),
    pub v: (f64, f64),
    /// Height of the traction strip above the surface (0 without tractions).
    pub strip: f64,
    /// Pixels per unit (estimated from the view's size).
    pub px: f64,
    /// The colour bar's horizontal extent.
    pub bar: (f64, f64),
    /// Centres of the title row and of the legend row (above the strip).
    pub title_row: f64,
    pub legend_row: f64,
    /// What the view shows at first: `[u_min, u_max, v_min, v_max]`.
    pub bounds: [f64; 4],
}

impl Frame {
    /// The frame of `panel` in a view of about `view_px` pixels (width, height); `tick_chars`
    /// is the longest colour-bar label.
    pub fn new(panel: &Panel, has_strip: bool, view_px: (f64, f64), tick_chars: usize) -> Self {
        let (du, dv) = (step(&panel.x), step(&panel.z));
        let u = (panel.x.min - 0.5 * du, panel.x.max + 0.5 * du);
        let v = (panel.z.min - 0.5 * dv, panel.z.max + 0.5 * dv);
        let (width, depth) = (u.1 - u.0, v.1 - v.0);
        let strip = if has_strip { 0.2 * depth } else { 0.0 };
        // Two passes: the text's size in units depends on the scale, the scale on the bounds.
        let mut px = (view_px.0 / (1.3 * width)).min(view_px.1 / (1.5 * depth));
        let mut frame = None;
        for _ in 0..2 {
            let label = LABEL_PX / px;
            let gap = 8.0 / px;
            let bar = (u.1 + 0.03 * width, u.1 + 0.03 * width + 16.0 / px);
            let legend_row = v.0 - strip - 1.1 * label;
            let title_row = if has_strip {
                legend_row - 1.4 * label
            } else {
                v.0 - 1.1 * label
            };
            let right = bar.1 + gap + (tick_chars as f64 * CHAR_PX + 12.0) / px;
            let bounds = [u.0 - gap, right, title_row - 0.9 * label, v.1 + 2.5 * label];
            let fit =
                (view_px.0 / (bounds[1] - bounds[0])).min(view_px.1 / (bounds[3] - bounds[2]));
            frame = Some(Self {
                u,
                v,
                strip,
                px: fit,
                bar,
                title_row,
                legend_row,
                bounds,
            });
            px = fit;
        }
        frame.expect("two passes")
    }

    pub(super) fn label_height(&self) -> f64 {
        LABEL_PX / self.px
    }

    /// Where a leader from `point` meets the label centred at `centre`: the middle of the
    /// label's top edge, or of its bottom edge for a label above the point.
    pub(super) fn leader_end(&self, (cu, cv): (f64, f64), (_, v): (f64, f64)) -> [f32; 2] {
        let edge = if cv >= v { -0.5 } else { 0.5 };
        [cu as f32, (cv + edge * self.label_height()) as f32]
    }

    /// The anchor point of a label whose text is centred at `(u, v)`.
    pub(super) fn anchor(&self, u: f64, v: f64) -> [f32; 2] {
        [u as f32, (v - 0.5 * self.label_height()) as f32]
    }
}

pub(super) fn step(axis: &crate::field::Axis) -> f64 {
    if axis.count > 1 {
        axis.step()
    } else {
        1.0
    }
}
