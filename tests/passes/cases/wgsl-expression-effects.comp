// target: wgsl
#version 450
// Increments and assignments whose value is used become commas over temporaries, then move before
// their statement, as does an index with a call; one under && stays (the printer refuses it), a
// statement's own does not change.
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { int count; double v[]; };
int next(inout int c) { c += 1; return c; }
void main() {
  int n = 0;
  v[n++] = 1.5lf;                 // the index: the old n
  double acc;
  v[++n] = (acc = v[0]) * acc;    // ++n, then the assignment's value
  v[next(n)] *= 2.0lf;            // an index with a call: computed once
  count += 1;                     // a statement of its own: unchanged
  bool more = n > 0 && count++ > 2;
  v[n] = double(more);
}
