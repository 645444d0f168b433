//! The worked examples and test vectors of the math notes (docs/math/screw.md §7, docs/math/point-rules.md §5, docs/math/subdivision.md §3.3 and §7,
//! docs/math/presets.md §2.5), checked natively and, compiled to wasm, in headless Chromium.
//!
//! The math notes print six decimals (docs/math/README.md §3), so comparisons with printed numbers use `PRINTED` (half a unit in
//! the sixth decimal, plus rounding of the inputs that are themselves printed).

// The math notes print values like 0.707107 (docs/math/README.md §3): comparing with them is the point.
#![allow(clippy::approx_constant)]

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::{DVec2, DVec3};
use screwbender::{
    presets, screw, screw_paper, BasisPair, PaperScrew, Pose, Rules, Scheme, Screw, ScrewKind,
    Subdivision,
};
use testkit::{assert_pose_near, assert_vec_near, pose};

/// Tolerance against numbers printed with six decimals.
const PRINTED: f64 = 2e-6;
/// Tolerance for exact (not printed) expectations.
const EXACT: f64 = 1e-13;

fn general(kind: ScrewKind) -> screwbender::ScrewParameters {
    match kind {
        ScrewKind::General(p) => p,
        other => panic!("expected a general screw, got {other:?}"),
    }
}

/// The printed screw parameters of an example.
struct Expected {
    axis: [f64; 3],
    angle_deg: f64,
    slide: f64,
    foot: [f64; 3],
}

/// Checks the screw parameters and the poses at several t by both routes.
fn check_example(
    name: &str,
    l0: Pose,
    l1: Pose,
    expected: Expected,
    table: &[(f64, [f64; 3], [f64; 4])],
) {
    let Expected {
        axis,
        angle_deg,
        slide,
        foot,
    } = expected;
    let p = general(Screw::between(&l0, &l1).parameters());
    assert_vec_near(
        p.axis,
        DVec3::from_array(axis),
        PRINTED,
        &format!("{name} axis"),
    );
    assert!(
        (p.angle - angle_deg.to_radians()).abs() < PRINTED,
        "{name} angle {}",
        p.angle.to_degrees()
    );
    assert!(
        (p.slide - slide).abs() < PRINTED,
        "{name} slide {}",
        p.slide
    );
    assert_vec_near(
        p.foot,
        DVec3::from_array(foot),
        PRINTED,
        &format!("{name} foot"),
    );
    let paper = general(PaperScrew::between(&l0, &l1).kind);
    assert_vec_near(paper.axis, p.axis, 1e-12, &format!("{name} paper axis"));
    assert_vec_near(paper.foot, p.foot, 1e-12, &format!("{name} paper foot"));
    assert_vec_near(paper.point, p.point, 1e-12, &format!("{name} paper point"));
    for &(t, o, q) in table {
        let want = pose(o, q);
        assert_pose_near(
            &screw(&l0, t, &l1),
            &want,
            PRINTED,
            &format!("{name} t={t}"),
        );
        assert_pose_near(
            &screw_paper(&l0, t, &l1),
            &want,
            PRINTED,
            &format!("{name} paper t={t}"),
        );
    }
}

#[test]
fn example_a_quarter_turn_with_lift() {
    let l0 = pose([0.0; 3], [1.0, 0.0, 0.0, 0.0]);
    let l1 = pose([2.0, 0.0, 1.0], [0.707107, 0.0, 0.0, 0.707107]);
    check_example(
        "A",
        l0,
        l1,
        Expected {
            axis: [0.0, 0.0, 1.0],
            angle_deg: 90.0,
            slide: 1.0,
            foot: [1.0, 1.0, 0.0],
        },
        &[
            (0.5, [1.0, -0.414214, 0.5], [0.923880, 0.0, 0.0, 0.382683]),
            (
                0.25,
                [0.458804, -0.306563, 0.25],
                [0.980785, 0.0, 0.0, 0.195090],
            ),
            (1.5, [2.414214, 1.0, 1.5], [0.382683, 0.0, 0.0, 0.923880]),
            (
                -0.5,
                [-0.414214, 1.0, -0.5],
                [0.923880, 0.0, 0.0, -0.382683],
            ),
        ],
    );
    let paper = PaperScrew::between(&l0, &l1);
    assert_eq!(paper.pair, Some(BasisPair::IJ));
    assert_vec_near(
        general(paper.kind).point,
        DVec3::new(1.0, 1.0, 0.5),
        PRINTED,
        "A point P",
    );
}

