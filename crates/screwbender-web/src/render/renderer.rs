//! The wgpu renderer, shaped like the wgpu examples: [`Renderer::init`], [`Renderer::resize`],
//! [`Renderer::update`] (uniforms), [`Renderer::render`].
//!
//! It draws two passes into one (multisampled when the adapter allows) target:
//! the *scene* (instanced lit meshes, then wide line segments, depth-tested) and the *overlay*
//! (the gizmo: same pipelines, depth cleared first so it is never hidden by the scene).

use wgpu::util::DeviceExt;

use super::gpu::{
    mesh_vertices, Globals, MeshVertex, INSTANCE_FLOATS, INSTANCE_LAYOUT, MESH_VERTEX_LAYOUT,
    SEGMENT_FLOATS, SEGMENT_LAYOUT,
};
use screwbender::mesh::Mesh;

/// Depth buffer format (available on WebGPU and WebGL2).
const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth24Plus;
/// Preferred MSAA sample count (used when the surface format supports it).
const MSAA_SAMPLES: u32 = 4;
/// Default background colour as displayed (sRGB-encoded): the paper's white, slightly cooled
/// (the page may set another one: [`Renderer::set_background`]).
const CLEAR: wgpu::Color = wgpu::Color {
    r: 0.91,
    g: 0.925,
    b: 0.945,
    a: 1.0,
};

/// A growable GPU buffer holding `len` items.
struct Dynamic {
    buffer: wgpu::Buffer,
    capacity: u64,
    len: u32,
}

impl Dynamic {
    fn new(device: &wgpu::Device, label: &str) -> Dynamic {
        Dynamic {
            buffer: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: 256,
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
            capacity: 256,
            len: 0,
        }
    }

    /// Uploads `data` (`stride` floats per item), reallocating when it does not fit.
    fn upload(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, data: &[f32], stride: usize) {
        let bytes: &[u8] = bytemuck::cast_slice(data);
        let size = bytes.len() as u64;
        if size > self.capacity {
            let capacity = size.next_power_of_two();
            self.buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("dynamic"),
                size: capacity,
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            self.capacity = capacity;
        }
        if !bytes.is_empty() {
            queue.write_buffer(&self.buffer, 0, bytes);
        }
        self.len = (data.len() / stride) as u32;
    }
}

impl Dynamic {
    /// Overwrites items `first..first + count` (`stride` floats each) from `data` (the whole
    /// array). Returns false, writing nothing, when the range is not inside the buffer.
    fn write_range(
        &self,
        queue: &wgpu::Queue,
        data: &[f32],
        stride: usize,
        first: usize,
        count: usize,
    ) -> bool {
        let (a, b) = (first * stride, (first + count) * stride);
        if first + count > self.len as usize || b > data.len() {
            return false;
        }
        queue.write_buffer(
            &self.buffer,
            (a * 4) as u64,
            bytemuck::cast_slice(&data[a..b]),
        );
        true
    }
}

/// A mesh with its own instance list.
struct MeshSlot {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
    instances: Dynamic,
    overlay: bool,
}

/// A list of line segments.
struct LineLayer {
    segments: Dynamic,
    overlay: bool,
}

/// The renderer: device, surface, pipelines and the scene's buffers.
pub struct Renderer {
    surface: wgpu::Surface<'static>,
    device: wgpu::Device,
    queue: wgpu::Queue,
    config: wgpu::SurfaceConfiguration,
    backend: wgpu::Backend,
    samples: u32,
    globals: Globals,
    globals_buffer: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    mesh_pipeline: wgpu::RenderPipeline,
    line_pipeline: wgpu::RenderPipeline,
    depth: wgpu::TextureView,
    msaa: Option<wgpu::TextureView>,
    meshes: Vec<Option<MeshSlot>>,
    lines: Vec<Option<LineLayer>>,
    /// The background as displayed (sRGB-encoded, opaque).
    clear: wgpu::Color,
    /// Line widths are multiplied by this (a picture drawn at k times the canvas size).
    line_scale: f32,
}

/// Why the renderer could not start (shown in the page).
pub type InitError = String;

