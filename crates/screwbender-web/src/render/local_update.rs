//! Live dragging with local re-subdivision (docs/math/local-update.md): the JS class `DragSession`.
//!
//! While a control pose is dragged, the page keeps a `DragSession`: a [`ScrewBender`] whose
//! refined motion is updated in place by [`ScrewBender::set_control_pose`] (only the refined
//! poses within the moved pose's influence window are recomputed), together with the GPU-ready
//! strobe instances and trajectory segments, of which only the entries that depend on rewritten
//! refined poses are refreshed. The renderer uploads them straight from wasm memory
//! (`Renderer.applyDrag`), so a drag step never copies the whole motion through JavaScript.
//! A drag step therefore costs O(window + changed samples), independent of the number of
//! control poses. The session is discarded on release and the page rebuilds from its `Motion`.

use glam::DVec3;
use wasm_bindgen::prelude::*;

use super::gpu::{write_instance, write_segment, LineStyle, INSTANCE_FLOATS, SEGMENT_FLOATS};
use crate::convert::poses_from_array;
use crate::motion::MotionHandle;
use screwbender::{Motion, Pose, ScrewBender, SubdivisionBuffers};

/// A drag in progress: the smoothed motion plus its strobe instances and trajectory segments.
#[wasm_bindgen(js_name = DragSession)]
pub struct DragSession {
    bender: ScrewBender,
    /// The working buffers of the re-subdivided window, kept from one drag step to the next.
    buffers: SubdivisionBuffers<Pose>,
    strobe_count: usize,
    colors: [[f32; 3]; 2],
    points: Vec<DVec3>,
    style: LineStyle,
    pub(super) strobe: Vec<f32>,
    pub(super) segments: Vec<f32>,
    /// Instance ranges `(first, count)` rewritten since the last upload.
    pub(super) dirty_strobe: Vec<(usize, usize)>,
    /// Segment ranges `(first, count)` rewritten since the last upload.
    pub(super) dirty_segments: Vec<(usize, usize)>,
    /// Everything must be uploaded (new session or full rebuild).
    pub(super) dirty_all: bool,
}

/// Adds item `i` to a list of ranges, extending the last range when `i` follows it.
fn mark(ranges: &mut Vec<(usize, usize)>, i: usize) {
    match ranges.last_mut() {
        Some((first, count)) if *first + *count == i => *count += 1,
        _ => ranges.push((i, 1)),
    }
}

impl DragSession {
    fn strobe_parameter(&self, k: usize) -> f64 {
        let (a, b) = self.bender.domain();
        let denom = if self.bender.is_closed() {
            self.strobe_count as f64
        } else {
            self.strobe_count.saturating_sub(1).max(1) as f64
        };
        a + (b - a) * k as f64 / denom
    }

    fn write_strobe(&mut self, k: usize) {
        let u = self.strobe_parameter(k);
        let t = if self.strobe_count > 1 {
            k as f32 / (self.strobe_count - 1) as f32
        } else {
            0.0
        };
        let [a, b] = self.colors;
        let rgba = [
            a[0] + (b[0] - a[0]) * t,
            a[1] + (b[1] - a[1]) * t,
            a[2] + (b[2] - a[2]) * t,
            1.0,
        ];
        let pose = self.bender.pose_at(u);
        let at = k * INSTANCE_FLOATS;
        write_instance(&mut self.strobe[at..at + INSTANCE_FLOATS], &pose, 1.0, rgba);
    }

    /// Number of trajectory segments per body point.
    fn segments_per_point(&self) -> usize {
        let n = self.bender.refined().poses().len();
        if self.bender.is_closed() {
            n
        } else {
            n - 1
        }
    }

    fn write_segment_at(&mut self, point: usize, j: usize) {
        let poses = self.bender.refined().poses();
        let n = poses.len();
        let p = self.points[point];
        let a = poses[j].transform_point(p);
        let b = poses[(j + 1) % n].transform_point(p);
        let at = (point * self.segments_per_point() + j) * SEGMENT_FLOATS;
        let style = self.style;
        write_segment(&mut self.segments[at..at + SEGMENT_FLOATS], a, b, &style);
    }

    fn rebuild_all(&mut self) {
        self.dirty_all = true;
        self.strobe = vec![0.0; self.strobe_count * INSTANCE_FLOATS];
        for k in 0..self.strobe_count {
            self.write_strobe(k);
        }
        let per = self.segments_per_point();
        self.segments = vec![0.0; self.points.len() * per * SEGMENT_FLOATS];
        for p in 0..self.points.len() {
            for j in 0..per {
                self.write_segment_at(p, j);
            }
        }
    }
}

