struct df_double {
  hi: f32,
  lo: f32,
}

struct df_dvec2 {
  hi: vec2<f32>,
  lo: vec2<f32>,
}

struct B {
  s: array<df_double>,
}

@group(0) @binding(0) var<storage, read_write> df_block_B: B;
struct df_uniforms_t {
  df_guard: f32,  // offset 0
}
@group(0) @binding(1) var<uniform> df_uniforms: df_uniforms_t;

fn df_two_sum(a: f32, b: f32) -> df_double {
  var s_1: f32 = ((a + b) - df_uniforms.df_guard);
  var bb: f32 = ((s_1 - a) - df_uniforms.df_guard);
  var ab: f32 = (s_1 - bb);
  var da: f32 = (a - ab);
  var db: f32 = (b - bb);
  var e: f32 = (da + db);
  return df_double(s_1, e);
}

fn df_fast_two_sum(a: f32, b: f32) -> df_double {
  var s_1: f32 = ((a + b) - df_uniforms.df_guard);
  var z: f32 = ((s_1 - a) - df_uniforms.df_guard);
  var e: f32 = (b - z);
  return df_double(s_1, e);
}

fn df_finish(z: df_double, f: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
}

fn df_add(a: df_double, b: df_double) -> df_double {
  var s_1: df_double = df_two_sum(a.hi, b.hi);
  var t: df_double = df_two_sum(a.lo, b.lo);
  var c: f32 = (s_1.lo + t.hi);
  var v: df_double = df_fast_two_sum(s_1.hi, c);
  var w: f32 = (t.lo + v.lo);
  var z: df_double = df_fast_two_sum(v.hi, w);
  var r: df_double = df_finish(z, s_1.hi);
  return r;
}

fn df_mul_pow2(a: df_double, p: f32) -> df_double {
  var h: f32 = (a.hi * p);
  var l: f32 = (a.lo * p);
  var r: df_double = df_finish(df_double(h, l), h);
  return r;
}

fn df_make_dvec2_1_1(a0: df_double, a1: df_double) -> df_dvec2 {
  return df_dvec2(vec2<f32>(a0.hi, a1.hi), vec2<f32>(a0.lo, a1.lo));
}

fn df_assign_component_dvec2(v: ptr<function, df_dvec2>, i: i32, x: df_double) -> df_double {
  (*v).hi[i] = x.hi;
  (*v).lo[i] = x.lo;
  return x;
}

fn scale(x: ptr<function, df_double>) {
  (*x) = df_mul_pow2((*x), 2.0f);
}

fn df_main() {
  var w: df_dvec2 = df_make_dvec2_1_1(df_block_B.s[0i], df_block_B.s[1i]);
  {
    var df_out1: df_double = df_double(w.hi[1i], w.lo[1i]);
    scale(&df_out1);
    _ = df_assign_component_dvec2(&w, 1i, df_out1);
  }
  {
    var df_arg1: df_double = df_block_B.s[2i];
    scale(&df_arg1);
    df_block_B.s[2i] = df_arg1;
  }
  df_block_B.s[3i] = df_add(df_double(w.hi[0i], w.lo[0i]), df_double(w.hi[1i], w.lo[1i]));
}


@compute @workgroup_size(1, 1, 1)
fn main() {
  df_main();
}
