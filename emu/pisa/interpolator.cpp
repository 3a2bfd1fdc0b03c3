// The instruction set of pisa_isa.h executed on excess-three words, with the step counts of the
// timing model.
#include "emu/pisa/interpolator.h"

#include <algorithm>

#include <fmt/format.h>

namespace alp85::pisa {

Interpolator::Interpolator(std::vector<std::uint32_t> rom) {
    load_rom(std::move(rom));
    reset();
}

void Interpolator::load_rom(std::vector<std::uint32_t> rom) {
    // Packages of 64 words: the last one is fitted whole (unprogrammed words read 0, "ADD 0,0,0").
    std::size_t n = (rom.size() + kRomPackage - 1) / kRomPackage * kRomPackage;
    if (n > static_cast<std::size_t>(kRomMax)) n = kRomMax;
    rom.resize(n, 0);
    for (auto& w : rom) w &= kWordMask;
    rom_ = std::move(rom);
}

void Interpolator::reset() {
    rwm_.fill(Word{});
    ind_.fill(false);
    out_.fill(Word{});
    for (auto& c : in_) c.fill(0);
    reader_.reset();
    pc_ = 0;
    now_ = 0;
    executed_ = 0;
    idle_ = 0;
    next_tick_ = ~std::uint64_t{0};
    fault_.reset();
}

void Interpolator::sync() {
    while (now_ >= next_tick_) {
        ind_[kClk] = true;
        next_tick_ += kClockSteps;
    }
    reader_.advance(now_);
}

bool Interpolator::indicator(int s) const {
    switch (s & 63) {
        case kRdr: return reader_.flag();
        case kRun: return reader_.running();
        case kEot: return reader_.at_end();
        default: return ind_[static_cast<std::size_t>(s & 63)];
    }
}

void Interpolator::set_indicator(int s, bool v) {
    switch (s & 63) {
        case kClk:
            // SET starts the time base: a tick every 6 ms from now (§4: "sensed and started as an
            // indicator"); either way the flag is lowered.
            if (v) next_tick_ = now_ + kClockSteps;
            ind_[kClk] = false;
            break;
        case kRdr:
            if (!v) reader_.reset_flag();
            break;
        case kRun:
            if (v) reader_.start(now_);
            else reader_.stop();
            break;
        case kEot: break;  // the reader's own
        default: ind_[static_cast<std::size_t>(s & 63)] = v;
    }
}

void Interpolator::step() {
    if (fault_ || ind_[kEnd]) return;
    sync();
    if (pc_ >= rom_.size()) {
        fault_ = fmt::format("instruction fetched from {:04d}, beyond the fitted ROM ({} words)", pc_, rom_.size());
        return;
    }
    std::uint32_t w = rom_[pc_];
    bool idle = pc_ >= idle_first_ && pc_ <= idle_last_;
    std::uint64_t t0 = now_;
    pc_ = static_cast<std::uint16_t>((pc_ + 1) & 4095);
    exec(w);
    ++executed_;
    if (idle) idle_ += now_ - t0;
}

bool Interpolator::skip_wait(std::uint64_t limit) {
    // "L: TRS F,S / JMP L" with S low changes nothing but time until the next event that can
    // raise S (a clock tick, the reader's flag): whole turns of the loop are counted at once, so
    // time, instruction counts and the turn in which S is seen are exactly those of stepping.
    if (pc_ + 1u >= rom_.size()) return false;
    Fields a = unpack(rom_[pc_]), b = unpack(rom_[pc_ + 1u]);
    if (a.op != Op::TRS || b.op != Op::JMP || b.f() != pc_ || indicator(a.a)) return false;
    if (a.a != kClk && a.a != kRdr) return false;
    std::uint64_t event = a.a == kClk ? next_tick_ : reader_.next_event();
    if (event == ~std::uint64_t{0}) event = limit;
    constexpr std::uint64_t turn = steps(Op::TRS) + steps(Op::JMP);
    if (event <= now_ + turn) return false;
    std::uint64_t turns = (std::min(event, limit) - now_ - 1) / turn;
    if (turns == 0) return false;
    bool idle = pc_ >= idle_first_ && pc_ <= idle_last_;
    now_ += turns * turn;
    executed_ += 2 * turns;
    if (idle) idle_ += turns * turn;
    return true;
}

Stop Interpolator::run(std::uint64_t max_steps) {
    std::uint64_t limit = now_ + max_steps;
    while (!ind_[kEnd] && !fault_ && now_ < limit) {
        if (!skip_wait(limit)) step();
    }
    if (fault_) return {StopReason::Fault, *fault_};
    if (ind_[kEnd]) return {StopReason::End, {}};
    return {StopReason::StepLimit, {}};
}

void Interpolator::exec(std::uint32_t word) {
    Fields f = unpack(word);
    auto& A = rwm_[f.a];
    const Word& B = rwm_[f.b];
    Word& C = rwm_[f.c];
    std::uint64_t cost = static_cast<std::uint64_t>(steps(f.op));
    switch (f.op) {
        case Op::ADD: {
            auto r = add(A, B);
            if (r.overflow) ind_[kOvf] = true;
            C = r.sum;
            break;
        }
        case Op::SUB: {
            auto r = sub(B, A);
            if (r.overflow) ind_[kOvf] = true;
            C = r.sum;
            break;
        }
        case Op::ADS: {
            auto r = rwm_[kAdsSign].negative() ? sub(B, A) : add(A, B);
            if (r.overflow) ind_[kOvf] = true;
            C = r.sum;
            break;
        }
        case Op::MOD: {
            bool neg = A.negative() != B.negative();
            C.cell[7] = static_cast<std::uint8_t>((C.cell[7] & 7u) | (neg ? 8u : 0u));
            break;
        }
        case Op::ABS: {
            if (A.negative()) {
                auto r = sub(Word{}, A);
                if (r.overflow) ind_[kOvf] = true;  // |-50 000 000| does not fit
                C = r.sum;
            } else {
                C = A;
            }
            break;
        }
        case Op::MOV: C = A; break;
        case Op::SHF: {
            unsigned n = f.b & 15u;
            if (f.b & kShiftRight) {
                C = shift_right(A, n);
            } else {
                bool ovf = false;
                C = shift_left(A, n, ovf);
                if (ovf) ind_[kOvf] = true;
            }
            break;
        }
        case Op::STO: {
            std::uint16_t c = f.f();
            A = Word{};
            A.cell[0] = static_cast<std::uint8_t>(c & 15u);
            A.cell[1] = static_cast<std::uint8_t>((c >> 4) & 15u);
            A.cell[2] = static_cast<std::uint8_t>((c >> 8) & 15u);
            break;
        }
        case Op::JMP: pc_ = f.f(); break;
        case Op::JMI:
            pc_ = static_cast<std::uint16_t>(A.cell[0] | (A.cell[1] << 4) | (A.cell[2] << 8));
            break;
        case Op::TZE: if (A.zero()) pc_ = f.f(); break;
        case Op::TPL: if (!A.negative()) pc_ = f.f(); break;
        case Op::TRS: if (indicator(f.a)) pc_ = f.f(); break;
        case Op::SRI: set_indicator(f.a, (f.c & 1u) != 0); break;
        case Op::IN: {
            unsigned n = f.c < 1 ? 1 : f.c > 8 ? 8 : f.c;
            cost = static_cast<std::uint64_t>(steps(f.op, n));
            const auto& src = f.b == 0 ? reader_.buffer() : in_[f.b];
            Word w;  // the digits above the n transferred are cleared
            // Code conversion, external BCD to excess-three: + 3 (a code above 9 stays as the
            // adder gives it, modulo 16).
            for (unsigned i = 0; i < n; ++i) w.cell[i] = static_cast<std::uint8_t>((src[i] + 3) & 15u);
            A = w;
            break;
        }
        case Op::OUT: {
            unsigned n = f.c < 1 ? 1 : f.c > 8 ? 8 : f.c;
            cost = static_cast<std::uint64_t>(steps(f.op, n));
            Word& reg = out_[f.b];
            for (unsigned i = 0; i < n; ++i) reg.cell[i] = A.cell[i];
            now_ += cost;
            if (on_output_) on_output_(f.b, reg, now_);
            return;
        }
    }
    now_ += cost;
}

}  // namespace alp85::pisa