#[wasm_bindgen(js_class = DragSession)]
impl DragSession {
    /// Starts a session on `motion` as it is now (its control poses, closedness and options;
    /// the motion crosses into Rust as itself, not as numbers read out of it), with `strobe`
    /// instances coloured from the first to the second colour of `colors` (6 numbers, linear
    /// RGB), and the local body `points` (3 numbers each) whose trajectories are drawn with
    /// `line` = `[r, g, b, a, width, bias]`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        motion: &MotionHandle,
        strobe: usize,
        colors: &[f32],
        points: &[f64],
        line: &[f32],
    ) -> Result<DragSession, JsError> {
        let bender = motion.with_refined(ScrewBender::clone)?;
        if colors.len() != 6 {
            return Err(JsError::new(
                "colors: expected 6 numbers (two linear RGB colours)",
            ));
        }
        let rgb = |c: &[f32]| [c[0], c[1], c[2]];
        if line.len() != 6 {
            return Err(JsError::new("line: expected [r, g, b, a, width, bias]"));
        }
        let mut session = DragSession {
            bender,
            buffers: SubdivisionBuffers::new(),
            strobe_count: strobe.min(screwbender::MAX_REFINED_POSES),
            colors: [rgb(&colors[..3]), rgb(&colors[3..])],
            points: points
                .chunks_exact(3)
                .map(|c| DVec3::new(c[0], c[1], c[2]))
                .collect(),
            style: LineStyle {
                rgba: [line[0], line[1], line[2], line[3]],
                width: line[4],
                bias: line[5],
            },
            strobe: Vec::new(),
            segments: Vec::new(),
            dirty_strobe: Vec::new(),
            dirty_segments: Vec::new(),
            dirty_all: true,
        };
        session.rebuild_all();
        Ok(session)
    }

    /// Moves control pose `i` to `pose` (7 numbers) and refreshes what it influences. Returns
    /// `[start, count]`, the refined index range rewritten (cyclic). On error nothing changes.
    #[wasm_bindgen(js_name = setPose)]
    pub fn set_pose(&mut self, i: usize, pose: &[f64]) -> Result<Vec<u32>, JsError> {
        let pose = poses_from_array(pose, "pose")?
            .pop()
            .ok_or_else(|| JsError::new("pose: expected 7 numbers"))?;
        let (start, count) = self
            .bender
            .set_control_pose_with(i, pose, &mut self.buffers)?;
        let n = self.bender.refined().poses().len();
        if count >= n {
            self.rebuild_all();
            return Ok(vec![0, n as u32]);
        }
        // Spans touching a rewritten pose: first = start − 1 … start + count − 1 (cyclic).
        let first = (start + n - 1) % n;
        let spans = count + 1;
        let touched = |j: usize| (j + n - first) % n < spans;
        let h = 0.5f64.powi(self.bender.subdivision().levels as i32);
        for k in 0..self.strobe_count {
            let u = self.strobe_parameter(k);
            let j = ((u / h).floor().max(0.0) as usize).min(n - 1);
            // A sample on a knot may be evaluated on either neighbouring span.
            if touched(j) || touched((j + n - 1) % n) {
                self.write_strobe(k);
                mark(&mut self.dirty_strobe, k);
            }
        }
        let per = self.segments_per_point();
        for p in 0..self.points.len() {
            for s in 0..spans {
                let j = (first + s) % n;
                if j < per {
                    self.write_segment_at(p, j);
                    mark(&mut self.dirty_segments, p * per + j);
                }
            }
        }
        Ok(vec![start as u32, count as u32])
    }

    /// The pose of the smoothed motion at parameter `u` (7 numbers).
    #[wasm_bindgen(js_name = poseAt)]
    pub fn pose_at(&self, u: f64) -> Vec<f64> {
        let p: Pose = self.bender.pose_at(u);
        let q = screwbender::quat_to_wxyz(p.rotation);
        vec![p.origin.x, p.origin.y, p.origin.z, q[0], q[1], q[2], q[3]]
    }

    /// The control poses, 7 numbers per pose (origin, quaternion `w, x, y, z`).
    pub fn poses(&self) -> Vec<f64> {
        crate::convert::poses_to_array(self.bender.control())
    }

    /// The refined poses of the smoothed motion, 7 numbers per pose.
    pub fn refined(&self) -> Vec<f64> {
        crate::convert::poses_to_array(self.bender.refined().poses())
    }

    /// Number of refined poses.
    #[wasm_bindgen(getter, js_name = refinedCount)]
    pub fn refined_count(&self) -> usize {
        self.bender.refined().poses().len()
    }
}
