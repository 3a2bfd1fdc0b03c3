// The 8085/8080 instruction loop, interrupt logic and pins. See i8085.h for the model's scope and
// docs/cpu.md for the flag rules (documented and undocumented) and their sources, and for how the
// loop is made from the opcode table.
#include "emu/core/i8085.h"

#include <array>
#include <string_view>
#include <type_traits>
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
using isa::Flow;

// ---- what each opcode does, read from the opcode table (asm/isa.h) ----------------------------
// The table's mnemonic names the operation, its operand template the registers and immediate
// bytes, its flow the transfer of control, its T-states the cost and flags_written() the flags.
// Each opcode's body in the loop is chosen at compile time from this decoding.
enum class Kind : std::uint8_t {
    Nop, Mov, Mvi, Lxi, Stax, Ldax, Inx, Dcx, Inr, Dcr, Dad, Rlc, Rrc, Ral, Rar, Daa, Cma, Stc, Cmc,
    Add, Adc, Sub, Sbb, Ana, Xra, Ora, Cmp, Shld, Lhld, Sta, Lda, Push, Pop, Xthl, Xchg, Sphl,
    Out, In, Ei, Di, Rim, Sim, Dsub, Arhl, Rdel, Ldhi, Ldsi, Shlx, Lhlx,
    Transfer,  // the flow field says what it does: jumps, calls, returns, restarts, PCHL, HLT
};

struct KindName {
    std::string_view mnemonic;
    Kind kind;
};
constexpr KindName kKinds[] = {
    {"NOP", Kind::Nop},   {"MOV", Kind::Mov},   {"MVI", Kind::Mvi},   {"LXI", Kind::Lxi},   {"STAX", Kind::Stax},
    {"LDAX", Kind::Ldax}, {"INX", Kind::Inx},   {"DCX", Kind::Dcx},   {"INR", Kind::Inr},   {"DCR", Kind::Dcr},
    {"DAD", Kind::Dad},   {"RLC", Kind::Rlc},   {"RRC", Kind::Rrc},   {"RAL", Kind::Ral},   {"RAR", Kind::Rar},
    {"DAA", Kind::Daa},   {"CMA", Kind::Cma},   {"STC", Kind::Stc},   {"CMC", Kind::Cmc},   {"ADD", Kind::Add},
    {"ADI", Kind::Add},   {"ADC", Kind::Adc},   {"ACI", Kind::Adc},   {"SUB", Kind::Sub},   {"SUI", Kind::Sub},
    {"SBB", Kind::Sbb},   {"SBI", Kind::Sbb},   {"ANA", Kind::Ana},   {"ANI", Kind::Ana},   {"XRA", Kind::Xra},
    {"XRI", Kind::Xra},   {"ORA", Kind::Ora},   {"ORI", Kind::Ora},   {"CMP", Kind::Cmp},   {"CPI", Kind::Cmp},
    {"SHLD", Kind::Shld}, {"LHLD", Kind::Lhld}, {"STA", Kind::Sta},   {"LDA", Kind::Lda},   {"PUSH", Kind::Push},
    {"POP", Kind::Pop},   {"XTHL", Kind::Xthl}, {"XCHG", Kind::Xchg}, {"SPHL", Kind::Sphl}, {"OUT", Kind::Out},
    {"IN", Kind::In},     {"EI", Kind::Ei},     {"DI", Kind::Di},     {"RIM", Kind::Rim},   {"SIM", Kind::Sim},
    {"DSUB", Kind::Dsub}, {"ARHL", Kind::Arhl}, {"RDEL", Kind::Rdel}, {"LDHI", Kind::Ldhi}, {"LDSI", Kind::Ldsi},
    {"SHLX", Kind::Shlx}, {"LHLX", Kind::Lhlx},
};

// Register operands in the encoding's order (B C D E H L M A: M is 6, A is 7); kImm is a d8 operand.
constexpr int kM = 6, kImm = 8, kNone = -1;
constexpr int reg_index(std::string_view s) {
    constexpr std::string_view names[] = {"B", "C", "D", "E", "H", "L", "M", "A"};
    for (int i = 0; i < 8; ++i)
        if (s == names[i]) return i;
    return s == "d8" ? kImm : kNone;
}
// Register pairs: B D H SP (PUSH and POP: PSW in SP's place).
constexpr int pair_index(std::string_view s) {
    constexpr std::string_view names[] = {"B", "D", "H", "SP"};
    for (int i = 0; i < 4; ++i)
        if (s == names[i]) return i;
    return s == "PSW" ? 3 : kNone;
}

struct Decoded {
    Kind kind = Kind::Nop;
    Flow flow = Flow::Next;
    int dst = kNone, src = kNone;  // registers (reg_index), or for pairs pair_index in dst
    unsigned imm = 0;              // immediate bytes, from the operand template
    std::uint8_t cond_flag = 0;    // the flag a conditional transfer tests (0: unconditional)
    bool cond_set = true;          // taken when that flag is set (true) or clear (false)
    std::uint16_t vector = 0;      // RST n, RSTV: where the restart goes
    std::uint8_t flags = 0;        // flags written (asm/isa.h flags_written)
};

constexpr Decoded decode(std::uint8_t op) {
    const isa::OpInfo& o = isa::kOpcodes[op];
    Decoded d;
    d.flow = o.flow;
    d.flags = isa::flags_written(op, false);
    d.kind = Kind::Transfer;
    for (const KindName& k : kKinds)
        if (k.mnemonic == o.mnemonic) d.kind = k.kind;
    // Operands: "r,r", "r,d8", "rp,d16", "r", "rp", "d8", "a16", "p8", a restart number.
    const std::string_view ops = o.operands;
    const auto comma = ops.find(',');
    const std::string_view first = comma == std::string_view::npos ? ops : ops.substr(0, comma);
    const std::string_view second = comma == std::string_view::npos ? std::string_view{} : ops.substr(comma + 1);
    for (std::string_view x : {first, second}) {
        if (x == "d8" || x == "p8") d.imm = 1;
        if (x == "d16" || x == "a16") d.imm = 2;
    }
    switch (d.kind) {
        case Kind::Mov: d.dst = reg_index(first), d.src = reg_index(second); break;
        case Kind::Mvi: d.dst = reg_index(first), d.src = kImm; break;
        case Kind::Inr: case Kind::Dcr: d.dst = reg_index(first); break;
        case Kind::Add: case Kind::Adc: case Kind::Sub: case Kind::Sbb:
        case Kind::Ana: case Kind::Xra: case Kind::Ora: case Kind::Cmp: d.src = reg_index(first); break;
        case Kind::Lxi: case Kind::Stax: case Kind::Ldax: case Kind::Inx: case Kind::Dcx:
        case Kind::Dad: case Kind::Push: case Kind::Pop: d.dst = pair_index(first); break;
        default: break;
    }
    if (o.flow == Flow::Restart) d.vector = static_cast<std::uint16_t>((first[0] - '0') * 8);
    if (o.flow == Flow::RestartIf) d.vector = 0x40;  // RSTV: the restart after RST 7 (8 × 8)
    if (o.flow == Flow::JumpIf || o.flow == Flow::CallIf || o.flow == Flow::ReturnIf || o.flow == Flow::RestartIf) {
        // The condition is the mnemonic after its first letter (J, C, R); RSTV tests V.
        const std::string_view cc = o.flow == Flow::RestartIf ? std::string_view{"V"} : o.mnemonic.substr(1);
        struct Cc {
            std::string_view name;
            std::uint8_t flag;
            bool set;
        };
        constexpr Cc ccs[] = {{"NZ", F_Z, false}, {"Z", F_Z, true},   {"NC", F_CY, false}, {"C", F_CY, true},
                              {"PO", F_P, false}, {"PE", F_P, true},  {"P", F_S, false},   {"M", F_S, true},
                              {"NK", F_K, false}, {"K", F_K, true},   {"V", F_V, true}};
        for (const Cc& c : ccs)
            if (c.name == cc) d.cond_flag = c.flag, d.cond_set = c.set;
    }
    return d;
}

