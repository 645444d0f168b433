//! The playground's wgpu renderer for JavaScript: the class `Renderer` (feature `render`).
//!
//! The page owns the scene (which poses, colours, lines) and the camera; the renderer owns the
//! GPU. Meshes live in numbered *slots*, each drawn once per instance (a column-major 4×4 model
//! matrix and an RGBA colour, 20 floats); line segments live in numbered *layers* (12 floats per
//! segment: start `xyz`, width in physical pixels, end `xyz`, depth offset, RGBA). Slots and
//! layers flagged `overlay` are drawn after the scene with a cleared depth buffer (the gizmo).
//! Colours are linear RGB.

mod gpu;
mod local_update;
mod renderer;

use wasm_bindgen::prelude::*;

pub use gpu::{INSTANCE_FLOATS, SEGMENT_FLOATS};
pub use local_update::DragSession;
use renderer::Renderer;

use screwbender::mesh::Mesh;

/// The WebGPU/WebGL2 renderer of the playground (JS class `Renderer`).
#[wasm_bindgen(js_name = Renderer)]
pub struct RendererHandle {
    inner: Renderer,
    /// The PIP morph of the last scene asked for (scene id, cycle): its pairs of pieces are
    /// combined once, then every frame and strobe copy only evaluates them.
    morph: Option<(String, bool, screwbender::PipMorph)>,
}

/// The mesh for a mesh name (see [`Mesh::named`]), as a JS error when unknown.
fn mesh_by_name(name: &str) -> Result<Mesh, JsError> {
    Mesh::named(name).map_err(|e| JsError::new(&e.to_string()))
}

#[wasm_bindgen(js_class = Renderer)]
impl RendererHandle {
    /// Starts the renderer on `canvas` (drawing buffer `width × height` physical pixels):
    /// WebGPU when `allowWebgpu` and an adapter exists, else WebGL2. Rejects with a readable
    /// message when neither works.
    pub async fn create(
        canvas: web_sys::HtmlCanvasElement,
        #[wasm_bindgen(js_name = allowWebgpu)] allow_webgpu: bool,
        width: u32,
        height: u32,
    ) -> Result<RendererHandle, JsError> {
        let inner = Renderer::init(canvas, allow_webgpu, width, height)
            .await
            .map_err(|e| JsError::new(&e))?;
        Ok(RendererHandle { inner, morph: None })
    }

    /// The active backend: `"WebGPU"` or `"WebGL2"`.
    #[wasm_bindgen(getter)]
    pub fn backend(&self) -> String {
        self.inner.backend_name().to_string()
    }

    /// The MSAA sample count (1 when multisampling is not available).
    #[wasm_bindgen(getter)]
    pub fn samples(&self) -> u32 {
        self.inner.samples()
    }

    /// The largest drawing-buffer side the device allows, in physical pixels (a picture drawn
    /// larger than the canvas must fit it).
    #[wasm_bindgen(getter, js_name = maxSize)]
    pub fn max_size(&self) -> u32 {
        self.inner.max_size()
    }

    /// Sets the background colour as displayed: sRGB-encoded `r`, `g`, `b` in 0..=1 (the
    /// default is a light grey, `0.91, 0.925, 0.945`). Throws naming the component that is not a
    /// number in 0..=1, and then keeps the previous background. Drawn from the next frame on.
    #[wasm_bindgen(js_name = setBackground)]
    pub fn set_background(&mut self, r: f64, g: f64, b: f64) -> Result<(), JsError> {
        for (name, c) in [("r", r), ("g", g), ("b", b)] {
            if !(0.0..=1.0).contains(&c) {
                return Err(JsError::new(&format!(
                    "background {name}: {c} is not a number in 0..1"
                )));
            }
        }
        self.inner.set_background([r, g, b]);
        Ok(())
    }

    /// Multiplies every line width by `scale` from the next `setCamera` on (1 by default): a
    /// picture drawn at `scale` times the canvas size (a 2× screenshot) keeps the lines'
    /// proportions. Throws when `scale` is not a finite number in 0.1..=16, and then keeps the
    /// previous scale.
    #[wasm_bindgen(js_name = setLineScale)]
    pub fn set_line_scale(&mut self, scale: f64) -> Result<(), JsError> {
        if !(0.1..=16.0).contains(&scale) {
            return Err(JsError::new(&format!(
                "line scale: {scale} is not a number in 0.1..16"
            )));
        }
        self.inner.set_line_scale(scale as f32);
        Ok(())
    }

    /// Resizes the drawing buffer (physical pixels: CSS size × devicePixelRatio).
    pub fn resize(&mut self, width: u32, height: u32) {
        self.inner.resize(width, height);
    }

    /// Sets the camera: `viewProj` a column-major 4×4 (world → clip, depth 0..1), `eye` the
    /// camera position.
    #[wasm_bindgen(js_name = setCamera)]
    pub fn set_camera(
        &mut self,
        #[wasm_bindgen(js_name = viewProj)] view_proj: &[f32],
        eye: &[f32],
    ) -> Result<(), JsError> {
        let vp: [f32; 16] = view_proj
            .try_into()
            .map_err(|_| JsError::new("viewProj: expected 16 numbers"))?;
        let eye: [f32; 3] = eye
            .try_into()
            .map_err(|_| JsError::new("eye: expected 3 numbers"))?;
        self.inner.update(vp, eye);
        Ok(())
    }

