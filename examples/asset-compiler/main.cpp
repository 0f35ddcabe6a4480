// lower_assets SRC_DIR OUT_DIR [--target es300] [-j N]
//
// Lowers every .vert/.frag/.comp (also NAME.vert.glsl, ...) under SRC_DIR with
// doublet::lower, on N threads (default: all cores), and writes OUT_DIR/<same relative
// path> plus <that>.json, the manifest. #include is resolved by an Includer that only
// reads inside SRC_DIR, the way an asset pipeline keeps builds hermetic. Exit status 1 if
// any shader failed (the others are still written).
#include <doublet/doublet.hpp>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::optional<std::string> read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool write_file(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream out(p, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

// Resolves `#include "x"` next to the including file, never outside the asset root.
class AssetIncluder : public doublet::Includer {
 public:
  explicit AssetIncluder(fs::path root) : root_(fs::weakly_canonical(std::move(root))) {}

  std::optional<doublet::IncludeResult> include(std::string_view requested, std::string_view includer) override {
    fs::path candidate = fs::weakly_canonical(fs::path(includer).parent_path() / requested);
    auto [end, _] = std::mismatch(root_.begin(), root_.end(), candidate.begin(), candidate.end());
    if (end != root_.end()) return std::nullopt;  // outside the asset root
    auto text = read_file(candidate);
    if (!text) return std::nullopt;
    return doublet::IncludeResult{candidate.string(), std::move(*text)};
  }

 private:
  fs::path root_;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: lower_assets SRC_DIR OUT_DIR [--target es300] [-j N]\n";
    return 2;
  }
  const fs::path src = argv[1], out = argv[2];
  doublet::Target target = doublet::Target::Es300;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  for (int i = 3; i + 1 < argc; i += 2) {
    std::string opt = argv[i];
    if (opt == "--target" && doublet::parse_target(argv[i + 1])) {
      target = *doublet::parse_target(argv[i + 1]);
    } else if (opt == "-j") {
      threads = static_cast<unsigned>(std::max(1, std::atoi(argv[i + 1])));
    } else {
      std::cerr << "lower_assets: bad option " << opt << " " << argv[i + 1] << "\n";
      return 2;
    }
  }

  std::vector<fs::path> shaders;
  for (const auto& e : fs::recursive_directory_iterator(src))
    if (e.is_regular_file() && doublet::stage_from_path(e.path().string())) shaders.push_back(e.path());
  std::sort(shaders.begin(), shaders.end());

  // doublet::lower is thread-safe: each worker lowers whole files, one at a time.
  std::atomic<size_t> next{0};
  std::atomic<int> failures{0};
  std::mutex print;
  auto worker = [&] {
    AssetIncluder includer(src);
    for (size_t i; (i = next.fetch_add(1)) < shaders.size();) {
      const fs::path& path = shaders[i];
      doublet::Options options;
      options.stage = doublet::stage_from_path(path.string());
      options.target = target;
      options.file_name = path.string();
      options.includer = &includer;
      doublet::Result r = doublet::lower(read_file(path).value_or(""), options);

      const fs::path dest = out / fs::relative(path, src);
      bool written = r.ok && write_file(dest, r.output) && write_file(dest.string() + ".json", r.manifest.to_json());
      std::lock_guard lock(print);
      for (const auto& d : r.diagnostics) std::cerr << doublet::format_diagnostic(d) << "\n";
      if (written) {
        std::cout << "lowered " << fs::relative(path, src).string() << " (" << r.included_files.size()
                  << " includes)\n";
      } else {
        ++failures;
        std::cerr << "lower_assets: " << path.string() << " failed\n";
      }
    }
  };
  std::vector<std::jthread> pool;
  for (unsigned t = 0; t < std::min<size_t>(threads, shaders.size()); ++t) pool.emplace_back(worker);
  pool.clear();  // join

  std::cout << shaders.size() - failures << " of " << shaders.size() << " shaders lowered to "
            << doublet::to_string(target) << "\n";
  return failures == 0 ? 0 : 1;
}
