// @doublet/host: the JavaScript twin of include/doublet/split.hpp and the uniform/block parts of
// include/doublet/pack.hpp. A shader lowered by `doublet lower` takes each double as a float pair
// (hi = float(x), lo = float(x - hi); docs/verify.md) or, in mode exact, as the two uint32 words of
// its binary64 pattern, low word first (docs/modes.md). This module computes both, bit for bit as
// the C++ helpers do (tests/js checks it against them), and fills uniforms and block members from
// the manifest that `doublet lower --manifest` writes. No dependencies.

const LITTLE_ENDIAN = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;
const scratch = new DataView(new ArrayBuffer(8));

/** hi = float(x), lo = float(x - hi); lo = 0 where hi is ±Inf or NaN (x - Inf would be NaN). */
export function split(x) {
  const hi = Math.fround(x);
  // Math.fround rounds to nearest-even like C++'s static_cast<float>; x - hi is the same double
  // subtraction, so the pair matches doublet::split bit for bit (-0 gives hi = -0, lo = +0).
  const lo = Number.isFinite(hi) ? Math.fround(x - hi) : 0;
  return { hi, lo };
}

/** split() of every element: two Float32Arrays of values.length. */
export function splitArray(values) {
  const n = values.length;
  const hi = new Float32Array(n);
  const lo = new Float32Array(n);
  for (let i = 0; i < n; ++i) {
    const p = split(values[i]);
    hi[i] = p.hi;
    lo[i] = p.lo;
  }
  return { hi, lo };
}

/** hi + lo in double, except that a zero keeps hi's sign ((-0, +0) is -0), as doublet::join. */
export function join(hi, lo) {
  if (hi === 0 && lo === 0) return hi;
  return hi + lo;
}

/** Mode exact: the binary64 words of x, low word first (a shader's uvec2.x, .y). */
export function exactWords(x) {
  scratch.setFloat64(0, x, true);
  return new Uint32Array([scratch.getUint32(0, true), scratch.getUint32(4, true)]);
}

/** exactWords() of every element: 2 × values.length words, element after element. */
export function exactWordsArray(values) {
  const n = values.length;
  // On a little-endian host the bytes of a Float64Array already are the words, low first.
  if (LITTLE_ENDIAN) return new Uint32Array(Float64Array.from(values).buffer);
  const words = new Uint32Array(2 * n);
  for (let i = 0; i < n; ++i) {
    scratch.setFloat64(0, values[i], true);
    words[2 * i] = scratch.getUint32(0, true);
    words[2 * i + 1] = scratch.getUint32(4, true);
  }
  return words;
}

/** The double whose words (low first) are words[offset], words[offset + 1]. */
export function fromExactWords(words, offset = 0) {
  scratch.setUint32(0, words[offset] >>> 0, true);
  scratch.setUint32(4, words[offset + 1] >>> 0, true);
  return scratch.getFloat64(0, true);
}

/**
 * Writes one double into block memory (std140/std430, little-endian as WebGL/WebGPU buffers are).
 * 'df64': a lowered `df_double { float hi; float lo; }`, hi at byteOffset and lo at byteOffset + 4
 * (the manifest's hi_offset 0 / lo_offset 4 for a double member). 'exact': the two words.
 */
export function writeDouble(view, byteOffset, x, mode) {
  if (mode === 'df64') {
    const p = split(x);
    view.setFloat32(byteOffset, p.hi, true);
    view.setFloat32(byteOffset + 4, p.lo, true);
  } else if (mode === 'exact') {
    const w = exactWords(x);
    view.setUint32(byteOffset, w[0], true);
    view.setUint32(byteOffset + 4, w[1], true);
  } else {
    throw new Error(`writeDouble: mode must be 'df64' or 'exact', not '${mode}'`);
  }
}

// The shape of a double type: "double" {rows 1, columns 1, elements 1}, "dvec3[2]" {3, 1, 2},
// "dmat2x3" {3, 2, 1}, "double[]" elements 0 (runtime-sized); null for a type without doubles.
function doubleShape(type) {
  const m = /^(?:double|dvec([234])|dmat([234])(?:x([234]))?)(?:\[(\d*)\])?$/.exec(type);
  if (!m) return null;
  const columns = m[2] ? Number(m[2]) : 1;
  const rows = m[2] ? Number(m[3] ?? m[2]) : (m[1] ? Number(m[1]) : 1);
  const elements = m[4] === undefined ? 1 : (m[4] === '' ? 0 : Number(m[4]));
  return { rows, columns, elements };
}
function asList(name, value, count) {
  const list = typeof value === 'number' ? [value] : Array.from(value);
  if (list.length !== count) throw new Error(`'${name}': expected ${count} value(s), got ${list.length}`);
  return list;
}
const isExact = (v) => v.encoding === 'binary64-words';