#[test]
fn example_b_120_degrees_about_111() {
    let l0 = Pose::IDENTITY;
    let l1 = pose([1.0, 2.0, 3.0], [0.5, 0.5, 0.5, 0.5]);
    let s = 1.0 / 3f64.sqrt();
    check_example(
        "B",
        l0,
        l1,
        Expected {
            axis: [s, s, s],
            angle_deg: 120.0,
            slide: 2.0 * 3f64.sqrt(),
            foot: [-1.0 / 3.0, -1.0 / 3.0, 2.0 / 3.0],
        },
        &[(
            0.5,
            [1.0 / 3.0, 4.0 / 3.0, 4.0 / 3.0],
            [0.866025, 0.288675, 0.288675, 0.288675],
        )],
    );
    let paper = PaperScrew::between(&l0, &l1);
    assert_eq!(
        paper.pair,
        Some(BasisPair::IJ),
        "ties pick the lowest index"
    );
    assert_vec_near(
        general(paper.kind).point,
        DVec3::new(2.0, 2.0, 5.0) / 3.0,
        PRINTED,
        "B point",
    );
}

#[test]
fn example_c_raw_angle_is_negative() {
    let l0 = pose([0.0; 3], [0.0, 1.0, 0.0, 0.0]);
    let l1 = pose([2.0, 0.0, 1.0], [0.0, 0.707107, 0.707107, 0.0]);
    let paper = PaperScrew::between(&l0, &l1);
    assert_vec_near(
        paper.raw_axis,
        DVec3::new(0.0, 0.0, -1.0),
        PRINTED,
        "C raw axis",
    );
    assert!(
        (paper.raw_angle.to_degrees() + 90.0).abs() < 1e-4,
        "raw r = {}",
        paper.raw_angle
    );
    check_example(
        "C",
        l0,
        l1,
        Expected {
            axis: [0.0, 0.0, 1.0],
            angle_deg: 90.0,
            slide: 1.0,
            foot: [1.0, 1.0, 0.0],
        },
        &[(0.5, [1.0, -0.414214, 0.5], [0.0, 0.923880, 0.382683, 0.0])],
    );
}

#[test]
fn example_d_pure_translation() {
    let l0 = Pose::IDENTITY;
    let l1 = pose([3.0, 4.0, 0.0], [1.0, 0.0, 0.0, 0.0]);
    match Screw::between(&l0, &l1).parameters() {
        ScrewKind::Translation {
            direction,
            distance,
        } => {
            assert_vec_near(direction, DVec3::new(0.6, 0.8, 0.0), EXACT, "D direction");
            assert!((distance - 5.0).abs() < EXACT);
        }
        other => panic!("expected a translation, got {other:?}"),
    }
    assert_pose_near(
        &screw(&l0, 0.5, &l1),
        &pose([1.5, 2.0, 0.0], [1.0, 0.0, 0.0, 0.0]),
        EXACT,
        "D",
    );
    assert_pose_near(
        &screw_paper(&l0, 0.5, &l1),
        &pose([1.5, 2.0, 0.0], [1.0, 0.0, 0.0, 0.0]),
        EXACT,
        "D paper",
    );
}

#[test]
fn example_e_identical_poses() {
    let l0 = pose([1.0, -2.0, 0.5], [0.923381, 0.102598, -0.307794, 0.205196]);
    assert_eq!(Screw::between(&l0, &l0).parameters(), ScrewKind::Identity);
    for t in [-3.0, 0.0, 0.3, 1.0, 7.5] {
        assert_pose_near(&screw(&l0, t, &l0), &l0, EXACT, "E");
    }
}

