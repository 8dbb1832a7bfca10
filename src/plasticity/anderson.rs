//! Anderson acceleration of a fixed-point iteration `x = G(x)`.
//!
//! With the residuals `f_k = G(x_k) - x_k` and the last `m` differences of the residuals
//! (`ΔF`) and of the images (`ΔG`), the next iterate is `x_(k+1) = G(x_k) - ΔG γ` with `γ`
//! the least-squares solution of `ΔF γ ≈ f_k` (Anderson 1965; Walker & Ni 2011, "type II",
//! no damping). With `m = 0` it is the plain iteration.
//!
//! The vectors may grow between iterations (cells joining the plastic zone): entries appended
//! by [`Anderson::grow`] had `x = G(x)` at every earlier iterate, so their differences are
//! zero.
//!
//! ## References
//! - D. G. Anderson, Iterative procedures for nonlinear integral equations, *J. ACM* 12
//!   (1965) 547–560.
//! - H. F. Walker, P. Ni, Anderson acceleration for fixed-point iterations, *SIAM J. Numer.
//!   Anal.* 49 (2011) 1715–1735.

use std::collections::VecDeque;

/// The history of an accelerated fixed point.
#[derive(Clone, Debug, Default)]
pub struct Anderson {
    depth: usize,
    previous: Option<(Vec<f64>, Vec<f64>)>,
    differences: VecDeque<(Vec<f64>, Vec<f64>)>,
}

impl Anderson {
    /// An accelerator keeping `depth` differences.
    pub fn new(depth: usize) -> Self {
        Self {
            depth,
            previous: None,
            differences: VecDeque::new(),
        }
    }

    /// Forgets the history (a new step, or a restart).
    pub fn reset(&mut self) {
        self.previous = None;
        self.differences.clear();
    }

    /// Appends entries whose `x` and `G(x)` were both `values` at every earlier iterate.
    pub fn grow(&mut self, values: &[f64]) {
        if let Some((g, f)) = &mut self.previous {
            g.extend_from_slice(values);
            f.extend(std::iter::repeat_n(0.0, values.len()));
        }
        for (dg, df) in self.differences.iter_mut() {
            dg.extend(std::iter::repeat_n(0.0, values.len()));
            df.extend(std::iter::repeat_n(0.0, values.len()));
        }
    }

    /// The next iterate from the current one `x` and its image `g = G(x)`, into `x`.
    ///
    /// # Panics
    /// If `x` and `g` differ in length from each other or from the history.
    pub fn next(&mut self, x: &mut [f64], g: &[f64]) {
        assert_eq!(x.len(), g.len(), "x and G(x)");
        let f: Vec<f64> = g.iter().zip(x.iter()).map(|(g, x)| g - x).collect();
        if let Some((g_prev, f_prev)) = self.previous.take() {
            assert_eq!(g_prev.len(), g.len(), "the history's length");
            let dg: Vec<f64> = g.iter().zip(&g_prev).map(|(a, b)| a - b).collect();
            let df: Vec<f64> = f.iter().zip(&f_prev).map(|(a, b)| a - b).collect();
            self.differences.push_back((dg, df));
            while self.differences.len() > self.depth {
                self.differences.pop_front();
            }
        }
        self.previous = Some((g.to_vec(), f.clone()));
        x.copy_from_slice(g);
        let m = self.differences.len();
        if m == 0 {
            return;
        }
        // Normal equations of min |f - ΔF γ|, lightly regularised.
        let mut a = vec![vec![0.0; m]; m];
        let mut b = vec![0.0; m];
        for (i, (_, dfi)) in self.differences.iter().enumerate() {
            b[i] = dot(dfi, &f);
            for (j, (_, dfj)) in self.differences.iter().enumerate().take(i + 1) {
                let value = dot(dfi, dfj);
                a[i][j] = value;
                a[j][i] = value;
            }
        }
        let trace: f64 = (0..m).map(|i| a[i][i]).sum();
        if !(trace > 0.0 && trace.is_finite()) {
            return;
        }
        for (i, row) in a.iter_mut().enumerate() {
            row[i] += 1e-12 * trace;
        }
        let Some(gamma) = solve(a, b) else {
            self.differences.clear();
            return;
        };
        for ((dg, _), &weight) in self.differences.iter().zip(&gamma) {
            for (value, d) in x.iter_mut().zip(dg) {
                *value -= weight * d;
            }
        }
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Gaussian elimination with partial pivoting of a small system.
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    for k in 0..n {
        let pivot = (k..n).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()))?;
        if a[pivot][k] == 0.0 || !a[pivot][k].is_finite() {
            return None;
        }
        a.swap(k, pivot);
        b.swap(k, pivot);
        let (upper, lower) = a.split_at_mut(k + 1);
        let pivot_row = &upper[k];
        for (offset, row) in lower.iter_mut().enumerate() {
            let factor = row[k] / pivot_row[k];
            for (value, p) in row.iter_mut().zip(pivot_row).skip(k) {
                *value -= factor * p;
            }
            b[k + 1 + offset] -= factor * b[k];
        }
    }
    let mut x = vec![0.0; n];
    for k in (0..n).rev() {
        let sum: f64 = (k + 1..n).map(|j| a[k][j] * x[j]).sum();
        x[k] = (b[k] - sum) / a[k][k];
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A linear contraction `G(x) = M x + c` with a slow mode: the plain iteration needs
    /// hundreds of iterations, the accelerated one a handful.
    #[test]
    fn a_slow_linear_fixed_point_converges_fast() {
        let n = 6;
        let rates = [0.98, 0.9, 0.7, 0.5, -0.3, 0.95];
        let c: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
        let fixed: Vec<f64> = (0..n).map(|i| c[i] / (1.0 - rates[i])).collect();
        let g = |x: &[f64]| -> Vec<f64> { (0..n).map(|i| rates[i] * x[i] + c[i]).collect() };
        let run = |depth: usize| {
            let mut anderson = Anderson::new(depth);
            let mut x = vec![0.0; n];
            for iteration in 1..=2000 {
                let image = g(&x);
                let error = fixed
                    .iter()
                    .zip(&x)
                    .fold(0.0f64, |m, (a, b)| m.max((a - b).abs() / a.abs()));
                if error < 1e-10 {
                    return iteration;
                }
                anderson.next(&mut x, &image);
            }
            2000
        };
        let (plain, accelerated) = (run(0), run(5));
        assert!(plain > 500, "plain: {plain}");
        assert!(accelerated < 20, "accelerated: {accelerated}");
    }
}
