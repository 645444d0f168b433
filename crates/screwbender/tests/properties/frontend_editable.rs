//! The editable motion every binding wraps (screwbender::frontend::EditableMotion): refused
//! edits change nothing and name the element, the refinement is cached until an edit, and any
//! sequence of edits then a refinement gives the refinement of the edited document bit for bit.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use screwbender::frontend::{EditableMotion, OptionsInput};
use screwbender::{MotionDocument, Pose, Rules, Scheme, ScrewBender, Subdivision};
use testkit::Rng;

fn motion(n: usize, seed: u64) -> EditableMotion {
    let mut rng = Rng::new(seed);
    let doc = MotionDocument::new(rng.cycle(n, 0.8), true);
    EditableMotion::new(doc, Subdivision::new(Scheme::FourPoint, Rules::Direct, 3)).unwrap()
}

fn bits(poses: &[Pose]) -> Vec<[u64; 7]> {
    poses.iter().map(testkit::pose_bits).collect()
}

/// What a motion of this document and these options is when built from nothing.
fn fresh(m: &EditableMotion) -> Vec<[u64; 7]> {
    let doc = m.document();
    let built = ScrewBender::new(doc.poses.clone(), doc.closed, m.subdivision()).unwrap();
    bits(built.refined().poses())
}

#[test]
fn a_refused_edit_changes_nothing_and_names_the_element() {
    let mut m = motion(4, 1);
    m.refined().unwrap();
    let before = (m.document().clone(), m.subdivision());
    let err = m.set_pose(4, Pose::IDENTITY).unwrap_err();
    assert_eq!(err.path(), "index");
    assert!(err.to_string().contains("an integer from 0 to 3"), "{err}");
    let err = m
        .set_times(Some(vec![0.0, 2.0, 1.0, 3.0, 4.0]))
        .unwrap_err();
    assert_eq!(err.path(), "times[2]", "{err}");
    let err = m
        .set_options(&OptionsInput {
            levels: Some(99.0),
            ..OptionsInput::default()
        })
        .unwrap_err();
    assert_eq!(err.path(), "levels");
    let err = m.insert_pose(9, None).unwrap_err();
    assert_eq!(err.path(), "index");
    m.remove_pose(0).unwrap();
    m.remove_pose(0).unwrap();
    let err = m.remove_pose(0).unwrap_err();
    assert!(err.to_string().contains("poses"), "{err}");
    assert_eq!(m.document().poses.len(), 2);
    m.set_document(before.0.clone()).unwrap();
    assert_eq!((m.document().clone(), m.subdivision()), before);
}

#[test]
fn the_refinement_is_kept_until_an_edit() {
    let mut m = motion(5, 2);
    assert!(!m.is_refined());
    let first = m.refined_poses().unwrap().as_ptr();
    assert!(m.is_refined());
    assert_eq!(m.refined_poses().unwrap().as_ptr(), first, "computed again");
    assert!(m.set_name(Some("x".into())).is_ok());
    assert!(!m.is_refined(), "an edit keeps a stale refinement");
    // A refused edit keeps the refinement: the state it belongs to is unchanged.
    m.refined().unwrap();
    assert!(m.set_closed(true).is_ok());
    m.refined().unwrap();
    assert!(m.set_pose(7, Pose::IDENTITY).is_err());
    assert!(m.is_refined());
}

#[test]
fn an_open_motion_has_no_midpoint_after_its_last_pose() {
    let mut m = motion(4, 3);
    m.set_closed(false).unwrap();
    let err = m.insert_pose(3, None).unwrap_err();
    assert!(err.to_string().contains("an integer from 0 to 2"), "{err}");
    assert_eq!(m.insert_pose(3, Some(Pose::IDENTITY)).unwrap(), 4);
    assert_eq!(m.insert_pose(0, None).unwrap(), 1);
    assert_eq!(m.document().poses.len(), 6);
}

/// Any sequence of edits, with evaluations between them, leaves the refinement of the
/// edited document bit for bit: the cache never serves a stale or differently computed
/// motion (the incremental drag path included).
#[test]
fn edits_then_refine_is_the_refinement_of_the_edited_document() {
    for seed in 0..64u64 {
        let mut rng = Rng::new(1000 + seed);
        let mut m = motion(3 + (seed % 5) as usize, seed);
        for step in 0..12 {
            let n = m.document().poses.len();
            let pick = (rng.next_u64() % n as u64) as usize;
            let done = match rng.next_u64() % 8 {
                0 | 1 => m.set_pose(pick, rng.pose(1.0)),
                2 => m.insert_pose(pick, None).map(drop),
                3 => m.insert_pose(pick, Some(rng.pose(1.0))).map(drop),
                4 => m.remove_pose(pick),
                5 => m.set_closed(rng.next_u64() % 2 == 0),
                6 => m.set_options(&OptionsInput {
                    scheme: Some(["bspline", "fourpoint", "jarek"][pick % 3]),
                    levels: Some((rng.next_u64() % 5) as f64),
                    ..OptionsInput::default()
                }),
                _ => m.set_times(Some(
                    (0..n + usize::from(m.document().closed))
                        .map(|k| k as f64 * 0.5)
                        .collect(),
                )),
            };
            // Some edits are refused (a third pose removed from two, a half turn under the
            // split rules): the motion then stays valid and unchanged.
            let _ = done;
            match rng.next_u64() % 3 {
                0 => {}
                1 => {
                    m.refined().unwrap();
                }
                _ => {
                    m.refined_poses().unwrap();
                }
            }
            // One accessor at a time, so that either cache may be the one an edit finds.
            let want = fresh(&m);
            if rng.next_u64() % 2 == 0 {
                let got = bits(m.refined_poses().unwrap());
                assert_eq!(got, want, "seed {seed}, step {step}: cached poses");
            } else {
                let got = bits(m.refined().unwrap().refined().poses());
                assert_eq!(got, want, "seed {seed}, step {step}: cached motion");
            }
        }
    }
}
