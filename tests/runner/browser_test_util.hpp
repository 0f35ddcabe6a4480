// Browser tests run in headless Chromium (tools/browser). Where no browser is installed they are
// skipped with the reason, unless DOUBLET_REQUIRE_BROWSER=1 (set by .ci/run), where that fails.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "runner/browser.hpp"

#define DOUBLET_REQUIRE_BROWSER_OR_SKIP()                                                  \
  do {                                                                                     \
    std::string why_no_browser = doublet::runner::browser_unavailable_reason();            \
    if (!why_no_browser.empty()) {                                                         \
      const char* required = std::getenv("DOUBLET_REQUIRE_BROWSER");                      \
      if (required && std::string(required) == "1") FAIL() << "no browser: " << why_no_browser; \
      GTEST_SKIP() << "no browser: " << why_no_browser;                                    \
    }                                                                                      \
  } while (0)