/// The WebGPU instance, adapter and device that every renderer of the page shares once the
/// first one has opened them (one per wasm instance: many figures, one device). WebGL2 devices
/// are not shared: wgpu binds a WebGL2 adapter to the context of one canvas.
#[derive(Clone)]
struct SharedGpu {
    instance: wgpu::Instance,
    adapter: wgpu::Adapter,
    device: wgpu::Device,
    queue: wgpu::Queue,
}

thread_local! {
    /// The shared WebGPU device (None until a renderer opens one; wasm has one thread).
    static SHARED_WEBGPU: std::cell::RefCell<Option<SharedGpu>> =
        const { std::cell::RefCell::new(None) };
}

impl Renderer {
    /// Creates the device on `canvas`: WebGPU when an adapter exists (and `allow_webgpu`), else
    /// WebGL2. `width`, `height` are the drawing-buffer size in physical pixels.
    pub async fn init(
        canvas: web_sys::HtmlCanvasElement,
        allow_webgpu: bool,
        width: u32,
        height: u32,
    ) -> Result<Renderer, InitError> {
        let shared = if allow_webgpu {
            SHARED_WEBGPU.with(|s| s.borrow().clone())
        } else {
            None
        };
        let (surface, adapter, device, queue) = match shared {
            Some(g) => {
                let surface = g
                    .instance
                    .create_surface(wgpu::SurfaceTarget::Canvas(canvas))
                    .map_err(|e| format!("cannot create a drawing surface on the canvas: {e}"))?;
                (surface, g.adapter, g.device, g.queue)
            }
            None => Self::open(canvas, allow_webgpu).await?,
        };
        Self::with_device(surface, adapter, device, queue, width, height)
    }

