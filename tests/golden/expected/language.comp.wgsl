fn df_runtime_u32(x: u32) -> u32 {
  return x;
}

struct df_double {
  hi: f32,
  lo: f32,
}

struct S {
  a: df_double,
  b: i32,
}

struct B {
  v: array<f32>,
}

@group(0) @binding(0) var<storage, read_write> df_block_B: B;
const big: array<f32, 2> = array<f32, 2>(0x1.2ced32p+126f, (-2.5f));
var<private> g: f32 = 2.0f;
struct df_uniforms_t {
  @align(16) arr: array<vec4<f32>, 3>,  // offset 0
  df_guard: f32,  // offset 48
}
@group(0) @binding(1) var<uniform> df_uniforms: df_uniforms_t;

fn df_finish(z: df_double, f: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
}

fn df_to_float(a: df_double) -> f32 {
  var f: f32 = ((a.hi + a.lo) - df_uniforms.df_guard);
  var r: df_double = df_finish(df_double(f, 0.0f), a.hi);
  return r.hi;
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

fn df_fast_two_sum(a: f32, b: f32) -> df_double {
  var s: f32 = ((a + b) - df_uniforms.df_guard);
  var z: f32 = ((s - a) - df_uniforms.df_guard);
  var e: f32 = (b - z);
  return df_double(s, e);
}

fn df_mul_f2(a: df_double, b: f32) -> df_double {
  var c: df_double = df_two_prod(a.hi, b);
  var cl2: f32 = (a.lo * b);
  var cl3: f32 = (c.lo + cl2);
  var z: df_double = df_fast_two_sum(c.hi, cl3);
  var r: df_double = df_finish(z, c.hi);
  return r;
}

fn df_main() {
  var i: i32 = 0i;
  var m: i32 = i32(-2147483647i - 1i);
  var inf: f32 = bitcast<f32>(df_runtime_u32(2139095040u));
  var s: S = S(df_double((1.0f - df_uniforms.df_guard), (0.0f + df_uniforms.df_guard)), 2i);
  var t: S = s;
  df_block_B.v[i] = 1.0f;
  i++;
  df_block_B.v[1i] = select(((-2.5f) + df_uniforms.arr[2i][1i]), inf, (s.b == t.b));
  {
    loop {
      if !(((i < 10i) && (df_block_B.v[0i] > 0.0f))) { break; }
      i += 2i;
      if ((i == 5i)) {
        break;
      }
    }
  }
  switch (i) {
    case 1i, 2i: {
      {
        {
          df_block_B.v[2i] = 3.0f;
          break;
        }
      }
    }
    default: {
      {
        {
          df_block_B.v[2i] = f32(m);
        }
      }
    }
  }
  df_block_B.v[3i] = ((df_to_float(df_mul_f2(s.a, g)) + 0x1.dac67p-2f) + 0.5f);
  df_block_B.v[4i] = (f32((i >> u32(1i))) + f32((u32(i) << 2u)));
  var bits: vec2<u32> = bitcast<vec2<u32>>(vec2<f32>(df_block_B.v[6i], df_block_B.v[7i]));
  bits = (((bits >> vec2<u32>(23u)) & vec2<u32>(255u)) | ((bits << vec2<u32>(1u, 2u)) ^ vec2<u32>(1u)));
  df_block_B.v[6i] = (bitcast<f32>(bits[0i]) + bitcast<f32>(bits[1i]));
  var bb: vec2<bool> = vec2<bool>(true, true);
  df_block_B.v[5i] = (select(1.0f, 2.0f, bb[0i]) + select(0.0f, 1.0f, all(bb)));
}


@compute @workgroup_size(4, 1, 1)
fn main() {
  df_main();
}
