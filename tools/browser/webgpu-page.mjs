// WebGPU page for doublet's WGSL target (src/runner/webgpu.cpp writes job.json next to it).
//   job.kind == 'validate': job.modules = [{name, stage, code}]; each module is compiled
//     (createShaderModule + getCompilationInfo) and put in a pipeline (compute, or render with a
//     minimal partner stage) inside a validation error scope. Reports {adapter, results: [{name, ok, messages}]}.
//   job.kind == 'compute': job.code, job.groups [x,y,z], job.buffers = [{group (0 if absent), binding, kind: 'uniform'|
//     'storage'|'read-only-storage', data (base64)}]; runs one dispatch and reports {adapter, buffers
//     (base64, the storage buffers read back, in job order), messages}.
const fromBase64 = (s) => Uint8Array.from(atob(s), (c) => c.charCodeAt(0));
const toBase64 = (bytes) => {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
};
const messagesOf = async (module) =>
  (await module.getCompilationInfo()).messages.map((m) => `${m.type} ${m.lineNum}:${m.linePos}: ${m.message}`);

async function adapterAndDevice() {
  if (!navigator.gpu) throw new Error('navigator.gpu is missing: no WebGPU in this browser');
  const adapter = await navigator.gpu.requestAdapter();
  if (!adapter) throw new Error('no WebGPU adapter');
  const device = await adapter.requestDevice();
  const info = adapter.info || {};
  return { device, name: [info.vendor, info.architecture, info.device, info.description].filter((x) => x).join(' / ') };
}

async function validate(device, m) {
  device.pushErrorScope('validation');
  const module = device.createShaderModule({ code: m.code });
  const messages = await messagesOf(module);
  if (m.stage === 'comp') {
    device.createComputePipeline({ layout: 'auto', compute: { module, entryPoint: 'main' } });
  } else if (m.stage === 'vert') {
    // One vertex buffer per @location input of the entry point (float inputs only).
    // (mode exact's inputs are u32 words: vec2<u32>, vec4<u32>)
    const buffers = [...m.code.matchAll(/@location\((\d+)\) df_in_\w+: (?:vec(\d)<([fui])32>|([fui])32)/g)].map((x) => {
      const kind = { f: 'float32', u: 'uint32', i: 'sint32' }[x[3] || x[4]];
      return { arrayStride: 16, attributes: [{ shaderLocation: Number(x[1]), offset: 0, format: x[2] ? `${kind}x${x[2]}` : kind }] };
    });
    device.createRenderPipeline({ layout: 'auto', vertex: { module, entryPoint: 'main', buffers }, primitive: { topology: 'point-list' },
                                  depthStencil: { format: 'depth32float', depthWriteEnabled: true, depthCompare: 'always' } });
  } else {
    const vertex = device.createShaderModule({ code: '@vertex fn main() -> @builtin(position) vec4<f32> { return vec4<f32>(0.0); }' });
    const outputs = [...m.code.matchAll(/@location\((\d+)\)[^,]*: vec4<f32>,/g)].map((x) => Number(x[1]));
    const targets = [];
    for (const k of outputs) targets[k] = { format: 'rgba32float' };
    const inputs = /fn main\([^)]*@location/.test(m.code);
    if (!inputs)
      device.createRenderPipeline({ layout: 'auto', vertex: { module: vertex, entryPoint: 'main' },
                                    fragment: { module, entryPoint: 'main', targets }, primitive: { topology: 'point-list' } });
  }
  const error = await device.popErrorScope();
  if (error) messages.push(`validation: ${error.message}`);
  return { name: m.name, ok: !error && !messages.some((x) => x.startsWith('error')), messages };
}

async function compute(device, job) {
  device.pushErrorScope('validation');
  const module = device.createShaderModule({ code: job.code });
  const messages = await messagesOf(module);
  // One bind group per @group index up to the highest used (an unused one is empty).
  const groupOf = (b) => b.group ?? 0;
  const groupCount = 1 + Math.max(0, ...job.buffers.map(groupOf));
  const layouts = [...Array(groupCount).keys()].map((g) => device.createBindGroupLayout({
    entries: job.buffers.filter((b) => groupOf(b) === g)
      .map((b) => ({ binding: b.binding, visibility: GPUShaderStage.COMPUTE, buffer: { type: b.kind } })),
  }));
  const pipeline = device.createComputePipeline({
    layout: device.createPipelineLayout({ bindGroupLayouts: layouts }), compute: { module, entryPoint: 'main' } });
  const buffers = job.buffers.map((b) => {
    const data = fromBase64(b.data);
    const size = Math.max(16, Math.ceil(data.length / 16) * 16);
    const usage = (b.kind === 'uniform' ? GPUBufferUsage.UNIFORM : GPUBufferUsage.STORAGE) | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST;
    const buffer = device.createBuffer({ size, usage });
    const padded = new Uint8Array(size);
    padded.set(data);
    device.queue.writeBuffer(buffer, 0, padded);
    return { buffer, size, length: data.length, kind: b.kind };
  });
  const bindGroups = layouts.map((layout, g) => device.createBindGroup({
    layout,
    entries: job.buffers.map((b, i) => ({ b, i })).filter(({ b }) => groupOf(b) === g)
      .map(({ b, i }) => ({ binding: b.binding, resource: { buffer: buffers[i].buffer } })),
  }));
  const encoder = device.createCommandEncoder();
  const pass = encoder.beginComputePass();
  pass.setPipeline(pipeline);
  bindGroups.forEach((group, g) => pass.setBindGroup(g, group));
  pass.dispatchWorkgroups(...job.groups);
  pass.end();
  const reads = buffers.map((b) => {
    const read = device.createBuffer({ size: b.size, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
    encoder.copyBufferToBuffer(b.buffer, 0, read, 0, b.size);
    return read;
  });
  device.queue.submit([encoder.finish()]);
  const error = await device.popErrorScope();
  if (error) throw new Error(`WebGPU validation: ${error.message}\n${messages.join('\n')}`);
  const out = [];
  for (let i = 0; i < reads.length; ++i) {
    await reads[i].mapAsync(GPUMapMode.READ);
    out.push(toBase64(new Uint8Array(reads[i].getMappedRange()).slice(0, buffers[i].length)));
  }
  return { buffers: out, messages };
}

window.doubletResult = (async () => {
  const job = await (await fetch('job.json')).json();
  const { device, name } = await adapterAndDevice();
  if (job.kind === 'validate') {
    const results = [];
    for (const m of job.modules) results.push(await validate(device, m));
    return { adapter: name, results };
  }
  return { adapter: name, ...(await compute(device, job)) };
})();
