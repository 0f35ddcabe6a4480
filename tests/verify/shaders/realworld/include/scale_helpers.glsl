// Included by scaled.comp through -I.
double scaled(double v) { return v * 1.25lf + 0.5lf; }
