// The jitter scene of `doublet demo jitter` (docs/demo.md): two 1.2 m boxes 2.75 m apart on a
// geostationary orbit, a camera circling them from 10 m to 50 m; the transform in JavaScript's
// doubles as the reference, and the wobble measure (the largest frame-to-frame change of a vertex's
// screen-space error, in pixels).
const geoRadius = 42164137.0, gap = 2.75, orbitAngle = 0.7;
const add = (a, b, k = 1) => a.map((x, i) => x + k * b[i]);
const scale = (a, k) => a.map((x) => x * k);
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const normalize = (a) => scale(a, 1 / Math.hypot(...a));
const centre = [geoRadius * Math.cos(orbitAngle), geoRadius * Math.sin(orbitAngle), 0];
const radial = [Math.cos(orbitAngle), Math.sin(orbitAngle), 0];
const alongTrack = [-Math.sin(orbitAngle), Math.cos(orbitAngle), 0];
const north = [0, 0, 1];

// Two boxes, 36 vertices each (two triangles per face), shaded per face.
export function geometry() {
  const positions = [], colors = [];
  const axes = [alongTrack, radial, north];
  for (const [offset, base] of [[-gap / 2, [1.0, 0.78, 0.25]], [gap / 2, [0.45, 0.75, 1.0]]]) {
    const boxCentre = add(centre, alongTrack, offset), half = 0.6;
    for (let axis = 0; axis < 3; ++axis)
      for (const sign of [-1, 1]) {
        const n = scale(axes[axis], sign * half), u = scale(axes[(axis + 1) % 3], half), v = scale(axes[(axis + 2) % 3], half);
        const shade = 0.55 + 0.15 * axis + (sign > 0 ? 0.15 : 0);
        for (const [cu, cv] of [[-1, -1], [1, -1], [1, 1], [-1, -1], [1, 1], [-1, 1]]) {
          positions.push(...add(add(add(boxCentre, n), u, cu), v, cv));
          colors.push(...base.map((b) => b * shade));
        }
      }
  }
  return { positions, colors };
}

// Frame s in [0, 1]: the eye (doubles) and the rotation-projection matrix, rounded to float as
// the shader receives it (column-major).
export function camera(s, aspect) {
  const distance = 10 + 40 * s, azimuth = 0.35 + 0.5 * s, elevation = 0.3;
  const dir = add(add(scale(radial, -Math.cos(azimuth) * Math.cos(elevation)), alongTrack,
                      Math.sin(azimuth) * Math.cos(elevation)), north, Math.sin(elevation));
  const eye = add(centre, dir, distance);
  const forward = scale(dir, -1), right = normalize(cross(forward, north)), up = cross(right, forward);
  const f = 1 / Math.tan(15 * Math.PI / 180), near = 0.5, far = 500;
  const m = new Float32Array(16);
  for (let c = 0; c < 3; ++c) {
    m[c * 4 + 0] = f / aspect * right[c];
    m[c * 4 + 1] = f * up[c];
    m[c * 4 + 2] = (far + near) / (near - far) * -forward[c];
    m[c * 4 + 3] = forward[c];
  }
  m[14] = 2 * far * near / (near - far);
  return { eye, viewProjection: m };
}

// gl_Position of every vertex in doubles (the float matrix, the exact eye-relative position).
export function referenceClip(positions, cam) {
  const clip = [], m = cam.viewProjection;
  for (let i = 0; i < positions.length; i += 3) {
    const rel = [positions[i] - cam.eye[0], positions[i + 1] - cam.eye[1], positions[i + 2] - cam.eye[2], 1];
    for (let r = 0; r < 4; ++r) clip.push(rel.reduce((sum, x, c) => sum + m[c * 4 + r] * x, 0));
  }
  return clip;
}

export function wobble(clipFrames, referenceFrames, width, height) {
  const pixel = (c, i, axis) => (c[i + axis] / c[i + 3] * 0.5 + 0.5) * (axis ? height : width);
  let wobblePx = 0, maxErrorPx = 0, previous = null;
  clipFrames.forEach((clip, f) => {
    const error = [];
    for (let i = 0; i < clip.length; i += 4) {
      const dx = pixel(clip, i, 0) - pixel(referenceFrames[f], i, 0), dy = pixel(clip, i, 1) - pixel(referenceFrames[f], i, 1);
      error.push(dx, dy);
      maxErrorPx = Math.max(maxErrorPx, Math.hypot(dx, dy));
    }
    if (previous)
      for (let k = 0; k < error.length; k += 2)
        wobblePx = Math.max(wobblePx, Math.hypot(error[k] - previous[k], error[k + 1] - previous[k + 1]));
    previous = error;
  });
  return { wobble_px: wobblePx, max_error_px: maxErrorPx };
}
