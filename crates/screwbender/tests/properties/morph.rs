//! Shape morphing by Minkowski combination (scene A8): the weights interpolate the control
//! shapes with a C¹ blend, and the combination's extents are the weighted sums of the shapes'
//! extents (support functions add) — natively and in the browser.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::DVec3;
use screwbender::presets::{preset, Shape};
use screwbender::ErrorKind;
use screwbender::{morph_mesh, morph_weights, MORPH_RESOLUTION};

/// Largest coordinate of the mesh along `d` (its support value).
fn extent(shapes: &[Shape], w: &[f64], d: DVec3) -> f64 {
    let m = morph_mesh(shapes, w, MORPH_RESOLUTION).unwrap();
    m.positions
        .iter()
        .map(|p| p.dot(d))
        .fold(f64::MIN, f64::max)
}

#[test]
fn weights_interpolate_the_control_shapes_with_a_c1_blend() {
    for closed in [true, false] {
        let n = 5;
        for i in 0..n - usize::from(!closed) {
            let w = morph_weights(n, closed, i as f64);
            let mut want = vec![0.0; n];
            want[i] = 1.0;
            assert_eq!(w, want, "u = {i}");
        }
        for k in 0..200 {
            let u = k as f64 * 0.0237;
            let w = morph_weights(n, closed, u);
            assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-15);
            assert!(w.iter().all(|&x| x >= 0.0));
            // Zero rate at the knots: the blend is flat there.
            let h = 1e-6;
            let i = u.round();
            let a = morph_weights(n, closed, i + h);
            let b = morph_weights(n, closed, i);
            assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-10));
        }
    }
}

#[test]
fn extents_are_weighted_sums_of_the_shapes_extents() {
    let block = Shape::Block {
        size: [2.0, 1.0, 0.5],
        base: false,
    };
    let cone = Shape::Cone {
        radius: 0.4,
        height: 3.0,
    };
    let shapes = [block, cone];
    for d in [DVec3::X, DVec3::NEG_X, DVec3::Z, DVec3::NEG_Z, DVec3::Y] {
        let a = extent(&shapes, &[1.0, 0.0], d);
        let b = extent(&shapes, &[0.0, 1.0], d);
        for t in [0.25, 0.5, 0.8] {
            let got = extent(&shapes, &[1.0 - t, t], d);
            assert!(
                (got - ((1.0 - t) * a + t * b)).abs() < 1e-12,
                "{d}: {got} vs {}",
                (1.0 - t) * a + t * b
            );
        }
    }
    // A block alone: its half extents.
    assert!((extent(&shapes, &[1.0, 0.0], DVec3::X) - 1.0).abs() < 1e-15);
    assert!((extent(&shapes, &[1.0, 0.0], DVec3::Z) - 0.25).abs() < 1e-15);
}

#[test]
fn the_morph_scene_gives_closed_finite_meshes_with_outward_normals() {
    let s = preset("pip_morph5").unwrap();
    assert_eq!(s.morph_shapes.len(), s.poses.len());
    for k in 0..25 {
        let w = morph_weights(s.morph_shapes.len(), true, k as f64 * 0.2);
        let m = morph_mesh(&s.morph_shapes, &w, MORPH_RESOLUTION).unwrap();
        assert!(m.positions.iter().all(|p| p.is_finite()));
        // Every vertex is the support point for its normal: no vertex lies further along it.
        for (p, n) in m.positions.iter().zip(&m.normals).step_by(37) {
            let h = p.dot(*n);
            assert!(m.positions.iter().all(|q| q.dot(*n) <= h + 1e-12));
        }
    }
}

#[test]
fn bad_weights_are_refused() {
    let s = [Shape::Sphere { radius: 1.0 }];
    assert!(matches!(
        morph_mesh(&s, &[-0.5], 8).as_ref().map_err(|e| e.kind()),
        Err(ErrorKind::OutOfRange { .. })
    ));
    assert!(matches!(
        morph_mesh(&s, &[f64::NAN], 8)
            .as_ref()
            .map_err(|e| e.kind()),
        Err(ErrorKind::OutOfRange { .. })
    ));
    assert!(matches!(
        morph_mesh(&s, &[1.0, 0.0], 8)
            .as_ref()
            .map_err(|e| e.kind()),
        Err(ErrorKind::OutOfRange { .. })
    ));
    assert!(matches!(
        morph_mesh(&[], &[], 8).as_ref().map_err(|e| e.kind()),
        Err(ErrorKind::TooFewPoses { .. })
    ));
}