template <std::uint8_t Op>
constexpr Decoded kDecoded = decode(Op);

// Every opcode is decoded to a body: a name the table uses that the loop does not know would
// otherwise run as a transfer with no flow.
constexpr bool all_decoded() {
    for (unsigned i = 0; i < 256; ++i) {
        const Decoded d = decode(static_cast<std::uint8_t>(i));
        if ((d.kind == Kind::Transfer) != (d.flow != Flow::Next)) return false;
        if ((d.flow == Flow::JumpIf || d.flow == Flow::CallIf || d.flow == Flow::ReturnIf) && d.cond_flag == 0) return false;
    }
    return true;
}
static_assert(all_decoded(), "an opcode of asm/isa.h has no body in the CPU loop");

// ---- per-variant data: the 8080 and the 8085 differ only in these --------------------------------
// A batch runs at most kBatchTStates, so it holds fewer than 2^kCountBits instructions (each takes
// at least 4 T-states): T-states and instructions share one counter (I8085::execute).
constexpr unsigned kCountBits = 24;
constexpr std::uint64_t kBatchTStates = std::uint64_t{1} << 25;

struct VariantData {
    std::int64_t cost[256];   // T-states << kCountBits, plus one instruction
    std::int64_t taken[256];  // extra T-states of a taken condition << kCountBits
    std::uint8_t szp[256];    // S, Z and P of a result; on the 8080 also flag bit 1, always 1
    std::uint8_t inr[256];    // the flags INR writes, by the value incremented
    std::uint8_t dcr[256];    // the flags DCR writes, by the value decremented
    std::uint8_t body[256];   // the opcode whose body runs: itself, or on the 8080 alias8080
    std::uint8_t vk;          // V and K as the variant has them: V|K on the 8085, none on the 8080
    std::uint8_t ana_ac;      // ANA's AC: always set on the 8085; on the 8080 bit 3 of (A OR x)
    std::uint8_t psw_keep;    // POP PSW: the bits of the popped byte the flag register holds
    std::uint8_t psw_set;     // and those always set (8080 bit 1)
};

constexpr VariantData make_variant(Variant v) {
    const bool i8080 = v == Variant::I8080;
    VariantData d{};
    for (unsigned i = 0; i < 256; ++i) {
        const isa::OpInfo& o = isa::kOpcodes[i];
        const unsigned t = i8080 ? o.t8080 : o.t8085, taken = i8080 ? o.t8080_taken : o.t8085_taken;
        d.cost[i] = (std::int64_t{t} << kCountBits) + 1;
        d.taken[i] = std::int64_t{taken - t} << kCountBits;
        d.body[i] = i8080 ? o.alias8080 : static_cast<std::uint8_t>(i);
        unsigned ones = 0;
        for (unsigned b = 0; b < 8; ++b) ones += (i >> b) & 1;
        d.szp[i] = static_cast<std::uint8_t>((i & 0x80 ? F_S : 0) | (i == 0 ? F_Z : 0) | (ones % 2 == 0 ? F_P : 0) |
                                             (i8080 ? 0x02 : 0));
    }
    d.vk = i8080 ? 0 : F_V | F_K;
    // INR/DCR as the ALU's +1/-1 (DCR adds FFH): AC is the carry out of bit 3; V only for 7FH+1
    // and 80H-1; K = V XOR S. CY is theirs to keep (flags_written).
    for (unsigned x = 0; x < 256; ++x) {
        const unsigned up = (x + 1) & 0xFF, down = (x - 1) & 0xFF;
        const unsigned v_up = x == 0x7F ? F_V : 0, v_down = x == 0x80 ? F_V : 0;
        const auto k = [](unsigned v, unsigned r) { return ((v << 6) ^ r) & 0x80 ? F_K : 0; };
        d.inr[x] = static_cast<std::uint8_t>(d.szp[up] | ((up & 0x0F) == 0 ? F_AC : 0) |
                                             ((v_up | k(v_up, up)) & d.vk));
        d.dcr[x] = static_cast<std::uint8_t>(d.szp[down] | ((x & 0x0F) != 0 ? F_AC : 0) |
                                             ((v_down | k(v_down, down)) & d.vk));
    }
    d.ana_ac = i8080 ? 0 : F_AC;
    d.psw_keep = i8080 ? 0xD7 : 0xF7;  // bit 3 always 0; the 8080 has no V (bit 1) and no K (bit 5)
    d.psw_set = i8080 ? 0x02 : 0x00;
    return d;
}
constexpr VariantData kVariants[2] = {make_variant(Variant::I8085), make_variant(Variant::I8080)};
// The INR and DCR tables hold only flags the opcode table says INR and DCR write.
constexpr bool inr_dcr_within_table() {
    for (const VariantData& d : kVariants)
        for (unsigned x = 0; x < 256; ++x)
            if ((d.inr[x] | d.dcr[x]) & ~(isa::flags_written(0x04, false) & isa::flags_written(0x05, false)))
                return false;
    return true;
}
static_assert(inr_dcr_within_table(), "INR/DCR flag tables");