#[test]
fn example_f_half_turn_with_lift_tie_break() {
    let l0 = Pose::IDENTITY;
    let l1 = pose([2.0, 0.0, 1.0], [0.0, 0.0, 0.0, 1.0]);
    let p = general(Screw::between(&l0, &l1).parameters());
    assert_vec_near(p.axis, DVec3::Z, EXACT, "F axis");
    assert!((p.slide - 1.0).abs() < EXACT && (p.angle - std::f64::consts::PI).abs() < EXACT);
    assert_vec_near(p.point, DVec3::new(1.0, 0.0, 0.5), EXACT, "F point");
    let want = pose([1.0, -1.0, 0.5], [0.707107, 0.0, 0.0, 0.707107]);
    assert_pose_near(&screw(&l0, 0.5, &l1), &want, PRINTED, "F");
    // The tie-break does not depend on which sign the input quaternion has.
    let l1n = Pose::new(l1.origin, -l1.rotation);
    assert_pose_near(&screw(&l0, 0.5, &l1n), &want, PRINTED, "F with −q");
}

#[test]
fn example_g_half_turn_without_lift_tie_break() {
    let l0 = Pose::IDENTITY;
    let l1 = pose([2.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]);
    let want = pose([1.0, -1.0, 0.0], [0.707107, 0.0, 0.0, 0.707107]);
    assert_pose_near(&screw(&l0, 0.5, &l1), &want, PRINTED, "G");
    let l1n = Pose::new(l1.origin, -l1.rotation);
    assert_pose_near(&screw(&l0, 0.5, &l1n), &want, PRINTED, "G with −q");
}

#[test]
fn example_h_general_3d() {
    let l0 = pose([1.0, -2.0, 0.5], [0.923381, 0.102598, -0.307794, 0.205196]);
    let l1 = pose([3.0, 1.0, -1.0], [0.339683, 0.792594, 0.226455, -0.452911]);
    check_example(
        "H",
        l0,
        l1,
        Expected {
            axis: [0.812176, 0.537469, -0.226931],
            angle_deg: 153.130442,
            slide: 3.577155,
            foot: [0.837946, -1.167796, 0.233131],
        },
        &[
            (
                0.5,
                [2.049490, -0.801655, -0.787323],
                [0.804536, 0.570212, -0.051810, -0.157787],
            ),
            (
                0.25,
                [1.597626, -1.540942, -0.214676],
                [0.914519, 0.356092, -0.190324, 0.025091],
            ),
            (
                1.25,
                [3.714597, 1.700958, -0.723122],
                [0.036215, 0.776267, 0.335438, -0.532522],
            ),
        ],
    );
    let paper = PaperScrew::between(&l0, &l1);
    assert_eq!(paper.pair, Some(BasisPair::IJ));
    assert_vec_near(
        paper.raw_axis,
        DVec3::new(-0.812176, -0.537469, 0.226931),
        PRINTED,
        "H raw S",
    );
    assert!((paper.raw_angle + 153.130442f64.to_radians()).abs() < PRINTED);
    assert_vec_near(
        general(paper.kind).point,
        DVec3::new(1.985021, -0.408702, -0.087375),
        PRINTED,
        "H P",
    );
}

/// docs/math/point-rules.md: one step of each point scheme on the L polygon, by both rule sets.
#[test]
fn l_polygon_one_step() {
    let l = presets::polygon_presets().remove(0).vertices;
    let expected = testkit::l_polygon_one_step();
    for (scheme, want) in expected {
        for rules in [Rules::Direct, Rules::SplitThenTweak] {
            let got = Subdivision::new(scheme, rules, 1).apply(&l, true).unwrap();
            for (j, (g, w)) in got.iter().zip(&want).enumerate() {
                assert!(
                    (*g - *w).length() < 1e-14,
                    "{scheme} {rules} vertex {j}: {g} vs {w}"
                );
            }
        }
    }
}

/// docs/math/subdivision.md §3: the V1 misprint does not reduce to the 4-point rule; the correction does.
#[test]
fn v1_erratum_numeric_example() {
    use screwbender::Blend;
    let (a, b, c, d) = (
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(2.0, 0.0),
        DVec2::new(3.0, 3.0),
    );
    let mid = DVec2::blend(&b, 0.5, &c);
    let m = (a + b + c + d) / 4.0;
    let corrected = DVec2::blend(&m, 1.25, &mid);
    let misprint = DVec2::blend(&mid, 1.25, &m);
    assert!((corrected - DVec2::new(1.5, -0.1875)).length() < 1e-15);
    assert!((misprint - DVec2::new(1.5, 0.9375)).length() < 1e-15);
    // And the library's split-tweak 4-point rule on the cycle (a,b,c,d) gives the corrected point.
    let out = Subdivision::new(Scheme::FourPoint, Rules::SplitThenTweak, 1)
        .apply(&[a, b, c, d], true)
        .unwrap();
    let expect = (-a + 9.0 * b + 9.0 * c - d) / 16.0;
    assert!((out[3] - expect).length() < 1e-15, "{} vs {expect}", out[3]);
}

