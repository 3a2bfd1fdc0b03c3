// Writing an output file so that it is either complete or absent: the bytes go to a temporary
// file beside the target, which is renamed over it only when everything was written. A target
// that exists and is not a regular file (/dev/null, a pipe, a symbolic link) is written through
// instead: renaming over it would replace the device or the link itself.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace alp85 {

// For output written piece by piece (traces): write to stream(), then commit(). Destroyed
// without commit() (an error, an exception), it removes the temporary file.
class AtomicOutput {
public:
    explicit AtomicOutput(std::filesystem::path path);  // throws std::runtime_error
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;
    ~AtomicOutput();

    std::ostream& stream() { return out_; }
    void commit();  // throws std::runtime_error naming the path (disk full, rename failed)

private:
    std::filesystem::path path_, tmp_;  // tmp_ empty when writing through
    std::ofstream out_;
    bool done_ = false;
};

// Throws std::runtime_error naming the path and the reason; no temporary file is left behind.
void write_atomic(const std::filesystem::path& path, std::string_view bytes);
inline void write_atomic(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    write_atomic(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace alp85
