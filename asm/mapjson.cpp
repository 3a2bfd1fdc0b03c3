// The JSON map for the debugger: symbols and the source line of every emitted byte.
#include <nlohmann/json.hpp>

#include "asm/asm85.h"

namespace alp85::asm85 {

std::string write_json_map(const Result& r, const OutputFormat& f) {
    nlohmann::ordered_json j;
    j["format"] = "alp85-asm-map";
    j["version"] = 1;
    if (!f.unit.empty()) j["unit"] = std::string(f.unit);
    j["files"] = r.files;
    j["start"] = r.image.start_address ? nlohmann::ordered_json(*r.image.start_address) : nlohmann::ordered_json(nullptr);
    auto& syms = j["symbols"] = nlohmann::ordered_json::array();
    for (const auto& s : r.symbols) {
        nlohmann::ordered_json o;
        o["name"] = s.name;
        o["value"] = s.value;
        o["kind"] = std::string(kind_name(s.kind));
        o["file"] = s.file;
        o["line"] = s.line;
        syms.push_back(std::move(o));
    }
    auto& lines = j["lines"] = nlohmann::ordered_json::array();
    for (const auto& l : r.line_map) {
        nlohmann::ordered_json o;
        o["address"] = l.address;
        o["length"] = l.length;
        o["file"] = l.file;
        o["line"] = l.line;
        lines.push_back(std::move(o));
    }
    auto& segs = j["segments"] = nlohmann::ordered_json::array();
    auto unit = static_cast<std::size_t>(f.unit_bytes);
    for (const auto& s : r.image.segments()) segs.push_back({{"start", s.start / unit}, {"length", s.bytes.size() / unit}});
    return j.dump(1) + "\n";
}

}  // namespace alp85::asm85
