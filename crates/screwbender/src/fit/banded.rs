//! Symmetric positive definite systems with a band: the normal equations of a fit, where each
//! sample touches only four neighbouring control poses, so the matrix has nonzeros only within a
//! fixed distance of its diagonal. The Cholesky factor keeps the band, and the solve costs
//! `O(n b²)` for `n` unknowns and half-bandwidth `b` instead of the dense `O(n³)`.
//!
//! Written here rather than taken from a crate: the crates that offer banded Cholesky
//! factorisations pull in a dense linear-algebra stack (or LAPACK) for one forty-line routine,
//! and this one must run unchanged in the browser.

/// A symmetric matrix of which only the diagonal and `bandwidth` subdiagonals are stored.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct BandMatrix {
    n: usize,
    bandwidth: usize,
    /// Row `i` holds `A[i][i − d]` at `i·(bandwidth + 1) + d`, `d = 0..=bandwidth`.
    lower: Vec<f64>,
}

impl BandMatrix {
    /// The zero `n × n` matrix with half-bandwidth `bandwidth`.
    pub(crate) fn zeros(n: usize, bandwidth: usize) -> BandMatrix {
        BandMatrix {
            n,
            bandwidth,
            lower: vec![0.0; n * (bandwidth + 1)],
        }
    }

    /// The order `n`.
    pub(crate) fn len(&self) -> usize {
        self.n
    }

    /// Adds `value` to `A[i][j]` (and so to `A[j][i]`); `|i − j|` must be within the band.
    pub(crate) fn add(&mut self, i: usize, j: usize, value: f64) {
        let (i, j) = if i >= j { (i, j) } else { (j, i) };
        debug_assert!(i - j <= self.bandwidth, "outside the band");
        self.lower[i * (self.bandwidth + 1) + (i - j)] += value;
    }

    /// `A[i][i]`.
    pub(crate) fn diagonal(&self, i: usize) -> f64 {
        self.lower[i * (self.bandwidth + 1)]
    }

    /// Solves `A x = rhs` by the banded Cholesky factorisation `A = L Lᵀ`; `None` when `A` is
    /// not positive definite (a pivot ≤ 0 or not finite).
    pub(crate) fn solve(&self, rhs: &[f64]) -> Option<Vec<f64>> {
        let (n, b) = (self.n, self.bandwidth);
        let w = b + 1;
        let mut l = self.lower.clone();
        for i in 0..n {
            let lo = i.saturating_sub(b);
            for j in lo..=i {
                let mut s = l[i * w + (i - j)];
                for k in lo.max(j.saturating_sub(b))..j {
                    s -= l[i * w + (i - k)] * l[j * w + (j - k)];
                }
                if i == j {
                    if !(s > 0.0 && s.is_finite()) {
                        return None;
                    }
                    l[i * w] = s.sqrt();
                } else {
                    l[i * w + (i - j)] = s / l[j * w];
                }
            }
        }
        // L y = rhs, then Lᵀ x = y.
        let mut x = rhs.to_vec();
        for i in 0..n {
            let lo = i.saturating_sub(b);
            let mut s = x[i];
            for k in lo..i {
                s -= l[i * w + (i - k)] * x[k];
            }
            x[i] = s / l[i * w];
        }
        for i in (0..n).rev() {
            let mut s = x[i];
            for k in i + 1..(i + w).min(n) {
                s -= l[k * w + (k - i)] * x[k];
            }
            x[i] = s / l[i * w];
        }
        Some(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_banded_system_as_a_dense_one_would() {
        // A diagonally dominant pentadiagonal matrix, checked through A x = rhs.
        let (n, b) = (40, 2);
        let mut a = BandMatrix::zeros(n, b);
        for i in 0..n {
            a.add(i, i, 6.0 + (i % 3) as f64);
            if i >= 1 {
                a.add(i, i - 1, -1.5);
            }
            if i >= 2 {
                a.add(i - 2, i, 0.5 + 0.01 * i as f64);
            }
        }
        let rhs: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
        let x = a.solve(&rhs).unwrap();
        for (i, want) in rhs.iter().enumerate() {
            let s: f64 = (i.saturating_sub(b)..(i + b + 1).min(n))
                .map(|j| {
                    let (r, c) = if i >= j { (i, j) } else { (j, i) };
                    a.lower[r * (b + 1) + (r - c)] * x[j]
                })
                .sum();
            assert!((s - want).abs() < 1e-13, "row {i}: {s} vs {want}");
        }
        assert_eq!(a.len(), n);
        assert_eq!(a.diagonal(1), 7.0);
    }

    #[test]
    fn refuses_an_indefinite_matrix() {
        let mut a = BandMatrix::zeros(2, 1);
        a.add(0, 0, 1.0);
        a.add(1, 1, 1.0);
        a.add(0, 1, 2.0);
        assert_eq!(a.solve(&[1.0, 1.0]), None);
    }
}
