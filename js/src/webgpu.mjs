// WebGPU host helpers for shaders lowered with `doublet lower --target wgsl` (docs/web.md, "WebGPU
// binder"), driven by the manifest alone: the loose uniforms' buffer (the manifest's `wgsl-uniform`
// entry, df_uniforms, with the guard left at 0), and vertex buffers whose attributes carry the
// doubles as hi/lo float pairs (df64 modes) or binary64 words (mode exact) at the locations the
// manifest records.
import { setUniformsFromManifest, webgl2Attributes } from './index.mjs';

const isExact = (v) => v.encoding === 'binary64-words';

// WGSL member types: f32, vec3<f32>, vec4<u32>, mat4x4<f32>, ...
function wgslType(type) {
  const m = /^(?:(f32|i32|u32)|vec([234])<(f32|i32|u32)>|mat([234])x([234])<f32>)$/.exec(type);
  if (!m) return null;
  if (m[1]) return { scalar: m[1], columns: 1, rows: 1 };
  if (m[2]) return { scalar: m[3], columns: 1, rows: Number(m[2]) };
  return { scalar: 'f32', columns: Number(m[4]), rows: Number(m[5]) };
}

function writeScalar(view, offset, scalar, value) {
  if (scalar === 'f32') view.setFloat32(offset, value, true);
  else if (scalar === 'i32') view.setInt32(offset, value, true);
  else view.setUint32(offset, value >>> 0, true);
}

// One member of the uniform buffer: components in order, matrices column by column (a column of
// 2 floats is 8 bytes apart from the next, of 3 or 4 floats 16: WGSL's uniform layout). An array's
// elements are array_stride apart; an array of scalars or 2-vectors is padded to vec4 elements
// (its values fill each element's first components).
function writeMember(view, member, data) {
  const array = /^array<(.+), (\d+)>$/.exec(member.lowered_type);
  if (array) {
    const n = Number(array[2]);
    const list = Array.from(data);
    if (list.length % n !== 0) throw new Error(`'${member.name}' (${member.type}): ${list.length} values for ${n} elements`);
    const per = list.length / n;
    const element = wgslType(array[1]);
    if (!element || element.columns !== 1 || per > element.rows)
      throw new Error(`'${member.name}': arrays of ${array[1]} are not supported yet`);
    for (let k = 0; k < n; ++k)
      for (let c = 0; c < per; ++c) writeScalar(view, member.offset + k * member.array_stride + 4 * c, element.scalar, list[k * per + c]);
    return;
  }
  const t = wgslType(member.lowered_type);
  if (!t) throw new Error(`'${member.name}': members of type ${member.lowered_type} are not supported yet`);
  const list = typeof data === 'number' ? [data] : Array.from(data);
  if (list.length !== t.columns * t.rows)
    throw new Error(`'${member.name}' (${member.lowered_type}): expected ${t.columns * t.rows} value(s), got ${list.length}`);
  const columnStride = t.columns === 1 ? 0 : (t.rows === 2 ? 8 : 16);
  for (let c = 0; c < t.columns; ++c)
    for (let r = 0; r < t.rows; ++r)
      writeScalar(view, member.offset + c * columnStride + 4 * r, t.scalar, list[c * t.rows + r]);
}

/**
 * The bytes of the loose-uniform buffer of a WGSL shader: { group, binding, size, data } for
 * device.queue.writeBuffer and the bind group. `values` names the original uniforms: doubles as
 * numbers (components × elements), plain ones (float, vecN, int, matCxR column-major) likewise.
 * Uniforms with a default in the manifest are written at it unless named; the guard stays 0.
 */
