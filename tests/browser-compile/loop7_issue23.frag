#version 450
// Issue 23's first report: a loop of seven double statements that gave no result in Chromium within
// 30 s when the runtime had per-operation branches (docs/performance.md, "Compile time in the browser").
flat in dvec2 v_ab;
layout(location = 0) out uvec4 o;
void main() {
    double a = v_ab.x, b = v_ab.y, s = a;
    for (int k = 0; k < 2; ++k) {
        s = s + b * s; s = s + b * s; s = s + b * s; s = s + b * s;
        s = s + b * s; s = s + b * s; s = s + b * s;
    }
    o = uvec4(unpackDouble2x32(s), unpackDouble2x32(a));
}
