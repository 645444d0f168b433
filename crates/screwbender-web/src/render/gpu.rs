//! GPU-side data layouts: `#[repr(C)]` + bytemuck mirrors of the WGSL structs in
//! `the `.wgsl` files beside the renderer`. This module is the only place where the core's `f64` becomes `f32`.

use bytemuck::{Pod, Zeroable};
use glam::DVec3;

use screwbender::mesh::Mesh;

/// The per-frame uniform block `Globals` of `mesh.wgsl` and `line.wgsl` (128 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct Globals {
    /// Column-major view-projection matrix (world → clip, depth 0..1).
    pub view_proj: [f32; 16],
    /// Camera position (w unused).
    pub eye: [f32; 4],
    /// Unit direction towards the key light (w unused).
    pub light_dir: [f32; 4],
    /// Viewport width, height in physical pixels, 1/width, 1/height.
    pub viewport: [f32; 4],
    /// x: 1 when the shader must apply the sRGB transfer itself (non-sRGB target).
    pub params: [f32; 4],
}

/// One mesh vertex (`VertexIn` locations 0–1 of `mesh.wgsl`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct MeshVertex {
    /// Local position.
    pub position: [f32; 3],
    /// Local unit normal.
    pub normal: [f32; 3],
}

/// Floats per mesh instance as the page sends them: a column-major 4×4 model matrix and RGBA.
pub const INSTANCE_FLOATS: usize = 20;

/// Floats per line segment as the page sends them (`SegmentIn` of `line.wgsl`): start `xyz`,
/// width in physical pixels, end `xyz`, depth offset, RGBA.
pub const SEGMENT_FLOATS: usize = 12;

fn f32x3(v: DVec3) -> [f32; 3] {
    v.as_vec3().to_array()
}

/// The vertices of a core mesh, converted to `f32`.
pub fn mesh_vertices(mesh: &Mesh) -> Vec<MeshVertex> {
    mesh.positions
        .iter()
        .zip(&mesh.normals)
        .map(|(p, n)| MeshVertex {
            position: f32x3(*p),
            normal: f32x3(*n),
        })
        .collect()
}

/// The vertex buffer layout of [`MeshVertex`] (slot 0).
pub const MESH_VERTEX_LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
    array_stride: std::mem::size_of::<MeshVertex>() as u64,
    step_mode: wgpu::VertexStepMode::Vertex,
    attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3],
};

/// The per-instance buffer layout (slot 1): matrix columns at locations 2–5, colour at 6.
pub const INSTANCE_LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
    array_stride: (INSTANCE_FLOATS * 4) as u64,
    step_mode: wgpu::VertexStepMode::Instance,
    attributes: &wgpu::vertex_attr_array![
        2 => Float32x4, 3 => Float32x4, 4 => Float32x4, 5 => Float32x4, 6 => Float32x4
    ],
};

/// The per-segment instance buffer layout of `line.wgsl` (slot 0).
pub const SEGMENT_LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
    array_stride: (SEGMENT_FLOATS * 4) as u64,
    step_mode: wgpu::VertexStepMode::Instance,
    attributes: &wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4, 2 => Float32x4],
};

/// Writes one mesh instance (model matrix of `pose` scaled by `scale`, then RGBA) into `out`
/// ([`INSTANCE_FLOATS`] floats).
pub fn write_instance(out: &mut [f32], pose: &screwbender::Pose, scale: f64, rgba: [f32; 4]) {
    let m = pose.to_matrix() * glam::DMat4::from_scale(DVec3::splat(scale));
    out[..16].copy_from_slice(&m.as_mat4().to_cols_array());
    out[16..20].copy_from_slice(&rgba);
}

/// The look of a line: linear RGB + alpha, width in physical pixels, depth offset.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineStyle {
    /// Linear RGB and alpha.
    pub rgba: [f32; 4],
    /// Width in physical pixels.
    pub width: f32,
    /// Depth offset towards the camera (clip-space w units).
    pub bias: f32,
}

/// Writes one segment from `a` to `b` into `out` ([`SEGMENT_FLOATS`] floats).
pub fn write_segment(out: &mut [f32], a: DVec3, b: DVec3, style: &LineStyle) {
    let (a, b) = (f32x3(a), f32x3(b));
    out[..3].copy_from_slice(&a);
    out[3] = style.width;
    out[4..7].copy_from_slice(&b);
    out[7] = style.bias;
    out[8..12].copy_from_slice(&style.rgba);
}
