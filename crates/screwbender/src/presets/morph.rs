//! Shape morphing along a motion (paper Fig. 7b, the PIP idea): the object changes from the
//! convex shape of one control pose to that of the next by the Minkowski combination
//! `Σ wₖ Sₖ` of their convex hulls, with weights that depend smoothly on the motion parameter.
//!
//! A Minkowski combination is easiest in terms of support points: the point of `Σ wₖ Sₖ` that
//! is extreme in direction `d` is `Σ wₖ sₖ(d)`, with `sₖ(d)` the extreme point of `Sₖ` (for
//! `wₖ ≥ 0`). Sampling `d` over a sphere gives the combination's surface, and `d` is its outward
//! normal there: exact positions and normals at every sampled direction, for any convex shapes.
//! Non-convex objects morph through their convex hulls.

use glam::DVec3;

use crate::error::{Error, ErrorKind};
use crate::presets::mesh::Mesh;
use crate::presets::Shape;

/// Latitude bands of the direction sphere ([`morph_mesh`]); longitudes are twice as many.
pub const MORPH_RESOLUTION: usize = 24;

/// The extreme point of a point set in direction `d` (the support point of its convex hull).
fn support(points: &[DVec3], d: DVec3) -> DVec3 {
    points
        .iter()
        .copied()
        .max_by(|a, b| a.dot(d).total_cmp(&b.dot(d)))
        .unwrap_or(DVec3::ZERO)
}

/// The C¹ blend weights at motion parameter `u` of `count` control shapes (pose `i` at `u = i`;
/// a cycle wraps): on span `i → i + 1` the weight moves from shape `i` to `i + 1` by the
/// smoothstep `3f² − 2f³`, so the shape equals the control pose's at `u = i` and changes with
/// zero rate there. Weights are non-negative and sum to 1.
pub fn morph_weights(count: usize, closed: bool, u: f64) -> Vec<f64> {
    let mut w = vec![0.0; count];
    if count == 0 || !u.is_finite() {
        return w;
    }
    let spans = if closed { count } else { count - 1 };
    if spans == 0 {
        w[0] = 1.0;
        return w;
    }
    let u = if closed {
        u.rem_euclid(spans as f64)
    } else {
        u.clamp(0.0, spans as f64)
    };
    let i = (u.floor() as usize).min(spans - 1);
    let f = u - i as f64;
    let s = f * f * (3.0 - 2.0 * f);
    w[i] += 1.0 - s;
    w[(i + 1) % count] += s;
    w
}

/// The mesh of the Minkowski combination `Σ weights[k] · hull(shapes[k])`: a sphere of
/// `resolution` latitude bands of directions, each mapped to the combination's support point,
/// with the direction as normal. Errors: no shapes, a weight count that differs from the shape
/// count, or weights that are negative or not finite (a Minkowski combination needs `wₖ ≥ 0`).
pub fn morph_mesh(shapes: &[Shape], weights: &[f64], resolution: usize) -> Result<Mesh, Error> {
    if shapes.is_empty() {
        return Err(Error::new(
            "shapes",
            ErrorKind::TooFewPoses { found: 0, min: 1 },
        ));
    }
    if weights.len() != shapes.len() {
        return Err(Error::new(
            "weights",
            ErrorKind::OutOfRange {
                value: format!("{} weights", weights.len()),
                expected: format!("{} (one per shape)", shapes.len()),
            },
        ));
    }
    if let Some(k) = weights.iter().position(|w| !(w.is_finite() && *w >= 0.0)) {
        return Err(Error::new(
            format!("weights[{k}]"),
            ErrorKind::OutOfRange {
                value: weights[k].to_string(),
                expected: "a finite non-negative weight".into(),
            },
        ));
    }
    let hulls: Vec<(f64, Vec<DVec3>)> = shapes
        .iter()
        .zip(weights)
        .filter(|(_, &w)| w > 0.0)
        .map(|(s, &w)| (w, Mesh::from_shape(s).positions))
        .collect();
    let lat = resolution.max(4);
    let lon = 2 * lat;
    let mut mesh = Mesh::default();
    for i in 0..=lat {
        let theta = std::f64::consts::PI * i as f64 / lat as f64;
        for j in 0..lon {
            let phi = std::f64::consts::TAU * j as f64 / lon as f64;
            let d = DVec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            );
            let p = hulls.iter().map(|(w, pts)| support(pts, d) * *w).sum();
            mesh.positions.push(p);
            mesh.normals.push(d);
        }
    }
    let at = |i: usize, j: usize| (i * lon + j % lon) as u32;
    for i in 0..lat {
        for j in 0..lon {
            // Counter-clockwise seen from outside (normals point outwards).
            mesh.indices
                .extend([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            mesh.indices
                .extend([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    Ok(mesh)
}
