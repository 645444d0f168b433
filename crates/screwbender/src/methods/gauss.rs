//! Gauss–Legendre quadrature on `[0, 1]`.

/// Largest supported number of Gauss–Legendre nodes (Newton's iteration on `P_n` is reliable far
/// beyond; more nodes than this are never useful for the smooth pieces integrated here).
pub const MAX_GAUSS_NODES: usize = 64;

/// Newton's iteration for a Legendre root stops when its step is below this (the roots lie in
/// `[−1, 1]`, so this is at the level of the last bit).
const NEWTON_STEP_TOLERANCE: f64 = 1e-16;

/// Nodes and weights of the `n`-point Gauss–Legendre rule on `[0, 1]` (`1 ≤ n ≤`
/// [`MAX_GAUSS_NODES`]; other `n` are clamped into that range). Exact for polynomials of degree
/// `2n − 1`; the weights sum to 1.
///
/// Nodes are the roots of the Legendre polynomial `P_n`, found by Newton's method from the
/// Chebyshev-like guesses `cos(π(k − ¼)/(n + ½))`, mapped from `[−1, 1]` to `[0, 1]`.
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let n = n.clamp(1, MAX_GAUSS_NODES);
    let mut nodes = vec![0.0; n];
    let mut weights = vec![0.0; n];
    let nf = n as f64;
    for k in 0..n.div_ceil(2) {
        let mut x = (std::f64::consts::PI * (k as f64 + 0.75) / (nf + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            // P_n(x) and P_n'(x) by the three-term recurrence.
            let (mut p0, mut p1) = (1.0, x);
            for j in 2..=n {
                let jf = j as f64;
                let p2 = ((2.0 * jf - 1.0) * x * p1 - (jf - 1.0) * p0) / jf;
                p0 = p1;
                p1 = p2;
            }
            let pn = if n == 1 { x } else { p1 };
            let pm = if n == 1 { 1.0 } else { p0 };
            dp = nf * (x * pn - pm) / (x * x - 1.0);
            let dx = pn / dp;
            x -= dx;
            if dx.abs() < NEWTON_STEP_TOLERANCE {
                break;
            }
        }
        let w = 2.0 / ((1.0 - x * x) * dp * dp);
        // x is the k-th largest root; store ascending on [0, 1].
        nodes[n - 1 - k] = 0.5 * (1.0 + x);
        nodes[k] = 0.5 * (1.0 - x);
        weights[n - 1 - k] = 0.5 * w;
        weights[k] = 0.5 * w;
    }
    (nodes, weights)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_polynomials_exactly() {
        for n in [1, 2, 3, 5, 10, 17, 64] {
            let (x, w) = gauss_legendre(n);
            assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-14, "n={n}");
            for deg in 0..2 * n {
                let got: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(deg as i32)).sum();
                let exact = 1.0 / (deg as f64 + 1.0);
                assert!(
                    (got - exact).abs() < 1e-13,
                    "n={n} deg={deg}: {got} vs {exact}"
                );
            }
            assert!(x.windows(2).all(|p| p[0] < p[1]));
        }
    }
}
