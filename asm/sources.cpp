// Source files: reading them (CP/M ^Z padding, CR LF), caching, and finding INCLUDE files.
#include <algorithm>
#include <fstream>
#include <sstream>

#include "asm/assembler.h"

namespace alp85::asm85 {
namespace {

constexpr std::uintmax_t kMaxFileSize = 16u << 20;

}  // namespace

std::optional<std::string> read_disk_file(const std::filesystem::path& p) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) return std::nullopt;
    auto size = std::filesystem::file_size(p, ec);
    if (ec || size > kMaxFileSize) return std::nullopt;
    std::ifstream in(p, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::vector<std::string> split_lines(std::string_view text) {
    std::vector<std::string> lines;
    auto eof = text.find('\x1a');  // CP/M pads text files with ^Z after the end
    if (eof != std::string_view::npos) text = text.substr(0, eof);
    std::size_t start = 0;
    while (start < text.size()) {
        auto nl = text.find('\n', start);
        auto end = nl == std::string_view::npos ? text.size() : nl;
        std::string l(text.substr(start, end - start));
        if (!l.empty() && l.back() == '\r') l.pop_back();
        lines.push_back(std::move(l));
        if (nl == std::string_view::npos) break;
        start = nl + 1;
    }
    return lines;
}

Assembler::Assembler(const Options& options) : opt_(options) {
    if (!opt_.read_file) opt_.read_file = read_disk_file;
}

int Assembler::load_file(const std::filesystem::path& path, const std::string& shown) {
    std::error_code ec;
    auto canon = std::filesystem::weakly_canonical(path, ec);
    std::string key = ec ? path.string() : canon.string();
    if (auto it = file_index_.find(key); it != file_index_.end()) return it->second;
    auto text = opt_.read_file(path);
    if (!text) return -1;
    files_.push_back({shown, path, split_lines(*text)});
    int idx = static_cast<int>(files_.size() - 1);
    file_index_[key] = idx;
    return idx;
}

std::optional<std::filesystem::path> Assembler::find_include(const std::string& name) const {
    std::vector<std::filesystem::path> dirs;
    if (cur_line_ && cur_line_->file >= 0 && cur_line_->file < static_cast<int>(files_.size()))
        dirs.push_back(files_[static_cast<std::size_t>(cur_line_->file)].path.parent_path());
    for (auto& d : opt_.include_dirs) dirs.push_back(d);
    dirs.emplace_back(".");
    std::filesystem::path p(name);
    if (p.is_absolute()) return p;
    for (auto& d : dirs) {
        auto cand = d / p;
        if (opt_.read_file(cand)) return cand;
        // Period sources name files in upper case on case-sensitive disks: try the other case.
        auto lower = d / std::filesystem::path(to_upper(name));
        if (opt_.read_file(lower)) return lower;
        std::string low = name;
        std::transform(low.begin(), low.end(), low.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (opt_.read_file(d / low)) return d / low;
    }
    return std::nullopt;
}

}  // namespace alp85::asm85