    /// Opens an instance, adapter and device for `canvas` and its surface (see [`Self::init`]);
    /// a WebGPU device is kept for the renderers that follow.
    async fn open(
        canvas: web_sys::HtmlCanvasElement,
        allow_webgpu: bool,
    ) -> Result<
        (
            wgpu::Surface<'static>,
            wgpu::Adapter,
            wgpu::Device,
            wgpu::Queue,
        ),
        InitError,
    > {
        let backends = if allow_webgpu {
            wgpu::Backends::BROWSER_WEBGPU | wgpu::Backends::GL
        } else {
            wgpu::Backends::GL
        };
        let desc = wgpu::InstanceDescriptor {
            backends,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        };
        let instance = wgpu::util::new_instance_with_webgpu_detection(desc).await;
        let surface = instance
            .create_surface(wgpu::SurfaceTarget::Canvas(canvas))
            .map_err(|e| format!("cannot create a drawing surface on the canvas: {e}"))?;
        let adapter = instance
            .request_adapter(&wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::HighPerformance,
                force_fallback_adapter: false,
                compatible_surface: Some(&surface),
                apply_limit_buckets: false,
            })
            .await
            .map_err(|e| format!("no WebGPU or WebGL2 adapter: {e}"))?;
        let backend = adapter.get_info().backend;
        let limits = wgpu::Limits::downlevel_webgl2_defaults().using_resolution(adapter.limits());
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("screwbender"),
                required_features: wgpu::Features::empty(),
                required_limits: limits,
                experimental_features: wgpu::ExperimentalFeatures::disabled(),
                memory_hints: wgpu::MemoryHints::Performance,
                trace: wgpu::Trace::Off,
            })
            .await
            .map_err(|e| format!("cannot open the graphics device: {e}"))?;
        if backend == wgpu::Backend::BrowserWebGpu {
            let g = SharedGpu {
                instance,
                adapter: adapter.clone(),
                device: device.clone(),
                queue: queue.clone(),
            };
            SHARED_WEBGPU.with(|s| *s.borrow_mut() = Some(g));
        }
        Ok((surface, adapter, device, queue))
    }

    /// The renderer on an opened device: surface configuration, pipelines, targets.
    fn with_device(
        surface: wgpu::Surface<'static>,
        adapter: wgpu::Adapter,
        device: wgpu::Device,
        queue: wgpu::Queue,
        width: u32,
        height: u32,
    ) -> Result<Renderer, InitError> {
        let backend = adapter.get_info().backend;
        let caps = surface.get_capabilities(&adapter);
        let format = caps
            .formats
            .iter()
            .copied()
            .find(|f| !f.is_srgb())
            .or_else(|| caps.formats.first().copied())
            .ok_or("the canvas offers no texture format")?;
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            format,
            width: width.max(1),
            height: height.max(1),
            present_mode: wgpu::PresentMode::Fifo,
            desired_maximum_frame_latency: 2,
            alpha_mode: caps
                .alpha_modes
                .first()
                .copied()
                .unwrap_or(wgpu::CompositeAlphaMode::Auto),
            view_formats: vec![],
            ..surface
                .get_default_config(&adapter, width.max(1), height.max(1))
                .ok_or("the canvas surface is not supported by the adapter")?
        };
        surface.configure(&device, &config);
        let samples = if adapter
            .get_texture_format_features(format)
            .flags
            .sample_count_supported(MSAA_SAMPLES)
        {
            MSAA_SAMPLES
        } else {
            1
        };

        let globals = Globals {
            view_proj: glam::Mat4::IDENTITY.to_cols_array(),
            eye: [0.0, 0.0, 10.0, 1.0],
            light_dir: glam::Vec3::new(0.35, -0.45, 0.82)
                .normalize()
                .extend(0.0)
                .to_array(),
            viewport: [width as f32, height as f32, 1.0, 1.0],
            params: [if format.is_srgb() { 0.0 } else { 1.0 }, 0.0, 0.0, 0.0],
        };
        let globals_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("globals"),
            contents: bytemuck::bytes_of(&globals),
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });
        let bind_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("globals"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<Globals>() as u64),
                },
                count: None,
            }],
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("globals"),
            layout: &bind_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: globals_buffer.as_entire_binding(),
            }],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("globals"),
            bind_group_layouts: &[Some(&bind_layout)],
            immediate_size: 0,
        });
        let mesh_shader = device.create_shader_module(wgpu::include_wgsl!("mesh.wgsl"));
        let line_shader = device.create_shader_module(wgpu::include_wgsl!("line.wgsl"));
        let pipeline = |label: &str,
                        module: &wgpu::ShaderModule,
                        buffers: &[Option<wgpu::VertexBufferLayout<'_>>],
                        blend: Option<wgpu::BlendState>| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(&layout),
                vertex: wgpu::VertexState {
                    module,
                    entry_point: Some("vs_main"),
                    buffers,
                    compilation_options: Default::default(),
                },
                primitive: wgpu::PrimitiveState {
                    topology: wgpu::PrimitiveTopology::TriangleList,
                    cull_mode: None,
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    depth_write_enabled: Some(true),
                    depth_compare: Some(wgpu::CompareFunction::LessEqual),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: wgpu::MultisampleState {
                    count: samples,
                    ..Default::default()
                },
                fragment: Some(wgpu::FragmentState {
                    module,
                    entry_point: Some("fs_main"),
                    targets: &[Some(wgpu::ColorTargetState {
                        format,
                        blend,
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                    compilation_options: Default::default(),
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let mesh_pipeline = pipeline(
            "mesh",
            &mesh_shader,
            &[Some(MESH_VERTEX_LAYOUT), Some(INSTANCE_LAYOUT)],
            None,
        );
        let line_pipeline = pipeline(
            "line",
            &line_shader,
            &[Some(SEGMENT_LAYOUT)],
            Some(wgpu::BlendState::ALPHA_BLENDING),
        );
        let (depth, msaa) = Self::targets(&device, &config, samples);
        Ok(Renderer {
            surface,
            device,
            queue,
            config,
            backend,
            samples,
            globals,
            globals_buffer,
            bind_group,
            mesh_pipeline,
            line_pipeline,
            depth,
            msaa,
            meshes: Vec::new(),
            lines: Vec::new(),
            clear: CLEAR,
            line_scale: 1.0,
        })
    }

    fn targets(
        device: &wgpu::Device,
        config: &wgpu::SurfaceConfiguration,
        samples: u32,
    ) -> (wgpu::TextureView, Option<wgpu::TextureView>) {
        let size = wgpu::Extent3d {
            width: config.width,
            height: config.height,
            depth_or_array_layers: 1,
        };
        let texture = |label, format| {
            device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some(label),
                    size,
                    mip_level_count: 1,
                    sample_count: samples,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                    view_formats: &[],
                })
                .create_view(&Default::default())
        };
        let depth = texture("depth", DEPTH_FORMAT);
        let msaa = (samples > 1).then(|| texture("msaa", config.format));
        (depth, msaa)
    }

    /// `"WebGPU"` or `"WebGL2"`.
    pub fn backend_name(&self) -> &'static str {
        match self.backend {
            wgpu::Backend::BrowserWebGpu => "WebGPU",
            wgpu::Backend::Gl => "WebGL2",
            _ => "other",
        }
    }

    /// The largest drawing buffer side the device allows (physical pixels).
    pub fn max_size(&self) -> u32 {
        self.device.limits().max_texture_dimension_2d
    }

    /// Sets the background as displayed (sRGB-encoded components in 0..=1, opaque).
    pub fn set_background(&mut self, rgb: [f64; 3]) {
        self.clear = wgpu::Color {
            r: rgb[0],
            g: rgb[1],
            b: rgb[2],
            a: 1.0,
        };
    }

    /// Multiplies every line width by `scale` (> 0) from the next [`Renderer::update`] on: a
    /// picture drawn at `scale` times the canvas size keeps the lines' proportions.
    pub fn set_line_scale(&mut self, scale: f32) {
        self.line_scale = scale;
    }

    /// The MSAA sample count in use (1 = no multisampling).
    pub fn samples(&self) -> u32 {
        self.samples
    }

    /// Resizes the drawing buffer (physical pixels).
    pub fn resize(&mut self, width: u32, height: u32) {
        let (width, height) = (width.max(1), height.max(1));
        if width == self.config.width && height == self.config.height {
            return;
        }
        self.config.width = width;
        self.config.height = height;
        self.surface.configure(&self.device, &self.config);
        (self.depth, self.msaa) = Self::targets(&self.device, &self.config, self.samples);
    }

    /// Sets the camera (column-major view-projection, depth range 0..1) and eye position.
    pub fn update(&mut self, view_proj: [f32; 16], eye: [f32; 3]) {
        self.globals.view_proj = view_proj;
        self.globals.eye = [eye[0], eye[1], eye[2], 1.0];
        // The line shader turns widths in pixels into clip space through the viewport: a
        // smaller viewport than the target widens every line by the same factor.
        let (w, h) = (
            self.config.width as f32 / self.line_scale,
            self.config.height as f32 / self.line_scale,
        );
        self.globals.viewport = [w, h, 1.0 / w, 1.0 / h];
        self.queue
            .write_buffer(&self.globals_buffer, 0, bytemuck::bytes_of(&self.globals));
    }

    /// Replaces the mesh of `slot` (keeping its instances), drawn in the scene or the overlay.
    pub fn set_mesh(&mut self, slot: usize, mesh: &Mesh, overlay: bool) {
        let vertices: Vec<MeshVertex> = mesh_vertices(mesh);
        let vertices = self
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("mesh vertices"),
                contents: bytemuck::cast_slice(&vertices),
                usage: wgpu::BufferUsages::VERTEX,
            });
        let indices = self
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("mesh indices"),
                contents: bytemuck::cast_slice(&mesh.indices),
                usage: wgpu::BufferUsages::INDEX,
            });
        if self.meshes.len() <= slot {
            self.meshes.resize_with(slot + 1, || None);
        }
        let instances = match self.meshes[slot].take() {
            Some(old) => old.instances,
            None => Dynamic::new(&self.device, "instances"),
        };
        self.meshes[slot] = Some(MeshSlot {
            vertices,
            indices,
            index_count: mesh.indices.len() as u32,
            instances,
            overlay,
        });
    }

    /// Replaces the instances of mesh `slot` ([`INSTANCE_FLOATS`] floats each). Returns false
    /// when the slot has no mesh.
    pub fn set_instances(&mut self, slot: usize, data: &[f32]) -> bool {
        match self.meshes.get_mut(slot) {
            Some(Some(m)) => {
                m.instances
                    .upload(&self.device, &self.queue, data, INSTANCE_FLOATS);
                true
            }
            _ => false,
        }
    }

    /// Uploads only the listed `(first, count)` item ranges of `data` into the instances of
    /// `slot` (which must already hold `data`'s length); false if that does not hold.
    pub fn patch_instances(
        &mut self,
        slot: usize,
        data: &[f32],
        ranges: &[(usize, usize)],
    ) -> bool {
        match self.meshes.get(slot) {
            Some(Some(m)) if m.instances.len as usize * INSTANCE_FLOATS == data.len() => {
                ranges.iter().all(|&(f, c)| {
                    m.instances
                        .write_range(&self.queue, data, INSTANCE_FLOATS, f, c)
                })
            }
            _ => false,
        }
    }

    /// Like [`Renderer::patch_instances`] for line layer `layer`.
    pub fn patch_lines(&mut self, layer: usize, data: &[f32], ranges: &[(usize, usize)]) -> bool {
        match self.lines.get(layer) {
            Some(Some(l)) if l.segments.len as usize * SEGMENT_FLOATS == data.len() => {
                ranges.iter().all(|&(f, c)| {
                    l.segments
                        .write_range(&self.queue, data, SEGMENT_FLOATS, f, c)
                })
            }
            _ => false,
        }
    }

    /// Replaces line layer `layer` ([`SEGMENT_FLOATS`] floats per segment).
    pub fn set_lines(&mut self, layer: usize, data: &[f32], overlay: bool) {
        if self.lines.len() <= layer {
            self.lines.resize_with(layer + 1, || None);
        }
        let mut l = match self.lines[layer].take() {
            Some(l) => l,
            None => LineLayer {
                segments: Dynamic::new(&self.device, "segments"),
                overlay,
            },
        };
        l.overlay = overlay;
        l.segments
            .upload(&self.device, &self.queue, data, SEGMENT_FLOATS);
        self.lines[layer] = Some(l);
    }

    fn draw(&self, pass: &mut wgpu::RenderPass<'_>, overlay: bool) {
        pass.set_bind_group(0, &self.bind_group, &[]);
        pass.set_pipeline(&self.mesh_pipeline);
        for m in self.meshes.iter().flatten() {
            if m.overlay != overlay || m.instances.len == 0 || m.index_count == 0 {
                continue;
            }
            pass.set_vertex_buffer(0, m.vertices.slice(..));
            pass.set_vertex_buffer(1, m.instances.buffer.slice(..));
            pass.set_index_buffer(m.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..m.index_count, 0, 0..m.instances.len);
        }
        pass.set_pipeline(&self.line_pipeline);
        for l in self.lines.iter().flatten() {
            if l.overlay != overlay || l.segments.len == 0 {
                continue;
            }
            pass.set_vertex_buffer(0, l.segments.buffer.slice(..));
            pass.draw(0..6, 0..l.segments.len);
        }
    }

    /// Draws a frame. Returns false when the frame was skipped (surface lost or outdated; it is
    /// reconfigured for the next frame).
    pub fn render(&mut self) -> bool {
        let frame = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(f)
            | wgpu::CurrentSurfaceTexture::Suboptimal(f) => f,
            _ => {
                self.surface.configure(&self.device, &self.config);
                return false;
            }
        };
        let view = frame.texture.create_view(&Default::default());
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("frame"),
            });
        let (target, resolve) = match &self.msaa {
            Some(msaa) => (msaa, Some(&view)),
            None => (&view, None),
        };
        // The background is a display colour: decode it when the target encodes sRGB itself.
        let clear = if self.config.format.is_srgb() {
            let lin = |c: f64| c.powf(2.2);
            wgpu::Color {
                r: lin(self.clear.r),
                g: lin(self.clear.g),
                b: lin(self.clear.b),
                a: 1.0,
            }
        } else {
            self.clear
        };
        for overlay in [false, true] {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some(if overlay { "overlay" } else { "scene" }),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: target,
                    depth_slice: None,
                    resolve_target: if overlay { resolve } else { None },
                    ops: wgpu::Operations {
                        load: if overlay {
                            wgpu::LoadOp::Load
                        } else {
                            wgpu::LoadOp::Clear(clear)
                        },
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &self.depth,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Discard,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            self.draw(&mut pass, overlay);
        }
        self.queue.submit([encoder.finish()]);
        self.queue.present(frame);
        true
    }
}
