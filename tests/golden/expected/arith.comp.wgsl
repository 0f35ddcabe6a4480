struct df_double {
  hi: f32,
  lo: f32,
}

struct Inputs {
  xy: array<vec4<f32>>,
}

@group(0) @binding(0) var<storage, read> df_block_Inputs: Inputs;
struct Outputs {
  r: array<vec2<f32>>,
}

@group(0) @binding(1) var<storage, read_write> df_block_Outputs: Outputs;
struct df_uniforms_t {
  per_op: u32,  // offset 0
  count: u32,  // offset 4
  df_guard: f32,  // offset 8
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
  var r_1: df_double = df_finish(z, s.hi);
  return r_1;
}

fn df_neg(a: df_double) -> df_double {
  var h: f32 = -(a.hi);
  var l: f32 = -(a.lo);
  return df_double(h, l);
}

fn df_sub(a: df_double, b: df_double) -> df_double {
  var nb: df_double = df_neg(b);
  var z: df_double = df_add(a, nb);
  return z;
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

fn df_mul(a: df_double, b: df_double) -> df_double {
  var c: df_double = df_two_prod(a.hi, b.hi);
  var tl: f32 = (a.hi * b.lo);
  var th: f32 = (a.lo * b.hi);
  var cl2: f32 = (th + tl);
  var cl3: f32 = (c.lo + cl2);
  var z: df_double = df_fast_two_sum(c.hi, cl3);
  var r_1: df_double = df_finish(z, c.hi);
  return r_1;
}

fn df_mul_f(a: df_double, b: f32) -> df_double {
  var c: df_double = df_two_prod(a.hi, b);
  var cl2: f32 = (a.lo * b);
  var t: df_double = df_fast_two_sum(c.hi, cl2);
  var tl2: f32 = (t.lo + c.lo);
  var z: df_double = df_fast_two_sum(t.hi, tl2);
  var r_1: df_double = df_finish(z, c.hi);
  return r_1;
}

fn df_div(a: df_double, b: df_double) -> df_double {
  var th: f32 = ((a.hi / b.hi) - df_uniforms.df_guard);
  var r_1: df_double = df_mul_f(b, th);
  var pih: f32 = (a.hi - r_1.hi);
  var dl: f32 = (a.lo - r_1.lo);
  var d: f32 = (pih + dl);
  var tl: f32 = (d / b.hi);
  var z: df_double = df_fast_two_sum(th, tl);
  var q: df_double = df_finish(z, th);
  return q;
}

fn df_sqrt(a: df_double) -> df_double {
  var sh: f32 = (sqrt(a.hi) - df_uniforms.df_guard);
  var sq: df_double = df_two_prod(sh, sh);
  var r0: f32 = (a.hi - sq.hi);
  var rho1: f32 = (r0 - sq.lo);
  var rho2: f32 = (a.lo + rho1);
  var sh2: f32 = (sh * 2.0f);
  var sl: f32 = (rho2 / sh2);
  var z: df_double = df_fast_two_sum(sh, sl);
  var r_1: df_double = df_finish(z, sh);
  return r_1;
}

fn df_to_float(a: df_double) -> f32 {
  var f: f32 = ((a.hi + a.lo) - df_uniforms.df_guard);
  var r_1: df_double = df_finish(df_double(f, 0.0f), a.hi);
  return r_1.hi;
}

fn df_add_f(a: df_double, b: f32) -> df_double {
  var s: df_double = df_two_sum(a.hi, b);
  var v: f32 = (a.lo + s.lo);
  var z: df_double = df_fast_two_sum(s.hi, v);
  var r_1: df_double = df_finish(z, s.hi);
  return r_1;
}

fn df_main() {
  var z: df_double;
  var i: u32 = df_GlobalInvocationID[0i];
  if ((i >= df_uniforms.count)) {
    return;
  }
  var op: i32 = i32((i / df_uniforms.per_op));
  var x: df_double = df_two_sum(df_block_Inputs.xy[i][0i], df_block_Inputs.xy[i][1i]);
  var y: df_double = df_two_sum(df_block_Inputs.xy[i][2i], df_block_Inputs.xy[i][3i]);
  switch (op) {
    case 0i: {
      {
        {
          z = df_add(x, y);
          break;
        }
      }
    }
    case 1i: {
      {
        {
          z = df_sub(x, y);
          break;
        }
      }
    }
    case 2i: {
      {
        {
          z = df_mul(x, y);
          break;
        }
      }
    }
    case 3i: {
      {
        {
          z = df_div(x, y);
          break;
        }
      }
    }
    case 4i: {
      {
        {
          z = df_sqrt(x);
          break;
        }
      }
    }
    case 5i: {
      {
        {
          z = df_sub(df_add(x, y), x);
          break;
        }
      }
    }
    default: {
      {
        {
          z = df_div(df_add(df_mul(x, y), x), y);
          break;
        }
      }
    }
  }
  var hi: f32 = df_to_float(z);
  df_block_Outputs.r[i] = vec2<f32>(hi, df_to_float(df_add_f(z, -(hi))));
}

var<private> df_GlobalInvocationID: vec3<u32>;

@compute @workgroup_size(64, 1, 1)
fn main(@builtin(global_invocation_id) df_in_global_invocation_id: vec3<u32>) {
  df_GlobalInvocationID = df_in_global_invocation_id;
  df_main();
}
