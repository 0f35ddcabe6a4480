struct df_std140_df_double {
  @align(16) @size(16) v: df_double,
}

struct df_std140_float {
  @align(16) @size(16) v: f32,
}

struct df_double {
  hi: f32,
  lo: f32,
}

struct df_dvec3 {
  hi: vec3<f32>,
  lo: vec3<f32>,
}

struct Body {
  @align(16) @size(16) mass: df_double,
  radius: array<df_std140_float, 2>,
  position: df_dvec3,
}

struct Scene {
  scale: array<df_std140_df_double, 3>,
  @align(16) @size(16) origin: df_double,
  sun: Body,
  weights: array<df_std140_float, 2>,
}

@group(0) @binding(0) var<uniform> df_block_Scene: Scene;
struct Bodies {
  bodies: array<Body, 4>,
  masses: array<df_std140_df_double>,
}

@group(0) @binding(1) var<storage, read> df_block_Bodies: Bodies;
struct Results {
  r: array<df_std140_df_double>,
}

@group(0) @binding(2) var<storage, read_write> df_block_Results: Results;
struct df_uniforms_t {
  df_guard: f32,  // offset 0
}
@group(0) @binding(3) var<uniform> df_uniforms: df_uniforms_t;

fn df_split_float(a: f32) -> df_double {
  var bits: u32 = bitcast<u32>(a);
  var hi: f32 = bitcast<f32>((min((bits + 2048u), (bits | 2139092992u)) & 4294963200u));
  var lo: f32 = (a - hi);
  return df_double(hi, lo);
}

fn df_mul12_error_df_double_df_double_float(sa: df_double, sb: df_double, p: f32) -> f32 {
  var hh: f32 = (sa.hi * sb.hi);
  var hl: f32 = (sa.hi * sb.lo);
  var lh: f32 = (sa.lo * sb.hi);
  var ll: f32 = (sa.lo * sb.lo);
  var t1: f32 = (hh - p);
  var t2: f32 = (t1 + hl);
  var t3: f32 = (t2 + lh);
  var e: f32 = (t3 + ll);
  return e;
}

fn df_two_prod_float_float(a: f32, b: f32) -> df_double {
  var p: f32 = ((a * b) - df_uniforms.df_guard);
  var sa: df_double = df_split_float(a);
  var sb: df_double = df_split_float(b);
  var e: f32 = df_mul12_error_df_double_df_double_float(sa, sb, p);
  return df_double(p, e);
}

fn df_fast_two_sum_float_float(a: f32, b: f32) -> df_double {
  var s: f32 = ((a + b) - df_uniforms.df_guard);
  var z: f32 = ((s - a) - df_uniforms.df_guard);
  var e: f32 = (b - z);
  return df_double(s, e);
}

fn df_finish_df_double_float(z: df_double, f: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
}

fn df_mul_df_double_df_double(a: df_double, b: df_double) -> df_double {
  var c: df_double = df_two_prod_float_float(a.hi, b.hi);
  var tl: f32 = (a.hi * b.lo);
  var th: f32 = (a.lo * b.hi);
  var cl2: f32 = (th + tl);
  var cl3: f32 = (c.lo + cl2);
  var z: df_double = df_fast_two_sum_float_float(c.hi, cl3);
  var r_1: df_double = df_finish_df_double_float(z, c.hi);
  return r_1;
}

fn df_two_sum_float_float(a: f32, b: f32) -> df_double {
  var s: f32 = ((a + b) - df_uniforms.df_guard);
  var bb: f32 = ((s - a) - df_uniforms.df_guard);
  var ab: f32 = (s - bb);
  var da: f32 = (a - ab);
  var db: f32 = (b - bb);
  var e: f32 = (da + db);
  return df_double(s, e);
}

fn df_add_df_double_df_double(a: df_double, b: df_double) -> df_double {
  var s: df_double = df_two_sum_float_float(a.hi, b.hi);
  var t: df_double = df_two_sum_float_float(a.lo, b.lo);
  var c: f32 = (s.lo + t.hi);
  var v: df_double = df_fast_two_sum_float_float(s.hi, c);
  var w: f32 = (t.lo + v.lo);
  var z: df_double = df_fast_two_sum_float_float(v.hi, w);
  var r_1: df_double = df_finish_df_double_float(z, s.hi);
  return r_1;
}

fn df_neg_df_dvec3(a: df_dvec3) -> df_dvec3 {
  var h: vec3<f32> = -(a.hi);
  var l: vec3<f32> = -(a.lo);
  return df_dvec3(h, l);
}

fn df_two_sum_vec3_vec3(a: vec3<f32>, b: vec3<f32>) -> df_dvec3 {
  var s: vec3<f32> = ((a + b) - df_uniforms.df_guard);
  var bb: vec3<f32> = ((s - a) - df_uniforms.df_guard);
  var ab: vec3<f32> = (s - bb);
  var da: vec3<f32> = (a - ab);
  var db: vec3<f32> = (b - bb);
  var e: vec3<f32> = (da + db);
  return df_dvec3(s, e);
}

