// The 8085/8080 instruction loop, interrupt logic and pins. See i8085.h for the model's scope and
// docs/cpu.md for the flag rules (documented and undocumented) and their sources.
#include "emu/core/i8085.h"

#include <array>
#include <utility>

#include "asm/isa.h"

namespace alp85 {

namespace {

using isa::F_AC;
using isa::F_CY;
using isa::F_K;
using isa::F_P;
using isa::F_S;
using isa::F_V;
using isa::F_Z;

// ---- tables built at compile time from the one opcode table ----------------------------------
template <Variant V>
constexpr std::array<std::uint8_t, 256> make_base_tstates() {
    std::array<std::uint8_t, 256> t{};
    for (unsigned i = 0; i < 256; ++i)
        t[i] = V == Variant::I8085 ? isa::kOpcodes[i].t8085 : isa::kOpcodes[i].t8080;
    return t;
}
// Extra T-states when a conditional jump, call or return is taken.
template <Variant V>
constexpr std::array<std::uint8_t, 256> make_taken_extra() {
    std::array<std::uint8_t, 256> t{};
    for (unsigned i = 0; i < 256; ++i) {
        const auto& o = isa::kOpcodes[i];
        t[i] = V == Variant::I8085 ? o.t8085_taken - o.t8085 : o.t8080_taken - o.t8080;
    }
    return t;
}
// S, Z and P of a result; on the 8080 also flag bit 1, which always reads 1.
template <Variant V>
constexpr std::array<std::uint8_t, 256> make_szp() {
    std::array<std::uint8_t, 256> t{};
    for (unsigned i = 0; i < 256; ++i) {
        unsigned ones = 0;
        for (unsigned b = 0; b < 8; ++b) ones += (i >> b) & 1;
        t[i] = static_cast<std::uint8_t>((i & 0x80 ? F_S : 0) | (i == 0 ? F_Z : 0) | (ones % 2 == 0 ? F_P : 0) |
                                         (V == Variant::I8080 ? 0x02 : 0));
    }
    return t;
}
template <Variant V>
constexpr auto kBase = make_base_tstates<V>();
// A batch runs at most kBatchTStates, so it holds fewer than 2^kCountBits instructions (each takes
// at least 4 T-states): T-states and instructions share one counter (I8085::execute).
constexpr unsigned kCountBits = 24;
constexpr std::uint64_t kBatchTStates = std::uint64_t{1} << 25;
template <Variant V>
constexpr std::array<std::int64_t, 256> make_cost() {
    std::array<std::int64_t, 256> c{};
    for (unsigned i = 0; i < 256; ++i) c[i] = (std::int64_t{kBase<V>[i]} << kCountBits) + 1;
    return c;
}
template <Variant V>
constexpr auto kCost = make_cost<V>();
template <Variant V>
constexpr auto kTaken = make_taken_extra<V>();
template <Variant V>
constexpr auto kSZP = make_szp<V>();

static_assert(kBase<Variant::I8085>[0x40] == 4 && kBase<Variant::I8080>[0x40] == 5, "MOV r,r timing");
// The countdown fast path (JNZ, execute) times every DCR r like DCR B.
template <Variant V>
constexpr bool dcr_r_timed_alike() {
    for (unsigned op : {0x0Du, 0x15u, 0x1Du, 0x25u, 0x2Du, 0x3Du})
        if (kBase<V>[op] != kBase<V>[0x05]) return false;
    return true;
}
static_assert(dcr_r_timed_alike<Variant::I8085>() && dcr_r_timed_alike<Variant::I8080>(), "DCR r timing");
// The 16-bit fast path (countdown16) times DCX rp, MOV A,r and ORA r like DCX B, MOV A,B, ORA B.
template <Variant V>
constexpr bool delay16_timed_alike() {
    for (unsigned k = 0; k < 6; ++k)
        if (kBase<V>[0x78 + k] != kBase<V>[0x78] || kBase<V>[0xB0 + k] != kBase<V>[0xB0]) return false;
    return kBase<V>[0x1B] == kBase<V>[0x0B] && kBase<V>[0x2B] == kBase<V>[0x0B];
}
static_assert(delay16_timed_alike<Variant::I8085>() && delay16_timed_alike<Variant::I8080>(), "16-bit delay timing");

// ---- flag arithmetic ---------------------------------------------------------------------------
// V (8085, bit 1) = carry into bit 7 XOR carry out of bit 7, i.e. two's-complement overflow.
// K (8085, bit 5) = V XOR S after 8-bit arithmetic.
constexpr std::uint8_t vk_from_overflow(unsigned overflow80, unsigned r) {
    return static_cast<std::uint8_t>((overflow80 >> 6) | (((overflow80 ^ r) & 0x80) >> 2));
}

template <Variant V>
[[gnu::always_inline]] inline void alu_add(std::uint8_t& a, std::uint8_t& f, unsigned x, unsigned cin) {
    const unsigned r = a + x + cin;
    std::uint8_t fl = kSZP<V>[r & 0xFF] | ((r >> 8) & F_CY) | ((a ^ x ^ r) & F_AC);
    if constexpr (V == Variant::I8085) fl |= vk_from_overflow((a ^ r) & (x ^ r) & 0x80, r);
    f = fl;
    a = static_cast<std::uint8_t>(r);
}

// Subtraction is A + ~x + (1 - borrow) in the ALU: CY is the inverted carry (a borrow), AC the
// carry out of bit 3 of that addition.
template <Variant V>
[[gnu::always_inline]] inline std::uint8_t flags_sub(unsigned a, unsigned x, unsigned r) {
    std::uint8_t fl = kSZP<V>[r & 0xFF] | ((r >> 8) & F_CY) | (~(a ^ x ^ r) & F_AC);
    if constexpr (V == Variant::I8085) fl |= vk_from_overflow((a ^ x) & (a ^ r) & 0x80, r);
    return fl;
}

template <Variant V>
[[gnu::always_inline]] inline void alu_sub(std::uint8_t& a, std::uint8_t& f, unsigned x, unsigned bin) {
    const unsigned r = a - x - bin;
    f = flags_sub<V>(a, x, r);
    a = static_cast<std::uint8_t>(r);
}

template <Variant V>
[[gnu::always_inline]] inline void alu_cmp(std::uint8_t a, std::uint8_t& f, unsigned x) {
    f = flags_sub<V>(a, x, a - x);
}

// ANA: the 8085 always sets AC; the 8080 sets it to bit 3 of (A OR operand). CY cleared.
template <Variant V>
[[gnu::always_inline]] inline void alu_ana(std::uint8_t& a, std::uint8_t& f, unsigned x) {
    const unsigned ac = V == Variant::I8085 ? unsigned{F_AC} : ((a | x) & 0x08) << 1;
    a = static_cast<std::uint8_t>(a & x);
    f = static_cast<std::uint8_t>(kSZP<V>[a] | ac);
}

// INR/DCR leave CY alone. AC: carry out of bit 3 (DCR adds FFH). On the 8085 they set V and K
// like any ALU addition of +1/-1: V only for 7FH+1 and 80H-1.
template <Variant V>
[[gnu::always_inline]] inline std::uint8_t inr(std::uint8_t x, std::uint8_t& f) {
    const std::uint8_t r = static_cast<std::uint8_t>(x + 1);
    std::uint8_t fl = static_cast<std::uint8_t>((f & F_CY) | kSZP<V>[r] | ((r & 0x0F) == 0 ? F_AC : 0));
    if constexpr (V == Variant::I8085) fl |= vk_from_overflow(x == 0x7F ? 0x80 : 0, r);
    f = fl;
    return r;
}

template <Variant V>
[[gnu::always_inline]] inline std::uint8_t dcr(std::uint8_t x, std::uint8_t& f) {
    const std::uint8_t r = static_cast<std::uint8_t>(x - 1);
    std::uint8_t fl = static_cast<std::uint8_t>((f & F_CY) | kSZP<V>[r] | ((x & 0x0F) != 0 ? F_AC : 0));
    if constexpr (V == Variant::I8085) fl |= vk_from_overflow(x == 0x80 ? 0x80 : 0, r);
    f = fl;
    return r;
}

// DAA: add 06H if the low digit is above 9 or AC is set, 60H if A is above 99H or CY is set.
// CY is set by the second correction (never cleared); AC is the carry out of bit 3 of the add.
template <Variant V>
[[gnu::always_inline]] inline void daa(std::uint8_t& a, std::uint8_t& f) {
    unsigned corr = 0;
    unsigned cy = f & F_CY;
    if ((a & 0x0F) > 9 || (f & F_AC)) corr |= 0x06;
    if (a > 0x99 || cy) {
        corr |= 0x60;
        cy = F_CY;
    }
    const unsigned r = a + corr;
    std::uint8_t fl = static_cast<std::uint8_t>(kSZP<V>[r & 0xFF] | cy | ((a ^ corr ^ r) & F_AC));
    if constexpr (V == Variant::I8085) fl |= vk_from_overflow((a ^ r) & (corr ^ r) & 0x80, r);
    f = fl;
    a = static_cast<std::uint8_t>(r);
}

// DSUB (8085, undocumented): HL = HL - BC. The ALU does it as SUB L,C then SBB H,B, so S, P, AC,
// CY, V and K come from the high byte; Z reflects the whole 16-bit result.
inline void dsub(std::uint8_t& h, std::uint8_t& l, std::uint8_t b, std::uint8_t c, std::uint8_t& f) {
    const unsigned lo = static_cast<unsigned>(l) - c;
    const unsigned hi = static_cast<unsigned>(h) - b - ((lo >> 8) & 1);
    std::uint8_t fl = flags_sub<Variant::I8085>(h, b, hi);
    fl = static_cast<std::uint8_t>((fl & ~F_Z) | (((hi | lo) & 0xFF) == 0 ? F_Z : 0));
    f = fl;
    h = static_cast<std::uint8_t>(hi);
    l = static_cast<std::uint8_t>(lo);
}

}  // namespace

I8085::I8085(Bus& bus, Variant variant) : bus_(bus), variant_(variant) {
    r_.f = variant == Variant::I8080 ? 0x02 : 0x00;
    reset();
}

void I8085::reset() {
    r_.pc = 0;
    ie_ = false;
    ei_delay_ = false;
    trap_rim_ = false;
    halted_ = false;
    masks_ = 0x07;
    rst75_latch_ = false;
    trap_latch_ = false;
    if (sod_) {
        sod_ = false;
        if (on_sod) on_sod(false);
    }
}

std::uint8_t I8085::slow_read(std::uint16_t addr, std::uint64_t t) {
    t_ = t;
    return bus_.read(addr, t);
}

void I8085::slow_write(std::uint16_t addr, std::uint8_t value, std::uint64_t t) {
    t_ = t;
    bus_.write(addr, value, t);
}

// A handler that changes the memory map ends the batch: the next one picks the flat or paged loop.
std::uint8_t I8085::io_in(std::uint8_t port, std::uint64_t t) {
    const std::uint64_t maps = bus_.map_changes();
    const std::uint8_t v = bus_.in(port, t);
    if (bus_.map_changes() != maps) request_stop_batch();
    return v;
}
void I8085::io_out(std::uint8_t port, std::uint8_t value, std::uint64_t t) {
    const std::uint64_t maps = bus_.map_changes();
    bus_.out(port, value, t);
    if (bus_.map_changes() != maps) request_stop_batch();
}

void I8085::halt_entered() {
    halted_ = true;
    if (on_halt) on_halt();
}

// ---- the instruction loop ------------------------------------------------------------------------
// Registers live in locals for the whole batch; they are written back at its end and around the
// debug hooks. Memory: the page table's direct pointers, with a call only for device, ROM-write
// and unmapped-write pages. The T-state counter is advanced by the opcode's base T-states before
// its body runs (plus the extra of a taken condition), so a handler called from the body sees
// t - 3 = the first T-state of the instruction's last machine cycle (see tstates()).
template <Variant V, bool Debug, bool Flat, bool Fence>
void I8085::execute() {
    constexpr bool k85 = V == Variant::I8085;
    const std::uint8_t* const* const rp = bus_.read_pages();
    std::uint8_t* const* const wp = bus_.write_pages();
    std::uint8_t* const mem = bus_.flat_ram();  // Flat: all 64 KiB plain RAM in one block
    std::uint8_t a = r_.a, f = r_.f, b = r_.b, c = r_.c, d = r_.d, e = r_.e, h = r_.h, l = r_.l;
    std::uint16_t sp = r_.sp, pc = r_.pc;
    // One counter for T-states and instructions, counting down to the batch's end:
    //   rem = (L - T) * 2^kCountBits - N
    // with T the T-states and N the instructions run in this batch (N < 2^kCountBits, as a batch is
    // at most kBatchTStates long and every instruction takes at least 4 T-states) and L the
    // batch's limit, both from t0. rem <= 0 exactly when T >= L. One table entry per opcode adds
    // its T-states and one instruction at once (kCost).
    const std::uint64_t t0 = t_, n0 = instructions_;
    std::int64_t stop = 0, rem = 0;
    const auto limit_rel = [t0](std::uint64_t lim) -> std::int64_t {
        if (lim <= t0) return 0;
        const std::uint64_t d = lim - t0;
        return static_cast<std::int64_t>(d < kBatchTStates ? d : kBatchTStates) << kCountBits;
    };
    stop = limit_rel(limit_);
    rem = stop;
    std::uint8_t op = 0;
    // Fence: the fenced addresses, and the address of the instruction running (for fence_previous).
    [[maybe_unused]] const std::bitset<0x10000>* const fence = fence_;
    [[maybe_unused]] const std::uint8_t* const* const xp = exec_pages_.data();
    [[maybe_unused]] std::uint16_t ipc = fence_prev_;

// T-states now, and the instructions run; a new limit from limit_; the batch ends after this
// instruction.
#define TNOW() (t0 + (static_cast<std::uint64_t>(stop - rem) >> kCountBits))
#define NNOW() (n0 + (static_cast<std::uint64_t>(stop - rem) & ((1u << kCountBits) - 1)))
#define ADD_T(x) (rem -= static_cast<std::int64_t>(x) << kCountBits)
#define RELIMIT()                                                          \
    do {                                                                   \
        const std::int64_t acc_ = stop - rem;                              \
        stop = limit_rel(limit_);                                          \
        rem = stop - acc_;                                                 \
    } while (0)
#define END_BATCH()                                                        \
    do {                                                                   \
        rem -= stop;                                                       \
        stop = 0;                                                          \
    } while (0)

#define HL() static_cast<std::uint16_t>((h << 8) | l)
#define BC() static_cast<std::uint16_t>((b << 8) | c)
#define DE() static_cast<std::uint16_t>((d << 8) | e)
#define SAVE_REGS()                                                                 \
    do {                                                                            \
        r_.a = a, r_.f = f, r_.b = b, r_.c = c, r_.d = d, r_.e = e, r_.h = h, r_.l = l; \
        r_.sp = sp, r_.pc = pc, t_ = TNOW(), instructions_ = NNOW();              \
    } while (0)
#define LOAD_REGS()                                                                 \
    do {                                                                            \
        a = r_.a, f = r_.f, b = r_.b, c = r_.c, d = r_.d, e = r_.e, h = r_.h, l = r_.l; \
        sp = r_.sp, pc = r_.pc;                                                     \
    } while (0)
#define SYNC(back) (t_ = TNOW() - (back))
#define FETCH_AT(addr, when)                                               \
    ({                                                                     \
        const std::uint16_t fa_ = (addr);                                  \
        std::uint8_t fv_;                                                  \
        if constexpr (Flat) {                                              \
            fv_ = mem[fa_];                                                \
        } else {                                                           \
            const std::uint8_t* const fp_ = rp[fa_ >> 8];                  \
            if (fp_) [[likely]]                                            \
                fv_ = fp_[fa_ & 0xFF];                                     \
            else {                                                         \
                fv_ = slow_read(fa_, (when));                              \
                RELIMIT();                                                 \
            }                                                              \
        }                                                                  \
        fv_;                                                               \
    })
#define FETCH(addr) FETCH_AT(addr, TNOW() - 3)
#define RDD(addr)                                                          \
    ({                                                                     \
        const std::uint16_t ra_ = (addr);                                  \
        const std::uint8_t rv_ = FETCH(ra_);                               \
        if constexpr (Debug) {                                             \
            if (hooks_) {                                                  \
                SYNC(3);                                                   \
                hooks_->on_read(*this, ra_, rv_);                          \
                RELIMIT();                                                 \
            }                                                              \
        }                                                                  \
        rv_;                                                               \
    })
#define WR(addr, val)                                                      \
    do {                                                                   \
        const std::uint16_t wa_ = (addr);                                  \
        const std::uint8_t wv_ = static_cast<std::uint8_t>(val);           \
        if constexpr (Flat) {                                              \
            mem[wa_] = wv_;                                                \
        } else {                                                           \
            std::uint8_t* const wpp_ = wp[wa_ >> 8];                       \
            if (wpp_) [[likely]]                                           \
                wpp_[wa_ & 0xFF] = wv_;                                    \
            else {                                                         \
                slow_write(wa_, wv_, TNOW() - 3);                          \
                RELIMIT();                                                 \
            }                                                              \
        }                                                                  \
        if constexpr (Debug) {                                             \
            if (hooks_) {                                                  \
                SYNC(3);                                                   \
                hooks_->on_write(*this, wa_, wv_);                         \
                RELIMIT();                                                 \
            }                                                              \
        }                                                                  \
    } while (0)
#define DBG_IO(port, value, is_out)                                        \
    do {                                                                   \
        if constexpr (Debug) {                                             \
            if (hooks_) {                                                  \
                hooks_->on_io(*this, port, value, is_out);                 \
                RELIMIT();                                                 \
            }                                                              \
        }                                                                  \
    } while (0)
#define IMM8()                                                             \
    ({                                                                     \
        const std::uint8_t iv_ = FETCH(pc);                                \
        pc = static_cast<std::uint16_t>(pc + 1);                           \
        iv_;                                                               \
    })
#define IMM16()                                                            \
    ({                                                                     \
        const std::uint8_t lo_ = FETCH(pc);                                \
        const std::uint8_t hi_ = FETCH(static_cast<std::uint16_t>(pc + 1)); \
        pc = static_cast<std::uint16_t>(pc + 2);                           \
        static_cast<std::uint16_t>((hi_ << 8) | lo_);                      \
    })
#define PUSH2(hi, lo)                                                      \
    do {                                                                   \
        const std::uint8_t ph_ = static_cast<std::uint8_t>(hi);            \
        const std::uint8_t pl_ = static_cast<std::uint8_t>(lo);            \
        WR(static_cast<std::uint16_t>(sp - 1), ph_);                       \
        WR(static_cast<std::uint16_t>(sp - 2), pl_);                       \
        sp = static_cast<std::uint16_t>(sp - 2);                           \
    } while (0)
#define POPPC()                                                            \
    do {                                                                   \
        const std::uint8_t pl_ = RDD(sp);                                  \
        const std::uint8_t ph_ = RDD(static_cast<std::uint16_t>(sp + 1));  \
        sp = static_cast<std::uint16_t>(sp + 2);                           \
        pc = static_cast<std::uint16_t>((ph_ << 8) | pl_);                 \
    } while (0)
#define NEXT()                                                             \
    do {                                                                   \
        if (rem <= 0) [[unlikely]]                                         \
            goto done;                                                     \
        if constexpr (Debug) {                                             \
            if (hooks_) {                                                  \
                SAVE_REGS();                                               \
                const bool go_ = hooks_->before_instruction(*this);        \
                LOAD_REGS();                                               \
                RELIMIT();                                                 \
                if (!go_) {                                                \
                    deadline_ = TNOW();                                    \
                    goto done;                                             \
                }                                                          \
            }                                                              \
        }                                                                  \
        if constexpr (Fence) {                                             \
            /* a page with no fenced address: no test */                   \
            const std::uint8_t* const xpg_ = xp[pc >> 8];                  \
            if (xpg_) [[likely]] {                                         \
                op = xpg_[pc & 0xFF];                                      \
            } else {                                                       \
                if ((*fence)[pc] && (pc != pass_pc_ || TNOW() != pass_t_)) [[unlikely]] { \
                    fence_prev_ = ipc;                                     \
                    fence_hit_ = true;                                     \
                    deadline_ = TNOW();                                    \
                    goto done;                                             \
                }                                                          \
                op = FETCH_AT(pc, TNOW());                                 \
            }                                                              \
            ipc = pc;                                                      \
        } else {                                                           \
            op = FETCH_AT(pc, TNOW()); /* the opcode fetch starts now */   \
        }                                                                  \
        pc = static_cast<std::uint16_t>(pc + 1);                           \
        rem -= kDispatch.cost[op];                                         \
        goto* kDispatch.label[op];                                         \
    } while (0)

    // Each opcode's body and its cost (T-states and one instruction), one base register for both.
    struct Dispatch {
        const void* label[256];
        std::int64_t cost[256];
    };
    static const Dispatch kDispatch = {
        {
        &&op_00, &&op_01, &&op_02, &&op_03, &&op_04, &&op_05, &&op_06, &&op_07,
        &&op_08, &&op_09, &&op_0A, &&op_0B, &&op_0C, &&op_0D, &&op_0E, &&op_0F,
        &&op_10, &&op_11, &&op_12, &&op_13, &&op_14, &&op_15, &&op_16, &&op_17,
        &&op_18, &&op_19, &&op_1A, &&op_1B, &&op_1C, &&op_1D, &&op_1E, &&op_1F,
        &&op_20, &&op_21, &&op_22, &&op_23, &&op_24, &&op_25, &&op_26, &&op_27,
        &&op_28, &&op_29, &&op_2A, &&op_2B, &&op_2C, &&op_2D, &&op_2E, &&op_2F,
        &&op_30, &&op_31, &&op_32, &&op_33, &&op_34, &&op_35, &&op_36, &&op_37,
        &&op_38, &&op_39, &&op_3A, &&op_3B, &&op_3C, &&op_3D, &&op_3E, &&op_3F,
        &&op_40, &&op_41, &&op_42, &&op_43, &&op_44, &&op_45, &&op_46, &&op_47,
        &&op_48, &&op_49, &&op_4A, &&op_4B, &&op_4C, &&op_4D, &&op_4E, &&op_4F,
        &&op_50, &&op_51, &&op_52, &&op_53, &&op_54, &&op_55, &&op_56, &&op_57,
        &&op_58, &&op_59, &&op_5A, &&op_5B, &&op_5C, &&op_5D, &&op_5E, &&op_5F,
        &&op_60, &&op_61, &&op_62, &&op_63, &&op_64, &&op_65, &&op_66, &&op_67,
        &&op_68, &&op_69, &&op_6A, &&op_6B, &&op_6C, &&op_6D, &&op_6E, &&op_6F,
        &&op_70, &&op_71, &&op_72, &&op_73, &&op_74, &&op_75, &&op_76, &&op_77,
        &&op_78, &&op_79, &&op_7A, &&op_7B, &&op_7C, &&op_7D, &&op_7E, &&op_7F,
        &&op_80, &&op_81, &&op_82, &&op_83, &&op_84, &&op_85, &&op_86, &&op_87,
        &&op_88, &&op_89, &&op_8A, &&op_8B, &&op_8C, &&op_8D, &&op_8E, &&op_8F,
        &&op_90, &&op_91, &&op_92, &&op_93, &&op_94, &&op_95, &&op_96, &&op_97,
        &&op_98, &&op_99, &&op_9A, &&op_9B, &&op_9C, &&op_9D, &&op_9E, &&op_9F,
        &&op_A0, &&op_A1, &&op_A2, &&op_A3, &&op_A4, &&op_A5, &&op_A6, &&op_A7,
        &&op_A8, &&op_A9, &&op_AA, &&op_AB, &&op_AC, &&op_AD, &&op_AE, &&op_AF,
        &&op_B0, &&op_B1, &&op_B2, &&op_B3, &&op_B4, &&op_B5, &&op_B6, &&op_B7,
        &&op_B8, &&op_B9, &&op_BA, &&op_BB, &&op_BC, &&op_BD, &&op_BE, &&op_BF,
        &&op_C0, &&op_C1, &&op_C2, &&op_C3, &&op_C4, &&op_C5, &&op_C6, &&op_C7,
        &&op_C8, &&op_C9, &&op_CA, &&op_CB, &&op_CC, &&op_CD, &&op_CE, &&op_CF,
        &&op_D0, &&op_D1, &&op_D2, &&op_D3, &&op_D4, &&op_D5, &&op_D6, &&op_D7,
        &&op_D8, &&op_D9, &&op_DA, &&op_DB, &&op_DC, &&op_DD, &&op_DE, &&op_DF,
        &&op_E0, &&op_E1, &&op_E2, &&op_E3, &&op_E4, &&op_E5, &&op_E6, &&op_E7,
        &&op_E8, &&op_E9, &&op_EA, &&op_EB, &&op_EC, &&op_ED, &&op_EE, &&op_EF,
        &&op_F0, &&op_F1, &&op_F2, &&op_F3, &&op_F4, &&op_F5, &&op_F6, &&op_F7,
        &&op_F8, &&op_F9, &&op_FA, &&op_FB, &&op_FC, &&op_FD, &&op_FE, &&op_FF,
    },
        {
        kCost<V>[0x00], kCost<V>[0x01], kCost<V>[0x02], kCost<V>[0x03], kCost<V>[0x04], kCost<V>[0x05], kCost<V>[0x06], kCost<V>[0x07],
        kCost<V>[0x08], kCost<V>[0x09], kCost<V>[0x0A], kCost<V>[0x0B], kCost<V>[0x0C], kCost<V>[0x0D], kCost<V>[0x0E], kCost<V>[0x0F],
        kCost<V>[0x10], kCost<V>[0x11], kCost<V>[0x12], kCost<V>[0x13], kCost<V>[0x14], kCost<V>[0x15], kCost<V>[0x16], kCost<V>[0x17],
        kCost<V>[0x18], kCost<V>[0x19], kCost<V>[0x1A], kCost<V>[0x1B], kCost<V>[0x1C], kCost<V>[0x1D], kCost<V>[0x1E], kCost<V>[0x1F],
        kCost<V>[0x20], kCost<V>[0x21], kCost<V>[0x22], kCost<V>[0x23], kCost<V>[0x24], kCost<V>[0x25], kCost<V>[0x26], kCost<V>[0x27],
        kCost<V>[0x28], kCost<V>[0x29], kCost<V>[0x2A], kCost<V>[0x2B], kCost<V>[0x2C], kCost<V>[0x2D], kCost<V>[0x2E], kCost<V>[0x2F],
        kCost<V>[0x30], kCost<V>[0x31], kCost<V>[0x32], kCost<V>[0x33], kCost<V>[0x34], kCost<V>[0x35], kCost<V>[0x36], kCost<V>[0x37],
        kCost<V>[0x38], kCost<V>[0x39], kCost<V>[0x3A], kCost<V>[0x3B], kCost<V>[0x3C], kCost<V>[0x3D], kCost<V>[0x3E], kCost<V>[0x3F],
        kCost<V>[0x40], kCost<V>[0x41], kCost<V>[0x42], kCost<V>[0x43], kCost<V>[0x44], kCost<V>[0x45], kCost<V>[0x46], kCost<V>[0x47],
        kCost<V>[0x48], kCost<V>[0x49], kCost<V>[0x4A], kCost<V>[0x4B], kCost<V>[0x4C], kCost<V>[0x4D], kCost<V>[0x4E], kCost<V>[0x4F],
        kCost<V>[0x50], kCost<V>[0x51], kCost<V>[0x52], kCost<V>[0x53], kCost<V>[0x54], kCost<V>[0x55], kCost<V>[0x56], kCost<V>[0x57],
        kCost<V>[0x58], kCost<V>[0x59], kCost<V>[0x5A], kCost<V>[0x5B], kCost<V>[0x5C], kCost<V>[0x5D], kCost<V>[0x5E], kCost<V>[0x5F],
        kCost<V>[0x60], kCost<V>[0x61], kCost<V>[0x62], kCost<V>[0x63], kCost<V>[0x64], kCost<V>[0x65], kCost<V>[0x66], kCost<V>[0x67],
        kCost<V>[0x68], kCost<V>[0x69], kCost<V>[0x6A], kCost<V>[0x6B], kCost<V>[0x6C], kCost<V>[0x6D], kCost<V>[0x6E], kCost<V>[0x6F],
        kCost<V>[0x70], kCost<V>[0x71], kCost<V>[0x72], kCost<V>[0x73], kCost<V>[0x74], kCost<V>[0x75], kCost<V>[0x76], kCost<V>[0x77],
        kCost<V>[0x78], kCost<V>[0x79], kCost<V>[0x7A], kCost<V>[0x7B], kCost<V>[0x7C], kCost<V>[0x7D], kCost<V>[0x7E], kCost<V>[0x7F],
        kCost<V>[0x80], kCost<V>[0x81], kCost<V>[0x82], kCost<V>[0x83], kCost<V>[0x84], kCost<V>[0x85], kCost<V>[0x86], kCost<V>[0x87],
        kCost<V>[0x88], kCost<V>[0x89], kCost<V>[0x8A], kCost<V>[0x8B], kCost<V>[0x8C], kCost<V>[0x8D], kCost<V>[0x8E], kCost<V>[0x8F],
        kCost<V>[0x90], kCost<V>[0x91], kCost<V>[0x92], kCost<V>[0x93], kCost<V>[0x94], kCost<V>[0x95], kCost<V>[0x96], kCost<V>[0x97],
        kCost<V>[0x98], kCost<V>[0x99], kCost<V>[0x9A], kCost<V>[0x9B], kCost<V>[0x9C], kCost<V>[0x9D], kCost<V>[0x9E], kCost<V>[0x9F],
        kCost<V>[0xA0], kCost<V>[0xA1], kCost<V>[0xA2], kCost<V>[0xA3], kCost<V>[0xA4], kCost<V>[0xA5], kCost<V>[0xA6], kCost<V>[0xA7],
        kCost<V>[0xA8], kCost<V>[0xA9], kCost<V>[0xAA], kCost<V>[0xAB], kCost<V>[0xAC], kCost<V>[0xAD], kCost<V>[0xAE], kCost<V>[0xAF],
        kCost<V>[0xB0], kCost<V>[0xB1], kCost<V>[0xB2], kCost<V>[0xB3], kCost<V>[0xB4], kCost<V>[0xB5], kCost<V>[0xB6], kCost<V>[0xB7],
        kCost<V>[0xB8], kCost<V>[0xB9], kCost<V>[0xBA], kCost<V>[0xBB], kCost<V>[0xBC], kCost<V>[0xBD], kCost<V>[0xBE], kCost<V>[0xBF],
        kCost<V>[0xC0], kCost<V>[0xC1], kCost<V>[0xC2], kCost<V>[0xC3], kCost<V>[0xC4], kCost<V>[0xC5], kCost<V>[0xC6], kCost<V>[0xC7],
        kCost<V>[0xC8], kCost<V>[0xC9], kCost<V>[0xCA], kCost<V>[0xCB], kCost<V>[0xCC], kCost<V>[0xCD], kCost<V>[0xCE], kCost<V>[0xCF],
        kCost<V>[0xD0], kCost<V>[0xD1], kCost<V>[0xD2], kCost<V>[0xD3], kCost<V>[0xD4], kCost<V>[0xD5], kCost<V>[0xD6], kCost<V>[0xD7],
        kCost<V>[0xD8], kCost<V>[0xD9], kCost<V>[0xDA], kCost<V>[0xDB], kCost<V>[0xDC], kCost<V>[0xDD], kCost<V>[0xDE], kCost<V>[0xDF],
        kCost<V>[0xE0], kCost<V>[0xE1], kCost<V>[0xE2], kCost<V>[0xE3], kCost<V>[0xE4], kCost<V>[0xE5], kCost<V>[0xE6], kCost<V>[0xE7],
        kCost<V>[0xE8], kCost<V>[0xE9], kCost<V>[0xEA], kCost<V>[0xEB], kCost<V>[0xEC], kCost<V>[0xED], kCost<V>[0xEE], kCost<V>[0xEF],
        kCost<V>[0xF0], kCost<V>[0xF1], kCost<V>[0xF2], kCost<V>[0xF3], kCost<V>[0xF4], kCost<V>[0xF5], kCost<V>[0xF6], kCost<V>[0xF7],
        kCost<V>[0xF8], kCost<V>[0xF9], kCost<V>[0xFA], kCost<V>[0xFB], kCost<V>[0xFC], kCost<V>[0xFD], kCost<V>[0xFE], kCost<V>[0xFF],
        },
    };
    NEXT();
op_00:  // NOP
    NEXT();
op_01:  // LXI B,d16
    c = IMM8(); b = IMM8();
    NEXT();
op_02:  // STAX B
    WR(BC(), a);
    NEXT();
op_03:  // INX B
    { const unsigned v = ((b << 8) | c) + 1; if constexpr (k85) f = (f & ~F_K) | ((v >> 11) & F_K); b = (v >> 8) & 0xFF; c = v & 0xFF; }
    NEXT();
op_04:  // INR B
    b = inr<V>(b, f);
    NEXT();
op_05:  // DCR B
    b = dcr<V>(b, f);
    NEXT();
op_06:  // MVI B,d8
    b = IMM8();
    NEXT();
op_07:  // RLC
    { const unsigned cy = a >> 7; a = static_cast<std::uint8_t>((a << 1) | cy); f = (f & ~F_CY) | cy; }
    NEXT();
op_08:  // DSUB / 8080: NOP
    if constexpr (k85) dsub(h, l, b, c, f);
    NEXT();
op_09:  // DAD B
    { const unsigned v = HL() + ((b << 8) | c); f = (f & ~F_CY) | (v >> 16); h = (v >> 8) & 0xFF; l = v & 0xFF; }
    NEXT();
op_0A:  // LDAX B
    a = RDD(BC());
    NEXT();
op_0B:  // DCX B
    { const unsigned v = ((b << 8) | c) - 1; if constexpr (k85) f = (f & ~F_K) | ((v >> 11) & F_K); b = (v >> 8) & 0xFF; c = v & 0xFF; }
    NEXT();
op_0C:  // INR C
    c = inr<V>(c, f);
    NEXT();
op_0D:  // DCR C
    c = dcr<V>(c, f);
    NEXT();
op_0E:  // MVI C,d8
    c = IMM8();
    NEXT();
op_0F:  // RRC
    { const unsigned cy = a & 1; a = static_cast<std::uint8_t>((a >> 1) | (cy << 7)); f = (f & ~F_CY) | cy; }
    NEXT();
op_10:  // ARHL / 8080: NOP
    if constexpr (k85) { f = (f & ~F_CY) | (l & 1); l = static_cast<std::uint8_t>((l >> 1) | (h << 7)); h = static_cast<std::uint8_t>((h >> 1) | (h & 0x80)); }
    NEXT();
op_11:  // LXI D,d16
    e = IMM8(); d = IMM8();
    NEXT();
op_12:  // STAX D
    WR(DE(), a);
    NEXT();
op_13:  // INX D
    { const unsigned v = ((d << 8) | e) + 1; if constexpr (k85) f = (f & ~F_K) | ((v >> 11) & F_K); d = (v >> 8) & 0xFF; e = v & 0xFF; }
    NEXT();
op_14:  // INR D
    d = inr<V>(d, f);
    NEXT();
op_15:  // DCR D
    d = dcr<V>(d, f);
    NEXT();
op_16:  // MVI D,d8
    d = IMM8();
    NEXT();
op_17:  // RAL
    { const unsigned cy = a >> 7; a = static_cast<std::uint8_t>((a << 1) | (f & F_CY)); f = (f & ~F_CY) | cy; }
    NEXT();
op_18:  // RDEL / 8080: NOP
    if constexpr (k85) { const unsigned de = DE(); const unsigned v = ((de >> 15) ^ (de >> 14)) & 1; d = static_cast<std::uint8_t>((d << 1) | (e >> 7)); e = static_cast<std::uint8_t>((e << 1) | (f & F_CY)); f = (f & ~(F_CY | F_V)) | (de >> 15) | (v << 1); }
    NEXT();
op_19:  // DAD D
    { const unsigned v = HL() + ((d << 8) | e); f = (f & ~F_CY) | (v >> 16); h = (v >> 8) & 0xFF; l = v & 0xFF; }
    NEXT();
op_1A:  // LDAX D
    a = RDD(DE());
    NEXT();
op_1B:  // DCX D
    { const unsigned v = ((d << 8) | e) - 1; if constexpr (k85) f = (f & ~F_K) | ((v >> 11) & F_K); d = (v >> 8) & 0xFF; e = v & 0xFF; }
    NEXT();
op_1C:  // INR E
    e = inr<V>(e, f);
    NEXT();
op_1D:  // DCR E
    e = dcr<V>(e, f);
    NEXT();
op_1E:  // MVI E,d8
    e = IMM8();
    NEXT();
op_1F:  // RAR
    { const unsigned cy = a & 1; a = static_cast<std::uint8_t>((a >> 1) | ((f & F_CY) << 7)); f = (f & ~F_CY) | cy; }
    NEXT();
op_20:  // RIM / 8080: NOP
    if constexpr (k85) a = rim();
    NEXT();
op_21:  // LXI H,d16
    l = IMM8(); h = IMM8();
    NEXT();
op_22:  // SHLD a16
    { const std::uint16_t ad = IMM16(); WR(ad, l); WR(static_cast<std::uint16_t>(ad + 1), h); }
    NEXT();
op_23:  // INX H
    { const unsigned v = ((h << 8) | l) + 1; if constexpr (k85) f = (f & ~F_K) | ((v >> 11) & F_K); h = (v >> 8) & 0xFF; l = v & 0xFF; }
    NEXT();
op_24:  // INR H
    h = inr<V>(h, f);
    NEXT();
op_25:  // DCR H
    h = dcr<V>(h, f);
    NEXT();
op_26:  // MVI H,d8
    h = IMM8();
    NEXT();
op_27:  // DAA
    daa<V>(a, f);
    NEXT();
op_28:  // LDHI d8 / 8080: NOP
    if constexpr (k85) { const unsigned v = HL() + IMM8(); d = (v >> 8) & 0xFF; e = v & 0xFF; }
    NEXT();
op_29:  // DAD H
    { const unsigned v = HL() + ((h << 8) | l); f = (f & ~F_CY) | (v >> 16); h = (v >> 8) & 0xFF; l = v & 0xFF; }
    NEXT();
op_2A:  // LHLD a16
    { const std::uint16_t ad = IMM16(); l = RDD(ad); h = RDD(static_cast<std::uint16_t>(ad + 1)); }
    NEXT();
op_2B:  // DCX H
    { const unsigned v = ((h << 8) | l) - 1; if constexpr (k85) f = (f & ~F_K) | ((v >> 11) & F_K); h = (v >> 8) & 0xFF; l = v & 0xFF; }
    NEXT();
op_2C:  // INR L
    l = inr<V>(l, f);
    NEXT();
op_2D:  // DCR L
    l = dcr<V>(l, f);
    NEXT();
op_2E:  // MVI L,d8
    l = IMM8();
    NEXT();
op_2F:  // CMA
    a = static_cast<std::uint8_t>(~a);
    NEXT();
op_30:  // SIM / 8080: NOP
    if constexpr (k85) { SYNC(0); sim(a); END_BATCH(); }
    NEXT();
op_31:  // LXI SP,d16
    sp = IMM16();
    sp_load_ = 0x10000u | sp;
    NEXT();
op_32:  // STA a16
    { const std::uint16_t ad = IMM16(); WR(ad, a); }
    NEXT();
op_33:  // INX SP
    { const unsigned v = sp + 1u; if constexpr (k85) f = (f & ~F_K) | ((v >> 11) & F_K); sp = v & 0xFFFF; }
    NEXT();
op_34:  // INR M
    { std::uint8_t v = RDD(HL()); v = inr<V>(v, f); WR(HL(), v); }
    NEXT();
op_35:  // DCR M
    { std::uint8_t v = RDD(HL()); v = dcr<V>(v, f); WR(HL(), v); }
    NEXT();
op_36:  // MVI M,d8
    { const std::uint8_t v = IMM8(); WR(HL(), v); }
    NEXT();
op_37:  // STC
    f |= F_CY;
    NEXT();
op_38:  // LDSI d8 / 8080: NOP
    if constexpr (k85) { const unsigned v = sp + IMM8(); d = (v >> 8) & 0xFF; e = v & 0xFF; }
    NEXT();
op_39:  // DAD SP
    { const unsigned v = HL() + sp; f = (f & ~F_CY) | (v >> 16); h = (v >> 8) & 0xFF; l = v & 0xFF; }
    NEXT();
op_3A:  // LDA a16
    { const std::uint16_t ad = IMM16(); a = RDD(ad); }
    NEXT();
op_3B:  // DCX SP
    { const unsigned v = sp - 1u; if constexpr (k85) f = (f & ~F_K) | ((v >> 11) & F_K); sp = v & 0xFFFF; }
    NEXT();
op_3C:  // INR A
    a = inr<V>(a, f);
    NEXT();
op_3D:  // DCR A
    a = dcr<V>(a, f);
    NEXT();
op_3E:  // MVI A,d8
    a = IMM8();
    NEXT();
op_3F:  // CMC
    f ^= F_CY;
    NEXT();
op_40:  // MOV B,B
    NEXT();
op_41:  // MOV B,C
    b = c;
    NEXT();
op_42:  // MOV B,D
    b = d;
    NEXT();
op_43:  // MOV B,E
    b = e;
    NEXT();
op_44:  // MOV B,H
    b = h;
    NEXT();
op_45:  // MOV B,L
    b = l;
    NEXT();
op_46:  // MOV B,M
    b = RDD(HL());
    NEXT();
op_47:  // MOV B,A
    b = a;
    NEXT();
op_48:  // MOV C,B
    c = b;
    NEXT();
op_49:  // MOV C,C
    NEXT();
op_4A:  // MOV C,D
    c = d;
    NEXT();
op_4B:  // MOV C,E
    c = e;
    NEXT();
op_4C:  // MOV C,H
    c = h;
    NEXT();
op_4D:  // MOV C,L
    c = l;
    NEXT();
op_4E:  // MOV C,M
    c = RDD(HL());
    NEXT();
op_4F:  // MOV C,A
    c = a;
    NEXT();
op_50:  // MOV D,B
    d = b;
    NEXT();
op_51:  // MOV D,C
    d = c;
    NEXT();
op_52:  // MOV D,D
    NEXT();
op_53:  // MOV D,E
    d = e;
    NEXT();
op_54:  // MOV D,H
    d = h;
    NEXT();
op_55:  // MOV D,L
    d = l;
    NEXT();
op_56:  // MOV D,M
    d = RDD(HL());
    NEXT();
op_57:  // MOV D,A
    d = a;
    NEXT();
op_58:  // MOV E,B
    e = b;
    NEXT();
op_59:  // MOV E,C
    e = c;
    NEXT();
op_5A:  // MOV E,D
    e = d;
    NEXT();
op_5B:  // MOV E,E
    NEXT();
op_5C:  // MOV E,H
    e = h;
    NEXT();
op_5D:  // MOV E,L
    e = l;
    NEXT();
op_5E:  // MOV E,M
    e = RDD(HL());
    NEXT();
op_5F:  // MOV E,A
    e = a;
    NEXT();
op_60:  // MOV H,B
    h = b;
    NEXT();
op_61:  // MOV H,C
    h = c;
    NEXT();
op_62:  // MOV H,D
    h = d;
    NEXT();
op_63:  // MOV H,E
    h = e;
    NEXT();
op_64:  // MOV H,H
    NEXT();
op_65:  // MOV H,L
    h = l;
    NEXT();
op_66:  // MOV H,M
    h = RDD(HL());
    NEXT();
op_67:  // MOV H,A
    h = a;
    NEXT();
op_68:  // MOV L,B
    l = b;
    NEXT();
op_69:  // MOV L,C
    l = c;
    NEXT();
op_6A:  // MOV L,D
    l = d;
    NEXT();
op_6B:  // MOV L,E
    l = e;
    NEXT();
op_6C:  // MOV L,H
    l = h;
    NEXT();
op_6D:  // MOV L,L
    NEXT();
op_6E:  // MOV L,M
    l = RDD(HL());
    NEXT();
op_6F:  // MOV L,A
    l = a;
    NEXT();
op_70:  // MOV M,B
    WR(HL(), b);
    NEXT();
op_71:  // MOV M,C
    WR(HL(), c);
    NEXT();
op_72:  // MOV M,D
    WR(HL(), d);
    NEXT();
op_73:  // MOV M,E
    WR(HL(), e);
    NEXT();
op_74:  // MOV M,H
    WR(HL(), h);
    NEXT();
op_75:  // MOV M,L
    WR(HL(), l);
    NEXT();
op_76:  // HLT
    SYNC(0); halt_entered(); END_BATCH();
    NEXT();
op_77:  // MOV M,A
    WR(HL(), a);
    NEXT();
op_78:  // MOV A,B
    a = b;
    NEXT();
op_79:  // MOV A,C
    a = c;
    NEXT();
op_7A:  // MOV A,D
    a = d;
    NEXT();
op_7B:  // MOV A,E
    a = e;
    NEXT();
op_7C:  // MOV A,H
    a = h;
    NEXT();
op_7D:  // MOV A,L
    a = l;
    NEXT();
op_7E:  // MOV A,M
    a = RDD(HL());
    NEXT();
op_7F:  // MOV A,A
    NEXT();
op_80:  // ADD B
    alu_add<V>(a, f, b, 0);
    NEXT();
op_81:  // ADD C
    alu_add<V>(a, f, c, 0);
    NEXT();
op_82:  // ADD D
    alu_add<V>(a, f, d, 0);
    NEXT();
op_83:  // ADD E
    alu_add<V>(a, f, e, 0);
    NEXT();
op_84:  // ADD H
    alu_add<V>(a, f, h, 0);
    NEXT();
op_85:  // ADD L
    alu_add<V>(a, f, l, 0);
    NEXT();
op_86:  // ADD M
    { const std::uint8_t v = RDD(HL()); alu_add<V>(a, f, v, 0); }
    NEXT();
op_87:  // ADD A
    alu_add<V>(a, f, a, 0);
    NEXT();
op_88:  // ADC B
    alu_add<V>(a, f, b, f & 1);
    NEXT();
op_89:  // ADC C
    alu_add<V>(a, f, c, f & 1);
    NEXT();
op_8A:  // ADC D
    alu_add<V>(a, f, d, f & 1);
    NEXT();
op_8B:  // ADC E
    alu_add<V>(a, f, e, f & 1);
    NEXT();
op_8C:  // ADC H
    alu_add<V>(a, f, h, f & 1);
    NEXT();
op_8D:  // ADC L
    alu_add<V>(a, f, l, f & 1);
    NEXT();
op_8E:  // ADC M
    { const std::uint8_t v = RDD(HL()); alu_add<V>(a, f, v, f & 1); }
    NEXT();
op_8F:  // ADC A
    alu_add<V>(a, f, a, f & 1);
    NEXT();
op_90:  // SUB B
    alu_sub<V>(a, f, b, 0);
    NEXT();
op_91:  // SUB C
    alu_sub<V>(a, f, c, 0);
    NEXT();
op_92:  // SUB D
    alu_sub<V>(a, f, d, 0);
    NEXT();
op_93:  // SUB E
    alu_sub<V>(a, f, e, 0);
    NEXT();
op_94:  // SUB H
    alu_sub<V>(a, f, h, 0);
    NEXT();
op_95:  // SUB L
    alu_sub<V>(a, f, l, 0);
    NEXT();
op_96:  // SUB M
    { const std::uint8_t v = RDD(HL()); alu_sub<V>(a, f, v, 0); }
    NEXT();
op_97:  // SUB A
    alu_sub<V>(a, f, a, 0);
    NEXT();
op_98:  // SBB B
    alu_sub<V>(a, f, b, f & 1);
    NEXT();
op_99:  // SBB C
    alu_sub<V>(a, f, c, f & 1);
    NEXT();
op_9A:  // SBB D
    alu_sub<V>(a, f, d, f & 1);
    NEXT();
op_9B:  // SBB E
    alu_sub<V>(a, f, e, f & 1);
    NEXT();
op_9C:  // SBB H
    alu_sub<V>(a, f, h, f & 1);
    NEXT();
op_9D:  // SBB L
    alu_sub<V>(a, f, l, f & 1);
    NEXT();
op_9E:  // SBB M
    { const std::uint8_t v = RDD(HL()); alu_sub<V>(a, f, v, f & 1); }
    NEXT();
op_9F:  // SBB A
    alu_sub<V>(a, f, a, f & 1);
    NEXT();
op_A0:  // ANA B
    alu_ana<V>(a, f, b);
    NEXT();
op_A1:  // ANA C
    alu_ana<V>(a, f, c);
    NEXT();
op_A2:  // ANA D
    alu_ana<V>(a, f, d);
    NEXT();
op_A3:  // ANA E
    alu_ana<V>(a, f, e);
    NEXT();
op_A4:  // ANA H
    alu_ana<V>(a, f, h);
    NEXT();
op_A5:  // ANA L
    alu_ana<V>(a, f, l);
    NEXT();
op_A6:  // ANA M
    { const std::uint8_t v = RDD(HL()); alu_ana<V>(a, f, v); }
    NEXT();
op_A7:  // ANA A
    alu_ana<V>(a, f, a);
    NEXT();
op_A8:  // XRA B
    a ^= b; f = kSZP<V>[a];
    NEXT();
op_A9:  // XRA C
    a ^= c; f = kSZP<V>[a];
    NEXT();
op_AA:  // XRA D
    a ^= d; f = kSZP<V>[a];
    NEXT();
op_AB:  // XRA E
    a ^= e; f = kSZP<V>[a];
    NEXT();
op_AC:  // XRA H
    a ^= h; f = kSZP<V>[a];
    NEXT();
op_AD:  // XRA L
    a ^= l; f = kSZP<V>[a];
    NEXT();
op_AE:  // XRA M
    { const std::uint8_t v = RDD(HL()); a ^= v; f = kSZP<V>[a]; }
    NEXT();
op_AF:  // XRA A
    a ^= a; f = kSZP<V>[a];
    NEXT();
op_B0:  // ORA B
    a |= b; f = kSZP<V>[a];
    NEXT();
op_B1:  // ORA C
    a |= c; f = kSZP<V>[a];
    NEXT();
op_B2:  // ORA D
    a |= d; f = kSZP<V>[a];
    NEXT();
op_B3:  // ORA E
    a |= e; f = kSZP<V>[a];
    NEXT();
op_B4:  // ORA H
    a |= h; f = kSZP<V>[a];
    NEXT();
op_B5:  // ORA L
    a |= l; f = kSZP<V>[a];
    NEXT();
op_B6:  // ORA M
    { const std::uint8_t v = RDD(HL()); a |= v; f = kSZP<V>[a]; }
    NEXT();
op_B7:  // ORA A
    f = kSZP<V>[a];  // A OR A = A
    NEXT();
op_B8:  // CMP B
    alu_cmp<V>(a, f, b);
    NEXT();
op_B9:  // CMP C
    alu_cmp<V>(a, f, c);
    NEXT();
op_BA:  // CMP D
    alu_cmp<V>(a, f, d);
    NEXT();
op_BB:  // CMP E
    alu_cmp<V>(a, f, e);
    NEXT();
op_BC:  // CMP H
    alu_cmp<V>(a, f, h);
    NEXT();
op_BD:  // CMP L
    alu_cmp<V>(a, f, l);
    NEXT();
op_BE:  // CMP M
    { const std::uint8_t v = RDD(HL()); alu_cmp<V>(a, f, v); }
    NEXT();
op_BF:  // CMP A
    alu_cmp<V>(a, f, a);
    NEXT();
op_C0:  // RNZ
    if (!(f & F_Z)) { ADD_T(kTaken<V>[0xC0]); POPPC(); }
    NEXT();
op_C1:  // POP B
    c = RDD(sp); sp = sp + 1; b = RDD(sp); sp = sp + 1;
    NEXT();
op_C2:  // JNZ a16
    if (!(f & F_Z)) {
        const std::uint16_t from = static_cast<std::uint16_t>(pc - 1);
        pc = IMM16(); ADD_T(kTaken<V>[0xC2]);
        if constexpr (!Debug) {
            // Back onto the byte before it: perhaps "L: DCR r / JNZ L", a delay loop.
            if (static_cast<std::uint16_t>(from - pc) <= 3 && fast_loops_) [[unlikely]] {
                if (pc == static_cast<std::uint16_t>(from - 1)) goto countdown;
                if (pc == static_cast<std::uint16_t>(from - 3)) goto countdown16;
            }
        }
    } else { pc = pc + 2; }
    NEXT();
op_C3:  // JMP a16
    pc = IMM16();
    NEXT();
op_C4:  // CNZ a16
    if (!(f & F_Z)) { const std::uint16_t ad = IMM16(); ADD_T(kTaken<V>[0xC4]); PUSH2(pc >> 8, pc & 0xFF); pc = ad; } else { pc = pc + 2; }
    NEXT();
op_C5:  // PUSH B
    PUSH2(b, c);
    NEXT();
op_C6:  // ADI d8
    { const std::uint8_t v = IMM8(); alu_add<V>(a, f, v, 0); }
    NEXT();
op_C7:  // RST 0
    PUSH2(pc >> 8, pc & 0xFF); pc = 0x00;
    NEXT();
op_C8:  // RZ
    if ((f & F_Z)) { ADD_T(kTaken<V>[0xC8]); POPPC(); }
    NEXT();
op_C9:  // RET
    POPPC();
    NEXT();
op_CA:  // JZ a16
    if ((f & F_Z)) { pc = IMM16(); ADD_T(kTaken<V>[0xCA]); } else { pc = pc + 2; }
    NEXT();
op_CB:  // RSTV / 8080: JMP a16
    if constexpr (k85) { if (f & F_V) { ADD_T(kTaken<V>[0xCB]); PUSH2(pc >> 8, pc & 0xFF); pc = 0x40; } } else { pc = IMM16(); }
    NEXT();
op_CC:  // CZ a16
    if ((f & F_Z)) { const std::uint16_t ad = IMM16(); ADD_T(kTaken<V>[0xCC]); PUSH2(pc >> 8, pc & 0xFF); pc = ad; } else { pc = pc + 2; }
    NEXT();
op_CD:  // CALL a16
    { const std::uint16_t ad = IMM16(); PUSH2(pc >> 8, pc & 0xFF); pc = ad; }
    NEXT();
op_CE:  // ACI d8
    { const std::uint8_t v = IMM8(); alu_add<V>(a, f, v, f & 1); }
    NEXT();
op_CF:  // RST 1
    PUSH2(pc >> 8, pc & 0xFF); pc = 0x08;
    NEXT();
op_D0:  // RNC
    if (!(f & F_CY)) { ADD_T(kTaken<V>[0xD0]); POPPC(); }
    NEXT();
op_D1:  // POP D
    e = RDD(sp); sp = sp + 1; d = RDD(sp); sp = sp + 1;
    NEXT();
op_D2:  // JNC a16
    if (!(f & F_CY)) { pc = IMM16(); ADD_T(kTaken<V>[0xD2]); } else { pc = pc + 2; }
    NEXT();
op_D3:  // OUT p8
    { const std::uint8_t p = IMM8(); SYNC(3); io_out(p, a, t_); RELIMIT(); DBG_IO(p, a, true); }
    NEXT();
op_D4:  // CNC a16
    if (!(f & F_CY)) { const std::uint16_t ad = IMM16(); ADD_T(kTaken<V>[0xD4]); PUSH2(pc >> 8, pc & 0xFF); pc = ad; } else { pc = pc + 2; }
    NEXT();
op_D5:  // PUSH D
    PUSH2(d, e);
    NEXT();
op_D6:  // SUI d8
    { const std::uint8_t v = IMM8(); alu_sub<V>(a, f, v, 0); }
    NEXT();
op_D7:  // RST 2
    PUSH2(pc >> 8, pc & 0xFF); pc = 0x10;
    NEXT();
op_D8:  // RC
    if ((f & F_CY)) { ADD_T(kTaken<V>[0xD8]); POPPC(); }
    NEXT();
op_D9:  // SHLX / 8080: RET
    if constexpr (k85) { const std::uint16_t ad = DE(); WR(ad, l); WR(static_cast<std::uint16_t>(ad + 1), h); } else { POPPC(); }
    NEXT();
op_DA:  // JC a16
    if ((f & F_CY)) { pc = IMM16(); ADD_T(kTaken<V>[0xDA]); } else { pc = pc + 2; }
    NEXT();
op_DB:  // IN p8
    { const std::uint8_t p = IMM8(); SYNC(3); a = io_in(p, t_); RELIMIT(); DBG_IO(p, a, false); }
    NEXT();
op_DC:  // CC a16
    if ((f & F_CY)) { const std::uint16_t ad = IMM16(); ADD_T(kTaken<V>[0xDC]); PUSH2(pc >> 8, pc & 0xFF); pc = ad; } else { pc = pc + 2; }
    NEXT();
op_DD:  // JNK a16 / 8080: CALL a16
    if constexpr (k85) { if (!(f & F_K)) { pc = IMM16(); ADD_T(kTaken<V>[0xDD]); } else { pc = pc + 2; } } else { const std::uint16_t ad = IMM16(); PUSH2(pc >> 8, pc & 0xFF); pc = ad; }
    NEXT();
op_DE:  // SBI d8
    { const std::uint8_t v = IMM8(); alu_sub<V>(a, f, v, f & 1); }
    NEXT();
op_DF:  // RST 3
    PUSH2(pc >> 8, pc & 0xFF); pc = 0x18;
    NEXT();
op_E0:  // RPO
    if (!(f & F_P)) { ADD_T(kTaken<V>[0xE0]); POPPC(); }
    NEXT();
op_E1:  // POP H
    l = RDD(sp); sp = sp + 1; h = RDD(sp); sp = sp + 1;
    NEXT();
op_E2:  // JPO a16
    if (!(f & F_P)) { pc = IMM16(); ADD_T(kTaken<V>[0xE2]); } else { pc = pc + 2; }
    NEXT();
op_E3:  // XTHL
    { const std::uint8_t lo = RDD(sp); const std::uint16_t s1 = static_cast<std::uint16_t>(sp + 1); const std::uint8_t hi = RDD(s1); WR(sp, l); WR(s1, h); l = lo; h = hi; }
    NEXT();
op_E4:  // CPO a16
    if (!(f & F_P)) { const std::uint16_t ad = IMM16(); ADD_T(kTaken<V>[0xE4]); PUSH2(pc >> 8, pc & 0xFF); pc = ad; } else { pc = pc + 2; }
    NEXT();
op_E5:  // PUSH H
    PUSH2(h, l);
    NEXT();
op_E6:  // ANI d8
    { const std::uint8_t v = IMM8(); alu_ana<V>(a, f, v); }
    NEXT();
op_E7:  // RST 4
    PUSH2(pc >> 8, pc & 0xFF); pc = 0x20;
    NEXT();
op_E8:  // RPE
    if ((f & F_P)) { ADD_T(kTaken<V>[0xE8]); POPPC(); }
    NEXT();
op_E9:  // PCHL
    pc = HL();
    NEXT();
op_EA:  // JPE a16
    if ((f & F_P)) { pc = IMM16(); ADD_T(kTaken<V>[0xEA]); } else { pc = pc + 2; }
    NEXT();
op_EB:  // XCHG
    std::swap(d, h); std::swap(e, l);
    NEXT();
op_EC:  // CPE a16
    if ((f & F_P)) { const std::uint16_t ad = IMM16(); ADD_T(kTaken<V>[0xEC]); PUSH2(pc >> 8, pc & 0xFF); pc = ad; } else { pc = pc + 2; }
    NEXT();
op_ED:  // LHLX / 8080: CALL a16
    if constexpr (k85) { const std::uint16_t ad = DE(); l = RDD(ad); h = RDD(static_cast<std::uint16_t>(ad + 1)); } else { const std::uint16_t ad = IMM16(); PUSH2(pc >> 8, pc & 0xFF); pc = ad; }
    NEXT();
op_EE:  // XRI d8
    { const std::uint8_t v = IMM8(); a ^= v; f = kSZP<V>[a]; }
    NEXT();
op_EF:  // RST 5
    PUSH2(pc >> 8, pc & 0xFF); pc = 0x28;
    NEXT();
op_F0:  // RP
    if (!(f & F_S)) { ADD_T(kTaken<V>[0xF0]); POPPC(); }
    NEXT();
op_F1:  // POP PSW
    f = RDD(sp); f = k85 ? (f & 0xF7) : ((f & 0xD7) | 0x02); sp = sp + 1; a = RDD(sp); sp = sp + 1;
    NEXT();
op_F2:  // JP a16
    if (!(f & F_S)) { pc = IMM16(); ADD_T(kTaken<V>[0xF2]); } else { pc = pc + 2; }
    NEXT();
op_F3:  // DI
    ie_ = false; ei_delay_ = false;
    NEXT();
op_F4:  // CP a16
    if (!(f & F_S)) { const std::uint16_t ad = IMM16(); ADD_T(kTaken<V>[0xF4]); PUSH2(pc >> 8, pc & 0xFF); pc = ad; } else { pc = pc + 2; }
    NEXT();
op_F5:  // PUSH PSW
    PUSH2(a, f);
    NEXT();
op_F6:  // ORI d8
    { const std::uint8_t v = IMM8(); a |= v; f = kSZP<V>[a]; }
    NEXT();
op_F7:  // RST 6
    PUSH2(pc >> 8, pc & 0xFF); pc = 0x30;
    NEXT();
op_F8:  // RM
    if ((f & F_S)) { ADD_T(kTaken<V>[0xF8]); POPPC(); }
    NEXT();
op_F9:  // SPHL
    sp = HL();
    sp_load_ = 0x10000u | sp;
    NEXT();
op_FA:  // JM a16
    if ((f & F_S)) { pc = IMM16(); ADD_T(kTaken<V>[0xFA]); } else { pc = pc + 2; }
    NEXT();
op_FB:  // EI
    ie_ = true; ei_delay_ = true; END_BATCH();
    NEXT();
op_FC:  // CM a16
    if ((f & F_S)) { const std::uint16_t ad = IMM16(); ADD_T(kTaken<V>[0xFC]); PUSH2(pc >> 8, pc & 0xFF); pc = ad; } else { pc = pc + 2; }
    NEXT();
op_FD:  // JK a16 / 8080: CALL a16
    if constexpr (k85) { if (f & F_K) { pc = IMM16(); ADD_T(kTaken<V>[0xFD]); } else { pc = pc + 2; } } else { const std::uint16_t ad = IMM16(); PUSH2(pc >> 8, pc & 0xFF); pc = ad; }
    NEXT();
op_FE:  // CPI d8
    { const std::uint8_t v = IMM8(); alu_cmp<V>(a, f, v); }
    NEXT();
op_FF:  // RST 7
    PUSH2(pc >> 8, pc & 0xFF); pc = 0x38;
    NEXT();
countdown: __attribute__((unused)); {
    // "L: DCR r / JNZ L" with the JNZ just taken: the iterations that keep r non-zero and start
    // before the batch's limit are done at once. Nothing else can happen inside such a loop (no
    // memory or I/O access, pins change only between batches), so registers, flags, T-states and
    // the instruction count end exactly as instruction by instruction. Debug runs never get here.
    constexpr unsigned per = kBase<V>[0x05] + kBase<V>[0xC2] + kTaken<V>[0xC2];
    const std::uint8_t* const code = rp[pc >> 8];
    if (!code || !rp[static_cast<std::uint16_t>(pc + 3) >> 8] || rem <= 0) NEXT();
    if constexpr (Fence) {  // a breakpoint inside the loop sees every iteration
        for (unsigned k = 0; k < 4; ++k)
            if ((*fence)[static_cast<std::uint16_t>(pc + k)]) NEXT();
    }
    const std::uint64_t fit = static_cast<std::uint64_t>((stop >> kCountBits) - ((stop - rem) >> kCountBits)) / per;
#define COUNTDOWN(r)                                                                        \
    do {                                                                                    \
        const unsigned left = (r - 1u) & 0xFFu; /* iterations whose DCR leaves r non-zero */ \
        const unsigned m = fit < left ? static_cast<unsigned>(fit) : left;                  \
        if (m) {                                                                            \
            r = dcr<V>(static_cast<std::uint8_t>(r - m + 1), f);                            \
            rem -= (static_cast<std::int64_t>(per) * m << kCountBits) + 2 * m;              \
        }                                                                                   \
    } while (0)
    switch (code[pc & 0xFF]) {
        case 0x05: COUNTDOWN(b); break;
        case 0x0D: COUNTDOWN(c); break;
        case 0x15: COUNTDOWN(d); break;
        case 0x1D: COUNTDOWN(e); break;
        case 0x25: COUNTDOWN(h); break;
        case 0x2D: COUNTDOWN(l); break;
        case 0x3D: COUNTDOWN(a); break;
        default: break;  // another instruction (DCR M reads memory: not taken over)
    }
#undef COUNTDOWN
    NEXT();
}
countdown16: __attribute__((unused)); {
    // "L: DCX rp / MOV A,r / ORA r' / JNZ L" (r, r' the two halves of rp, in either order) with
    // the JNZ just taken: a 16-bit delay loop. The iterations that keep rp non-zero and start
    // before the batch's limit are done at once. After each iteration A = r | r' and the flags are
    // ORA's (DCX's K on the 8085 is overwritten by ORA), so only the last iteration's rp matters;
    // nothing inside touches memory or I/O. Debug runs never get here.
    constexpr unsigned per = kBase<V>[0x0B] + kBase<V>[0x78] + kBase<V>[0xB0] + kBase<V>[0xC2] + kTaken<V>[0xC2];
    const std::uint8_t* const code = rp[pc >> 8];
    const std::uint8_t* const code_end = rp[static_cast<std::uint16_t>(pc + 5) >> 8];
    if (!code || !code_end || rem <= 0) NEXT();
    if constexpr (Fence) {
        for (unsigned k = 0; k < 6; ++k)
            if ((*fence)[static_cast<std::uint16_t>(pc + k)]) NEXT();
    }
#define CODE_AT(k) (((pc + (k)) & 0xFF00) == (pc & 0xFF00) ? code[(pc + (k)) & 0xFF] : code_end[(pc + (k)) & 0xFF])
    const std::uint8_t dcx = code[pc & 0xFF], mov = CODE_AT(1), ora = CODE_AT(2);
#undef CODE_AT
    // DCX B/D/H is 0B/1B/2B; MOV A,r is 78+r; ORA r is B0+r; registers B C D E H L = 0..5.
    if ((dcx & 0xCF) != 0x0B || dcx == 0x3B) NEXT();
    const unsigned hi = (dcx >> 4) * 2, lo = hi + 1;
    const unsigned r1 = mov - 0x78u, r2 = ora - 0xB0u;
    if (!((r1 == hi && r2 == lo) || (r1 == lo && r2 == hi))) NEXT();
    const std::uint64_t fit = static_cast<std::uint64_t>((stop >> kCountBits) - ((stop - rem) >> kCountBits)) / per;
#define COUNTDOWN16(rh, rl)                                                                 \
    do {                                                                                    \
        const unsigned pair = static_cast<unsigned>(rh << 8 | rl);                          \
        const unsigned left = (pair - 1u) & 0xFFFFu; /* iterations leaving rp non-zero */   \
        const unsigned m = fit < left ? static_cast<unsigned>(fit) : left;                  \
        if (m) {                                                                            \
            const unsigned v = pair - m;                                                    \
            rh = static_cast<std::uint8_t>(v >> 8);                                         \
            rl = static_cast<std::uint8_t>(v);                                              \
            a = static_cast<std::uint8_t>(rh | rl);                                         \
            f = kSZP<V>[a];                                                                 \
            rem -= (static_cast<std::int64_t>(per) * m << kCountBits) + 4 * m;              \
        }                                                                                   \
    } while (0)
    switch (dcx) {
        case 0x0B: COUNTDOWN16(b, c); break;
        case 0x1B: COUNTDOWN16(d, e); break;
        default: COUNTDOWN16(h, l); break;
    }
#undef COUNTDOWN16
    NEXT();
}
done:
    SAVE_REGS();
#undef HL
#undef BC
#undef DE
#undef SAVE_REGS
#undef LOAD_REGS
#undef SYNC
#undef TNOW
#undef NNOW
#undef ADD_T
#undef RELIMIT
#undef END_BATCH
#undef FETCH
#undef FETCH_AT
#undef RDD
#undef WR
#undef DBG_IO
#undef IMM8
#undef IMM16
#undef PUSH2
#undef POPPC
#undef NEXT
}

// ---- batches and interrupts --------------------------------------------------------------------
template <Variant V, bool Debug>
std::uint64_t I8085::run_impl(std::uint64_t deadline) {
    const std::uint64_t start = t_;
    deadline_ = deadline;
    while (t_ < deadline_) {
        if (hold_) {  // HLDA: the bus belongs to another master until HOLD falls
            t_ = deadline_;
            break;
        }
        const bool after_ei = ei_delay_;
        accept_interrupt();
        if (t_ >= deadline_) break;
        if (halted_) {  // HALT: nothing happens until an interrupt is accepted
            t_ = deadline_;
            break;
        }
        const std::uint64_t before = instructions_;
        if (after_ei) {  // exactly one instruction after EI before any maskable interrupt
            ei_delay_ = false;
            limit_ = t_ + 1;
        } else {
            limit_ = deadline_;
        }
        // Plain RAM over all 64 KiB (a CP/M machine, the bare-core benchmarks): no page table.
        // Chosen per batch; a mapping changed by an I/O handler ends the batch (io_out, io_in).
        if constexpr (Debug) {
            execute<V, true, false, false>();
        } else if (fence_) {  // a debugger's breakpoints or runaway guard, on the plain path
            if (exec_pages_maps_ != bus_.map_changes()) map_exec_pages();
            execute<V, false, false, true>();  // the page table serves flat RAM too (one copy less to compile)
        } else if (bus_.flat_ram()) {
            execute<V, false, true, false>();
        } else {
            execute<V, false, false, false>();
        }
        if (after_ei && instructions_ == before) ei_delay_ = true;  // stopped before it ran
    }
    limit_ = 0;
    return t_ - start;
}

void I8085::set_fetch_fence(const std::bitset<0x10000>* fence) {
    fence_ = fence;
    fenced_pages_.reset();
    if (fence)
        for (unsigned p = 0; p < 256; ++p)
            for (unsigned a = p << 8; a < (p + 1) << 8; ++a)
                if ((*fence)[a]) {
                    fenced_pages_[p] = true;
                    break;
                }
    exec_pages_maps_ = ~std::uint64_t{0};
}

void I8085::map_exec_pages() {
    const std::uint8_t* const* const rp = bus_.read_pages();
    for (unsigned p = 0; p < 256; ++p) exec_pages_[p] = fenced_pages_[p] ? nullptr : rp[p];
    exec_pages_maps_ = bus_.map_changes();
}

std::uint64_t I8085::run(std::uint64_t deadline) {
    fence_hit_ = false;
    if (variant_ == Variant::I8085)
        return hooks_ ? run_impl<Variant::I8085, true>(deadline) : run_impl<Variant::I8085, false>(deadline);
    return hooks_ ? run_impl<Variant::I8080, true>(deadline) : run_impl<Variant::I8080, false>(deadline);
}

void I8085::push_pc_and_jump(std::uint16_t vector) {
    r_.sp = static_cast<std::uint16_t>(r_.sp - 1);
    bus_.write(r_.sp, static_cast<std::uint8_t>(r_.pc >> 8), t_);
    r_.sp = static_cast<std::uint16_t>(r_.sp - 1);
    bus_.write(r_.sp, static_cast<std::uint8_t>(r_.pc), t_);
    r_.pc = vector;
}

// Priority: TRAP, RST 7.5, RST 6.5, RST 5.5, INTR. Every acknowledge clears IE. TRAP ignores IE
// and the masks; the others need IE and (RST x.5) their mask bit clear. The instruction after EI
// always runs first (ei_delay_). Each acknowledge counts as one instruction.
void I8085::accept_interrupt() {
    const bool k85 = variant_ == Variant::I8085;
    std::uint16_t vector = 0;
    unsigned tstates = 0;
    if (k85 && trap_latch_ && trap_pin_) {
        trap_latch_ = false;
        trap_ie_ = ie_;
        trap_rim_ = true;
        vector = 0x24;
        tstates = 12;
    } else if (!ie_ || ei_delay_) {
        return;
    } else if (k85 && rst75_latch_ && !(masks_ & 0x04)) {
        rst75_latch_ = false;
        vector = 0x3C;
        tstates = 12;
    } else if (k85 && rst65_pin_ && !(masks_ & 0x02)) {
        vector = 0x34;
        tstates = 12;
    } else if (k85 && rst55_pin_ && !(masks_ & 0x01)) {
        vector = 0x2C;
        tstates = 12;
    } else if (intr_pin_) {
        const std::uint8_t opcode = on_inta ? on_inta(0) : 0xFF;
        const auto& info = isa::kOpcodes[opcode];
        if ((opcode & 0xC7) == 0xC7) {  // RST n
            vector = opcode & 0x38;
            tstates = k85 ? info.t8085 : info.t8080;
        } else if (opcode == 0xCD) {  // CALL: two more INTA cycles bring the address
            const std::uint8_t lo = on_inta ? on_inta(1) : 0xFF;
            const std::uint8_t hi = on_inta ? on_inta(2) : 0xFF;
            vector = static_cast<std::uint16_t>((hi << 8) | lo);
            tstates = k85 ? info.t8085 : info.t8080;
        } else {  // anything else: one INTA opcode cycle, nothing executed
            ie_ = false;
            halted_ = false;
            t_ += k85 ? 6 : 5;
            ++instructions_;
            return;
        }
    } else {
        return;
    }
    ie_ = false;
    halted_ = false;
    push_pc_and_jump(vector);
    t_ += tstates;
    ++instructions_;
}

std::uint8_t I8085::rim_value() const {
    const bool ie = trap_rim_ ? trap_ie_ : ie_;
    return static_cast<std::uint8_t>((sid_ ? 0x80 : 0) | (rst75_latch_ ? 0x40 : 0) | (rst65_pin_ ? 0x20 : 0) |
                                     (rst55_pin_ ? 0x10 : 0) | (ie ? 0x08 : 0) | masks_);
}

std::uint8_t I8085::rim() {
    const std::uint8_t v = rim_value();
    trap_rim_ = false;
    return v;
}

// SIM: bit 7 SOD, 6 SDE (latch SOD), 4 R7.5 (reset the 7.5 latch), 3 MSE (load masks), 2-0 masks.
void I8085::sim(std::uint8_t a) {
    if (a & 0x08) masks_ = a & 0x07;
    if (a & 0x10) rst75_latch_ = false;
    if (a & 0x40) {
        const bool level = (a & 0x80) != 0;
        if (level != sod_) {
            sod_ = level;
            if (on_sod) on_sod(level);
        }
    }
}

void I8085::set_trap(bool level) {
    if (variant_ != Variant::I8085) return;
    if (level && !trap_pin_) trap_latch_ = true;
    trap_pin_ = level;
    wake_check();
}

void I8085::set_rst75(bool level) {
    if (variant_ != Variant::I8085) return;
    if (level && !rst75_pin_) rst75_latch_ = true;
    rst75_pin_ = level;
    wake_check();
}

void I8085::set_rst65(bool level) {
    if (variant_ != Variant::I8085) return;
    rst65_pin_ = level;
    wake_check();
}

void I8085::set_rst55(bool level) {
    if (variant_ != Variant::I8085) return;
    rst55_pin_ = level;
    wake_check();
}

void I8085::set_intr(bool level) {
    intr_pin_ = level;
    wake_check();
}

void I8085::set_hold(bool level) {
    hold_ = level;
    if (hlda_ != level) {
        hlda_ = level;
        if (on_hlda) on_hlda(level);
    }
    wake_check();
}

}  // namespace alp85
