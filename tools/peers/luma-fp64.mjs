// Prints luma.gl's fp64 shader library as a luma.gl application on Mesa's software rasterizer gets
// it, as JSON on stdout: {"version", "uniforms", "glsl"}. "glsl" is what luma.gl's own assembler
// (assembleGLSLShaderPair) puts before an application's vertex shader when that shader uses the
// `fp64` module: the platform defines for an unrecognised GPU (luma.gl's default case, which enables
// its LUMA_FP64_* workarounds), the fp64arithmetic uniform block and the arithmetic and function
// sources. "uniforms" are the module's default uniform values (ONE = 1, SPLIT = 4097), which luma.gl
// uploads for the application. Nothing of luma.gl is stored in doublet's tree: the package comes
// from the npm registry (package-lock.json pins it). Used by `doublet bench --transcendentals
// --peer-luma` and tests/numeric/luma_peer_test.cpp.
import {readFileSync} from 'node:fs';
import {assembleGLSLShaderPair, fp64, fp64arithmetic} from '@luma.gl/shadertools';

// The installed version (the package's exports do not include its package.json).
const manifest = new URL('./node_modules/@luma.gl/shadertools/package.json', import.meta.url);
const {version} = JSON.parse(readFileSync(manifest, 'utf8'));

const marker = '// doublet: application shader starts here';
const vs = `#version 300 es\n${marker}\nvoid main() { gl_Position = vec4(0.0); }\n`;
const fs = '#version 300 es\nprecision highp float;\nout vec4 color;\nvoid main() { color = vec4(0.0); }\n';
const platformInfo = {type: 'webgl', gpu: 'unknown', shaderLanguage: 'glsl', shaderLanguageVersion: 300, features: new Set()};
const assembled = assembleGLSLShaderPair({platformInfo, vs, fs, modules: [fp64]}).vs;

const start = assembled.indexOf('\n') + 1;  // after "#version 300 es"
const end = assembled.indexOf(marker);
if (!assembled.startsWith('#version') || end < 0) {
  console.error('luma-fp64.mjs: unexpected assembled shader layout from @luma.gl/shadertools ' + version);
  process.exit(1);
}
process.stdout.write(JSON.stringify({version, uniforms: fp64arithmetic.defaultUniforms, glsl: assembled.slice(start, end)}) + '\n');
