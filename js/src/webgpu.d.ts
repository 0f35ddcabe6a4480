// Types of js/src/webgpu.mjs (docs/web.md, "WebGPU binder").
export interface UniformBufferBytes {
  group: number;
  binding: number;
  /** Bytes to allocate (a multiple of 16). */
  size: number;
  data: ArrayBuffer;
}
/** The loose-uniform buffer (df_uniforms) of a shader lowered with --target wgsl, from its manifest. */
export function wgslUniformBuffer(manifest: object, values?: Record<string, number | ArrayLike<number>>): UniformBufferBytes;

export interface VertexLayout {
  arrayStride: number;
  attributes: { shaderLocation: number; offset: number; format: string }[];
  parts: object[];
  manifest: object;
}
/** One interleaved vertex buffer layout for the named inputs (GPUVertexBufferLayout plus what packVertices needs). */
export function wgslVertexLayout(manifest: object, names: string[]): VertexLayout;
/** `count` vertices' bytes for the layout; values[name]: the input's components vertex after vertex. */
export function packVertices(layout: VertexLayout, values: Record<string, ArrayLike<number>>, count: number): ArrayBuffer;
