// Runs a scope under the "C" locale on the calling thread only (POSIX uselocale), so that
// snprintf("%g") and strtod in the passes write and read '.' whatever setlocale() the
// application embedding doublet made (docs/robustness.md, "Determinism"). Other threads and
// the process locale are untouched; the thread's previous locale is restored on exit.
#pragma once

#include <clocale>

#include <locale.h>

namespace doublet {

class ScopedCLocale {
 public:
  ScopedCLocale() {
    static const locale_t c_locale = newlocale(LC_ALL_MASK, "C", locale_t{});  // process lifetime
    if (c_locale) previous_ = uselocale(c_locale);
  }
  ~ScopedCLocale() {
    if (previous_) uselocale(previous_);
  }
  ScopedCLocale(const ScopedCLocale&) = delete;
  ScopedCLocale& operator=(const ScopedCLocale&) = delete;

 private:
  locale_t previous_{};
};

}  // namespace doublet
