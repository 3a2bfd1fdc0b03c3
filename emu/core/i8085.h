// Intel 8085A CPU (and, chosen at construction, the Intel 8080A it is compatible with).
//
// Pins modelled (8085):  A8-A15/AD0-AD7 and IO/M, RD, WR through the Bus (whole bus cycles, not
//   individual T-states); TRAP, RST 7.5, RST 6.5, RST 5.5, INTR inputs; INTA as a callback that
//   supplies the interrupting instruction; SID input, SOD output (callback on change); HOLD input
//   and HLDA output (callback on change). T-states are counted per instruction from the opcode
//   table asm/isa.h (the data sheets' figures).
// Not emulated: READY/wait states, RESET OUT, CLK OUT, S0/S1/ALE status timing; the position of
//   each access inside an instruction is approximated (see tstates()); INTA only accepts RST n and
//   CALL (any other byte is taken as a NOP acknowledge: 6 T-states, IE stays cleared); HOLD is
//   granted at instruction boundaries only. On the 8080 variant TRAP, RST 5.5-7.5, SID and SOD do
//   not exist: their setters are ignored and SOD stays low.
// docs/cpu.md describes the undocumented 8085 behaviour and where each rule comes from.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "emu/core/bus.h"

namespace alp85 {

enum class Variant : std::uint8_t { I8085, I8080 };

// Register file with data-sheet names. F is the flag byte of PSW exactly as PUSH PSW stores it.
struct Registers {
    std::uint8_t a = 0, f = 0, b = 0, c = 0, d = 0, e = 0, h = 0, l = 0;
    std::uint16_t sp = 0, pc = 0;
    std::uint16_t bc() const { return static_cast<std::uint16_t>(b << 8 | c); }
    std::uint16_t de() const { return static_cast<std::uint16_t>(d << 8 | e); }
    std::uint16_t hl() const { return static_cast<std::uint16_t>(h << 8 | l); }
    void set_bc(std::uint16_t v) { b = v >> 8; c = v & 0xFF; }
    void set_de(std::uint16_t v) { d = v >> 8; e = v & 0xFF; }
    void set_hl(std::uint16_t v) { h = v >> 8; l = v & 0xFF; }
};

class I8085;

// Debugger hooks. With hooks installed run() calls before_instruction between instructions and
// runs each alone in its fenced loop, which then reaches memory only through the calls that report
// to them; with none installed the loops contain no checks for them at all.
class DebugHooks {
public:
    virtual ~DebugHooks() = default;
    // Before each instruction (registers are current). Return false to stop the run before it.
    virtual bool before_instruction(I8085& cpu) = 0;
    // Data accesses of instructions: memory operands and stack traffic, not opcode or operand
    // fetches (use before_instruction for those). Registers in regs() are not current here.
    // Call cpu.request_stop() to end the run after the current instruction.
    virtual void on_read(I8085& cpu, std::uint16_t addr, std::uint8_t value) { (void)cpu, (void)addr, (void)value; }
    virtual void on_write(I8085& cpu, std::uint16_t addr, std::uint8_t value) { (void)cpu, (void)addr, (void)value; }
    virtual void on_io(I8085& cpu, std::uint8_t port, std::uint8_t value, bool is_out) {
        (void)cpu, (void)port, (void)value, (void)is_out;
    }
};

class I8085 {
public:
    explicit I8085(Bus& bus, Variant variant = Variant::I8085);

    Variant variant() const { return variant_; }
    Bus& bus() { return bus_; }

    // RESET IN: PC = 0, IE cleared, RST 5.5-7.5 masked, 7.5 latch and TRAP latch cleared, SOD
    // low, HALT left. Other registers keep their values (undefined on the chip). Counters are kept;
    // clear them with reset_counters().
    void reset();
    void reset_counters() { t_ = 0; instructions_ = 0; }

    Registers& regs() { return r_; }
    const Registers& regs() const { return r_; }

    // ---- running -------------------------------------------------------------------------------
    // Runs whole instructions (and interrupt acknowledges) while tstates() < deadline, or until a
    // stop is requested. A halted or held CPU idles up to the deadline. Returns the T-states run.
    std::uint64_t run(std::uint64_t deadline);
    // One instruction, or one interrupt acknowledge, or (halted) one idle T-state.
    std::uint64_t step() { return run(t_ + 1); }
    // Shortens the current run: it returns after the instruction during which tstates() reaches t.
    // Safe from I/O and memory handlers and from debug hooks.
    void stop_at(std::uint64_t t) {
        if (t < deadline_) deadline_ = t;
        if (t < limit_) limit_ = t;
    }
    void request_stop() { stop_at(0); }

