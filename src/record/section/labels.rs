//! Labels placed without overlapping (each other, the marked points, the outlines), and the
//! ticks of axes and colour bars.

use super::*;

/// A label's box in units, centred at `(u, v)`.
#[derive(Clone, Copy, Debug)]
pub(super) struct LabelBox {
    pub(super) u: f64,
    pub(super) v: f64,
    pub(super) half_width: f64,
    pub(super) half_height: f64,
}

impl LabelBox {
    #[cfg(test)]
    pub(super) fn overlaps(&self, other: &LabelBox) -> bool {
        self.within(other, 0.0)
    }

    /// Whether the two boxes come closer than `gap` (units) above or below each other, or
    /// overlap side by side.
    fn within(&self, other: &LabelBox, gap: f64) -> bool {
        (self.u - other.u).abs() < self.half_width + other.half_width
            && (self.v - other.v).abs() < self.half_height + other.half_height + gap
    }
}

/// What labels must not cover, besides one another.
#[derive(Clone, Copy, Debug, Default)]
pub struct Avoid<'a> {
    /// Labels already in place (the title and legend rows): centre and text.
    pub labels: &'a [((f64, f64), &'a str)],
    /// Marked points (the extremes, the material points): no label covers one.
    pub dots: &'a [(f64, f64)],
    /// Points along drawn lines (the outlines): covered only where no other place is free.
    pub lines: &'a [(f64, f64)],
}

/// The free pixels kept between two labels' boxes.
const LABEL_GAP_PX: f64 = 4.0;

/// Half the size of the box kept free around a marked point (its dot is 4 points in radius).
pub(super) const DOT_PX: f64 = 6.0;

/// Places labels at their preferred centres, kept inside the map's width (a label is
/// centred on its point, so one near a side would be cut by the view's edge). A label is wanted
/// just below its point; one that would cover an earlier label, a label of `avoid` or a
/// marked point goes beside it (right, then left), else just above it, else further down or
/// up by label heights, and where possible it covers no line either. Returns the centres.
pub(super) fn place_labels(
    frame: &Frame,
    wanted: &[((f64, f64), &str)],
    avoid: &Avoid<'_>,
) -> Vec<(f64, f64)> {
    let height = frame.label_height();
    let step = height + LABEL_GAP_PX / frame.px;
    // Two labels placed one above the other keep a gap the eye sees, not a shared edge
    // (candidates a label height and that gap apart).
    let boxed = |(u, v): (f64, f64), text: &str| LabelBox {
        u,
        v,
        half_width: 0.5 * (text.chars().count() as f64 * CHAR_PX + 10.0) / frame.px,
        half_height: 0.5 * height,
    };
    let point = |&(u, v): &(f64, f64), half: f64| LabelBox {
        u,
        v,
        half_width: half,
        half_height: half,
    };
    let dots: Vec<LabelBox> = avoid
        .dots
        .iter()
        .map(|p| point(p, DOT_PX / frame.px))
        .collect();
    let lines: Vec<LabelBox> = avoid.lines.iter().map(|p| point(p, 0.0)).collect();
    let mut placed: Vec<LabelBox> = avoid
        .labels
        .iter()
        .map(|&(at, text)| boxed(at, text))
        .collect();
    let mut centres = Vec::new();
    for &((u, v), text) in wanted {
        let half_width = boxed((u, v), text).half_width;
        let (left, right) = (frame.u.0 + half_width, frame.bar.0 - half_width);
        let point_u = u;
        let u = if left <= right {
            u.clamp(left, right)
        } else {
            0.5 * (frame.u.0 + frame.bar.0)
        };
        // Below the point as wanted; beside it, right then left, where that fits the map;
        // then above it, further down and up.
        let beside = half_width + (DOT_PX + 2.0) / frame.px;
        let point_v = v - 0.9 * height;
        let sides = [point_u + beside, point_u - beside]
            .into_iter()
            .filter(|side| (left..=right).contains(side))
            .map(|side| boxed((side, point_v), text));
        let candidates: Vec<LabelBox> = std::iter::once(boxed((u, v), text))
            .chain(sides)
            .chain(
                (1..12)
                    .flat_map(|k| [-f64::from(k) - 0.8, f64::from(k)])
                    .map(|shift| boxed((u, v + shift * step), text)),
            )
            .collect();
        // Other labels are kept a gap away (the first list); dots and lines only uncovered.
        let gap = LABEL_GAP_PX / frame.px;
        let clear = |b: &LabelBox, obstacles: &[&[LabelBox]]| {
            obstacles.iter().enumerate().all(|(k, list)| {
                let gap = if k == 0 { gap } else { 0.0 };
                list.iter().all(|o| !b.within(o, gap))
            })
        };
        // Lines are given up first, then nothing else: a label may only land on another if
        // there is no room at all.
        let chosen = [
            &[&placed[..], &dots[..], &lines[..]][..],
            &[&placed[..], &dots[..]][..],
            &[&placed[..]][..],
        ]
        .iter()
        .find_map(|obstacles| candidates.iter().find(|b| clear(b, obstacles)))
        .copied()
        .unwrap_or(candidates[0]);
        centres.push((chosen.u, chosen.v));
        placed.push(chosen);
    }
    centres
}

/// Nice tick values within `[lo, hi]`: at most `most` of them, steps of 1, 2 or 5 x 10^k.
pub fn nice_ticks(lo: f64, hi: f64, most: usize) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite()) || hi <= lo || most < 2 {
        return vec![lo, hi];
    }
    let raw = (hi - lo) / (most - 1) as f64;
    let magnitude = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * magnitude)
        .find(|s| (((hi - lo) / s).floor() as usize) < most)
        .unwrap_or(10.0 * magnitude);
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// Tick labels with as many decimals as the tick step needs (`0.2`, `0.4`; `500`, `1000`),
/// or in exponent form for very small or large values.
pub fn tick_texts(ticks: &[f64]) -> Vec<String> {
    let largest = ticks.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    let step = ticks
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .fold(f64::INFINITY, f64::min);
    if !(step.is_finite() && step > 0.0) || largest >= 1e5 || step < 1e-3 {
        return ticks.iter().map(|&t| short(t)).collect();
    }
    let decimals = (-(step.log10() + 1e-9).floor()).max(0.0) as usize;
    ticks
        .iter()
        .map(|&t| format!("{:.decimals$}", snap(t)).replace('-', "\u{2212}"))
        .collect()
}
