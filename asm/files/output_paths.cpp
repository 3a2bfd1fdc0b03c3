#include "asm/files/output_paths.h"

#include <filesystem>
#include <system_error>

#include <sys/stat.h>

namespace alp85 {

bool same_file(const std::string& a, const std::string& b) {
    namespace fs = std::filesystem;
    struct stat sa {}, sb {};
    if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0)  // /dev/null twice destroys nothing
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino && !S_ISCHR(sa.st_mode);
    // At least one does not exist yet: the same path written two ways (./x, a/../x, a link to the
    // folder) is still one file.
    std::error_code ea, eb;
    const fs::path pa = fs::weakly_canonical(fs::absolute(a), ea), pb = fs::weakly_canonical(fs::absolute(b), eb);
    if (ea || eb) return fs::absolute(a).lexically_normal() == fs::absolute(b).lexically_normal();
    return pa.lexically_normal() == pb.lexically_normal();
}

std::string output_clash(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const NamedPath& o = outputs[i];
        if (o.path.empty()) continue;
        for (const NamedPath& in : inputs)
            if (!in.path.empty() && same_file(o.path, in.path))
                return o.role + " '" + o.path + "' is " + in.role + " '" + in.path +
                       "': writing it would destroy the input";
        for (std::size_t j = 0; j < i; ++j)
            if (!outputs[j].path.empty() && same_file(o.path, outputs[j].path))
                return outputs[j].role + " '" + outputs[j].path + "' and " + o.role + " '" + o.path +
                       "' name one file: one would overwrite the other";
    }
    return {};
}

}  // namespace alp85
