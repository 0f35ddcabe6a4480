struct df_dvec2 {
  hi: vec2<f32>,
  lo: vec2<f32>,
}

struct df_double {
  hi: f32,
  lo: f32,
}

var<private> center: df_dvec2;
var<private> scale: df_double;
var<private> color: vec4<f32>;
struct df_uniforms_t {
  center_hi: vec2<f32>,  // offset 0
  center_lo: vec2<f32>,  // offset 8
  scale_hi: f32,  // offset 16
  scale_lo: f32,  // offset 20
  max_iterations: i32,  // offset 24
  df_guard: f32,  // offset 28
}
@group(0) @binding(0) var<uniform> df_uniforms: df_uniforms_t;

fn df_two_sum_vec2_vec2(a: vec2<f32>, b: vec2<f32>) -> df_dvec2 {
  var s: vec2<f32> = ((a + b) - df_uniforms.df_guard);
  var bb: vec2<f32> = ((s - a) - df_uniforms.df_guard);
  var ab: vec2<f32> = (s - bb);
  var da: vec2<f32> = (a - ab);
  var db: vec2<f32> = (b - bb);
  var e: vec2<f32> = (da + db);
  return df_dvec2(s, e);
}

fn df_fast_two_sum_vec2_vec2(a: vec2<f32>, b: vec2<f32>) -> df_dvec2 {
  var s: vec2<f32> = ((a + b) - df_uniforms.df_guard);
  var z: vec2<f32> = ((s - a) - df_uniforms.df_guard);
  var e: vec2<f32> = (b - z);
  return df_dvec2(s, e);
}

fn df_finish_df_double_float(z: df_double, f: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
}

fn df_finish_df_dvec2_vec2(z: df_dvec2, f: vec2<f32>) -> df_dvec2 {
  var r0: df_double = df_finish_df_double_float(df_double(z.hi[0i], z.lo[0i]), f[0i]);
  var r1: df_double = df_finish_df_double_float(df_double(z.hi[1i], z.lo[1i]), f[1i]);
  return df_dvec2(vec2<f32>(r0.hi, r1.hi), vec2<f32>(r0.lo, r1.lo));
}

fn df_add_df_dvec2_df_dvec2(a: df_dvec2, b: df_dvec2) -> df_dvec2 {
  var s: df_dvec2 = df_two_sum_vec2_vec2(a.hi, b.hi);
  var t: df_dvec2 = df_two_sum_vec2_vec2(a.lo, b.lo);
  var c: vec2<f32> = (s.lo + t.hi);
  var v: df_dvec2 = df_fast_two_sum_vec2_vec2(s.hi, c);
  var w: vec2<f32> = (t.lo + v.lo);
  var z: df_dvec2 = df_fast_two_sum_vec2_vec2(v.hi, w);
  var r: df_dvec2 = df_finish_df_dvec2_vec2(z, s.hi);
  return r;
}

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

fn df_mul(a: df_double, b: df_double) -> df_double {
  var c: df_double = df_two_prod_float_float(a.hi, b.hi);
  var tl: f32 = (a.hi * b.lo);
  var th: f32 = (a.lo * b.hi);
  var cl2: f32 = (th + tl);
  var cl3: f32 = (c.lo + cl2);
  var z: df_double = df_fast_two_sum_float_float(c.hi, cl3);
  var r: df_double = df_finish_df_double_float(z, c.hi);
  return r;
}

fn df_neg(a: df_double) -> df_double {
  var h: f32 = -(a.hi);
  var l: f32 = -(a.lo);
  return df_double(h, l);
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
  var r: df_double = df_finish_df_double_float(z, s.hi);
  return r;
}

fn df_sub(a: df_double, b: df_double) -> df_double {
  var nb: df_double = df_neg(b);
  var z: df_double = df_add_df_double_df_double(a, nb);
  return z;
}

fn df_to_float(a: df_dvec2) -> vec2<f32> {
  var f: vec2<f32> = ((a.hi + a.lo) - df_uniforms.df_guard);
  var r: df_dvec2 = df_finish_df_dvec2_vec2(df_dvec2(f, vec2<f32>(0.0f, 0.0f)), a.hi);
  return r.hi;
}

fn df_split_vec2(a: vec2<f32>) -> df_dvec2 {
  var bits: vec2<u32> = bitcast<vec2<u32>>(a);
  var hi: vec2<f32> = bitcast<vec2<f32>>((min((bits + 2048u), (bits | vec2<u32>(2139092992u))) & vec2<u32>(4294963200u)));
  var lo: vec2<f32> = (a - hi);
  return df_dvec2(hi, lo);
}

