//! Nice numbers: axis ticks and contour levels in steps of 1, 2 or 5 times a power of ten, and
//! the compact number formats of tick and contour labels.

/// The minus sign of typeset numbers (U+2212), wider than a hyphen.
const MINUS: char = '\u{2212}';

/// Nice steps (1, 2, 5 x 10^k) from the largest one below `raw` upwards, endlessly.
pub(crate) fn nice_steps(raw: f64) -> impl Iterator<Item = f64> {
    let raw = if raw.is_finite() && raw > 0.0 {
        raw
    } else {
        1.0
    };
    let exponent = raw.log10().floor() as i32 - 1;
    (0..).map(move |i: i32| {
        let mantissa = [1.0, 2.0, 5.0][i.rem_euclid(3) as usize];
        mantissa * 10f64.powi(exponent + i.div_euclid(3))
    })
}

/// The multiples of `step` within `[lo, hi]` (ends included with a small tolerance).
pub(crate) fn multiples(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    if step.is_nan() || step <= 0.0 || !lo.is_finite() || !hi.is_finite() || hi < lo {
        return Vec::new();
    }
    let slack = 1e-9;
    let first = (lo / step - slack).ceil() as i64;
    let last = (hi / step + slack).floor() as i64;
    if last < first || last - first > 10_000 {
        return Vec::new();
    }
    (first..=last).map(|k| k as f64 * step).collect()
}

/// Decimal places that show every multiple of a nice `step` exactly.
pub(crate) fn decimals_for_step(step: f64) -> usize {
    if !step.is_finite() || step <= 0.0 {
        return 0;
    }
    let exponent = (step.log10() + 1e-9).floor() as i32;
    (-exponent).max(0) as usize
}

/// `value` with a fixed number of decimals and a typographic minus; never "−0".
pub(crate) fn format_fixed(value: f64, decimals: usize) -> String {
    let text = format!("{value:.decimals$}");
    typeset_minus(&text)
}

/// `value` as short as it can be written: "0.25", "−0.1", "120", "1.5e−05" for tiny values.
pub(crate) fn format_compact(value: f64) -> String {
    if value == 0.0 || !value.is_finite() {
        return format_fixed(if value.is_finite() { 0.0 } else { value }, 0);
    }
    let magnitude = value.abs();
    if !(1e-4..1e7).contains(&magnitude) {
        let text = format!("{value:.2e}").replace('-', "\u{2212}");
        return text;
    }
    // Six significant digits, then drop trailing zeros.
    let decimals = (5 - magnitude.log10().floor() as i32).max(0) as usize;
    let mut text = format!("{value:.decimals$}");
    if text.contains('.') {
        let trimmed = text.trim_end_matches('0').trim_end_matches('.').len();
        text.truncate(trimmed);
    }
    typeset_minus(&text)
}

/// Contour level labels: each level as short as it can be written, all with the same number of
/// decimals ("0.10", "0.12", ... rather than "0.1", "0.12").
pub(crate) fn format_levels(levels: &[f64]) -> Vec<String> {
    let decimals = levels
        .iter()
        .map(|v| format_compact(*v))
        .filter(|t| !t.contains('e'))
        .map(|t| t.split_once('.').map_or(0, |(_, fraction)| fraction.len()))
        .max()
        .unwrap_or(0);
    levels
        .iter()
        .map(|v| {
            let magnitude = v.abs();
            if magnitude != 0.0 && !(1e-4..1e7).contains(&magnitude) {
                format_compact(*v)
            } else {
                format_fixed(*v, decimals)
            }
        })
        .collect()
}

/// `value` to three significant digits ("0.300", "12.5", "1520"), typographic minus.
pub(crate) fn format_significant(value: f64) -> String {
    if value == 0.0 || !value.is_finite() {
        return format_fixed(if value.is_finite() { 0.0 } else { value }, 3);
    }
    let decimals = (2 - value.abs().log10().floor() as i32).max(0) as usize;
    format_fixed(value, decimals)
}

fn typeset_minus(text: &str) -> String {
    match text.strip_prefix('-') {
        // "-0.00" rounds a tiny negative value to zero: drop the sign.
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        Some(rest) => format!("{MINUS}{rest}"),
        None => text.to_string(),
    }
}

/// Ticks of one axis: positions and their labels.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Ticks {
    pub values: Vec<f64>,
    pub labels: Vec<String>,
}