// Mode exact splits a dvec3/dvec4 over two lowered variables (NAME_xy + NAME_z/NAME_zw): the words
// of doubles [first, first + doubles) of each group of `per` doubles in `list` (an array element, a
// vertex), group after group.
function exactPartWords(list, per, first, doubles) {
  const picked = [];
  for (let g = 0; g * per < list.length; ++g)
    for (let c = first; c < first + doubles; ++c) picked.push(list[g * per + c]);
  return exactWordsArray(picked);
}

// Byte offsets of double k (element-major, then column, then row) of a block member: [hi, lo] in
// df64, [words] in mode exact.
function doubleOffsets(member, shape, blockOffset, k) {
  const perElement = shape.rows * shape.columns;
  const e = Math.floor(k / perElement), column = Math.floor((k % perElement) / shape.rows), row = k % shape.rows;
  const base = blockOffset + member.offset + e * (member.array_stride ?? 0) + column * (member.matrix_stride ?? 0);
  return isExact(member) ? [base + 8 * row] : [base + member.hi_offset + 4 * row, base + member.lo_offset + 4 * row];
}

function checkedShape(member, fn) {
  const shape = doubleShape(member.type);
  if (!shape) throw new Error(`${fn}: '${member.name}' has type ${member.type}; only double, dvecN and dmatCxR members (and arrays of them) hold doubles`);
  return shape;
}

/**
 * Writes a double member of a block the manifest lists (`members` of a uniform or buffer block) into
 * `view`, the block's memory starting at `blockOffset`: double, dvecN, dmatCxR (column-major values)
 * and arrays of them (elements one after another; a runtime-sized array takes as many elements as
 * `value` holds). df64: component c's hi at offset + hi_offset + 4c, lo at offset + lo_offset + 4c,
 * matrix columns matrix_stride apart (hi and lo matrices each), elements array_stride apart; exact:
 * the doubles' words at the member's original std140/std430 offsets, 8 bytes apart.
 */
export function writeBlockMember(view, member, value, blockOffset = 0) {
  const shape = checkedShape(member, 'writeBlockMember');
  const per = shape.rows * shape.columns;
  const list = typeof value === 'number' ? [value] : Array.from(value);
  const count = shape.elements === 0 ? list.length : per * shape.elements;
  if (list.length !== count || count % per !== 0)
    throw new Error(`'${member.name}': expected ${shape.elements === 0 ? `a multiple of ${per}` : count} value(s), got ${list.length}`);
  list.forEach((x, k) => {
    const at = doubleOffsets(member, shape, blockOffset, k);
    if (isExact(member)) {
      writeDouble(view, at[0], x, 'exact');
    } else {
      const p = split(x);
      view.setFloat32(at[0], p.hi, true);
      view.setFloat32(at[1], p.lo, true);
    }
  });
}

/**
 * Reads a double member back as doubles (hi + lo with join, or the words): `elements` elements of a
 * runtime-sized array, else the member's own size. The inverse of writeBlockMember, for results a
 * shader wrote to a storage buffer.
 */
export function readBlockMember(view, member, blockOffset = 0, elements = undefined) {
  const shape = checkedShape(member, 'readBlockMember');
  const count = shape.rows * shape.columns * (elements ?? (shape.elements || 1));
  const out = new Float64Array(count);
  for (let k = 0; k < count; ++k) {
    const at = doubleOffsets(member, shape, blockOffset, k);
    out[k] = isExact(member)
      ? fromExactWords([view.getUint32(at[0], true), view.getUint32(at[0] + 4, true)])
      : join(view.getFloat32(at[0], true), view.getFloat32(at[1], true));
  }
  return out;
}

// gl.uniform{N}fv / gl.uniform{N}uiv for a lowered type ("vec3", "float[2]", "uvec4", "uvec2[2]").
// A uniform that holds no double, at its manifest default: {name, type, setter, data}.
function plainUniform(v) {
  const base = v.lowered_type.replace(/\[\d+\]$/, '');
  const m = /^(?:(float|int|uint|bool)|(vec|ivec|uvec|bvec)([234]))$/.exec(base);
  if (!m) throw new Error(`'${v.name}': no uniform setter for its default (type ${v.lowered_type})`);
  const kind = m[1] || { vec: 'float', ivec: 'int', uvec: 'uint', bvec: 'bool' }[m[2]];
  const components = m[3] ? Number(m[3]) : 1;
  const [suffix, Array_] = { float: ['fv', Float32Array], int: ['iv', Int32Array], bool: ['iv', Int32Array],
                             uint: ['uiv', Uint32Array] }[kind];
  return { name: v.lowered_names[0], type: v.lowered_type, setter: `uniform${components}${suffix}`,
           data: Array_.from(v.default) };
}

