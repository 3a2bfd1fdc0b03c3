// setBreakpoints and its kin: every breakpoint bound through the assembler's line map and
// symbols, answered with where it really is.
#include <filesystem>
#include <functional>

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
        for (Breakpoint& b : list) {
            resolve(b, path);
            if (b.verified) check_options(b);
        }
    const SymbolTable* symbols = session_ ? &session_->debugger().program() : nullptr;
    for (Breakpoint& b : bps_.function) {
        b.addresses.clear();
        const auto v = symbols ? symbols->value_of(b.name) : std::nullopt;
        b.verified = v.has_value();
        if (v) b.addresses = {*v};
        b.message = v ? "" : fmt::format("no symbol '{}' in the loaded programs", b.name);
        if (b.verified) check_options(b);
    }
    for (Breakpoint& b : bps_.instruction) b.verified = !b.addresses.empty();
    arm();
}

// The Debugger's own breakpoints and watchpoints stand for the client's: conditions, hit
// conditions and log points are theirs, so a run (forward or back) stops where the client asked,
// counted once. Hit counts survive re-arming. Points made in the debug console are left alone.
void Adapter::arm() {
    if (!session_) return;
    debug::Debugger& d = session_->debugger();
    std::map<std::pair<int, std::uint16_t>, unsigned> hits;  // (DAP id, address) -> hits so far
    for (const int n : engine_points_) {
        if (const debug::Breakpoint* b = d.breakpoint(n)) hits[{engine_to_dap_[n], b->address}] = b->hits;
        else if (const debug::Watchpoint* w = d.watchpoint(n)) hits[{engine_to_dap_[n], w->first}] = w->hits;
        d.remove(n);
    }
    engine_points_.clear();
    engine_to_dap_.clear();
    auto keep = [&](int number, int id, std::uint16_t at, const std::string& condition, const std::string& hit,
                    const std::string& log) {
        if (number == 0) return;
        int col = 0;
        if (!condition.empty()) d.set_condition(number, condition, col);
        if (!hit.empty()) d.set_hit_condition(number, hit);
        if (!log.empty()) d.set_log_message(number, log);
        if (const auto it = hits.find({id, at}); it != hits.end()) d.set_hits(number, it->second);
        engine_points_.push_back(number);
        engine_to_dap_[number] = id;
    };
    auto add = [&](const std::vector<Breakpoint>& list) {
        for (const Breakpoint& b : list)
            if (b.verified)
                for (const std::uint16_t a : b.addresses)
                    keep(d.add_breakpoint_at(a).number, b.id, a, b.condition, b.hit_condition, b.log_message);
    };
    for (const auto& [path, list] : bps_.source) add(list);
    add(bps_.function);
    add(bps_.instruction);
    for (const DataBreakpoint& x : bps_.data) {
        if (!x.verified) continue;
        debug::WatchSpec spec;
        spec.kind = x.access == "read" ? debug::WatchKind::Read
                    : x.access == "write" ? debug::WatchKind::Write
                                          : debug::WatchKind::Access;
        spec.first = x.address;
        spec.last = static_cast<std::uint16_t>(x.address + x.length - 1);
        spec.what = x.what;
        keep(d.add_watchpoint(spec).number, x.id, x.address, x.condition, x.hit_condition, {});
    }
}

namespace {

// One object of a request's `breakpoints`: a fresh id from `next_id`, where it is (`read_where`:
// its line, function or instruction), then the options every kind shares; a hit condition that is
// none of DAP's forms is refused here.
Breakpoint new_breakpoint(const Json& spec, int& next_id, const std::function<void(Breakpoint&)>& read_where) {
    Breakpoint b;
    b.id = next_id++;
    read_where(b);
    b.condition = opt_string(spec, "condition").value_or("");
    b.hit_condition = opt_string(spec, "hitCondition").value_or("");
    b.log_message = opt_string(spec, "logMessage").value_or("");
    return b;
}

// A condition is the debugger's expression (docs/debugging.md): "" or why it is not one.
std::string condition_error(const debug::Debugger& d, const std::string& condition) {
    if (condition.empty()) return {};
    debug::ExprError err;
    if (debug::Expr::parse(condition, d.program(), err, debug::Expr::Names::RegistersFirst, 0, &d.variables())) return {};
    return fmt::format("condition '{}': {} (column {})", condition, err.message, err.col);
}

std::string hit_condition_error(const std::string& hit) {
    if (hit.empty() || debug::HitCondition::parse(hit)) return {};
    return fmt::format("hit condition '{}' is not N, ==N, >=N, >N, <N, <=N or %N", hit);
}

}  // namespace