fn spec_65_input() -> Vec<Pose> {
    vec![
        pose([0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]),
        pose([4.0, 0.0, 0.0], [0.707107, 0.0, 0.0, 0.707107]),
        pose([4.0, 4.0, 0.0], [0.707107, 0.707107, 0.0, 0.0]),
        pose([0.0, 4.0, 1.0], [1.0, 0.0, 0.0, 0.0]),
    ]
}

type Slot = (usize, [f64; 3], [f64; 4]);

fn check_step(scheme: Scheme, rules: Rules, slots: &[Slot]) {
    let input = spec_65_input();
    let out = Subdivision::new(scheme, rules, 1)
        .apply(&input, true)
        .unwrap();
    assert_eq!(out.len(), 8);
    for &(j, o, q) in slots {
        assert_pose_near(
            &out[j],
            &pose(o, q),
            PRINTED,
            &format!("{scheme} {rules} Q{j}"),
        );
    }
}

/// docs/math/subdivision.md §7, all six rule sets.
#[test]
fn one_step_vectors_all_rule_sets() {
    let bspline_new: [Slot; 4] = [
        (1, [2.0, -0.828427, 0.0], [0.923880, 0.0, 0.0, 0.382683]),
        (
            3,
            [3.333333, 2.0, -0.666667],
            [0.816497, 0.408248, 0.0, 0.408248],
        ),
        (5, [2.0, 3.792893, 0.5], [0.923880, 0.382683, 0.0, 0.0]),
        (7, [0.0, 2.0, 0.5], [1.0, 0.0, 0.0, 0.0]),
    ];
    let mut bspline_v2 = vec![
        (
            0,
            [0.379364, 0.148249, 0.125],
            [0.995185, 0.0, 0.0, 0.098017],
        ),
        (
            2,
            [3.354988, 0.112787, -0.322629],
            [0.814870, 0.106288, 0.0, 0.569815],
        ),
        (
            4,
            [3.177371, 3.447406, -0.109328],
            [0.814870, 0.569815, 0.0, 0.106288],
        ),
        (6, [0.5, 3.424374, 0.718602], [0.995185, 0.098017, 0.0, 0.0]),
    ];
    bspline_v2.extend(bspline_new);
    check_step(Scheme::BSpline, Rules::Direct, &bspline_v2);
    let mut bspline_v1 = vec![
        (
            0,
            [0.378400, 0.158044, 0.125],
            [0.995185, 0.0, 0.0, 0.098017],
        ),
        (
            2,
            [3.347832, 0.114408, -0.346670],
            [0.816107, 0.106697, 0.0, 0.567966],
        ),
        (
            4,
            [3.168485, 3.442228, -0.106182],
            [0.816107, 0.567966, 0.0, 0.106697],
        ),
        (6, [0.5, 3.414819, 0.715188], [0.995185, 0.098017, 0.0, 0.0]),
    ];
    bspline_v1.extend(bspline_new);
    check_step(Scheme::BSpline, Rules::SplitThenTweak, &bspline_v1);

    let input = spec_65_input();
    let olds: Vec<Slot> = input
        .iter()
        .enumerate()
        .map(|(i, p)| (2 * i, p.origin.to_array(), p.rotation_wxyz()))
        .collect();
    let mut fp_v2 = vec![
        (
            1,
            [2.156999, -1.396237, 0.148975],
            [0.907681, -0.058707, 0.0, 0.415534],
        ),
        (
            3,
            [3.801476, 2.278426, -0.655520],
            [0.757581, 0.461558, 0.0, 0.461558],
        ),
        (
            5,
            [2.211475, 4.348445, 0.719499],
            [0.907681, 0.415534, 0.0, -0.058707],
        ),
        (
            7,
            [-0.338362, 2.244855, 0.633750],
            [0.997584, -0.049127, 0.0, -0.049127],
        ),
    ];
    fp_v2.extend(olds.iter().copied());
    check_step(Scheme::FourPoint, Rules::Direct, &fp_v2);
    let mut fp_v1 = vec![
        (
            1,
            [2.194524, -1.360852, 0.176439],
            [0.905548, -0.054185, 0.0, 0.420770],
        ),
        (
            3,
            [3.728461, 2.273388, -0.732318],
            [0.766053, 0.454512, 0.0, 0.454512],
        ),
        (
            5,
            [2.240656, 4.290803, 0.746679],
            [0.905548, 0.420770, 0.0, -0.054185],
        ),
        (
            7,
            [-0.341381, 2.250782, 0.629190],
            [0.997464, -0.050325, 0.0, -0.050325],
        ),
    ];
    fp_v1.extend(olds.iter().copied());
    check_step(Scheme::FourPoint, Rules::SplitThenTweak, &fp_v1);

    check_step(
        Scheme::Jarek,
        Rules::Direct,
        &[
            (
                0,
                [0.193383, 0.063596, 0.0625],
                [0.998795, 0.0, 0.0, 0.049068],
            ),
            (
                1,
                [2.075735, -1.113307, 0.067594],
                [0.916213, -0.029142, 0.0, 0.399631],
            ),
            (
                2,
                [3.679467, 0.022079, -0.172664],
                [0.764815, 0.053366, 0.0, 0.642036],
            ),
            (
                3,
                [3.567601, 2.131455, -0.670686],
                [0.788436, 0.434953, 0.0, 0.434953],
            ),
            (
                4,
                [3.577336, 3.744768, -0.063574],
                [0.764815, 0.642036, 0.0, 0.053366],
            ),
            (
                5,
                [2.098844, 4.071856, 0.606985],
                [0.916213, 0.399631, 0.0, -0.029142],
            ),
            (
                6,
                [0.25, 3.706469, 0.873802],
                [0.998795, 0.049068, 0.0, 0.0],
            ),
            (
                7,
                [-0.171657, 2.116482, 0.570438],
                [0.999397, -0.024549, 0.0, -0.024549],
            ),
        ],
    );
    check_step(
        Scheme::Jarek,
        Rules::SplitThenTweak,
        &[
            (
                0,
                [0.193082, 0.069727, 0.0625],
                [0.998795, 0.0, 0.0, 0.049068],
            ),
            (
                1,
                [2.092554, -1.098905, 0.080539],
                [0.915254, -0.027108, 0.0, 0.401964],
            ),
            (
                2,
                [3.675453, 0.021679, -0.187950],
                [0.765698, 0.053635, 0.0, 0.640961],
            ),
            (
                3,
                [3.534893, 2.129959, -0.703488],
                [0.791951, 0.431749, 0.0, 0.431749],
            ),
            (
                4,
                [3.571584, 3.741674, -0.061969],
                [0.765698, 0.640961, 0.0, 0.053635],
            ),
            (
                5,
                [2.112809, 4.047469, 0.619329],
                [0.915254, 0.401964, 0.0, -0.027108],
            ),
            (
                6,
                [0.25, 3.700414, 0.871968],
                [0.998795, 0.049068, 0.0, 0.0],
            ),
            (
                7,
                [-0.173849, 2.119463, 0.567754],
                [0.999366, -0.025179, 0.0, -0.025179],
            ),
        ],
    );
}

/// Scene A5: the pendulum's refined poses all lie on the one screw, at the 4-point limit of the
/// zig-zag 0,1,0,1 (fractions listed in `presets.md`).
#[test]
fn pendulum_fractions() {
    let sc = presets::preset("pendulum").unwrap();
    let s = Screw::between(&sc.poses[0], &sc.poses[1]);
    let refined = Subdivision::new(Scheme::FourPoint, Rules::Direct, 3)
        .apply(&sc.poses, true)
        .unwrap();
    let fractions = [
        0.0, 0.0625, 0.1875, 0.3359375, 0.5, 0.6640625, 0.8125, 0.9375, 1.0, 0.9375,
    ];
    for (k, &f) in fractions.iter().enumerate() {
        assert_pose_near(
            &refined[k % refined.len()],
            &s.at(f),
            1e-12,
            &format!("τ = {k}/8"),
        );
    }
    // The bob stays at distance 4 from the pivot.
    for p in &refined {
        assert!(((p.origin - DVec3::new(0.0, 0.0, 4.0)).length() - 4.0).abs() < 1e-12);
    }
}