    // T-state counter. Between runs: the T-state after the last instruction. Inside an I/O handler:
    // the first T-state of the IN/OUT's I/O machine cycle (exact). Inside a memory-mapped device
    // handler: the first T-state of the instruction's last machine cycle (exact for single-access
    // instructions such as MOV M,r, LDA, STA, MVI M; approximate for multi-access ones).
    std::uint64_t tstates() const { return t_; }
    std::uint64_t instructions() const { return instructions_; }

    // ---- state -----------------------------------------------------------------------------------
    bool halted() const { return halted_; }
    bool interrupts_enabled() const { return ie_; }
    std::uint8_t masks() const { return masks_; }  // bit 2 M7.5, bit 1 M6.5, bit 0 M5.5
    bool rst75_latched() const { return rst75_latch_; }
    bool trap_latched() const { return trap_latch_; }
    bool sod() const { return sod_; }
    // The input pins' levels as last driven (a logic analyzer's view; the latches are above).
    bool trap_pin() const { return trap_pin_; }
    bool rst75_pin() const { return rst75_pin_; }
    bool rst65_pin() const { return rst65_pin_; }
    bool rst55_pin() const { return rst55_pin_; }
    bool intr_pin() const { return intr_pin_; }
    bool sid() const { return sid_; }
    bool hlda() const { return hlda_; }
    // What RIM would load into A now (without RIM's side effect on the TRAP-saved IE).
    std::uint8_t rim_value() const;

    // Snapshot of everything above (registers, interrupt state, pins, counters); load throws
    // SnapshotError and leaves the CPU unchanged on a bad record (emu/core/i8085_snapshot.cpp).
    void save(std::vector<std::uint8_t>& out) const;
    void load(std::span<const std::uint8_t> in);

    // ---- pins (the board drives these between runs or from handlers) ------------------------------
    void set_trap(bool level);   // rising edge latched; taken while latched AND still high
    void set_rst75(bool level);  // rising edge sets the 7.5 latch
    void set_rst65(bool level);
    void set_rst55(bool level);
    void set_intr(bool level);
    void set_sid(bool level) { sid_ = level; }
    void set_hold(bool level);

    // INTA: called for each INTA machine cycle of an INTR acknowledge (n = 0 the opcode, 1 and 2
    // the address bytes of a CALL). Without a callback the bus floats: FFH = RST 7.
    std::function<std::uint8_t(unsigned n)> on_inta;
    std::function<void(bool level)> on_sod;
    std::function<void(bool level)> on_hlda;
    // HLT executed (the status lines show HALT). A front end may call request_stop() here.
    std::function<void()> on_halt;

    // Counted delay loops ("L: DCR r / JNZ L") run to their end in one step when no debug hooks are
    // installed: the same state and T-states, without executing each iteration. On by default; off
    // to measure the interpreter alone (alp85 bench cpu) or to compare (tests/core).
    void set_fast_loops(bool on) { fast_loops_ = on; }
    bool fast_loops() const { return fast_loops_; }

    // ---- debugging -------------------------------------------------------------------------------
    void set_debug_hooks(DebugHooks* hooks) { hooks_ = hooks; }
    DebugHooks* debug_hooks() const { return hooks_; }

