// setBreakpoints and its kin: every breakpoint bound through the assembler's line map and
// symbols, answered with where it really is.
#include <filesystem>

#include <fmt/format.h>

#include "emu/dap/adapter.h"

namespace alp85::dap {
namespace {

std::string canonical(const std::string& path) {
    std::error_code ec;
    const auto p = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : p.string();
}

}  // namespace

Json Adapter::breakpoint_json(const Breakpoint& b, const std::string& path) const {
    Json j = {{"id", b.id}, {"verified", b.verified}};
    if (!b.message.empty()) j["message"] = b.message;
    if (!path.empty()) {
        j["source"] = source_of(path);
        j["line"] = b.bound_line.value_or(b.line) - (lines_start_at_1_ ? 0 : 1);
    }
    if (!b.addresses.empty()) j["instructionReference"] = hex4(b.addresses.front());
    return j;
}

void Adapter::resolve(Breakpoint& b, const std::string& path) {
    b.addresses.clear();
    b.bound_line.reset();
    b.verified = false;
    b.message.clear();
    if (!session_) {
        b.message = "not bound yet: no program is loaded";
        return;
    }
    const debug::Debugger& d = session_->debugger();
    auto loc = d.locate_line(canonical(path), b.line);
    if (!loc.error.empty()) loc = d.locate_line(std::filesystem::path(path).filename().string(), b.line);
    if (!loc.error.empty()) {
        b.message = loc.error;
        return;
    }
    b.addresses = loc.addresses;
    b.bound_line = loc.bound ? loc.bound->line : b.line;
    if (loc.bound) b.message = fmt::format("moved from line {} to line {}, the next line with code", b.line, loc.bound->line);
    b.verified = !b.addresses.empty();
}

void Adapter::resolve_breakpoints() {
    for (auto& [path, list] : bps_.source)
        for (Breakpoint& b : list) resolve(b, path);
    const SymbolTable* symbols = session_ ? &session_->debugger().program() : nullptr;
    for (Breakpoint& b : bps_.function) {
        b.addresses.clear();
        const auto v = symbols ? symbols->value_of(b.name) : std::nullopt;
        b.verified = v.has_value();
        if (v) b.addresses = {*v};
        b.message = v ? "" : fmt::format("no symbol '{}' in the loaded programs", b.name);
    }
    for (Breakpoint& b : bps_.instruction) b.verified = !b.addresses.empty();
    arm();
}

void Adapter::arm() {
    if (!session_) return;
    Machine& m = session_->machine();
    m.clear_breakpoints();
    m.clear_watchpoints();
    auto add = [&m](const std::vector<Breakpoint>& list) {
        for (const Breakpoint& b : list)
            if (b.verified)
                for (const std::uint16_t a : b.addresses) m.add_breakpoint(a);
    };
    for (const auto& [path, list] : bps_.source) add(list);
    add(bps_.function);
    add(bps_.instruction);
    for (const DataBreakpoint& d : bps_.data)
        if (d.verified)
            for (unsigned i = 0; i < d.length; ++i) m.add_watchpoint(static_cast<std::uint16_t>(d.address + i));
    if (run_.active && run_.kind == Run::Kind::Over) m.add_breakpoint(run_.target);
}

namespace {

// The options every kind shares; a hit condition that is none of DAP's forms is refused here.
void read_options(const Json& spec, Breakpoint& b) {
    b.condition = opt_string(spec, "condition").value_or("");
    b.hit_condition = opt_string(spec, "hitCondition").value_or("");
    b.log_message = opt_string(spec, "logMessage").value_or("");
}

bool check_options(Breakpoint& b) {
    if (!b.hit_condition.empty() && !hit_condition_met(b.hit_condition, 0)) {
        b.verified = false;
        b.message = fmt::format("hit condition '{}' is not N, ==N, >=N, >N, <N, <=N or %N", b.hit_condition);
        return false;
    }
    if (!b.condition.empty()) {
        b.verified = false;
        b.message = "conditions need the debugger engine's expressions (issue #15)";
        return false;
    }
    return true;
}

}  // namespace

void Adapter::set_breakpoints(const Json& args, Json& body) {
    const Json& src = opt_object(args, "source");
    const std::string path = need_string(src, "path");
    std::vector<Breakpoint> list;
    for (const Json& spec : opt_array(args, "breakpoints")) {
        Breakpoint b;
        b.id = bps_.next_id++;
        b.line = static_cast<int>(need_int(spec, "line")) + (lines_start_at_1_ ? 0 : 1);
        read_options(spec, b);
        resolve(b, path);
        if (b.verified) check_options(b);
        list.push_back(std::move(b));
    }
    Json out = Json::array();
    for (const Breakpoint& b : list) out.push_back(breakpoint_json(b, path));
    if (list.empty()) bps_.source.erase(path);
    else bps_.source[path] = std::move(list);
    arm();
    body = {{"breakpoints", out}};
}

void Adapter::set_function_breakpoints(const Json& args, Json& body) {
    std::vector<Breakpoint> list;
    Json out = Json::array();
    for (const Json& spec : opt_array(args, "breakpoints")) {
        Breakpoint b;
        b.id = bps_.next_id++;
        b.name = need_string(spec, "name");
        read_options(spec, b);
        list.push_back(std::move(b));
    }
    bps_.function = std::move(list);
    resolve_breakpoints();
    for (Breakpoint& b : bps_.function) {
        if (b.verified) check_options(b);
        Json j = breakpoint_json(b, {});
        if (b.verified) {
            if (const auto line = session_->debugger().program().line_of(b.addresses.front())) {
                j["source"] = source_of(line->file);
                j["line"] = line->line - (lines_start_at_1_ ? 0 : 1);
            }
        }
        out.push_back(std::move(j));
    }
    arm();
    body = {{"breakpoints", out}};
}

void Adapter::set_instruction_breakpoints(const Json& args, Json& body) {
    std::vector<Breakpoint> list;
    Json out = Json::array();
    for (const Json& spec : opt_array(args, "breakpoints")) {
        Breakpoint b;
        b.id = bps_.next_id++;
        b.name = need_string(spec, "instructionReference");
        read_options(spec, b);
        try {
            const auto a = static_cast<std::uint16_t>(address_of(b.name) + opt_int(spec, "offset").value_or(0));
            b.addresses = {a};
            b.verified = check_options(b);
        } catch (const RequestError& e) {
            b.message = e.what();
        }
        out.push_back(breakpoint_json(b, {}));
        list.push_back(std::move(b));
    }
    bps_.instruction = std::move(list);
    arm();
    body = {{"breakpoints", out}};
}

void Adapter::set_exception_breakpoints(const Json& args, Json&) {
    bool runaway = false;
    for (const Json& f : opt_array(args, "filters")) {
        if (!f.is_string()) throw RequestError("argument 'filters' must hold strings");
        if (f == "runaway") runaway = true;
        else throw RequestError(fmt::format("no exception filter '{}' (there is \"runaway\")", f.get<std::string>()));
    }
    config_.stop_on_runaway = runaway;
    runaway_armed_ = runaway;
}

void Adapter::data_breakpoint_info(const Json& args, Json& body) {
    const std::string name = need_string(args, "name");
    const auto ref = opt_int(args, "variablesReference");
    const auto target = data_target(name, ref.value_or(0));
    if (!target) {
        body = {{"dataId", nullptr}, {"description", fmt::format("'{}' is not in memory: only memory can be watched", name)}};
        return;
    }
    body = {{"dataId", data_id(target->first, target->second)},
            {"description", fmt::format("{} ({:04X}H, {} byte{})", name, target->first, target->second,
                                        target->second == 1 ? "" : "s")},
            {"accessTypes", Json::array({"readWrite"})},
            {"canPersist", true}};
}

void Adapter::set_data_breakpoints(const Json& args, Json& body) {
    std::vector<DataBreakpoint> list;
    Json out = Json::array();
    for (const Json& spec : opt_array(args, "breakpoints")) {
        DataBreakpoint d;
        d.id = bps_.next_id++;
        d.data_id = need_string(spec, "dataId");
        d.access = opt_string(spec, "accessType").value_or("readWrite");
        d.hit_condition = opt_string(spec, "hitCondition").value_or("");
        d.condition = opt_string(spec, "condition").value_or("");
        const auto parsed = parse_data_id(d.data_id);
        if (!parsed) d.message = fmt::format("'{}' is not a dataId that dataBreakpointInfo gave", d.data_id);
        else if (d.access != "readWrite") d.message = "only readWrite (any access) is watched until the debugger engine (issue #15)";
        else if (!d.condition.empty()) d.message = "conditions need the debugger engine's expressions (issue #15)";
        else if (!d.hit_condition.empty() && !hit_condition_met(d.hit_condition, 0)) d.message = "a hit condition is N, ==N, >=N, >N, <N, <=N or %N";
        else {
            d.address = parsed->first;
            d.length = parsed->second;
            d.verified = true;
        }
        Json j = {{"id", d.id}, {"verified", d.verified}};
        if (!d.message.empty()) j["message"] = d.message;
        out.push_back(std::move(j));
        list.push_back(std::move(d));
    }
    bps_.data = std::move(list);
    arm();
    body = {{"breakpoints", out}};
}

void Adapter::breakpoint_locations(const Json& args, Json& body) {
    const std::string path = need_string(opt_object(args, "source"), "path");
    const int base = lines_start_at_1_ ? 0 : 1;
    const int line = static_cast<int>(need_int(args, "line")) + base;
    const int end = std::min(static_cast<int>(opt_int(args, "endLine").value_or(line - base)) + base, line + 10000);
    Json out = Json::array();
    if (session_) {
        const SymbolTable& t = session_->debugger().program();
        for (int l = line; l <= end; ++l)
            if (!t.addresses_of(canonical(path), l).empty()) out.push_back({{"line", l - base}});
    }
    body = {{"breakpoints", out}};
}

bool Adapter::stop_at_breakpoint(std::uint16_t pc, std::vector<int>& ids) {
    bool stop = false;
    for (Breakpoint* b : bps_.at(pc)) {
        ++b->hits;
        if (!b->hit_condition.empty() && !hit_condition_met(b->hit_condition, b->hits).value_or(false)) continue;
        if (!b->log_message.empty()) {
            output("console", interpolate(b->log_message));
            continue;
        }
        stop = true;
        ids.push_back(b->id);
    }
    return stop;
}

bool Adapter::stop_at_data(std::uint16_t address, std::vector<int>& ids) {
    bool stop = false;
    for (DataBreakpoint* d : bps_.data_at(address)) {
        ++d->hits;
        if (!d->hit_condition.empty() && !hit_condition_met(d->hit_condition, d->hits).value_or(false)) continue;
        stop = true;
        ids.push_back(d->id);
    }
    return stop;
}

}  // namespace alp85::dap