fn df_fast_two_sum_vec3_vec3(a: vec3<f32>, b: vec3<f32>) -> df_dvec3 {
  var s: vec3<f32> = ((a + b) - df_uniforms.df_guard);
  var z: vec3<f32> = ((s - a) - df_uniforms.df_guard);
  var e: vec3<f32> = (b - z);
  return df_dvec3(s, e);
}

fn df_finish_df_dvec3_vec3(z: df_dvec3, f: vec3<f32>) -> df_dvec3 {
  var r0: df_double = df_finish_df_double_float(df_double(z.hi[0i], z.lo[0i]), f[0i]);
  var r1: df_double = df_finish_df_double_float(df_double(z.hi[1i], z.lo[1i]), f[1i]);
  var r2: df_double = df_finish_df_double_float(df_double(z.hi[2i], z.lo[2i]), f[2i]);
  return df_dvec3(vec3<f32>(r0.hi, r1.hi, r2.hi), vec3<f32>(r0.lo, r1.lo, r2.lo));
}

fn df_add_df_dvec3_df_dvec3(a: df_dvec3, b: df_dvec3) -> df_dvec3 {
  var s: df_dvec3 = df_two_sum_vec3_vec3(a.hi, b.hi);
  var t: df_dvec3 = df_two_sum_vec3_vec3(a.lo, b.lo);
  var c: vec3<f32> = (s.lo + t.hi);
  var v: df_dvec3 = df_fast_two_sum_vec3_vec3(s.hi, c);
  var w: vec3<f32> = (t.lo + v.lo);
  var z: df_dvec3 = df_fast_two_sum_vec3_vec3(v.hi, w);
  var r_1: df_dvec3 = df_finish_df_dvec3_vec3(z, s.hi);
  return r_1;
}

fn df_sub_df_dvec3_df_dvec3(a: df_dvec3, b: df_dvec3) -> df_dvec3 {
  var nb: df_dvec3 = df_neg_df_dvec3(b);
  var z: df_dvec3 = df_add_df_dvec3_df_dvec3(a, nb);
  return z;
}

fn df_norm_scale(h: vec3<f32>) -> vec2<f32> {
  var ah: vec3<f32> = abs(h);
  var big: bool = any((ah > vec3<f32>(0x1p+60f, 0x1p+60f, 0x1p+60f)));
  var small: bool = all((ah < vec3<f32>(0x1p-36f, 0x1p-36f, 0x1p-36f)));
  var down: f32 = select(1.0f, 0x1p-90f, big);
  var s: f32 = select(down, 0x1p+90f, small);
  var up: f32 = select(1.0f, 0x1p+90f, big);
  var back: f32 = select(up, 0x1p-90f, small);
  return vec2<f32>(s, back);
}

fn df_scale_pow2_df_dvec3_float(a: df_dvec3, s: f32) -> df_dvec3 {
  var h: vec3<f32> = (a.hi * s);
  var l: vec3<f32> = (a.lo * s);
  return df_dvec3(h, l);
}

fn df_scale_pow2_df_double_float(a: df_double, s: f32) -> df_double {
  var h: f32 = (a.hi * s);
  var l: f32 = (a.lo * s);
  return df_double(h, l);
}

fn df_split_vec3(a: vec3<f32>) -> df_dvec3 {
  var bits: vec3<u32> = bitcast<vec3<u32>>(a);
  var hi: vec3<f32> = bitcast<vec3<f32>>((min((bits + 2048u), (bits | vec3<u32>(2139092992u))) & vec3<u32>(4294963200u)));
  var lo: vec3<f32> = (a - hi);
  return df_dvec3(hi, lo);
}

fn df_mul12_error_df_dvec3_df_dvec3_vec3(sa: df_dvec3, sb: df_dvec3, p: vec3<f32>) -> vec3<f32> {
  var hh: vec3<f32> = (sa.hi * sb.hi);
  var hl: vec3<f32> = (sa.hi * sb.lo);
  var lh: vec3<f32> = (sa.lo * sb.hi);
  var ll: vec3<f32> = (sa.lo * sb.lo);
  var t1: vec3<f32> = (hh - p);
  var t2: vec3<f32> = (t1 + hl);
  var t3: vec3<f32> = (t2 + lh);
  var e: vec3<f32> = (t3 + ll);
  return e;
}

fn df_two_prod_vec3_vec3(a: vec3<f32>, b: vec3<f32>) -> df_dvec3 {
  var p: vec3<f32> = ((a * b) - df_uniforms.df_guard);
  var sa: df_dvec3 = df_split_vec3(a);
  var sb: df_dvec3 = df_split_vec3(b);
  var e: vec3<f32> = df_mul12_error_df_dvec3_df_dvec3_vec3(sa, sb, p);
  return df_dvec3(p, e);
}

