// doublet::Includer: #include resolved by the application (here from memory), nested
// includes, the includer's path passed along, the files reported in included_files, and
// a missing include reported as a diagnostic.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"

namespace {

class MemoryIncluder : public doublet::Includer {
 public:
  std::map<std::string, std::string> files;
  std::vector<std::pair<std::string, std::string>> requests;  // (requested, includer)

  std::optional<doublet::IncludeResult> include(std::string_view requested, std::string_view includer) override {
    requests.emplace_back(requested, includer);
    auto it = files.find("mem/" + std::string(requested));
    if (it == files.end()) return std::nullopt;
    return doublet::IncludeResult{it->first, it->second};
  }
};

doublet::Options compute_options(doublet::Includer* includer) {
  doublet::Options o;
  o.stage = doublet::Stage::Compute;
  o.target = doublet::Target::Es310;
  o.file_name = "main.comp";
  o.includer = includer;
  return o;
}

const char* kMain = R"(#version 310 es
#include "pairs.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { vec2 v[]; };
uniform double k;
void main() { v[0] = store_pair(load_pair(v[0]) * k); }
)";

TEST(Includer, ResolvesNestedIncludesFromMemory) {
  MemoryIncluder inc;
  inc.files["mem/pairs.glsl"] = "#include \"load.glsl\"\nvec2 store_pair(double d) { float h = float(d); return vec2(h, float(d - double(h))); }\n";
  inc.files["mem/load.glsl"] = "double load_pair(vec2 p) { return double(p.x) + double(p.y); }\n";
  doublet::Result r = doublet::lower(kMain, compute_options(&inc));
  for (const auto& d : r.diagnostics) ADD_FAILURE() << doublet::format_diagnostic(d);
  ASSERT_TRUE(r.ok);
  EXPECT_NE(r.output.find("load_pair"), std::string::npos);
  EXPECT_FALSE(std::regex_search(std::regex_replace(r.output, std::regex("//[^\n]*"), ""),
                                 std::regex(R"(\b(double|dvec[234])\b)")))
      << r.output;
  ASSERT_EQ(inc.requests.size(), 2u);
  EXPECT_EQ(inc.requests[0].first, "pairs.glsl");
  EXPECT_EQ(inc.requests[1].first, "load.glsl");
  EXPECT_EQ(inc.requests[1].second, "mem/pairs.glsl") << "a nested include names the file that includes it";
  EXPECT_EQ(r.included_files, (std::vector<std::string>{"mem/pairs.glsl", "mem/load.glsl"}));
}

TEST(Includer, MissingIncludeIsADiagnostic) {
  MemoryIncluder inc;  // empty
  doublet::Result r = doublet::lower(kMain, compute_options(&inc));
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].severity, doublet::Severity::Error);
  EXPECT_NE(doublet::format_diagnostic(r.diagnostics[0]).find("pairs.glsl"), std::string::npos)
      << doublet::format_diagnostic(r.diagnostics[0]);
}

TEST(Includer, OverridesIncludeDirs) {
  MemoryIncluder inc;
  inc.files["mem/pairs.glsl"] = "double load_pair(vec2 p) { return double(p.x) + double(p.y); }\n"
                                "vec2 store_pair(double d) { float h = float(d); return vec2(h, float(d - double(h))); }\n";
  doublet::Options o = compute_options(&inc);
  o.include_dirs = {"/nonexistent"};
  doublet::Result r = doublet::lower(kMain, o);
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.included_files, (std::vector<std::string>{"mem/pairs.glsl"}));
}

}  // namespace