    // A fetch fence: the addresses where a debugger must look before the instruction runs (its
    // breakpoints, and for a runaway guard every address that is not code). While one is set and
    // no debug hooks are installed, run() takes its plain path with one bit test per opcode fetch,
    // and stops before fetching an opcode at a fenced address: fence_stopped() is then true until
    // the next run(), and fence_previous() is the address of the instruction that ran before it.
    // pass_fence() lets the instruction at the PC through once, now (an interrupt acknowledged
    // first takes the pass away). Delay loops over a fenced address are not run at once.
    // The caller keeps the set alive while it is installed; nullptr removes it. The CPU notes
    // which 256-byte pages hold a fenced address (opcodes in the other pages are fetched through a
    // page table of their own, with no test), each page the first time an opcode is fetched there
    // (a debugger installs the set at every stop; a run visits a few pages): install it again
    // after changing it.
    void set_fetch_fence(const std::bitset<0x10000>* fence);
    const std::bitset<0x10000>* fetch_fence() const { return fence_; }
    bool fence_stopped() const { return fence_hit_; }
    std::uint16_t fence_previous() const { return fence_prev_; }
    void pass_fence() {
        pass_pc_ = r_.pc;
        pass_t_ = t_;
    }
    // The value the last LXI SP or SPHL loaded into SP, if one has run: where the program put its
    // stack, the base of a backtrace. One store in those two instructions, no cost elsewhere. Host
    // bookkeeping for debuggers, not machine state (not in snapshots).
    std::optional<std::uint16_t> stack_load() const {
        if (!(sp_load_ & 0x10000u)) return std::nullopt;
        return static_cast<std::uint16_t>(sp_load_);
    }

private:
    // The instruction loop, one per way of reaching memory (the variant is data): the page table,
    // one flat 64 KiB block, or the page table behind a fetch fence or debug hooks.
    enum class Mem : std::uint8_t { Paged, Flat, Fenced };
    template <Mem M>
    void execute();  // runs until t_ >= limit_
    template <auto M>  // M: a Mem (GCC 12 rejects the private enum in the definition's head)
    struct Loop;  // one batch's registers, counter and memory tables, and the opcodes' bodies
    void request_stop_batch() { limit_ = 0; }  // end this batch only (run() goes on)
    void accept_interrupt();
    void map_exec_pages();  // exec_pages_ from the bus's read pages and fenced_pages_
    void note_fenced_page(unsigned page);  // fence_seen_ and fenced_pages_ for one page
    void push_pc_and_jump(std::uint16_t vector);
    void wake_check() { limit_ = 0; }  // a pin changed: revisit interrupts after this instruction
    std::uint8_t rim();                  // RIM: rim_value(), and the TRAP-saved IE is consumed
    void sim(std::uint8_t a);            // SIM
    void halt_entered();
    [[gnu::noinline]] std::uint8_t slow_read(std::uint16_t addr, std::uint64_t t, bool data);
    [[gnu::noinline]] void slow_write(std::uint16_t addr, std::uint8_t value, std::uint64_t t);
    [[gnu::noinline]] std::uint8_t io_in(std::uint8_t port, std::uint64_t t);
    [[gnu::noinline]] void io_out(std::uint8_t port, std::uint8_t value, std::uint64_t t);

    Bus& bus_;
    Variant variant_;
    Registers r_;
    DebugHooks* hooks_ = nullptr;

    std::uint64_t t_ = 0;
    std::uint64_t instructions_ = 0;
    std::uint64_t deadline_ = 0;  // end of the current run()
    std::uint64_t limit_ = 0;     // end of the current inner loop (<= deadline_)

    bool ie_ = false;
    bool ei_delay_ = false;    // EI executed: no maskable interrupt before the next instruction ends
    bool trap_ie_ = false;     // IE as it was when TRAP was taken, for the next RIM
    bool trap_rim_ = false;    // the next RIM reports trap_ie_
    bool halted_ = false;
    std::uint8_t masks_ = 0x07;
    bool rst75_latch_ = false, rst75_pin_ = false;
    bool trap_latch_ = false, trap_pin_ = false;
    bool rst65_pin_ = false, rst55_pin_ = false, intr_pin_ = false;
    bool sid_ = false, sod_ = false;
    bool hold_ = false, hlda_ = false;
    bool fast_loops_ = true;  // host setting, not machine state: not in snapshots
    const std::bitset<0x10000>* fence_ = nullptr;  // host settings and findings, not in snapshots
    std::bitset<256> fence_seen_;                   // pages looked at since the fence was set
    std::bitset<256> fenced_pages_;                 // of those, the pages holding a fenced address
    // Opcode fetches behind a fence: the read page where it holds no fenced address, else null.
    std::array<const std::uint8_t*, 256> exec_pages_{};
    std::uint64_t exec_pages_maps_ = ~std::uint64_t{0};  // bus_.map_changes() they were made for
    bool fence_hit_ = false;
    std::uint16_t fence_prev_ = 0;
    std::uint16_t pass_pc_ = 0;
    std::uint64_t pass_t_ = ~std::uint64_t{0};
    std::uint32_t sp_load_ = 0;  // bit 16: an LXI SP or SPHL has run; bits 0-15: the value
};

}  // namespace alp85