function setterFor(loweredType) {
  const base = loweredType.replace(/\[\d+\]$/, '');
  const matrix = /^mat([234])(?:x([234]))?$/.exec(base);
  if (matrix) {  // df64 matrices: NAME_hi/NAME_lo as matCxR, column-major, transpose false
    const columns = Number(matrix[1]), rows = Number(matrix[2] ?? matrix[1]);
    return { setter: `uniformMatrix${columns === rows ? columns : `${columns}x${rows}`}fv`, components: columns * rows, matrix: true };
  }
  const m = /^(float|vec([234])|uvec([24]))$/.exec(base);
  if (!m) throw new Error(`no uniform setter for lowered type ${loweredType}`);
  if (m[3]) return { setter: `uniform${m[3]}uiv`, components: Number(m[3]) };
  const components = m[2] ? Number(m[2]) : 1;
  return { setter: `uniform${components}fv`, components };
}

/**
 * For each double uniform named in `values` (a number, or components × elements numbers), the
 * lowered uniforms a WebGL2 host sets: [{name, type, setter, data}], e.g.
 *   {name: 'eye_hi', type: 'vec3', setter: 'uniform3fv', data: Float32Array[3]}
 *   gl[u.setter](gl.getUniformLocation(program, u.name), u.data)
 * df64: NAME_hi / NAME_lo (the manifest's lowered_names). Mode exact: the words, dvec3/dvec4 as
 * NAME_xy + NAME_z/NAME_zw. The guard uniform is never listed: GL zero-fills it (docs/web.md).
 * A uniform declared with an initializer has its value in the manifest ("default"; GLSL ES has no
 * uniform initializers, so the host sets it): every such uniform not named in `values` is listed at
 * that value, plain ones (int n = 3) too, with their setter (uniform1iv, ...).
 * Double matrices (column-major values): df64 gives NAME_hi/NAME_lo with `uniformMatrixNfv` (call it
 * with transpose false: applyUniforms does), mode exact the words packed into a uvec4 array.
 * Throws for a name that is not a double uniform of the manifest.
 */
export function setUniformsFromManifest(manifest, values) {
  const out = [];
  const given = { ...values };
  for (const v of manifest.variables) {
    if (v.storage !== 'uniform' || !v.default || v.name in given) continue;
    if (v.split) given[v.name] = v.default;
    else out.push(plainUniform(v));
  }
  for (const [name, value] of Object.entries(given)) {
    const v = manifest.variables.find((e) => e.name === name);
    const shape = v && v.storage === 'uniform' && v.split ? doubleShape(v.type) : null;
    if (!shape) throw new Error(`'${name}' is not a double/dvecN uniform in the manifest`);
    const n = shape.rows * shape.columns;
    const list = asList(name, value, n * shape.elements);
    if (isExact(v) && shape.columns > 1) {
      // A double matrix's words, column-major, low word first, packed into uvec4[N] (the last one
      // padded with zeros).
      const type = v.lowered_types[0];
      const count = Number(/\[(\d+)\]$/.exec(type)[1]);
      const data = new Uint32Array(4 * count);
      data.set(exactWordsArray(list));
      out.push({ name: v.lowered_names[0], type, setter: 'uniform4uiv', data });
    } else if (isExact(v)) {
      // Each lowered variable holds the next components/2 doubles of every element.
      let first = 0;
      v.lowered_names.forEach((lowered, part) => {
        const type = v.lowered_types[part];
        const { setter, components } = setterFor(type);
        out.push({ name: lowered, type, setter, data: exactPartWords(list, n, first, components / 2) });
        first += components / 2;
      });
    } else {
      if (v.lowered_names.length !== 2) throw new Error(`'${name}': expected lowered names hi and lo`);
      const { setter } = setterFor(v.lowered_type);
      const { hi, lo } = splitArray(list);
      out.push({ name: v.lowered_names[0], type: v.lowered_type, setter, data: hi });
      out.push({ name: v.lowered_names[1], type: v.lowered_type, setter, data: lo });
    }
  }
  return out;
}