constexpr unsigned op_tstates(Variant v, std::uint8_t op, bool taken = false) {
    const isa::OpInfo& o = isa::kOpcodes[op];
    return v == Variant::I8080 ? (taken ? o.t8080_taken : o.t8080) : (taken ? o.t8085_taken : o.t8085);
}
static_assert(op_tstates(Variant::I8085, 0x40) == 4 && op_tstates(Variant::I8080, 0x40) == 5, "MOV r,r timing");
// The countdown fast path (JNZ, execute) times every DCR r like DCR B.
constexpr bool dcr_r_timed_alike(Variant v) {
    for (unsigned op : {0x0Du, 0x15u, 0x1Du, 0x25u, 0x2Du, 0x3Du})
        if (op_tstates(v, static_cast<std::uint8_t>(op)) != op_tstates(v, 0x05)) return false;
    return true;
}
static_assert(dcr_r_timed_alike(Variant::I8085) && dcr_r_timed_alike(Variant::I8080), "DCR r timing");
// The 16-bit fast path (countdown16) times DCX rp, MOV A,r and ORA r like DCX B, MOV A,B, ORA B.
constexpr bool delay16_timed_alike(Variant v) {
    for (unsigned k = 0; k < 6; ++k)
        if (op_tstates(v, static_cast<std::uint8_t>(0x78 + k)) != op_tstates(v, 0x78) ||
            op_tstates(v, static_cast<std::uint8_t>(0xB0 + k)) != op_tstates(v, 0xB0))
            return false;
    return op_tstates(v, 0x1B) == op_tstates(v, 0x0B) && op_tstates(v, 0x2B) == op_tstates(v, 0x0B);
}
static_assert(delay16_timed_alike(Variant::I8085) && delay16_timed_alike(Variant::I8080), "16-bit delay timing");

// ---- flag arithmetic ---------------------------------------------------------------------------
// V (8085, bit 1) = carry into bit 7 XOR carry out of bit 7, i.e. two's-complement overflow.
// K (8085, bit 5) = V XOR S after 8-bit arithmetic. `vk` keeps them (the 8085) or not (the 8080).
[[gnu::always_inline]] inline std::uint8_t vk_from_overflow(unsigned overflow80, unsigned r, std::uint8_t vk) {
    return static_cast<std::uint8_t>(((overflow80 >> 6) | (((overflow80 ^ r) & 0x80) >> 2)) & vk);
}

// Addition: the flags of A + x + carry-in, all of them.
[[gnu::always_inline]] inline std::uint8_t flags_add(const VariantData& vd, unsigned a, unsigned x, unsigned r) {
    return static_cast<std::uint8_t>(vd.szp[r & 0xFF] | ((r >> 8) & F_CY) | ((a ^ x ^ r) & F_AC) |
                                     vk_from_overflow((a ^ r) & (x ^ r) & 0x80, r, vd.vk));
}

// Subtraction is A + ~x + (1 - borrow) in the ALU: CY is the inverted carry (a borrow), AC the
// carry out of bit 3 of that addition.
[[gnu::always_inline]] inline std::uint8_t flags_sub(const VariantData& vd, unsigned a, unsigned x, unsigned r) {
    return static_cast<std::uint8_t>(vd.szp[r & 0xFF] | ((r >> 8) & F_CY) | (~(a ^ x ^ r) & F_AC) |
                                     vk_from_overflow((a ^ x) & (a ^ r) & 0x80, r, vd.vk));
}