bool Adapter::check_options(Breakpoint& b) {
    std::string why = hit_condition_error(b.hit_condition);
    if (why.empty() && session_) why = condition_error(session_->debugger(), b.condition);
    if (why.empty()) return true;
    b.verified = false;
    b.message = why;
    return false;
}

void Adapter::set_breakpoints(const Json& args, Json& body) {
    const Json& src = opt_object(args, "source");
    const std::string path = need_string(src, "path");
    std::vector<Breakpoint> list;
    for (const Json& spec : opt_objects(args, "breakpoints")) {
        Breakpoint b = new_breakpoint(spec, bps_.next_id,
                                      [&](Breakpoint& n) { n.line = need_line(spec, "line", lines_start_at_1_); });
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
    for (const Json& spec : opt_objects(args, "breakpoints"))
        list.push_back(new_breakpoint(spec, bps_.next_id, [&](Breakpoint& b) { b.name = need_string(spec, "name"); }));
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
    for (const Json& spec : opt_objects(args, "breakpoints")) {
        Breakpoint b = new_breakpoint(spec, bps_.next_id,
                                      [&](Breakpoint& n) { n.name = need_string(spec, "instructionReference"); });
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
    if (session_) session_->debugger().set_runaway_guard(runaway ? &map_.code : nullptr);
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
            {"accessTypes", Json::array({"write", "read", "readWrite"})},
            {"canPersist", true}};
}

void Adapter::set_data_breakpoints(const Json& args, Json& body) {
    std::vector<DataBreakpoint> list;
    Json out = Json::array();
    for (const Json& spec : opt_objects(args, "breakpoints")) {
        DataBreakpoint d;
        d.id = bps_.next_id++;
        d.data_id = need_string(spec, "dataId");
        d.access = opt_string(spec, "accessType").value_or("readWrite");
        d.hit_condition = opt_string(spec, "hitCondition").value_or("");
        d.condition = opt_string(spec, "condition").value_or("");
        const auto parsed = parse_data_id(d.data_id);
        if (!parsed) d.message = fmt::format("'{}' is not a dataId that dataBreakpointInfo gave", d.data_id);
        else if (d.access != "read" && d.access != "write" && d.access != "readWrite")
            d.message = fmt::format("accessType '{}' is not read, write or readWrite", d.access);
        else if (!session_) d.message = "no program yet: send 'launch' first";
        else if (const std::string why = condition_error(session_->debugger(), d.condition); !why.empty()) d.message = why;
        else if (const std::string why2 = hit_condition_error(d.hit_condition); !why2.empty()) d.message = why2;
        else {
            const auto name = session_->debugger().program().name_at(parsed->first);
            d.what = fmt::format("{} ({:04X}H)", name.value_or(fmt::format("{:04X}H", parsed->first)), parsed->first);
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
    const int line = need_line(args, "line", lines_start_at_1_);
    const int end = args.contains("endLine") ? std::min(need_line(args, "endLine", lines_start_at_1_), line + 10000) : line;
    Json out = Json::array();
    if (session_) {
        const SymbolTable& t = session_->debugger().program();
        for (int l = line; l <= end; ++l)
            if (!t.addresses_of(canonical(path), l).empty()) out.push_back({{"line", l - base}});
    }
    body = {{"breakpoints", out}};
}

}  // namespace alp85::dap
