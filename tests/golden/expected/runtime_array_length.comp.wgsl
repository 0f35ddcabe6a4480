struct df_double {
  hi: f32,
  lo: f32,
}

struct Samples {
  count: i32,
  weights: array<f32>,
}

@group(0) @binding(0) var<storage, read_write> df_block_Samples: Samples;
struct Values {
  total: df_double,
  values: array<df_double>,
}

@group(0) @binding(1) var<storage, read_write> df_block_Values: Values;
struct df_uniforms_t {
  df_guard: f32,  // offset 0
}
@group(0) @binding(2) var<uniform> df_uniforms: df_uniforms_t;

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

fn df_finish(z: df_double, f: f32) -> df_double {
  var az: f32 = abs(z.hi);
  var regular: bool = all(vec2<bool>((az > 0.0f), (az <= 0x1.fffffep+127f)));
  var h: f32 = select(f, z.hi, regular);
  var l: f32 = select(0.0f, z.lo, regular);
  return df_double(h, l);
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

fn df_main() {
  df_block_Samples.count = i32(arrayLength(&df_block_Samples.weights));
  var s: df_double = df_double((0.0f + df_uniforms.df_guard), (0.0f + df_uniforms.df_guard));
  {
    var i: i32 = 0i;
    loop {
      if !((i < i32(arrayLength(&df_block_Values.values)))) { break; }
      s = df_add(s, df_mul_f2(df_block_Values.values[i], df_block_Samples.weights[(i % i32(arrayLength(&df_block_Samples.weights)))]));
      continuing {
        i++;
      }
    }
  }
  df_block_Values.total = s;
}


@compute @workgroup_size(64, 1, 1)
fn main() {
  df_main();
}
