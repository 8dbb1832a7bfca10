//! Which panels share a colour scale: runs of consecutive panels with the same
//! [`PanelScale`](super::PanelScale) (or the figure's shared scale), each with its colour range,
//! contour levels and colour-bar caption. Layout puts one colour bar after each group; the plan
//! colours and contours each panel on its group's scale.

use std::ops::Range;

use ndarray::ArrayView2;

use super::colormap::ColorScale;
use super::contour::choose_levels;
use super::{ColorMap, Figure, Levels, Panel};

/// The quantile of a map's values (a sweep's: over all its steps) that sets the top of a
/// robust colour range ([`robust_top`]).
pub const ROBUST_QUANTILE: f64 = 0.995;

/// The top of a robust colour range of `values` (a map, or all steps of a sweep; only the positive ones,
/// where a field is mostly zero, as a pressure outside the contact): their
/// [`ROBUST_QUANTILE`] quantile, so that a few spikes (a single cell at twice the hardness) do
/// not darken every other value; values beyond are drawn in the top colour, the true maximum
/// still labelled. Returns the top and whether it is below the largest value.
pub fn robust_top(values: &[f64]) -> (f64, bool) {
    let mut positive: Vec<f64> = values
        .iter()
        .copied()
        .filter(|v| v.is_finite() && *v > 0.0)
        .collect();
    if positive.is_empty() {
        return (0.0, false);
    }
    positive.sort_by(f64::total_cmp);
    let largest = positive[positive.len() - 1];
    let at = ((positive.len() - 1) as f64 * ROBUST_QUANTILE).round() as usize;
    let top = positive[at];
    (top, top < largest)
}

/// Splits an axis or colour-bar caption into its name and its unit as written after a number:
/// `σvM / p0` gives (`σvM`, ` p0`), `p (MPa)` gives (`p`, ` MPa`), `x/a` gives (`x`, `a`).
pub fn name_and_unit(label: &str) -> (String, String) {
    let label = label.trim();
    if let (Some(open), true) = (label.rfind(" ("), label.ends_with(')')) {
        let unit = &label[open + 2..label.len() - 1];
        return (label[..open].to_string(), format!(" {unit}"));
    }
    if let Some((name, unit)) = label.rsplit_once(" / ") {
        return (name.to_string(), format!(" {unit}"));
    }
    if let Some((name, unit)) = label.rsplit_once('/') {
        return (name.to_string(), unit.to_string());
    }
    (label.to_string(), String::new())
}

/// A run of consecutive panels drawn on one colour scale, with one colour bar after its last
/// panel.
#[derive(Clone, Debug)]
pub(crate) struct ScaleGroup<'f> {
    /// Indices of the group's panels in the figure.
    pub panels: Range<usize>,
    /// Caption of the group's colour bar.
    pub value_label: &'f str,
    pub colormap: ColorMap,
    /// Spans the finite values of the group's panels (see [`ColorScale::for_range`]).
    pub scale: ColorScale,
    /// Contour levels of the group's maps, also marked on its colour bar.
    pub levels: Vec<f64>,
    /// Whether the group's values reach below and above its colour range (a range given by
    /// [`PanelScale::range`](super::PanelScale::range)): those are drawn in the end colours,
    /// and the colour bar ends in a triangle on that side (as matplotlib's `extend`).
    pub beyond: [bool; 2],
}

/// The scale groups of `figure`, left to right; none when it has no panels.
pub(crate) fn scale_groups(figure: &Figure) -> Vec<ScaleGroup<'_>> {
    let mut runs: Vec<(Range<usize>, Scale<'_>)> = Vec::new();
    for (index, panel) in figure.panels.iter().enumerate() {
        let scale = Scale::of(figure, panel);
        match runs.last_mut() {
            Some((range, last)) if *last == scale => range.end = index + 1,
            _ => runs.push((index..index + 1, scale)),
        }
    }
    runs.into_iter()
        .map(|(panels, wanted)| {
            let values = figure.panels[panels.clone()]
                .iter()
                .map(|p| p.values.view());
            let data = finite_range(values);
            let (min, max) = wanted.range.unwrap_or(data);
            let scale = ColorScale::for_range(wanted.colormap, min, max);
            let slack = 1e-12 * (scale.hi - scale.lo).abs();
            let beyond = [data.0 < scale.lo - slack, data.1 > scale.hi + slack];
            let skip_zero = wanted.colormap != ColorMap::Diverging && min >= 0.0;
            ScaleGroup {
                panels,
                value_label: wanted.value_label,
                colormap: wanted.colormap,
                scale,
                levels: choose_levels(wanted.levels, min, max, skip_zero),
                beyond,
            }
        })
        .collect()
}

impl Figure {
    /// The colour ranges the figure is drawn with: one `(panels, (lo, hi))` per group of
    /// consecutive panels sharing a colour scale (one colour bar each), left to right.
    pub fn colour_ranges(&self) -> Vec<(Range<usize>, (f64, f64))> {
        scale_groups(self)
            .into_iter()
            .map(|group| (group.panels, (group.scale.lo, group.scale.hi)))
            .collect()
    }
}

/// What a panel asks of its colour scale.
#[derive(PartialEq)]
struct Scale<'f> {
    value_label: &'f str,
    colormap: ColorMap,
    levels: &'f Levels,
    range: Option<(f64, f64)>,
}

impl<'f> Scale<'f> {
    /// A panel's scale: its own, or the figure's shared one.
    fn of(figure: &'f Figure, panel: &'f Panel) -> Self {
        match &panel.scale {
            Some(own) => Self {
                value_label: &own.value_label,
                colormap: own.colormap,
                levels: &own.levels,
                range: own.range,
            },
            None => Self {
                value_label: &figure.value_label,
                colormap: figure.colormap,
                levels: &figure.levels,
                range: None,
            },
        }
    }
}

/// Smallest and largest finite value over all maps (0, 0 when there is none).
fn finite_range<'a>(maps: impl Iterator<Item = ArrayView2<'a, f64>>) -> (f64, f64) {
    let mut range: Option<(f64, f64)> = None;
    for map in maps {
        for &v in map.iter().filter(|v| v.is_finite()) {
            range = Some(range.map_or((v, v), |(lo, hi)| (lo.min(v), hi.max(v))));
        }
    }
    range.unwrap_or((0.0, 0.0))
}
