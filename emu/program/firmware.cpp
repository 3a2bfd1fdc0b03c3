#include "emu/program/firmware.h"

#include <stdexcept>
#include <system_error>

#include <nlohmann/json.hpp>

#include "emu/program/ihex.h"

#ifdef ALP85_HAVE_MONITOR
#include "monitor_embed.h"
namespace alp85 {
extern const char kMonitorMap[];  // monitor.json, embedded by emu/embed_text.cmake
}
#endif
#ifdef ALP85_HAVE_THESIS
namespace alp85 {
extern const char kThesisHex[], kThesisMap[], kThesisFixedHex[], kThesisFixedMap[];  // emu/embed_text.cmake
}
#endif
#ifdef ALP85_HAVE_MASTER
namespace alp85 {
extern const char kMasterHex[], kMasterMap[];  // emu/embed_text.cmake
}
#endif

namespace alp85::firmware {
namespace {

namespace fs = std::filesystem;

// The build embeds asm85's maps, which name their sources by the paths they were assembled from
// (in the source tree). An installed alp85 reads them with the installed copies' paths instead,
// so that the debugger lists and binds source lines without the source tree.
std::string with_sources_located(const char* map) {
    nlohmann::json j = nlohmann::json::parse(map, nullptr, /*allow_exceptions=*/false);
    if (!j.is_object() || !j.contains("files") || !j["files"].is_array()) return map;
    bool moved = false;
    for (auto& file : j["files"]) {
        if (!file.is_string()) continue;
        std::string now = locate_source(file.get<std::string>());
        if (now != file.get<std::string>()) {
            file = std::move(now);
            moved = true;
        }
    }
    return moved ? j.dump() : std::string(map);
}

void load_map(Firmware& f, const char* map) {
    if (const std::string err = f.symbols.load_map_text(with_sources_located(map)); !err.empty())
        throw std::logic_error("the built-in " + f.name + " map is damaged: " + err);
}

[[maybe_unused]] Firmware from_hex(std::string name, const char* hex, const char* map) {
    Firmware f;
    f.name = std::move(name);
    std::vector<std::uint8_t> bytes(0x10000);
    std::vector<bool> used(0x10000);
    const std::string err = load_intel_hex(hex, [&](std::uint16_t a, std::uint8_t b) {
        bytes[a] = b;
        used[a] = true;
    });
    if (!err.empty()) throw std::logic_error("the built-in " + f.name + " image is damaged: " + err);
    for (std::size_t a = 0; a < used.size();) {
        if (!used[a]) {
            ++a;
            continue;
        }
        ImageSegment seg{static_cast<std::uint16_t>(a), {}};
        while (a < used.size() && used[a]) seg.bytes.push_back(bytes[a++]);
        f.segments.push_back(std::move(seg));
    }
    load_map(f, map);
    return f;
}

}  // namespace

#ifdef ALP85_HAVE_MONITOR
bool have_monitor() { return true; }
Firmware monitor() {
    Firmware f;
    f.name = "monitor";
    f.segments.push_back({kMonitorRom_origin, {kMonitorRom, kMonitorRom + kMonitorRom_size}});
    load_map(f, kMonitorMap);
    return f;
}
const char* monitor_map() { return kMonitorMap; }
#else
bool have_monitor() { return false; }
Firmware monitor() { return {}; }
const char* monitor_map() { return ""; }
#endif

std::vector<Entry> builtin() {
    std::vector<Entry> out;
    if (have_monitor()) out.push_back({"monitor", "the ALP 85 monitor EPROM at 0000H (firmware/monitor)"});
#ifdef ALP85_HAVE_THESIS
    out.push_back({"thesis", "the thesis firmware of Appendix B at 0800H, as printed (firmware/thesis)"});
    out.push_back({"thesis-fixed", "the thesis firmware with its errata repaired (firmware/thesis/RECONSTRUCTION.md)"});
#endif
#ifdef ALP85_HAVE_MASTER
    out.push_back({"master", "the master program at 3000H in the expansion EPROM, which it fits (firmware/master, docs/contours.md)"});
#endif
    return out;
}

fs::path data_dir() {
    static const fs::path dir = [] {
        std::error_code ec;
        // Installed: <prefix>/bin/alp85 and <prefix>/share/alp85 (ALP85_DATA_FROM_BIN, "../share/alp85"
        // with GNUInstallDirs' defaults). /proc/self/exe is the executable the kernel ran.
        if (const fs::path exe = fs::read_symlink("/proc/self/exe", ec); !ec) {
            const fs::path installed = (exe.parent_path() / ALP85_DATA_FROM_BIN).lexically_normal();
            if (fs::is_directory(installed / "firmware", ec)) return installed;
        }
        // A build folder: the source tree it was built from.
        const fs::path source = ALP85_SOURCE_DIR;
        if (fs::is_directory(source / "firmware", ec)) return source;
        return fs::path{};
    }();
    return dir;
}

std::string locate_source(const std::string& path) {
    const fs::path rel = fs::path(path).lexically_relative(ALP85_SOURCE_DIR);
    if (rel.empty() || *rel.begin() == "..") return path;
    const fs::path dir = data_dir();
    if (dir.empty()) return path;
    std::error_code ec;
    const fs::path there = dir / rel;
    return fs::exists(there, ec) ? there.string() : path;
}

std::optional<Firmware> find(std::string_view name) {
    if (name == "monitor" && have_monitor()) return monitor();
#ifdef ALP85_HAVE_THESIS
    if (name == "thesis") return from_hex("thesis", kThesisHex, kThesisMap);
    if (name == "thesis-fixed") return from_hex("thesis-fixed", kThesisFixedHex, kThesisFixedMap);
#endif
#ifdef ALP85_HAVE_MASTER
    if (name == "master") {
        Firmware f = from_hex("master", kMasterHex, kMasterMap);
        f.expansion_eprom = true;
        return f;
    }
#endif
    return std::nullopt;
}

}  // namespace alp85::firmware