fn df_mul12_error_df_dvec2_df_dvec2_vec2(sa: df_dvec2, sb: df_dvec2, p: vec2<f32>) -> vec2<f32> {
  var hh: vec2<f32> = (sa.hi * sb.hi);
  var hl: vec2<f32> = (sa.hi * sb.lo);
  var lh: vec2<f32> = (sa.lo * sb.hi);
  var ll: vec2<f32> = (sa.lo * sb.lo);
  var t1: vec2<f32> = (hh - p);
  var t2: vec2<f32> = (t1 + hl);
  var t3: vec2<f32> = (t2 + lh);
  var e: vec2<f32> = (t3 + ll);
  return e;
}

fn df_two_prod_vec2_vec2(a: vec2<f32>, b: vec2<f32>) -> df_dvec2 {
  var p: vec2<f32> = ((a * b) - df_uniforms.df_guard);
  var sa: df_dvec2 = df_split_vec2(a);
  var sb: df_dvec2 = df_split_vec2(b);
  var e: vec2<f32> = df_mul12_error_df_dvec2_df_dvec2_vec2(sa, sb, p);
  return df_dvec2(p, e);
}

fn df_mul_f2(a: df_dvec2, b: vec2<f32>) -> df_dvec2 {
  var c: df_dvec2 = df_two_prod_vec2_vec2(a.hi, b);
  var cl2: vec2<f32> = (a.lo * b);
  var cl3: vec2<f32> = (c.lo + cl2);
  var z: df_dvec2 = df_fast_two_sum_vec2_vec2(c.hi, cl3);
  var r: df_dvec2 = df_finish_df_dvec2_vec2(z, c.hi);
  return r;
}

fn df_mul_pow2(a: df_double, p: f32) -> df_double {
  var h: f32 = (a.hi * p);
  var l: f32 = (a.lo * p);
  var r: df_double = df_finish_df_double_float(df_double(h, l), h);
  return r;
}

fn df_sqr(a: df_double) -> df_double {
  var p: f32 = ((a.hi * a.hi) - df_uniforms.df_guard);
  var s: df_double = df_split_float(a.hi);
  var hh: f32 = (s.hi * s.hi);
  var hl: f32 = (s.hi * s.lo);
  var hl2: f32 = (hl + hl);
  var ll: f32 = (s.lo * s.lo);
  var t1: f32 = (hh - p);
  var t2: f32 = (t1 + hl2);
  var e: f32 = (t2 + ll);
  var c: f32 = (a.hi * a.lo);
  var c2: f32 = (c + c);
  var cl3: f32 = (e + c2);
  var z: df_double = df_fast_two_sum_float_float(p, cl3);
  var r: df_double = df_finish_df_double_float(z, p);
  return r;
}

fn df_splat_dvec2(s: df_double) -> df_dvec2 {
  return df_dvec2(vec2<f32>(s.hi), vec2<f32>(s.lo));
}

fn df_make_dvec2_1_1(a0: df_double, a1: df_double) -> df_dvec2 {
  return df_dvec2(vec2<f32>(a0.hi, a1.hi), vec2<f32>(a0.lo, a1.lo));
}

fn df_main() {
  center = df_dvec2(df_uniforms.center_hi, df_uniforms.center_lo);
  scale = df_double(df_uniforms.scale_hi, df_uniforms.scale_lo);
  var c: df_dvec2 = df_add_df_dvec2_df_dvec2(center, df_mul_f2(df_splat_dvec2(scale), df_FragCoord.xy));
  var z: df_dvec2 = df_dvec2(vec2<f32>((0.0f + df_uniforms.df_guard), (0.0f + df_uniforms.df_guard)), vec2<f32>((0.0f + df_uniforms.df_guard), (0.0f + df_uniforms.df_guard)));
  var n: i32 = 0i;
  {
    loop {
      if !((n < df_uniforms.max_iterations)) { break; }
      z = df_add_df_dvec2_df_dvec2(df_make_dvec2_1_1(df_sub(df_sqr(df_double(z.hi[0i], z.lo[0i])), df_sqr(df_double(z.hi[1i], z.lo[1i]))), df_mul(df_mul_pow2(df_double(z.hi[0i], z.lo[0i]), 2.0f), df_double(z.hi[1i], z.lo[1i]))), c);
      if ((dot(df_to_float(z), df_to_float(z)) > 4.0f)) {
        break;
      }
      continuing {
        n++;
      }
    }
  }
  var t: f32 = (f32(n) / f32(df_uniforms.max_iterations));
  color = vec4<f32>(t, (t * t), sqrt(t), 1.0f);
}

var<private> df_FragCoord: vec4<f32>;

struct df_stage_out {
  @location(0) color: vec4<f32>,
}

@fragment
fn main(@builtin(position) df_in_position: vec4<f32>) -> df_stage_out {
  df_FragCoord = df_in_position;
  df_main();
  return df_stage_out(color);
}