export function wgslUniformBuffer(manifest, values = {}) {
  const block = manifest.variables.find((v) => v.layout === 'wgsl-uniform');
  if (!block) throw new Error('the manifest has no wgsl-uniform buffer (target wgsl with loose uniforms)');
  const size = Math.max(16, Math.ceil(Math.max(...block.members.map((m) => m.offset + m.size)) / 16) * 16);
  const data = new ArrayBuffer(size);
  const view = new DataView(data);
  const doubles = {}, plain = new Map();
  for (const [name, value] of Object.entries(values)) {
    const v = manifest.variables.find((e) => e.name === name && e.storage === 'uniform' && e !== block);
    if (!v) throw new Error(`'${name}' is not a uniform in the manifest`);
    if (v.split) doubles[name] = value;
    else plain.set(v.lowered_names[0], value);
  }
  // Doubles (and every default) as the WebGL2 binder lowers them, by lowered name.
  const writes = setUniformsFromManifest(manifest, doubles).filter((u) => !plain.has(u.name));
  for (const [name, value] of plain) writes.push({ name, data: value });
  for (const w of writes) {
    const member = block.members.find((m) => m.name === w.name);
    if (!member) throw new Error(`'${w.name}' is not a member of the uniform buffer`);
    writeMember(view, member, w.data);
  }
  return { group: block.group, binding: block.binding, size, data };
}

// GPUVertexFormat of a lowered input type; bytes and component kind.
function vertexFormat(type) {
  const m = /^(?:(float|int|uint)|(vec|ivec|uvec)([234]))$/.exec(type);
  if (!m) throw new Error(`no vertex format for an input of type ${type}`);
  const kind = m[1] || { vec: 'float', ivec: 'int', uvec: 'uint' }[m[2]];
  const n = m[3] ? Number(m[3]) : 1;
  const name = { float: 'float32', int: 'sint32', uint: 'uint32' }[kind];
  return { format: n === 1 ? name : `${name}x${n}`, kind, components: n, bytes: 4 * n };
}

/**
 * One interleaved vertex buffer for the inputs `names` (original names, in this order):
 * { arrayStride, attributes: [{ shaderLocation, offset, format }], parts, manifest } — a
 * GPUVertexBufferLayout (parts and manifest: what packVertices needs). A dvec3 input in df64 is two float32x3 attributes (hi, lo) at
 * the manifest's two locations; in mode exact its words (uint32x4 + uint32x2).
 */
export function wgslVertexLayout(manifest, names) {
  const attributes = [], parts = [];
  let offset = 0;
  for (const name of names) {
    const v = manifest.variables.find((e) => e.name === name && e.storage === 'in');
    if (!v) throw new Error(`'${name}' is not an input in the manifest`);
    if (!v.locations || v.locations.length !== v.lowered_names.length)
      throw new Error(`'${name}': the manifest has no locations for it (lower with --target wgsl)`);
    v.lowered_names.forEach((lowered, k) => {
      const f = vertexFormat(isExact(v) ? v.lowered_types[k] : v.lowered_type);
      attributes.push({ shaderLocation: v.locations[k], offset, format: f.format });
      parts.push({ name, variable: v, part: k, offset, ...f });
      offset += f.bytes;
    });
  }
  return { arrayStride: offset, attributes, parts, manifest };
}

/**
 * The bytes of `count` vertices for a layout from wgslVertexLayout: values[name] holds the input's
 * components vertex after vertex (doubles as numbers; split or packed into words as for WebGL2's
 * attributes, webgl2Attributes, then interleaved).
 */
export function packVertices(layout, values, count) {
  const data = new ArrayBuffer(layout.arrayStride * count);
  const view = new DataView(data);
  const lowered = new Map();  // lowered name -> { size, data } of each attribute
  for (const name of new Set(layout.parts.map((p) => p.name)))
    for (const a of webgl2Attributes(layout.manifest, name, values[name] ?? [])) lowered.set(a.name, a);
  for (const p of layout.parts) {
    const a = lowered.get(p.variable.lowered_names[p.part]);
    if (a.data.length !== a.size * count)
      throw new Error(`'${p.name}': expected ${count} vertices, got ${a.data.length / a.size}`);
    const scalar = a.data instanceof Float32Array ? 'f32' : (a.data instanceof Int32Array ? 'i32' : 'u32');
    for (let i = 0; i < count; ++i)
      for (let c = 0; c < a.size; ++c) writeScalar(view, i * layout.arrayStride + p.offset + 4 * c, scalar, a.data[i * a.size + c]);
  }
  return data;
}
