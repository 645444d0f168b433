// Wide anti-aliased-by-MSAA line segments, expanded to screen-space quads in the vertex shader
// (WebGPU and WebGL2 only draw 1-pixel lines natively). One instance per segment; 6 vertices
// per instance, no vertex buffer. Mirrors `Globals` and `Segment` in src/web/render/gpu.rs.

struct Globals {
    view_proj: mat4x4<f32>,
    eye: vec4<f32>,
    light_dir: vec4<f32>,
    viewport: vec4<f32>,
    params: vec4<f32>,
};

@group(0) @binding(0) var<uniform> globals: Globals;

struct SegmentIn {
    // Start point (xyz) and width in CSS pixels scaled by the device-pixel ratio (w).
    @location(0) a: vec4<f32>,
    // End point (xyz); w: depth offset towards the camera, in clip-space w units.
    @location(1) b: vec4<f32>,
    @location(2) color: vec4<f32>,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
};

// Clip-space w below which a point is behind the near plane for our purpose.
const MIN_W: f32 = 1e-4;

fn encode(c: vec3<f32>) -> vec3<f32> {
    if globals.params.x > 0.5 {
        let lo = c * 12.92;
        let hi = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
        return select(hi, lo, c <= vec3<f32>(0.0031308));
    }
    return c;
}

@vertex
fn vs_main(@builtin(vertex_index) vi: u32, s: SegmentIn) -> VertexOut {
    var c0 = globals.view_proj * vec4<f32>(s.a.xyz, 1.0);
    var c1 = globals.view_proj * vec4<f32>(s.b.xyz, 1.0);
    var out: VertexOut;
    out.color = vec4<f32>(encode(s.color.rgb), s.color.a);
    if c0.w < MIN_W && c1.w < MIN_W {
        out.clip = vec4<f32>(2.0, 2.0, 2.0, 1.0);
        return out;
    }
    // Clip the segment against the plane w = MIN_W so both ends project sensibly.
    if c0.w < MIN_W {
        c0 = mix(c0, c1, (MIN_W - c0.w) / (c1.w - c0.w));
    } else if c1.w < MIN_W {
        c1 = mix(c1, c0, (MIN_W - c1.w) / (c0.w - c1.w));
    }
    let half_vp = globals.viewport.xy * 0.5;
    let s0 = c0.xy / c0.w * half_vp;
    let s1 = c1.xy / c1.w * half_vp;
    var dir = s1 - s0;
    let len = length(dir);
    if len < 1e-6 {
        dir = vec2<f32>(1.0, 0.0);
    } else {
        dir = dir / len;
    }
    let nrm = vec2<f32>(-dir.y, dir.x);
    // Quad corners: (end, side) for the two triangles.
    var ends = array<f32, 6>(0.0, 1.0, 1.0, 0.0, 1.0, 0.0);
    var sides = array<f32, 6>(-1.0, -1.0, 1.0, -1.0, 1.0, 1.0);
    let t = ends[vi];
    let side = sides[vi];
    let half_w = 0.5 * s.a.w;
    var c = c0;
    var along = -1.0;
    if t > 0.5 {
        c = c1;
        along = 1.0;
    }
    // Extend past the ends by half the width (square caps join polylines without gaps).
    let offset_px = nrm * side * half_w + dir * along * half_w;
    let offset = offset_px / half_vp * c.w;
    out.clip = vec4<f32>(c.xy + offset, c.z - s.b.w, c.w);
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    return in.color;
}