/// The densest nice ticks over `[lo, hi]` that `fits` accepts (it sees the step and the
/// labels). When no step of 1, 2 or 5 times a power of ten both fits and leaves two ticks (a
/// short colour bar over ±0.0425: 0.02 is too dense, 0.05 leaves only 0), steps of 4 times a
/// power of ten are tried (−0.04, 0, 0.04); failing that, the two ends of the range are
/// labelled to three significant digits.
pub(crate) fn choose_ticks(lo: f64, hi: f64, fits: impl Fn(f64, &[String]) -> bool) -> Ticks {
    let span = hi - lo;
    if span.is_finite() && span > 0.0 {
        let candidate = |step: f64| -> Option<Ticks> {
            let values = multiples(lo, hi, step);
            if values.len() < 2 {
                return None;
            }
            let decimals = decimals_for_step(step);
            let labels: Vec<String> = values.iter().map(|v| format_fixed(*v, decimals)).collect();
            fits(step, &labels).then_some(Ticks { values, labels })
        };
        for step in nice_steps(span / 20.0).take(12) {
            if multiples(lo, hi, step).len() < 2 {
                break;
            }
            if let Some(ticks) = candidate(step) {
                return ticks;
            }
        }
        // Twice the steps of 2: 4 times a power of ten.
        let fours = nice_steps(span / 20.0)
            .take(12)
            .filter(|step| {
                let mantissa = step / 10f64.powf(step.log10().floor());
                (mantissa - 2.0).abs() < 1e-6
            })
            .map(|step| 2.0 * step);
        for step in fours {
            if let Some(ticks) = candidate(step) {
                return ticks;
            }
        }
    }
    let values = vec![lo, hi];
    let labels = values
        .iter()
        .map(|v| {
            if *v == 0.0 {
                format_compact(*v)
            } else {
                format_significant(*v)
            }
        })
        .collect();
    Ticks { values, labels }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_steps_are_one_two_five() {
        let steps: Vec<f64> = nice_steps(0.3).take(5).collect();
        let expected = [0.01, 0.02, 0.05, 0.1, 0.2];
        for (s, e) in steps.iter().zip(expected) {
            assert!((s - e).abs() < 1e-12, "{steps:?}");
        }
    }

    #[test]
    fn multiples_include_the_ends() {
        assert_eq!(multiples(0.0, 2.0, 0.5), vec![0.0, 0.5, 1.0, 1.5, 2.0]);
        let m = multiples(-0.3, 0.3, 0.1);
        assert_eq!(m.len(), 7);
        assert!((m[0] + 0.3).abs() < 1e-12);
    }

    #[test]
    fn formats() {
        assert_eq!(format_fixed(-1.5, 1), "\u{2212}1.5");
        assert_eq!(format_fixed(-0.0001, 2), "0.00");
        assert_eq!(format_compact(0.25), "0.25");
        assert_eq!(format_compact(-0.1), "\u{2212}0.1");
        assert_eq!(format_compact(120.0), "120");
        assert_eq!(format_compact(0.1 + 0.2), "0.3");
        assert_eq!(format_significant(0.30042), "0.300");
        assert_eq!(
            format_levels(&[0.1, 0.12, 0.2]),
            vec!["0.10", "0.12", "0.20"]
        );
        assert_eq!(format_levels(&[-1.0, 0.5]), vec!["\u{2212}1.0", "0.5"]);
        assert_eq!(format_levels(&[100.0, 200.0]), vec!["100", "200"]);
        assert_eq!(format_significant(1523.4), "1523");
        assert_eq!(decimals_for_step(0.5), 1);
        assert_eq!(decimals_for_step(0.05), 2);
        assert_eq!(decimals_for_step(20.0), 0);
    }

    #[test]
    fn choose_ticks_takes_the_densest_that_fits() {
        let ticks = choose_ticks(-2.0, 2.0, |step, _| step >= 0.5);
        assert_eq!(ticks.values.len(), 9);
        assert_eq!(ticks.labels[0], "\u{2212}2.0");
        let ticks = choose_ticks(0.0, 2.0, |_, labels| labels.len() <= 3);
        assert_eq!(ticks.labels, vec!["0", "1", "2"]);
    }

    #[test]
    fn choose_ticks_tries_fours_before_the_ends() {
        // 0.02 is too dense and 0.05 leaves only 0: steps of 0.04 label −0.04, 0, 0.04.
        let ticks = choose_ticks(-0.0425, 0.0425, |step, _| step > 0.03);
        assert_eq!(ticks.labels, vec!["\u{2212}0.04", "0.00", "0.04"]);
        // Nothing fits: the ends, to three significant digits (zero as "0").
        let ticks = choose_ticks(-0.042491, 0.042491, |_, _| false);
        assert_eq!(ticks.labels, vec!["\u{2212}0.0425", "0.0425"]);
        let ticks = choose_ticks(0.0, 1523.4, |_, _| false);
        assert_eq!(ticks.labels, vec!["0", "1523"]);
    }
}
