// Lit, instanced triangle meshes: every instance is a rigid pose (column-major model matrix,
// possibly uniformly scaled) and an RGBA colour. Mirrors `Globals`, `MeshVertex` and
// `Instance` in src/web/render/gpu.rs.

struct Globals {
    view_proj: mat4x4<f32>,
    // Camera position (w unused).
    eye: vec4<f32>,
    // Direction *towards* the key light, unit (w unused).
    light_dir: vec4<f32>,
    // Viewport width, height in physical pixels, then 1/width, 1/height.
    viewport: vec4<f32>,
    // x: 1 when the target is not sRGB and the shader must encode gamma itself.
    params: vec4<f32>,
};

@group(0) @binding(0) var<uniform> globals: Globals;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) m0: vec4<f32>,
    @location(3) m1: vec4<f32>,
    @location(4) m2: vec4<f32>,
    @location(5) m3: vec4<f32>,
    @location(6) color: vec4<f32>,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
};

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    let model = mat4x4<f32>(v.m0, v.m1, v.m2, v.m3);
    let world = model * vec4<f32>(v.position, 1.0);
    var out: VertexOut;
    out.clip = globals.view_proj * world;
    out.world = world.xyz;
    out.normal = (model * vec4<f32>(v.normal, 0.0)).xyz;
    out.color = v.color;
    return out;
}

// Linear to sRGB transfer (the target may be a plain UNORM format).
fn encode(c: vec3<f32>) -> vec3<f32> {
    if globals.params.x > 0.5 {
        let lo = c * 12.92;
        let hi = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
        return select(hi, lo, c <= vec3<f32>(0.0031308));
    }
    return c;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let to_eye = normalize(globals.eye.xyz - in.world);
    var n = normalize(in.normal);
    // Two-sided lighting: imported meshes may have inconsistent winding.
    if dot(n, to_eye) < 0.0 {
        n = -n;
    }
    let l = globals.light_dir.xyz;
    let base = in.color.rgb;
    // Hemisphere ambient (sky above, ground below; z is up), key diffuse, fill, Blinn specular.
    let sky = mix(vec3<f32>(0.32, 0.30, 0.28), vec3<f32>(0.45, 0.48, 0.55), 0.5 + 0.5 * n.z);
    let key = max(dot(n, l), 0.0);
    let fill = max(dot(n, normalize(vec3<f32>(-l.x, -l.y, 0.3))), 0.0) * 0.25;
    let h = normalize(l + to_eye);
    let spec = pow(max(dot(n, h), 0.0), 48.0) * 0.35;
    let rim = pow(1.0 - max(dot(n, to_eye), 0.0), 3.0) * 0.15;
    let lit = base * (sky + vec3<f32>(0.85 * key + fill)) + vec3<f32>(spec + rim);
    return vec4<f32>(encode(lit), in.color.a);
}
