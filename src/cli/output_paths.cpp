#include "output_paths.hpp"

#include <filesystem>
#include <system_error>

#include <sys/stat.h>

namespace doublet::cli {
namespace {
namespace fs = std::filesystem;

struct FileIdentity {
  bool exists = false;
  bool char_device = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string canonical;  // symlinks resolved as far as the path exists
};

FileIdentity identify(const std::string& path) {
  FileIdentity id;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    id.exists = true;
    id.char_device = S_ISCHR(st.st_mode);
    id.device = st.st_dev;
    id.inode = st.st_ino;
  }
  std::error_code ec;
  fs::path canonical = fs::weakly_canonical(fs::absolute(path, ec), ec);
  id.canonical = ec ? fs::path(path).lexically_normal().string() : canonical.string();
  return id;
}

bool same_file(const FileIdentity& a, const FileIdentity& b) {
  if (a.exists && b.exists) return a.device == b.device && a.inode == b.inode;
  return a.canonical == b.canonical;
}

}  // namespace

std::string FileClash::describe() const {
  if (other_is_input) return output.label + " is " + other.label + " itself";
  return other.label + " and " + output.label + " are the same file";
}

std::optional<FileClash> find_file_clash(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs) {
  std::vector<FileIdentity> input_ids, output_ids;
  for (const NamedFile& in : inputs) input_ids.push_back(identify(in.path));
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    FileIdentity id = identify(outputs[i].path);
    if (!id.char_device) {
      for (std::size_t k = 0; k < output_ids.size(); ++k)
        if (same_file(id, output_ids[k])) return FileClash{outputs[i], outputs[k], false};
      for (std::size_t k = 0; k < input_ids.size(); ++k)
        if (same_file(id, input_ids[k])) return FileClash{outputs[i], inputs[k], true};
    }
    output_ids.push_back(std::move(id));
  }
  return std::nullopt;
}

}  // namespace doublet::cli
