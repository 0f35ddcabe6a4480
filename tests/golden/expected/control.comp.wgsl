fn df_select_df_double(f: df_double, t: df_double, c: bool) -> df_double {
  if c {
    return t;
  }
  return f;
}

fn df_float_isnan(x: f32) -> bool {
  let m = bitcast<u32>(x) & u32(0x7fffffffu);
  return m > u32(0x7f800000u);
}

fn df_mod_float_float(x: f32, y: f32) -> f32 {
  return x - y * floor(x / y);
}

struct df_dvec2 {
  hi: vec2<f32>,
  lo: vec2<f32>,
}

struct df_double {
  hi: f32,
  lo: f32,
}

struct Data {
  acc: array<df_dvec2, 16>,
  f: array<f32>,
}

@group(0) @binding(2) var<storage, read_write> df_block_Data: Data;
var<workgroup> tile: array<f32, 16>;
struct df_uniforms_t {
  df_guard: f32,  // offset 0
}
@group(0) @binding(3) var<uniform> df_uniforms: df_uniforms_t;

fn df_finish(z: df_double, f_1: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f_1, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
}

fn df_to_float(a: df_double) -> f32 {
  var f_1: f32 = ((a.hi + a.lo) - df_uniforms.df_guard);
  var r: df_double = df_finish(df_double(f_1, 0.0f), a.hi);
  return r.hi;
}

fn df_from_float(f_1: f32) -> df_double {
  return df_double(f_1, 0.0f);
}

fn df_two_sum(a: f32, b: f32) -> df_double {
  var s: f32 = ((a + b) - df_uniforms.df_guard);
  var bb: f32 = ((s - a) - df_uniforms.df_guard);
  var ab: f32 = (s - bb);
  var da: f32 = (a - ab);
  var db: f32 = (b - bb);
  var e: f32 = (da + db);
  return df_double(s, e);
}

fn df_fast_two_sum(a: f32, b: f32) -> df_double {
  var s: f32 = ((a + b) - df_uniforms.df_guard);
  var z: f32 = ((s - a) - df_uniforms.df_guard);
  var e: f32 = (b - z);
  return df_double(s, e);
}

fn df_add(a: df_double, b: df_double) -> df_double {
  var s: df_double = df_two_sum(a.hi, b.hi);
  var t: df_double = df_two_sum(a.lo, b.lo);
  var c: f32 = (s.lo + t.hi);
  var v: df_double = df_fast_two_sum(s.hi, c);
  var w: f32 = (t.lo + v.lo);
  var z: df_double = df_fast_two_sum(v.hi, w);
  var r: df_double = df_finish(z, s.hi);
  return r;
}

fn df_split(a: f32) -> df_double {
  var bits: u32 = bitcast<u32>(a);
  var hi: f32 = bitcast<f32>((min((bits + 2048u), (bits | 2139092992u)) & 4294963200u));
  var lo: f32 = (a - hi);
  return df_double(hi, lo);
}

fn df_mul12_error(sa: df_double, sb: df_double, p: f32) -> f32 {
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

fn df_two_prod(a: f32, b: f32) -> df_double {
  var p: f32 = ((a * b) - df_uniforms.df_guard);
  var sa: df_double = df_split(a);
  var sb: df_double = df_split(b);
  var e: f32 = df_mul12_error(sa, sb, p);
  return df_double(p, e);
}

fn df_mul_f2(a: df_double, b: f32) -> df_double {
  var c: df_double = df_two_prod(a.hi, b);
  var cl2: f32 = (a.lo * b);
  var cl3: f32 = (c.lo + cl2);
  var z: df_double = df_fast_two_sum(c.hi, cl3);
  var r: df_double = df_finish(z, c.hi);
  return r;
}

fn df_mul_pow2(a: df_double, p: f32) -> df_double {
  var h: f32 = (a.hi * p);
  var l: f32 = (a.lo * p);
  var r: df_double = df_finish(df_double(h, l), h);
  return r;
}

fn df_assign_component_dvec2(v: ptr<function, df_dvec2>, i: i32, x: df_double) -> df_double {
  (*v).hi[i] = x.hi;
  (*v).lo[i] = x.lo;
  return x;
}

fn split(x: df_double, hi: ptr<function, f32>, count: ptr<function, f32>) {
  (*hi) = df_to_float(x);
  (*count) += 1.0f;
}

fn steps(n: i32) -> i32 {
  var n_v: i32 = n;
  var k: i32 = 0i;
  {
    loop {
      k++;
      n_v = (n_v / 2i);
      continuing {
        break if !((n_v > 1i));
      }
    }
  }
  return k;
}

fn df_main() {
  var hi: f32;
  var i: u32 = df_LocalInvocationIndex;
  tile[i] = f32(i);
  workgroupBarrier();
  var s: df_double = df_double((0.0f + df_uniforms.df_guard), (0.0f + df_uniforms.df_guard));
  {
    var k: i32 = 0i;
    loop {
      if !((k < 4i)) { break; }
      if ((k == 2i)) {
        continue;
      }
      s = df_add(s, df_mul_f2(df_double((0x1.99999ap-4f - df_uniforms.df_guard), ((-0x1.99999ap-30f) - df_uniforms.df_guard)), tile[((i + u32(k)) % 16u)]));
      continuing {
        k++;
      }
    }
  }
  var count: f32 = 0.0f;
  split(s, &hi, &count);
  var v: vec3<f32> = vec3<f32>(1.0f, 1.0f, 1.0f);
  { let df_swz1 = vec2<f32>(hi, count); v.x = df_swz1.x; v.z = df_swz1.y; };
  var m: f32 = df_mod_float_float(v[0i], 3.0f);
  {
    var df_arg1: df_dvec2 = df_block_Data.acc[i];
    _ = df_assign_component_dvec2(&df_arg1, 0i, s);
    df_block_Data.acc[i] = df_arg1;
  }
  {
    var df_arg2: df_dvec2 = df_block_Data.acc[i];
    _ = df_assign_component_dvec2(&df_arg2, 1i, df_select_df_double(df_mul_pow2(s, 2.0f), df_from_float(m), (i > 3u)));
    df_block_Data.acc[i] = df_arg2;
  }
  df_block_Data.f[i] = ((f32(steps((i32(i) + 3i))) + v[2i]) + select(0.0f, 1.0f, df_float_isnan(m)));
}

var<private> df_LocalInvocationIndex: u32;

@compute @workgroup_size(8, 2, 1)
fn main(@builtin(local_invocation_index) df_in_local_invocation_index: u32) {
  df_LocalInvocationIndex = df_in_local_invocation_index;
  df_main();
}
