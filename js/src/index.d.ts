// Hand-written declarations for src/index.mjs (@doublet/host).

/** A double as the float pair a lowered (df64) shader takes: hi = float(x), lo = float(x - hi). */
export interface FloatPair {
  hi: number;
  lo: number;
}
export function split(x: number): FloatPair;
export function splitArray(values: ArrayLike<number>): { hi: Float32Array; lo: Float32Array };
/** hi + lo; a zero keeps hi's sign. */
export function join(hi: number, lo: number): number;

/** Mode exact: the 2 binary64 words of x, low word first. */
export function exactWords(x: number): Uint32Array;
export function exactWordsArray(values: ArrayLike<number>): Uint32Array;
export function fromExactWords(words: ArrayLike<number>, offset?: number): number;

export type Mode = 'df64' | 'exact';
export function writeDouble(view: DataView, byteOffset: number, x: number, mode: Mode): void;

/** A block member as `doublet lower --manifest` lists it. */
export interface ManifestMember {
  name: string;
  type: string;
  lowered_type: string;
  offset: number;
  size: number;
  hi_offset?: number;
  lo_offset?: number;
  array_stride?: number;
  matrix_stride?: number;
  encoding?: 'binary64-words';
}
export interface ManifestVariable {
  name: string;
  storage: string;
  type: string;
  split: boolean;
  lowered_type: string;
  lowered_names: string[];
  lowered_types?: string[];
  locations?: number[];
  encoding?: 'binary64-words';
  layout?: 'std140' | 'std430';
  members?: ManifestMember[];
}
export interface Manifest {
  stage: string;
  target: string;
  mode?: string;
  variables: ManifestVariable[];
  guard?: { kind: string; uniform?: string; type?: string; required_value?: number };
}

/** double, dvecN, dmatCxR (column-major) members and arrays of them; a runtime-sized array takes as many elements as given. */
export function writeBlockMember(view: DataView, member: ManifestMember, value: number | ArrayLike<number>,
                                 blockOffset?: number): void;
/** The inverse: a member's doubles (`elements` of a runtime-sized array). */
export function readBlockMember(view: DataView, member: ManifestMember, blockOffset?: number, elements?: number): Float64Array;

export interface LoweredUniform {
  name: string;
  /** The lowered GLSL type, e.g. "vec3", "float[2]", "uvec4". */
  type: string;
  /** The WebGL2RenderingContext method to call, e.g. "uniform3fv", "uniform2uiv". */
  setter: string;
  data: Float32Array | Uint32Array | Int32Array;
}
export function setUniformsFromManifest(manifest: Manifest,
                                        values: Record<string, number | ArrayLike<number>>): LoweredUniform[];

/** Calls the setters of setUniformsFromManifest's list on the current program (matrices: transpose false). */
export function applyUniforms(gl: WebGL2RenderingContext, program: WebGLProgram, uniforms: LoweredUniform[]): void;

export interface WebGL2Binder {
  setDouble(name: string, x: number): void;
  setDoubles(name: string, values: ArrayLike<number>): void;
  /** A double matrix uniform, column-major. */
  setDMat(name: string, columnMajor: ArrayLike<number>): void;
}
/** Binds a lowered program's double uniforms by their original names; applies the manifest's defaults; checks the guard reads 0. */
export function createWebGL2Binder(gl: WebGL2RenderingContext, program: WebGLProgram, manifest: Manifest): WebGL2Binder;

export interface LoweredAttribute {
  name: string;
  /** Components per vertex (vertexAttribPointer's / vertexAttribIPointer's size). */
  size: number;
  /** true: words, Uint32Array, vertexAttribIPointer with UNSIGNED_INT (mode exact). */
  integer: boolean;
  data: Float32Array | Uint32Array;
}
/** The lowered attributes of a double input (hi/lo, or exact words) for components given vertex after vertex. */
export function webgl2Attributes(manifest: Manifest, name: string, values: ArrayLike<number>): LoweredAttribute[];
