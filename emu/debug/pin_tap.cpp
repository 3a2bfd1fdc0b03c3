#include "emu/debug/pin_tap.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "emu/util/text.h"

namespace alp85::debug {

namespace {

// The 8085 (nullptr), then every part: the sources of pins, in the order a recording lists them.
template <class Fn>
void for_each_pin_source(const Machine& m, Fn fn) {
    fn(static_cast<periph::Part*>(nullptr));
    for (periph::Part* p : m.parts()) fn(p);
}

void read_source_pins(const Machine& m, periph::Part* part, periph::Pins& pins, std::uint64_t t) {
    if (part)
        part->pins(pins, t);
    else
        m.cpu_pins(pins);
}

}  // namespace

bool PinTap::selects(const std::string& word, const PinName& pin) {
    const std::string w = to_upper(word), s = to_upper(pin.scope), n = to_upper(pin.name);
    return w == n || w == s || w == s + "." + n;
}

std::vector<PinTap::PinName> PinTap::pin_names(const Machine& machine) {
    std::vector<PinName> out;
    for_each_pin_source(machine, [&](periph::Part* part) {
        periph::Pins pins;
        read_source_pins(machine, part, pins, machine.now());
        for (const auto& p : pins.list()) out.push_back({p.scope, p.name, p.kind == periph::Pins::Kind::Real, p.exact});
    });
    return out;
}

std::string PinTap::check_selection(const Machine& machine, const std::vector<std::string>& selection) {
    const std::vector<PinName> all = pin_names(machine);
    for (const std::string& w : selection) {
        if (std::none_of(all.begin(), all.end(), [&](const PinName& p) { return selects(w, p); })) {
            std::vector<std::string> seen;
            std::string scopes;
            for (const PinName& p : all) {
                if (std::find(seen.begin(), seen.end(), p.scope) != seen.end()) continue;
                seen.push_back(p.scope);
                scopes += (scopes.empty() ? "" : ", ") + p.scope;
            }
            return fmt::format("no pin '{}' on the board (a pin such as PA0, 8155.PA0 or X.PULSE, or a whole part: {}; "
                               "docs/signals.md lists them)",
                               w, scopes);
        }
    }
    return {};
}

void PinTap::attach(Machine& machine, const std::vector<std::string>& selection, std::uint64_t period) {
    if (const std::string why = check_selection(machine, selection); !why.empty()) throw std::runtime_error(why);
    sources_.clear();
    channels_.clear();
    period_ = std::max<std::uint64_t>(period, 1);
    sampled_ = false;
    const std::uint64_t t = machine.now();
    // Parts catch up first: what is read at `t` is what the board shows at t.
    for (periph::Part* p : machine.parts()) p->advance(std::max(t, p->now()));
    for_each_pin_source(machine, [&](periph::Part* part) {
        Source s;
        s.part = part;
        s.first = channels_.size();
        read_source_pins(machine, part, s.pins, t);
        s.pins.set_naming(false);
        for (std::size_t i = 0; i < s.pins.size(); ++i) {
            const auto& p = s.pins.list()[i];
            const PinName name{p.scope, p.name, p.kind == periph::Pins::Kind::Real, p.exact};
            const bool chosen = selection.empty() || std::any_of(selection.begin(), selection.end(),
                                                                 [&](const std::string& w) { return selects(w, name); });
            if (!chosen) continue;
            s.selected.push_back(i);
            channels_.push_back({name, s.pins.levels()[i], s.pins.reals()[i]});
            if (!p.exact) sampled_ = true;
            if (p.exact && part) s.self_timed = true;
        }
        if (!s.selected.empty()) sources_.push_back(std::move(s));
    });
    machine_ = &machine;
    rewind(t);
}

void PinTap::rewind(std::uint64_t t) { next_sample_ = (t / period_ + 1) * period_; }

const std::vector<std::size_t>& PinTap::read(std::uint64_t t) {
    changed_.clear();
    for (Source& s : sources_) {
        s.pins.set_naming(false);
        read_source_pins(*machine_, s.part, s.pins, t);
        for (std::size_t k = 0; k < s.selected.size(); ++k) {
            const std::size_t i = s.selected[k];
            Channel& c = channels_[s.first + k];
            if (c.pin.real) {
                const double v = s.pins.reals()[i];
                if (v == c.value) continue;
                c.value = v;
            } else {
                const char v = s.pins.levels()[i];
                if (v == c.level) continue;
                c.level = v;
            }
            changed_.push_back(s.first + k);
        }
    }
    if (sampled_ && t >= next_sample_) next_sample_ = (t / period_ + 1) * period_;
    return changed_;
}

std::uint64_t PinTap::next(std::uint64_t last) const {
    std::uint64_t next = sampled_ ? next_sample_ : periph::Part::kNever;
    for (const Source& s : sources_)
        if (s.self_timed) next = std::min(next, std::max(s.part->next_pin_change(last), last + 1));
    return next;
}

}  // namespace alp85::debug