fn df_mul_df_dvec3_df_dvec3(a: df_dvec3, b: df_dvec3) -> df_dvec3 {
  var c: df_dvec3 = df_two_prod_vec3_vec3(a.hi, b.hi);
  var tl: vec3<f32> = (a.hi * b.lo);
  var th: vec3<f32> = (a.lo * b.hi);
  var cl2: vec3<f32> = (th + tl);
  var cl3: vec3<f32> = (c.lo + cl2);
  var z: df_dvec3 = df_fast_two_sum_vec3_vec3(c.hi, cl3);
  var r_1: df_dvec3 = df_finish_df_dvec3_vec3(z, c.hi);
  return r_1;
}

fn df_dot(a: df_dvec3, b: df_dvec3) -> df_double {
  var m: df_dvec3 = df_mul_df_dvec3_df_dvec3(a, b);
  var x: df_double = df_double(m.hi[0i], m.lo[0i]);
  var y: df_double = df_double(m.hi[1i], m.lo[1i]);
  var z: df_double = df_double(m.hi[2i], m.lo[2i]);
  var xy: df_double = df_add_df_double_df_double(x, y);
  var r_1: df_double = df_add_df_double_df_double(xy, z);
  return r_1;
}

fn df_sqrt(a: df_double) -> df_double {
  var sh: f32 = (sqrt(a.hi) - df_uniforms.df_guard);
  var sq: df_double = df_two_prod_float_float(sh, sh);
  var r0: f32 = (a.hi - sq.hi);
  var rho1: f32 = (r0 - sq.lo);
  var rho2: f32 = (a.lo + rho1);
  var sh2: f32 = (sh * 2.0f);
  var sl: f32 = (rho2 / sh2);
  var z: df_double = df_fast_two_sum_float_float(sh, sl);
  var r_1: df_double = df_finish_df_double_float(z, sh);
  return r_1;
}

fn df_length(a: df_dvec3) -> df_double {
  var k: vec2<f32> = df_norm_scale(a.hi);
  var b: df_dvec3 = df_scale_pow2_df_dvec3_float(a, k[0i]);
  var d: df_double = df_dot(b, b);
  var n: df_double = df_sqrt(d);
  var z: df_double = df_scale_pow2_df_double_float(n, k[1i]);
  var r_1: df_double = df_finish_df_double_float(z, z.hi);
  return r_1;
}

fn df_neg_df_double(a: df_double) -> df_double {
  var h: f32 = -(a.hi);
  var l: f32 = -(a.lo);
  return df_double(h, l);
}

fn df_sub_df_double_df_double(a: df_double, b: df_double) -> df_double {
  var nb: df_double = df_neg_df_double(b);
  var z: df_double = df_add_df_double_df_double(a, nb);
  return z;
}

fn df_from_int(i: i32) -> df_double {
  var q: i32 = (i / 65536i);
  var r_1: i32 = (i - (q * 65536i));
  var qf: f32 = ((f32(q) * 65536.0f) - df_uniforms.df_guard);
  var rf: f32 = (f32(r_1) - df_uniforms.df_guard);
  var z: df_double = df_two_sum_float_float(qf, rf);
  return z;
}

fn df_add_f(a: df_double, b: f32) -> df_double {
  var s: df_double = df_two_sum_float_float(a.hi, b);
  var v: f32 = (a.lo + s.lo);
  var z: df_double = df_fast_two_sum_float_float(s.hi, v);
  var r_1: df_double = df_finish_df_double_float(z, s.hi);
  return r_1;
}

fn df_main() {
  var i: u32 = df_GlobalInvocationID[0i];
  var b: Body = df_block_Bodies.bodies[(i % 4u)];
  var m: df_double = df_add_f(df_add_df_double_df_double(df_block_Bodies.masses[i].v, df_mul_df_double_df_double(b.mass, df_block_Scene.scale[(i % 3u)].v)), (b.radius[1i].v * df_block_Scene.weights[0i].v));
  df_block_Results.r[i].v = df_add_df_double_df_double(df_sub_df_double_df_double(df_add_df_double_df_double(m, df_mul_df_double_df_double(df_length(df_sub_df_dvec3_df_dvec3(b.position, df_block_Scene.sun.position)), df_block_Scene.sun.mass)), df_block_Scene.origin), df_from_int(i32(arrayLength(&df_block_Bodies.masses))));
}

var<private> df_GlobalInvocationID: vec3<u32>;

@compute @workgroup_size(16, 1, 1)
fn main(@builtin(global_invocation_id) df_in_global_invocation_id: vec3<u32>) {
  df_GlobalInvocationID = df_in_global_invocation_id;
  df_main();
}