    /// Puts the named mesh (see the module docs) in `slot`; returns its triangle count.
    #[wasm_bindgen(js_name = setMesh)]
    pub fn set_mesh(&mut self, slot: usize, name: &str, overlay: bool) -> Result<usize, JsError> {
        let mesh = mesh_by_name(name)?;
        self.inner.set_mesh(slot, &mesh, overlay);
        Ok(mesh.triangle_count())
    }

    /// Puts in `slot` the morphing object of a scene with per-pose shapes (`morphShapes`, scene
    /// A8) at motion parameter `u`: Kaul & Rossignac's PIP morph ([`screwbender::PipMorph`]),
    /// the union of the Minkowski combinations of the shapes' convex pieces with the C¹ blend
    /// of [`screwbender::morph_weights`]; at a control pose that pose's shape exactly. Returns
    /// the triangle count.
    #[wasm_bindgen(js_name = setMorphMesh)]
    pub fn set_morph_mesh(
        &mut self,
        slot: usize,
        scene: &str,
        closed: bool,
        u: f64,
    ) -> Result<usize, JsError> {
        if !u.is_finite() {
            return Err(JsError::new("u: not a finite number (NaN or infinity)"));
        }
        let cached = matches!(&self.morph, Some((id, c, _)) if id == scene && *c == closed);
        if !cached {
            let s = screwbender::presets::preset(scene)
                .ok_or_else(|| JsError::new(&format!("unknown scene {scene:?}")))?;
            let morph = screwbender::PipMorph::from_shapes(&s.morph_shapes, closed)?;
            self.morph = Some((scene.to_string(), closed, morph));
        }
        let (_, _, morph) = self.morph.as_ref().expect("set above");
        let mesh = morph.mesh_at(u)?;
        self.inner.set_mesh(slot, &mesh, false);
        Ok(mesh.triangle_count())
    }

    /// Parses an OBJ text ([`Mesh::from_obj`]: size and triangle limits), scales it to fit a
    /// cube of side `size` centred on the local origin and puts it in `slot`. Returns the
    /// triangle count; on error the slot keeps its previous mesh.
    #[wasm_bindgen(js_name = setObjMesh)]
    pub fn set_obj_mesh(&mut self, slot: usize, text: &str, size: f64) -> Result<usize, JsError> {
        let mesh = Mesh::from_obj(text)?.normalized(size);
        self.inner.set_mesh(slot, &mesh, false);
        Ok(mesh.triangle_count())
    }

    /// Reads a glTF 2.0 asset (`.glb`, or `.gltf` with embedded buffers; [`Mesh::from_gltf`]),
    /// scales it like [`RendererHandle::set_obj_mesh`] and puts it in `slot`. Returns the
    /// triangle count; on error the slot keeps its previous mesh.
    #[cfg(feature = "gltf-mesh")]
    #[wasm_bindgen(js_name = setGltfMesh)]
    pub fn set_gltf_mesh(
        &mut self,
        slot: usize,
        bytes: &[u8],
        size: f64,
    ) -> Result<usize, JsError> {
        let mesh = Mesh::from_gltf(bytes)?.normalized(size);
        self.inner.set_mesh(slot, &mesh, false);
        Ok(mesh.triangle_count())
    }

    /// Replaces the instances of mesh `slot` (20 floats each: matrix, RGBA).
    #[wasm_bindgen(js_name = setInstances)]
    pub fn set_instances(&mut self, slot: usize, data: &[f32]) -> Result<(), JsError> {
        if data.len() % INSTANCE_FLOATS != 0 {
            return Err(JsError::new("instances: length must be a multiple of 20"));
        }
        if !self.inner.set_instances(slot, data) {
            return Err(JsError::new(&format!("instances: slot {slot} has no mesh")));
        }
        Ok(())
    }

    /// Replaces line layer `layer` (12 floats per segment).
    #[wasm_bindgen(js_name = setLines)]
    pub fn set_lines(&mut self, layer: usize, data: &[f32], overlay: bool) -> Result<(), JsError> {
        if data.len() % SEGMENT_FLOATS != 0 {
            return Err(JsError::new("lines: length must be a multiple of 12"));
        }
        self.inner.set_lines(layer, data, overlay);
        Ok(())
    }

    /// Uploads a drag session's strobe instances into mesh `slot` and its trajectory segments
    /// into line `layer`, straight from wasm memory (see [`DragSession`]): only the ranges it
    /// rewrote since the last call, or everything the first time.
    #[wasm_bindgen(js_name = applyDrag)]
    pub fn apply_drag(
        &mut self,
        session: &mut DragSession,
        slot: usize,
        layer: usize,
    ) -> Result<(), JsError> {
        let patched = !session.dirty_all
            && self
                .inner
                .patch_instances(slot, &session.strobe, &session.dirty_strobe)
            && self
                .inner
                .patch_lines(layer, &session.segments, &session.dirty_segments);
        if !patched {
            self.set_instances(slot, &session.strobe)?;
            self.inner.set_lines(layer, &session.segments, false);
        }
        session.dirty_all = false;
        session.dirty_strobe.clear();
        session.dirty_segments.clear();
        Ok(())
    }

    /// Draws a frame; false when the surface was not ready (try again next frame).
    pub fn render(&mut self) -> bool {
        self.inner.render()
    }
}
