// Refusing an output that would destroy an input, or two outputs on one file, before anything is
// written (`asm85 x.asm -o x.asm` must not replace the source). Paths are compared by the file
// they name where it exists (device and inode: a link or another spelling is the same file),
// else by their normalized absolute form.
#pragma once

#include <string>
#include <vector>

namespace alp85 {

struct NamedPath {
    std::string path;  // as the user gave it ("" is no file and is skipped)
    std::string role;  // how the message names it: "-o", "--lst", "the source", "an INCLUDEd file"
};

// True when both paths name one file.
bool same_file(const std::string& a, const std::string& b);

// "" when no output is one of the inputs and no two outputs name one file; otherwise the first
// clash, e.g. "-o 'x.asm' is the source 'x.asm': writing it would destroy the input".
std::string output_clash(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

}  // namespace alp85
