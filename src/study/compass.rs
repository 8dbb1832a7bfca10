//! The compass search that locates a maximum from a good starting point: the pattern search of
//! R. Hooke and T. A. Jeeves, "'Direct search' solution of numerical and statistical problems",
//! *J. ACM* 8 (1961) 212–229, in its simplest form (exploratory moves only).

/// The largest `value` found from `start` (where it is `at_start`): each coordinate with a
/// step is moved up, then down, by its step, kept within its `bounds`, and a move is taken
/// when it raises the value; when no move does, every step is halved, until the largest is
/// 1e-9 or less. A coordinate whose step is 0 stays where it is. Returns the point and its
/// value.
pub(crate) fn compass_maximum<const N: usize>(
    value: impl Fn([f64; N]) -> f64,
    start: [f64; N],
    at_start: f64,
    steps: [f64; N],
    bounds: [(f64, f64); N],
) -> ([f64; N], f64) {
    let (mut at, mut best) = (start, at_start);
    let mut steps = steps;
    while steps.iter().fold(0.0f64, |m, h| m.max(*h)) > 1e-9 {
        let mut improved = false;
        for axis in (0..N).filter(|&axis| steps[axis] > 0.0) {
            for sign in [1.0, -1.0] {
                let mut trial = at;
                let (lo, hi) = bounds[axis];
                trial[axis] = (trial[axis] + sign * steps[axis]).clamp(lo, hi);
                let v = value(trial);
                if v > best {
                    (at, best) = (trial, v);
                    improved = true;
                }
            }
        }
        if !improved {
            steps.iter_mut().for_each(|h| *h *= 0.5);
        }
    }
    (at, best)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn it_climbs_to_a_smooth_peak_and_stops_at_a_bound() {
        // A paraboloid peaking at (0.3, -0.7): found to the search's 1e-9 steps.
        let bowl = |[x, y]: [f64; 2]| -((x - 0.3).powi(2) + 2.0 * (y + 0.7).powi(2));
        let inf = (f64::NEG_INFINITY, f64::INFINITY);
        let (at, best) = compass_maximum(bowl, [0.0, 0.0], bowl([0.0, 0.0]), [0.1, 0.1], [inf; 2]);
        assert!(
            (at[0] - 0.3).abs() < 1e-8 && (at[1] + 0.7).abs() < 1e-8,
            "{at:?}"
        );
        assert!(best <= 0.0 && best > -1e-15, "{best}");
        // y kept at or above 0: the peak on the bound, x still free; a step of 0 stays.
        let (at, _) = compass_maximum(
            bowl,
            [0.0, 0.0],
            bowl([0.0, 0.0]),
            [0.1, 0.1],
            [inf, (0.0, 1.0)],
        );
        assert!((at[0] - 0.3).abs() < 1e-8 && at[1] == 0.0, "{at:?}");
        let (at, _) = compass_maximum(bowl, [0.0, 0.0], bowl([0.0, 0.0]), [0.0, 0.1], [inf; 2]);
        assert!(at[0] == 0.0 && (at[1] + 0.7).abs() < 1e-8, "{at:?}");
    }
}