/**
 * Calls the WebGL2 setters of setUniformsFromManifest's list on `program` (current program:
 * gl.useProgram first). Matrices get transpose = false.
 */
export function applyUniforms(gl, program, uniforms) {
  for (const u of uniforms) {
    const location = gl.getUniformLocation(program, u.name);
    if (location === null) continue;  // optimised out by the driver: nothing to set
    if (u.setter.startsWith('uniformMatrix')) gl[u.setter](location, false, u.data);
    else gl[u.setter](location, u.data);
  }
}

/**
 * A WebGL2 binder for one program lowered by doublet: setDouble / setDoubles / setDMat write the
 * lowered uniforms of a double uniform by its original name; created with the manifest's
 * defaults applied. It checks the guard: the manifest's guard uniform must read 0 in the program
 * (GL zero-fills it; a host that set it would let the driver fold the error terms away).
 */
export function createWebGL2Binder(gl, program, manifest) {
  const guard = manifest.guard ?? {};
  if (guard.uniform) {  // kind 'uniform', or the zero the shader's uniforms are read through
    // "float[2]" (ES 3.00: read at a non-constant index, docs/accuracy.md): every element.
    const elements = Number(/\[(\d+)\]$/.exec(guard.type ?? '')?.[1] ?? 0);
    const names = elements ? Array.from({ length: elements }, (_, i) => `${guard.uniform}[${i}]`) : [guard.uniform];
    for (const name of names) {
      const location = gl.getUniformLocation(program, name);
      if (location !== null && gl.getUniform(program, location) !== (guard.required_value ?? 0))
        throw new Error(`the guard uniform '${name}' must stay ${guard.required_value ?? 0} (docs/web.md)`);
    }
  }
  const set = (values) => {
    gl.useProgram(program);
    applyUniforms(gl, program, setUniformsFromManifest({ ...manifest, variables: manifest.variables.filter((v) => !v.default || v.name in values) }, values));
  };
  gl.useProgram(program);
  applyUniforms(gl, program, setUniformsFromManifest(manifest, {}));  // the defaults
  return {
    setDouble: (name, x) => set({ [name]: x }),
    setDoubles: (name, values) => set({ [name]: values }),
    setDMat: (name, columnMajor) => set({ [name]: columnMajor }),
  };
}

/**
 * The WebGL2 attributes of a double input by its original name, for `count` vertices of `values`
 * (components vertex after vertex): [{name, size, integer, data}] — df64: NAME_hi and NAME_lo,
 * Float32Array, `gl.vertexAttribPointer(location, size, gl.FLOAT, ...)`; mode exact: the words
 * (NAME / NAME_xy + NAME_z / NAME_zw), Uint32Array, `gl.vertexAttribIPointer(location, size,
 * gl.UNSIGNED_INT, ...)`. A plain input is returned as is: one entry, Int32Array/Uint32Array for
 * int/uint inputs (integer true), else Float32Array.
 */
export function webgl2Attributes(manifest, name, values) {
  const v = manifest.variables.find((e) => e.name === name && (e.storage === 'in' || e.storage === 'attribute'));
  if (!v) throw new Error(`'${name}' is not an input in the manifest`);
  const list = Array.from(values);
  const shape = doubleShape(v.type);
  const sizeOf = (type) => Number(/([234])$/.exec(type.replace(/\[\d+\]$/, ''))?.[1] ?? 1);
  if (!v.split || !shape) {
    // A plain input: ints and uints as integers (vertexAttribIPointer), anything else as floats.
    const integer = /^(u?int|[iu]vec)/.exec(v.lowered_type)?.[0];
    const Array_ = !integer ? Float32Array : (integer.startsWith('u') ? Uint32Array : Int32Array);
    return [{ name: v.lowered_names[0], size: sizeOf(v.lowered_type), integer: Boolean(integer), data: Array_.from(list) }];
  }
  const n = shape.rows * shape.columns;
  if (list.length % n !== 0) throw new Error(`'${name}': ${list.length} numbers is not a whole number of ${v.type}`);
  if (!isExact(v)) {
    const { hi, lo } = splitArray(list);
    return [{ name: v.lowered_names[0], size: n, integer: false, data: hi },
            { name: v.lowered_names[1], size: n, integer: false, data: lo }];
  }
  // Mode exact: part k holds the next size/2 doubles' words of each vertex.
  let first = 0;
  return v.lowered_names.map((lowered, k) => {
    const size = sizeOf(v.lowered_types[k]);
    const data = exactPartWords(list, n, first, size / 2);
    first += size / 2;
    return { name: lowered, size, integer: true, data };
  });
}
