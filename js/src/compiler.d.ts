// Types of js/src/compiler.mjs: doublet's compiler as WebAssembly (docs/web.md).
export interface LowerOptions {
  /** 'vert' | 'frag' | 'comp'; taken from fileName's extension when absent. */
  stage?: 'vert' | 'frag' | 'comp';
  /** Named in diagnostics (default '<stdin>'). */
  fileName?: string;
  target?: 'es100' | 'es300' | 'es310' | 'es320' | 'glsl330' | 'glsl450' | 'webgl2' | 'wgsl';
  mode?: 'fp32' | 'rte' | 'df64-fast' | 'df64' | 'df64-int' | 'native' | 'exact' | 'rte-exact';
  /** Per-declaration modes, as --mode-for NAME=MODE. */
  modeFor?: Record<string, string>;
  /** -D NAME=VALUE. */
  defines?: Record<string, string | number>;
  /** -I DIR: Node only (the file system); in browsers use include. */
  includeDirs?: string[];
  /** Answers #include "name" synchronously: { path, contents }, or null when not found. */
  include?: (requested: string, includerPath: string) => { path: string; contents: string } | null;
  guard?: 'auto' | 'precise' | 'uniform';
  gpuShader5?: boolean;
  guardUniform?: string;
  hiSuffix?: string;
  loSuffix?: string;
  optimize?: boolean;
  disabledLints?: string[];
  lintErrors?: boolean;
  constantRangeErrors?: boolean;
}

export interface LowerDiagnostic {
  file: string;
  line: number;
  column: number;
  severity: 'error' | 'warning' | 'note';
  message: string;
  /** `file:line:col: error: message`, as the CLI prints it (without the newline). */
  text: string;
}

export interface LowerResult {
  ok: boolean;
  /** The lowered shader; '' unless ok. */
  output: string;
  /** The manifest (`doublet lower --manifest`), null unless ok. */
  manifest: Record<string, unknown> | null;
  diagnostics: LowerDiagnostic[];
  includedFiles: string[];
}

export function lower(source: string, options?: LowerOptions): Promise<LowerResult>;
