// Outputs must never destroy what is not theirs: before anything is written, every
// output is compared with every other output and with every input, by (device, inode)
// when both exist and by canonical path otherwise, so `-o x --manifest ./x`, a symlink
// to the input, `-MF` naming the input, or two batch inputs that map to one output name
// are all caught. Character devices (/dev/null, a terminal) are exempt: writing one twice
// destroys nothing.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace doublet::cli {

// A file named on the command line, and how messages name it: "-o 'out.vert'",
// "the input 'a.vert'", "the manifest 'out/a.vert.json' of 'a.vert'".
struct NamedFile {
  std::string path;
  std::string label;
};

struct FileClash {
  NamedFile output;
  NamedFile other;        // another output, or an input
  bool other_is_input = false;
  // "--manifest './x' and -o 'x' are the same file", "-MF 'a.vert' is the input 'a.vert' itself"
  std::string describe() const;
};

// The first output that is the same file as an earlier output or as an input.
std::optional<FileClash> find_file_clash(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs);

}  // namespace doublet::cli
