// The distance of a binary64 x to the nearest multiple of pi/2, in MPFR: where the trigonometric
// rules' 44-bit promise ends (docs/transcendentals.md, Limits). Shared by the df64 and the mode
// exact transcendental tests.
#pragma once

#include <mpfr.h>

#include <cmath>

// |x - k pi/2| for the nearest integer k (x is exact in binary64).
inline double distance_to_multiple_of_pio2(double x) {
  mpfr_t pio2, q, r;
  for (mpfr_ptr p : {pio2, q, r}) mpfr_init2(p, 256);
  mpfr_const_pi(pio2, MPFR_RNDN);
  mpfr_div_2ui(pio2, pio2, 1, MPFR_RNDN);
  mpfr_set_d(r, x, MPFR_RNDN);
  mpfr_div(q, r, pio2, MPFR_RNDN);
  mpfr_rint(q, q, MPFR_RNDN);
  mpfr_mul(q, q, pio2, MPFR_RNDN);
  mpfr_sub(r, r, q, MPFR_RNDN);
  const double d = std::fabs(mpfr_get_d(r, MPFR_RNDN));
  for (mpfr_ptr p : {pio2, q, r}) mpfr_clear(p);
  return d;
}