// The flag register after an instruction that computed `computed`: the bits the table says it
// writes come from `computed`, the others stay.
template <std::uint8_t Flags>
[[gnu::always_inline]] inline void write_flags(std::uint8_t& f, unsigned computed) {
    if constexpr (Flags == isa::kAllFlags)
        f = static_cast<std::uint8_t>(computed);  // bit 3 is 0 in both
    else
        f = static_cast<std::uint8_t>((f & ~Flags) | (computed & Flags));
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

// Device pages, ROM writes, unmapped pages; with debug hooks every access (the loop then has no
// pages), and the hooks see the data accesses (not the opcode and operand fetches).
std::uint8_t I8085::slow_read(std::uint16_t addr, std::uint64_t t, bool data) {
    t_ = t;
    const std::uint8_t v = bus_.read(addr, t);
    if (data && hooks_) hooks_->on_read(*this, addr, v);
    return v;
}

void I8085::slow_write(std::uint16_t addr, std::uint8_t value, std::uint64_t t) {
    t_ = t;
    bus_.write(addr, value, t);
    if (hooks_) hooks_->on_write(*this, addr, value);
}

// A handler that changes the memory map ends the batch: the next one picks the flat or paged loop.
std::uint8_t I8085::io_in(std::uint8_t port, std::uint64_t t) {
    const std::uint64_t maps = bus_.map_changes();
    const std::uint8_t v = bus_.in(port, t);
    if (bus_.map_changes() != maps) request_stop_batch();
    if (hooks_) hooks_->on_io(*this, port, v, false);
    return v;
}
void I8085::io_out(std::uint8_t port, std::uint8_t value, std::uint64_t t) {
    const std::uint64_t maps = bus_.map_changes();
    bus_.out(port, value, t);
    if (bus_.map_changes() != maps) request_stop_batch();
    if (hooks_) hooks_->on_io(*this, port, value, true);
}

void I8085::halt_entered() {
    halted_ = true;
    if (on_halt) on_halt();
}


// ---- the instruction loop ------------------------------------------------------------------------
// Registers live in locals for the whole batch; they are written back at its end and around the
// debug hooks. Memory: the page table's direct pointers, with a call only for device, ROM-write
// and unmapped-write pages (and, with debug hooks, for every access: the loop then reads and
// writes through a page table with no pages). The T-state counter is advanced by the opcode's
// base T-states before its body runs (plus the extra of a taken condition), so a handler called
// from the body sees t - 3 = the first T-state of the instruction's last machine cycle (see
// tstates()).
//
// Each opcode's body is `body(ic<op>)`: the decoding of asm/isa.h's entry (kDecoded) picks, at
// compile time, the operation, its registers, its immediate bytes, its transfer of control and
// the flags it writes. The per-variant label table sends the 8080's opcodes to the bodies of their
// alias8080, and the per-variant data (VariantData) carries the rest of the difference.

// Opcodes 00H-FFH as two hex digits, for the loop's labels.
#define ALP85_HEX16(X, h)                                                                             \
    X(h##0) X(h##1) X(h##2) X(h##3) X(h##4) X(h##5) X(h##6) X(h##7) X(h##8) X(h##9) X(h##A) X(h##B) \
    X(h##C) X(h##D) X(h##E) X(h##F)
#define ALP85_HEX256(X)                                                                                \
    ALP85_HEX16(X, 0) ALP85_HEX16(X, 1) ALP85_HEX16(X, 2) ALP85_HEX16(X, 3) ALP85_HEX16(X, 4)          \
    ALP85_HEX16(X, 5) ALP85_HEX16(X, 6) ALP85_HEX16(X, 7) ALP85_HEX16(X, 8) ALP85_HEX16(X, 9)          \
    ALP85_HEX16(X, A) ALP85_HEX16(X, B) ALP85_HEX16(X, C) ALP85_HEX16(X, D) ALP85_HEX16(X, E)          \
    ALP85_HEX16(X, F)
#define ALP85_BODY_ADDRESS(n) &&op_##n,
// One opcode: its body, then the dispatch of the next one (threaded: one indirect jump per body).
#define ALP85_BODY(n)         \
    op_##n : s.template body<0x##n>(); \
    goto* s.next();
#define ALP85_INLINE __attribute__((always_inline))

namespace {
// With debug hooks every access goes through the slow path: a page table with no pages.
constexpr std::array<std::uint8_t*, 256> kNoPages{};

struct Dispatch {
    const void* label[256];  // the body of each opcode, the 8080's aliases resolved
    VariantData vd;          // beside the labels: one base register for dispatch and data
};
}  // namespace

// The state of one batch: the registers, the counter and the memory's tables, all in one local
// object of execute() whose address never leaves it, so that the compiler keeps its fields in host
// registers. Its member functions are the loop's primitives and each opcode's body.
template <auto M>
struct I8085::Loop {
    static constexpr bool kFenced = M == Mem::Fenced;  // a fetch fence or debug hooks

    I8085& cpu;
    const Dispatch& kd;
    const VariantData& vd;
    const bool debug;  // debug hooks installed (kFenced only)
    const std::uint8_t* const* const code_pages;
    const std::uint8_t* const* const rp;
    std::uint8_t* const* const wp;
    std::uint8_t* const mem;  // Flat: all 64 KiB plain RAM in one block
    // Fenced: opcodes are fetched through exec_pages_ (null where a page holds a fenced address).
    const std::uint8_t* const* const xp;
    const std::bitset<0x10000>* const fence;
    const void* const end;  // the label that ends the batch
    std::uint16_t ipc;      // the instruction running, for fence_previous

    std::uint8_t a, f, b, c, d, e, h, l;
    std::uint16_t sp, pc;
    std::uint8_t op = 0;
    // One counter for T-states and instructions, counting down to the batch's end:
    //   rem = (L - T) * 2^kCountBits - N
    // with T the T-states and N the instructions run in this batch (N < 2^kCountBits, as a batch is
    // at most kBatchTStates long and every instruction takes at least 4 T-states) and L the
    // batch's limit, both from t0. rem <= 0 exactly when T >= L. One table entry per opcode adds
    // its T-states and one instruction at once (VariantData::cost).
    const std::uint64_t t0, n0;
    std::int64_t stop, rem;

    Loop(I8085& cpu_, const Dispatch& kd_, bool debug_, const void* end_)
        : cpu(cpu_), kd(kd_), vd(kd_.vd), debug(debug_), code_pages(cpu_.bus_.read_pages()),
          rp(debug_ ? kNoPages.data() : cpu_.bus_.read_pages()),
          wp(debug_ ? kNoPages.data() : cpu_.bus_.write_pages()), mem(cpu_.bus_.flat_ram()),
          xp(debug_ ? kNoPages.data() : cpu_.exec_pages_.data()), fence(debug_ ? nullptr : cpu_.fence_), end(end_),
          ipc(cpu_.fence_prev_), a(cpu_.r_.a), f(cpu_.r_.f), b(cpu_.r_.b), c(cpu_.r_.c), d(cpu_.r_.d),
          e(cpu_.r_.e), h(cpu_.r_.h), l(cpu_.r_.l), sp(cpu_.r_.sp), pc(cpu_.r_.pc), t0(cpu_.t_),
          n0(cpu_.instructions_), stop(limit_rel(cpu_.limit_)), rem(stop) {}

    ALP85_INLINE std::int64_t limit_rel(std::uint64_t lim) const {
        if (lim <= t0) return 0;
        const std::uint64_t dt = lim - t0;
        return static_cast<std::int64_t>(dt < kBatchTStates ? dt : kBatchTStates) << kCountBits;
    }
    // T-states now, and the instructions run; a new limit from limit_; the batch ends after this
    // instruction.
    ALP85_INLINE std::uint64_t tnow() const { return t0 + (static_cast<std::uint64_t>(stop - rem) >> kCountBits); }
    ALP85_INLINE std::uint64_t nnow() const {
        return n0 + (static_cast<std::uint64_t>(stop - rem) & ((std::uint64_t{1} << kCountBits) - 1));
    }
    ALP85_INLINE void relimit() {
        const std::int64_t done_so_far = stop - rem;
        stop = limit_rel(cpu.limit_);
        rem = stop - done_so_far;
    }
    ALP85_INLINE void end_batch() {
        rem -= stop;
        stop = 0;
    }
    ALP85_INLINE void sync(unsigned back) { cpu.t_ = tnow() - back; }
    ALP85_INLINE void save_regs() {
        Registers& r = cpu.r_;
        r.a = a, r.f = f, r.b = b, r.c = c, r.d = d, r.e = e, r.h = h, r.l = l;
        r.sp = sp, r.pc = pc, cpu.t_ = tnow(), cpu.instructions_ = nnow();
    }

    // ---- memory: opcode and operand fetches, data reads and writes -----------------------------
    ALP85_INLINE std::uint8_t fetch(std::uint16_t addr, std::uint64_t when) {
        if constexpr (M == Mem::Flat) {
            return mem[addr];
        } else {
            if (const std::uint8_t* const page = rp[addr >> 8]) [[likely]]
                return page[addr & 0xFF];
            const std::uint8_t v = cpu.slow_read(addr, when, false);
            relimit();
            return v;
        }
    }
    ALP85_INLINE std::uint8_t rd(std::uint16_t addr) {
        if constexpr (M == Mem::Flat) {
            return mem[addr];
        } else {
            if (const std::uint8_t* const page = rp[addr >> 8]) [[likely]]
                return page[addr & 0xFF];
            const std::uint8_t v = cpu.slow_read(addr, tnow() - 3, true);
            relimit();
            return v;
        }
    }
    ALP85_INLINE void wr(std::uint16_t addr, unsigned value) {
        const auto v = static_cast<std::uint8_t>(value);
        if constexpr (M == Mem::Flat) {
            mem[addr] = v;
        } else {
            if (std::uint8_t* const page = wp[addr >> 8]) [[likely]] {
                page[addr & 0xFF] = v;
            } else {
                cpu.slow_write(addr, v, tnow() - 3);
                relimit();
            }
        }
    }
    ALP85_INLINE std::uint8_t imm8() {
        const std::uint8_t v = fetch(pc, tnow() - 3);
        pc = static_cast<std::uint16_t>(pc + 1);
        return v;
    }
    ALP85_INLINE std::uint16_t imm16() {
        const std::uint8_t lo = fetch(pc, tnow() - 3);
        const std::uint8_t hi = fetch(static_cast<std::uint16_t>(pc + 1), tnow() - 3);
        pc = static_cast<std::uint16_t>(pc + 2);
        return static_cast<std::uint16_t>((hi << 8) | lo);
    }
    ALP85_INLINE void push16(unsigned v) {
        wr(static_cast<std::uint16_t>(sp - 1), v >> 8);
        wr(static_cast<std::uint16_t>(sp - 2), v & 0xFF);
        sp = static_cast<std::uint16_t>(sp - 2);
    }
    ALP85_INLINE std::uint16_t pop16() {
        const std::uint8_t lo = rd(sp);
        const std::uint8_t hi = rd(static_cast<std::uint16_t>(sp + 1));
        sp = static_cast<std::uint16_t>(sp + 2);
        return static_cast<std::uint16_t>((hi << 8) | lo);
    }

    // ---- registers by their encoding's number --------------------------------------------------
    template <int N>
    ALP85_INLINE std::uint8_t& reg() {
        static_assert(N >= 0 && N < 8 && N != kM);
        if constexpr (N == 0) return b;
        else if constexpr (N == 1) return c;
        else if constexpr (N == 2) return d;
        else if constexpr (N == 3) return e;
        else if constexpr (N == 4) return h;
        else if constexpr (N == 5) return l;
        else return a;
    }
    ALP85_INLINE std::uint16_t hl() const { return static_cast<std::uint16_t>((h << 8) | l); }
    template <int N>
    ALP85_INLINE unsigned get_pair() const {
        if constexpr (N == 0) return static_cast<unsigned>(b << 8 | c);
        else if constexpr (N == 1) return static_cast<unsigned>(d << 8 | e);
        else if constexpr (N == 2) return static_cast<unsigned>(h << 8 | l);
        else return sp;
    }
    template <int N>
    ALP85_INLINE void set_pair(unsigned v) {
        if constexpr (N == 0) b = static_cast<std::uint8_t>(v >> 8), c = static_cast<std::uint8_t>(v);
        else if constexpr (N == 1) d = static_cast<std::uint8_t>(v >> 8), e = static_cast<std::uint8_t>(v);
        else if constexpr (N == 2) h = static_cast<std::uint8_t>(v >> 8), l = static_cast<std::uint8_t>(v);
        else sp = static_cast<std::uint16_t>(v);
    }
    // An 8-bit operand: a register, M (the byte at HL) or the immediate byte.
    template <int N>
    ALP85_INLINE std::uint8_t operand() {
        if constexpr (N == kImm) return imm8();
        else if constexpr (N == kM) return rd(hl());
        else return reg<N>();
    }

    // ---- counted delay loops (JNZ taken back onto them) -----------------------------------------
    ALP85_INLINE void countdown() {
        // "L: DCR r / JNZ L" with the JNZ just taken: the iterations that keep r non-zero and
        // start before the batch's limit are done at once. Nothing else can happen inside such a
        // loop (no memory or I/O access, pins change only between batches), so registers, flags,
        // T-states and the instruction count end exactly as instruction by instruction.
        const unsigned per = static_cast<unsigned>((vd.cost[0x05] + vd.cost[0xC2] + vd.taken[0xC2]) >> kCountBits);
        const std::uint8_t* const code = code_pages[pc >> 8];
        if (!code || !code_pages[static_cast<std::uint16_t>(pc + 3) >> 8] || rem <= 0) return;
        if constexpr (kFenced) {  // a breakpoint inside the loop sees every iteration
            for (unsigned k = 0; k < 4; ++k)
                if (fence && (*fence)[static_cast<std::uint16_t>(pc + k)]) return;
        }
        const std::uint64_t fit = static_cast<std::uint64_t>((stop >> kCountBits) - ((stop - rem) >> kCountBits)) / per;
        const auto run_down = [&](std::uint8_t& r) ALP85_INLINE {
            const unsigned left = (r - 1u) & 0xFFu;  // iterations whose DCR leaves r non-zero
            const unsigned m = fit < left ? static_cast<unsigned>(fit) : left;
            if (!m) return;
            const unsigned x = static_cast<std::uint8_t>(r - m + 1);  // before the last DCR
            r = static_cast<std::uint8_t>(x - 1);
            f = static_cast<std::uint8_t>((f & ~kDecoded<0x05>.flags) | vd.dcr[x]);
            rem -= (static_cast<std::int64_t>(per) * m << kCountBits) + 2 * m;
        };
        switch (code[pc & 0xFF]) {
            case 0x05: run_down(b); break;
            case 0x0D: run_down(c); break;
            case 0x15: run_down(d); break;
            case 0x1D: run_down(e); break;
            case 0x25: run_down(h); break;
            case 0x2D: run_down(l); break;
            case 0x3D: run_down(a); break;
            default: break;  // another instruction (DCR M reads memory: not taken over)
        }
    }
    ALP85_INLINE void countdown16() {
        // "L: DCX rp / MOV A,r / ORA r' / JNZ L" (r, r' the two halves of rp, in either order)
        // with the JNZ just taken: a 16-bit delay loop. The iterations that keep rp non-zero and
        // start before the batch's limit are done at once. After each iteration A = r | r' and the
        // flags are ORA's (DCX's K on the 8085 is overwritten by ORA), so only the last
        // iteration's rp matters; nothing inside touches memory or I/O.
        const unsigned per = static_cast<unsigned>(
            (vd.cost[0x0B] + vd.cost[0x78] + vd.cost[0xB0] + vd.cost[0xC2] + vd.taken[0xC2]) >> kCountBits);
        const std::uint8_t* const code = code_pages[pc >> 8];
        const std::uint8_t* const code_end = code_pages[static_cast<std::uint16_t>(pc + 5) >> 8];
        if (!code || !code_end || rem <= 0) return;
        if constexpr (kFenced) {
            for (unsigned k = 0; k < 6; ++k)
                if (fence && (*fence)[static_cast<std::uint16_t>(pc + k)]) return;
        }
        const auto code_at = [&](unsigned k) ALP85_INLINE {
            const unsigned at = pc + k;
            return (at & 0xFF00) == (pc & 0xFF00) ? code[at & 0xFF] : code_end[at & 0xFF];
        };
        const std::uint8_t dcx = code[pc & 0xFF], mov = code_at(1), ora = code_at(2);
        // DCX B/D/H is 0B/1B/2B; MOV A,r is 78+r; ORA r is B0+r; registers B C D E H L = 0..5.
        if ((dcx & 0xCF) != 0x0B || dcx == 0x3B) return;
        const unsigned hi = (dcx >> 4) * 2, lo = hi + 1;
        const unsigned r1 = mov - 0x78u, r2 = ora - 0xB0u;
        if (!((r1 == hi && r2 == lo) || (r1 == lo && r2 == hi))) return;
        const std::uint64_t fit = static_cast<std::uint64_t>((stop >> kCountBits) - ((stop - rem) >> kCountBits)) / per;
        const auto run_down = [&](std::uint8_t& rh, std::uint8_t& rl) ALP85_INLINE {
            const unsigned pair = static_cast<unsigned>(rh << 8 | rl);
            const unsigned left = (pair - 1u) & 0xFFFFu;  // iterations leaving rp non-zero
            const unsigned m = fit < left ? static_cast<unsigned>(fit) : left;
            if (!m) return;
            const unsigned v = pair - m;
            rh = static_cast<std::uint8_t>(v >> 8);
            rl = static_cast<std::uint8_t>(v);
            a = static_cast<std::uint8_t>(rh | rl);
            write_flags<kDecoded<0xB0>.flags>(f, vd.szp[a]);
            rem -= (static_cast<std::int64_t>(per) * m << kCountBits) + 4 * m;
        };
        switch (dcx) {
            case 0x0B: run_down(b, c); break;
            case 0x1B: run_down(d, e); break;
            default: run_down(h, l); break;
        }
    }

    // ---- one opcode's body, from its decoding ----------------------------------------------------
    template <std::uint8_t kOp>
    ALP85_INLINE void body() {
        constexpr Decoded x = kDecoded<kOp>;
        constexpr std::uint8_t kFlags = x.flags;
        // The condition of a conditional transfer (always true for the others).
        [[maybe_unused]] const bool taken = x.cond_flag == 0 || ((f & x.cond_flag) != 0) == x.cond_set;
        // The extra T-states of a taken condition (none for an unconditional transfer).
        constexpr bool kChargeTaken = op_tstates(Variant::I8085, kOp, true) != op_tstates(Variant::I8085, kOp) ||
                                      op_tstates(Variant::I8080, kOp, true) != op_tstates(Variant::I8080, kOp);
        if constexpr (x.kind == Kind::Transfer) {
            if constexpr (x.flow == Flow::Jump || x.flow == Flow::JumpIf) {
                if (taken) {
                    [[maybe_unused]] const std::uint16_t from = static_cast<std::uint16_t>(pc - 1);
                    pc = imm16();
                    if constexpr (kChargeTaken) rem -= vd.taken[kOp];
                    if constexpr (kOp == 0xC2) {  // JNZ back onto the byte before it: a delay loop?
                        if (static_cast<std::uint16_t>(from - pc) <= 3 && cpu.fast_loops_ && !debug) [[unlikely]] {
                            if (pc == static_cast<std::uint16_t>(from - 1)) countdown();
                            else if (pc == static_cast<std::uint16_t>(from - 3)) countdown16();
                        }
                    }
                } else {
                    pc = static_cast<std::uint16_t>(pc + x.imm);
                }
            } else if constexpr (x.flow == Flow::Call || x.flow == Flow::CallIf) {
                if (taken) {
                    const std::uint16_t to = imm16();
                    if constexpr (kChargeTaken) rem -= vd.taken[kOp];
                    push16(pc);
                    pc = to;
                } else {
                    pc = static_cast<std::uint16_t>(pc + x.imm);
                }
            } else if constexpr (x.flow == Flow::Return || x.flow == Flow::ReturnIf) {
                if (taken) {
                    if constexpr (kChargeTaken) rem -= vd.taken[kOp];
                    pc = pop16();
                }
            } else if constexpr (x.flow == Flow::Restart || x.flow == Flow::RestartIf) {
                if (taken) {
                    if constexpr (kChargeTaken) rem -= vd.taken[kOp];
                    push16(pc);
                    pc = x.vector;
                }
            } else if constexpr (x.flow == Flow::JumpIndirect) {
                pc = hl();
            } else if constexpr (x.flow == Flow::Halt) {
                sync(0);
                cpu.halt_entered();
                end_batch();
            }
        } else if constexpr (x.kind == Kind::Nop) {
        } else if constexpr (x.kind == Kind::Mov || x.kind == Kind::Mvi) {
            if constexpr (x.dst == kM) {
                const std::uint8_t v = operand<x.src>();
                wr(hl(), v);
            } else {
                reg<x.dst>() = operand<x.src>();
            }
        } else if constexpr (x.kind == Kind::Lxi) {
            const std::uint8_t lo = imm8();
            const std::uint8_t hi = imm8();
            set_pair<x.dst>(static_cast<unsigned>(hi << 8 | lo));
            if constexpr (x.dst == 3) cpu.sp_load_ = 0x10000u | sp;
        } else if constexpr (x.kind == Kind::Stax) {
            wr(static_cast<std::uint16_t>(get_pair<x.dst>()), a);
        } else if constexpr (x.kind == Kind::Ldax) {
            a = rd(static_cast<std::uint16_t>(get_pair<x.dst>()));
        } else if constexpr (x.kind == Kind::Inx || x.kind == Kind::Dcx) {
            // The 8085's K: the 16-bit carry (INX of FFFFH) or borrow (DCX of 0000H), bit 16.
            const unsigned v = x.kind == Kind::Inx ? get_pair<x.dst>() + 1u : get_pair<x.dst>() - 1u;
            write_flags<kFlags>(f, (v >> 11) & vd.vk);
            set_pair<x.dst>(v & 0xFFFF);
        } else if constexpr (x.kind == Kind::Inr || x.kind == Kind::Dcr) {
            const std::uint8_t v = operand<x.dst>();
            const auto r = static_cast<std::uint8_t>(x.kind == Kind::Inr ? v + 1 : v - 1);
            // Only the bits the table says INR and DCR write are in these tables.
            f = static_cast<std::uint8_t>((f & ~kFlags) | (x.kind == Kind::Inr ? vd.inr[v] : vd.dcr[v]));
            if constexpr (x.dst == kM) wr(hl(), r);
            else reg<x.dst>() = r;
        } else if constexpr (x.kind == Kind::Dad) {
            const unsigned v = hl() + get_pair<x.dst>();
            write_flags<kFlags>(f, v >> 16);
            set_pair<2>(v & 0xFFFF);
        } else if constexpr (x.kind == Kind::Rlc) {
            const unsigned cy = a >> 7;
            a = static_cast<std::uint8_t>((a << 1) | cy);
            write_flags<kFlags>(f, cy);
        } else if constexpr (x.kind == Kind::Rrc) {
            const unsigned cy = a & 1;
            a = static_cast<std::uint8_t>((a >> 1) | (cy << 7));
            write_flags<kFlags>(f, cy);
        } else if constexpr (x.kind == Kind::Ral) {
            const unsigned cy = a >> 7;
            a = static_cast<std::uint8_t>((a << 1) | (f & F_CY));
            write_flags<kFlags>(f, cy);
        } else if constexpr (x.kind == Kind::Rar) {
            const unsigned cy = a & 1;
            a = static_cast<std::uint8_t>((a >> 1) | ((f & F_CY) << 7));
            write_flags<kFlags>(f, cy);
        } else if constexpr (x.kind == Kind::Daa) {
            // Add 06H if the low digit is above 9 or AC is set, 60H if A is above 99H or CY is
            // set. CY is set by the second correction (never cleared); AC is the carry out of bit
            // 3 of the add.
            unsigned corr = 0, cy = f & F_CY;
            if ((a & 0x0F) > 9 || (f & F_AC)) corr |= 0x06;
            if (a > 0x99 || cy) {
                corr |= 0x60;
                cy = F_CY;
            }
            const unsigned r = a + corr;
            write_flags<kFlags>(f, vd.szp[r & 0xFF] | cy | ((a ^ corr ^ r) & F_AC) |
                                       vk_from_overflow((a ^ r) & (corr ^ r) & 0x80, r, vd.vk));
            a = static_cast<std::uint8_t>(r);
        } else if constexpr (x.kind == Kind::Cma) {
            a = static_cast<std::uint8_t>(~a);
        } else if constexpr (x.kind == Kind::Stc) {
            write_flags<kFlags>(f, F_CY);
        } else if constexpr (x.kind == Kind::Cmc) {
            write_flags<kFlags>(f, ~f);
        } else if constexpr (x.kind == Kind::Add || x.kind == Kind::Adc) {
            const unsigned v = operand<x.src>();
            const unsigned r = a + v + (x.kind == Kind::Adc ? f & F_CY : 0u);
            write_flags<kFlags>(f, flags_add(vd, a, v, r));
            a = static_cast<std::uint8_t>(r);
        } else if constexpr (x.kind == Kind::Sub || x.kind == Kind::Sbb || x.kind == Kind::Cmp) {
            const unsigned v = operand<x.src>();
            const unsigned r = a - v - (x.kind == Kind::Sbb ? f & F_CY : 0u);
            write_flags<kFlags>(f, flags_sub(vd, a, v, r));
            if constexpr (x.kind != Kind::Cmp) a = static_cast<std::uint8_t>(r);
        } else if constexpr (x.kind == Kind::Ana) {
            // The 8085 always sets AC; the 8080 sets it to bit 3 of (A OR operand). CY cleared.
            const unsigned v = operand<x.src>();
            const unsigned ac = vd.ana_ac | (((a | v) & 0x08) << 1);
            a = static_cast<std::uint8_t>(a & v);
            write_flags<kFlags>(f, vd.szp[a] | ac);
        } else if constexpr (x.kind == Kind::Xra || x.kind == Kind::Ora) {
            const unsigned v = operand<x.src>();
            a = static_cast<std::uint8_t>(x.kind == Kind::Xra ? a ^ v : a | v);
            write_flags<kFlags>(f, vd.szp[a]);
        } else if constexpr (x.kind == Kind::Shld || x.kind == Kind::Shlx) {
            const std::uint16_t at = x.kind == Kind::Shld ? imm16() : static_cast<std::uint16_t>(get_pair<1>());
            wr(at, l);
            wr(static_cast<std::uint16_t>(at + 1), h);
        } else if constexpr (x.kind == Kind::Lhld || x.kind == Kind::Lhlx) {
            const std::uint16_t at = x.kind == Kind::Lhld ? imm16() : static_cast<std::uint16_t>(get_pair<1>());
            l = rd(at);
            h = rd(static_cast<std::uint16_t>(at + 1));
        } else if constexpr (x.kind == Kind::Sta) {
            wr(imm16(), a);
        } else if constexpr (x.kind == Kind::Lda) {
            a = rd(imm16());
        } else if constexpr (x.kind == Kind::Push) {
            if constexpr (x.dst == 3) push16(static_cast<unsigned>(a << 8 | f));  // PSW
            else push16(get_pair<x.dst>());
        } else if constexpr (x.kind == Kind::Pop) {
            const std::uint8_t lo = rd(sp);
            sp = static_cast<std::uint16_t>(sp + 1);
            const std::uint8_t hi = rd(sp);
            sp = static_cast<std::uint16_t>(sp + 1);
            if constexpr (x.dst == 3) {  // PSW: the flag byte as the variant holds it
                write_flags<kFlags>(f, (lo & vd.psw_keep) | vd.psw_set);
                a = hi;
            } else {
                set_pair<x.dst>(static_cast<unsigned>(hi << 8 | lo));
            }
        } else if constexpr (x.kind == Kind::Xthl) {
            const std::uint8_t lo = rd(sp);
            const auto s1 = static_cast<std::uint16_t>(sp + 1);
            const std::uint8_t hi = rd(s1);
            wr(sp, l);
            wr(s1, h);
            l = lo;
            h = hi;
        } else if constexpr (x.kind == Kind::Xchg) {
            std::swap(d, h);
            std::swap(e, l);
        } else if constexpr (x.kind == Kind::Sphl) {
            sp = hl();
            cpu.sp_load_ = 0x10000u | sp;
        } else if constexpr (x.kind == Kind::Out) {
            const std::uint8_t port = imm8();
            sync(3);
            cpu.io_out(port, a, cpu.t_);
            relimit();
        } else if constexpr (x.kind == Kind::In) {
            const std::uint8_t port = imm8();
            sync(3);
            a = cpu.io_in(port, cpu.t_);
            relimit();
        } else if constexpr (x.kind == Kind::Ei) {
            cpu.ie_ = true;
            cpu.ei_delay_ = true;
            end_batch();
        } else if constexpr (x.kind == Kind::Di) {
            cpu.ie_ = false;
            cpu.ei_delay_ = false;
        } else if constexpr (x.kind == Kind::Rim) {
            a = cpu.rim();
        } else if constexpr (x.kind == Kind::Sim) {
            sync(0);
            cpu.sim(a);
            end_batch();
        } else if constexpr (x.kind == Kind::Dsub) {
            // HL = HL - BC. The ALU does it as SUB L,C then SBB H,B, so S, P, AC, CY, V and K
            // come from the high byte; Z reflects the whole 16-bit result.
            const unsigned lo = static_cast<unsigned>(l) - c;
            const unsigned hi = static_cast<unsigned>(h) - b - ((lo >> 8) & 1);
            const unsigned fl = flags_sub(vd, h, b, hi);
            write_flags<kFlags>(f, (fl & ~F_Z) | (((hi | lo) & 0xFF) == 0 ? F_Z : 0));
            h = static_cast<std::uint8_t>(hi);
            l = static_cast<std::uint8_t>(lo);
        } else if constexpr (x.kind == Kind::Arhl) {
            // HL shifted right arithmetically; CY = old bit 0.
            const unsigned cy = l & 1;
            l = static_cast<std::uint8_t>((l >> 1) | (h << 7));
            h = static_cast<std::uint8_t>((h >> 1) | (h & 0x80));
            write_flags<kFlags>(f, cy);
        } else if constexpr (x.kind == Kind::Rdel) {
            // DE rotated left through CY; V = old bit 15 XOR old bit 14 (the sign changed).
            const unsigned de = get_pair<1>();
            const unsigned v = ((de >> 15) ^ (de >> 14)) & 1;
            set_pair<1>(((de << 1) | (f & F_CY)) & 0xFFFF);
            write_flags<kFlags>(f, (de >> 15) | (v << 1));
        } else if constexpr (x.kind == Kind::Ldhi || x.kind == Kind::Ldsi) {
            const unsigned base = x.kind == Kind::Ldhi ? get_pair<2>() : get_pair<3>();
            set_pair<1>((base + imm8()) & 0xFFFF);
        }
    }

    // ---- dispatch ----------------------------------------------------------------------------------
    // The next instruction's body, or the end of the batch.
    ALP85_INLINE const void* next() {
        if (rem <= 0) [[unlikely]]
            return end;
        if constexpr (kFenced) {
            if (const std::uint8_t* const page = xp[pc >> 8]) [[likely]] {
                op = page[pc & 0xFF];  // a page with no fenced address: no test
            } else {
                if (fence && (*fence)[pc] && (pc != cpu.pass_pc_ || tnow() != cpu.pass_t_)) [[unlikely]] {
                    cpu.fence_prev_ = ipc;
                    cpu.fence_hit_ = true;
                    cpu.deadline_ = tnow();
                    return end;
                }
                if (fence && !cpu.fence_seen_[pc >> 8]) cpu.note_fenced_page(pc >> 8);
                op = fetch(pc, tnow());
            }
            ipc = pc;
        } else {
            op = fetch(pc, tnow());  // the opcode fetch starts now
        }
        pc = static_cast<std::uint16_t>(pc + 1);
        rem -= vd.cost[op];
        return kd.label[op];
    }
};

template <I8085::Mem M>
void I8085::execute() {
    // The labels of the bodies, and per variant the table of where each opcode goes.
    static const void* const kBodies[256] = {ALP85_HEX256(ALP85_BODY_ADDRESS)};
    static const std::array<Dispatch, 2> kDispatch = [] {
        std::array<Dispatch, 2> d{};
        for (unsigned v = 0; v < 2; ++v) {
            d[v].vd = kVariants[v];
            for (unsigned i = 0; i < 256; ++i) d[v].label[i] = kBodies[d[v].vd.body[i]];
        }
        return d;
    }();
    // Read once through a volatile: the compiler then keeps the address in one register instead of
    // recomputing it from the table's base and the variant at every use (two registers).
    const Dispatch* volatile chosen = &kDispatch[variant_ == Variant::I8080 ? 1 : 0];
    Loop<M> s(*this, *chosen, M == Mem::Fenced && hooks_, &&done);
    goto* s.next();
    ALP85_HEX256(ALP85_BODY)
done:
    s.save_regs();
}

#undef ALP85_HEX16
#undef ALP85_HEX256
#undef ALP85_BODY_ADDRESS
#undef ALP85_BODY
#undef ALP85_INLINE

// ---- batches and interrupts --------------------------------------------------------------------
std::uint64_t I8085::run(std::uint64_t deadline) {
    fence_hit_ = false;
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
        if (hooks_ && !hooks_->before_instruction(*this)) {  // the debug hooks' batches are one instruction
            deadline_ = t_;
            break;
        }
        const std::uint64_t before = instructions_;
        if (after_ei) {  // exactly one instruction after EI before any maskable interrupt
            ei_delay_ = false;
            limit_ = t_ + 1;
        } else {
            limit_ = hooks_ ? t_ + 1 : deadline_;
        }
        // Debug hooks (called above before each instruction, which then runs alone in its batch, so
        // that the loop never writes its registers back for them) or a debugger's fetch fence: the
        // fenced loop. Plain RAM over all 64 KiB (a
        // CP/M machine, the bare-core benchmarks): no page table. Chosen per batch; a mapping
        // changed by an I/O handler ends the batch (io_out, io_in).
        if (hooks_ || fence_) {
            if (!hooks_ && exec_pages_maps_ != bus_.map_changes()) map_exec_pages();
            execute<Mem::Fenced>();
        } else if (bus_.flat_ram()) {
            execute<Mem::Flat>();
        } else {
            execute<Mem::Paged>();
        }
        if (after_ei && instructions_ == before) ei_delay_ = true;  // stopped before it ran
    }
    limit_ = 0;
    return t_ - start;
}

void I8085::set_fetch_fence(const std::bitset<0x10000>* fence) {
    // Every page starts unseen (fetched through the test) and is looked at once, when an opcode is
    // first fetched there: scanning all 65,536 addresses here was most of a debugger's stop.
    fence_ = fence;
    fence_seen_.reset();
    fenced_pages_.reset();
    exec_pages_maps_ = ~std::uint64_t{0};
}

void I8085::note_fenced_page(unsigned page) {
    fence_seen_[page] = true;
    for (unsigned a = page << 8; a < (page + 1) << 8; ++a)
        if ((*fence_)[a]) {
            fenced_pages_[page] = true;
            return;
        }
    // No fenced address: its opcodes go through the page table from the next fetch on. A mapping
    // changed since exec_pages_ were made is caught at the next batch (map_exec_pages).
    exec_pages_[page] = bus_.read_pages()[page];
}

void I8085::map_exec_pages() {
    const std::uint8_t* const* const rp = bus_.read_pages();
    for (unsigned p = 0; p < 256; ++p) exec_pages_[p] = fence_seen_[p] && !fenced_pages_[p] ? rp[p] : nullptr;
    exec_pages_maps_ = bus_.map_changes();
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
