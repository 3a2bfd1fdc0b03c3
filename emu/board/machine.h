// A board as one object: CPU, bus, 8155, 8279, keypad and display wired as its description
// (emu/board/board_description.h; the ALP 85 unless Options::board names another) declares, with a scheduler that runs the CPU in long batches up to the next peripheral event or
// outside input. The debugger and the script Session drive it, and the front ends drive those
// (docs/architecture.md); none of them re-implements the machine.
//
// Time is the CPU's T-state counter (3.072 MHz). Outside inputs (keys, RESET, VECT INTR) are
// events stamped in that time, so the same inputs always give the same run.
#pragma once

#include <algorithm>
#include <array>
#include <bitset>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "emu/board/board_description.h"
#include "emu/board/board_map.h"
#include "emu/core/bus.h"
#include "emu/core/i8085.h"
#include "emu/core/image.h"
#include "emu/board/input_queue.h"
#include "peripherals/i8155.h"
#include "peripherals/i8279.h"
#include "peripherals/i8355.h"
#include "peripherals/keypad.h"
#include "peripherals/machine_tool.h"
#include "peripherals/part.h"
#include "peripherals/serial_terminal.h"

namespace alp85 {

// A debugger's eyes on a run (Machine::set_observer): consulted before every instruction and at
// every data access and I/O transfer while installed. While none is installed the CPU runs its
// plain path and pays nothing for it.
class RunObserver {
public:
    virtual ~RunObserver() = default;
    // Before each instruction (registers current). True: stop before it (Stop::Observer).
    virtual bool before_instruction(const I8085& cpu) = 0;
    // Data accesses and I/O of the instruction running (its registers are not current). True:
    // stop after that instruction (Stop::Observer).
    virtual bool on_read(std::uint16_t addr, std::uint8_t value) { (void)addr, (void)value; return false; }
    virtual bool on_write(std::uint16_t addr, std::uint8_t value) { (void)addr, (void)value; return false; }
    virtual bool on_io(std::uint8_t port, std::uint8_t value, bool is_out) { (void)port, (void)value, (void)is_out; return false; }
    // Which of the above it needs: before_instruction is always called; these only when true.
    virtual bool wants_accesses() const { return false; }
    // The addresses where it must look before an instruction, when that is all it needs (no
    // accesses, no look at every instruction): the CPU then runs its plain path behind this fetch
    // fence (I8085::set_fetch_fence) and at_fence is called only there. nullptr: every instruction.
    // Asked whenever the observer is installed (Machine::set_observer).
    virtual const std::bitset<0x10000>* fetch_fence() const { return nullptr; }
    // Before an instruction at a fenced address (registers current; cpu.fence_previous() is the
    // instruction that ran before). True: stop before it (Stop::Observer).
    virtual bool at_fence(const I8085& cpu) { return before_instruction(cpu); }
};

// A logic analyzer on the board's pins (Machine::add_probe): a VCD recording, the window's Signals
// pane; several may look at once. While none is installed the board pays nothing for them: no
// call, and no look at a probe in the instruction loop.
class PinProbe {
public:
    virtual ~PinProbe() = default;
    // Pins may have changed at T-state t: a write to the 8155 (its ports, the sequencers' inputs
    // and the phase drives follow at once), TIMER OUT, the 8279's IRQ, an interrupt line, SOD; or
    // the probe's own clock reached t (next()), with every part advanced to t.
    virtual void look(std::uint64_t t) = 0;
    // The next T-state the probe wants to look at by itself (kNever: none): its sample clock, a
    // part's next_pin_change.
    virtual std::uint64_t next() const = 0;
};

class Machine {
public:
    struct Options {
        Variant cpu = Variant::I8085;
        periph::MachineTool::MotorModel motor = periph::MachineTool::MotorModel::Physical;
        bool machine_tool = true;  // false: the board alone, port B undriven (benchmarks, tests)
        bool expansion_eprom = false;  // board::kExpansionEprom mapped (thesis 5.3's expansion)
        const board::Board* board = &board::kAlp85;  // what the machine is: its bus, wiring, keys, display
    };

    // Why a run returned. (Breakpoints, watchpoints and the Stop a user sees are the debugger's,
    // emu/debug/debugger.h: the machine has none of its own.)
    enum class RunEnd : std::uint8_t {
        Deadline,   // the requested time was reached
        Condition,  // the caller's condition became true
        Target,     // run_to reached its address (the instruction there has not run)
        Observer,   // the installed RunObserver asked to stop
    };

    Machine();
    explicit Machine(Options options);
    Machine(const Machine&) = delete;
    Machine& operator=(const Machine&) = delete;
    ~Machine();

    // ---- memory ------------------------------------------------------------------------------
    // Places bytes into EPROM or RAM as a programmer or loader would (EPROMs are writable here).
    // Throws std::out_of_range naming the first address that is not on the board.
    void load(std::uint16_t address, std::span<const std::uint8_t> bytes);
    void load(const std::vector<ImageSegment>& image);
    // Bus view without side effects (reads FFH where nothing answers) and a debugger poke into
    // RAM or EPROM storage (false where nothing is mapped).
    std::uint8_t peek(std::uint16_t address) const { return bus_.peek(address); }
    bool poke(std::uint16_t address, std::uint8_t value);
    // The storage of a region of this board's description (empty if it has none such).
    std::span<std::uint8_t> storage(board::Memory id);
    // The memory regions fitted on this board: its description's, the optional ones when fitted.
    const std::vector<board::MemoryRegion>& memory_map() const { return map_; }
    // The chips' decoding fitted on this board, in either space.
    std::vector<board::DeviceRegion> device_map() const;
    const board::Board& board() const { return *options_.board; }
    // The board as its description says, as fitted now: memory map, devices, wiring, keys, display,
    // options (the debugger's and the script's `info board`).
    std::string describe_board() const;
    // Fits or removes a board option (its regions and chips; a ROM's contents are kept while it is
    // out). False: the board has no such option.
    bool set_option(std::string_view name, bool fitted);
    bool option(std::string_view name) const;
    // The ALP 85's expansion EPROM (option "expansion").
    void set_expansion_eprom(bool fitted) { set_option("expansion", fitted); }
    bool expansion_eprom() const { return options_.expansion_eprom; }

    // ---- control -----------------------------------------------------------------------------
    // RESET IN: the CPU and every part reset now (RESET OUT); memory and time are kept.
    void reset();
    std::uint64_t now() const { return cpu_.tstates(); }
    static constexpr std::uint64_t tstates_from_ms(double ms) { return board::tstates_from_ms(ms); }

    // Runs until `until` (whole instructions: it may end a few T-states after), until the
    // observer asks to stop, or until — checked after every batch and every OUT — `condition`
    // returns true.
    RunEnd run_until(std::uint64_t until, const std::function<bool()>& condition = {});
    RunEnd run_for(std::uint64_t tstates, const std::function<bool()>& condition = {}) {
        return run_until(now() + tstates, condition);
    }
    // Runs until the PC reaches `pc` (RunEnd::Target; not at the first instruction) or until
    // `until` (RunEnd::Deadline). Only `pc` stops it: the observer is not consulted meanwhile (a
    // debugger's "run to here").
    RunEnd run_to(std::uint16_t pc, std::uint64_t until);
    // Exactly one instruction (or interrupt acknowledge, or idle T-state when halted), whatever
    // the observer's fence says about the current PC.
    void step();

    // Whether anything but a reset can still end a HLT: maskable interrupts enabled (a key, VECT
    // INTR), the 8155's timer running (TIMER OUT is wired to TRAP), or an input still to come.
    bool can_wake() const;

    // ---- outside inputs ----------------------------------------------------------------------
    void key_at(periph::Key key, bool down, std::uint64_t at);
    void vect_intr_at(bool down, std::uint64_t at);
    void reset_key_at(bool down, std::uint64_t at);
    // A character typed at the serial terminal (connect_serial) at T-state `at`; ignored without one.
    void serial_at(std::uint8_t value, std::uint64_t at);
    const InputQueue& inputs() const { return inputs_; }
    // Every outside input applied so far, with its T-state, in the order applied: scheduling
    // these again on a machine restored to an earlier snapshot replays the run exactly.
    const std::vector<InputEvent>& input_log() const { return input_log_; }
    void replay(const std::vector<InputEvent>& events);
    const periph::Keypad& keypad() const { return keypad_; }

    // ---- display -----------------------------------------------------------------------------
    // Segment bytes (bit0 = a ... bit6 = g, bit7 = dp, 1 = lit), leftmost digit first; the board's
    // display_digits() of them, the rest dark.
    std::array<std::uint8_t, 8> display() const;
    unsigned display_digits() const { return options_.board->display.digits; }
    std::string display_text() const;             // nearest character per digit, '.' for dp
    std::array<std::string, 7> display_art() const;

    // ---- debugging -----------------------------------------------------------------------------
    // Called before every instruction while set (a trace); it puts the CPU on its debug path only
    // while installed.
    void set_trace(std::function<void(const I8085&)> trace);
    // Installs a debugger's run observer (nullptr removes it): the CPU's debug path, or its plain
    // path behind the observer's fetch fence, while installed. The observer must outlive its
    // installation.
    void set_observer(RunObserver* observer);
    RunObserver* observer() const;
    // Rewinding for reverse execution: after restore_bytes() of an earlier snapshot, the input log
    // is cut back to `log_size` entries (what had been applied at that snapshot) and the queue
    // holds `pending` (every input still to come on this timeline), numbered as before.
    void rewind_inputs(std::size_t log_size, const std::vector<InputEvent>& pending, std::uint64_t next_seq);

    // ---- parts ------------------------------------------------------------------------------------
    // Every part beside the CPU, in the order they are advanced, reset and saved.
    const std::vector<periph::Part*>& parts() const { return parts_; }
    periph::Part* find_part(std::string_view name) const;
    // Adds a part to the board (it must outlive the machine): it is advanced, reset and saved
    // with the others from now on; `io`, if given, answers the ports first..last. A front end or
    // test adding an accessory calls this; the board's own parts are attached by the constructor.
    void attach(periph::Part& part, IoDevice* io = nullptr, std::uint8_t first = 0, std::uint8_t last = 0);
    I8085& cpu() { return cpu_; }
    const I8085& cpu() const { return cpu_; }
    Bus& bus() { return bus_; }
    const Bus& bus() const { return bus_; }
    periph::I8155& rio() { return rio_; }  // the 8155 (RAM-I/O-timer)
    const periph::I8155& rio() const { return rio_; }
    periph::I8155* rio2() { return rio2_.get(); }  // a second 8155, on a board that has a place for one
    periph::I8355* rom8355() { return rom8355_.get(); }  // the ROM-I/O chip, on a board with one (the SDK-85)

    periph::I8279& kdc() { return kdc_; }  // the 8279 (keyboard/display controller)
    const periph::I8279& kdc() const { return kdc_; }
    periph::MachineTool& tool() { return tool_; }  // the machine tool on the 8155's ports A and B
    const periph::MachineTool& tool() const { return tool_; }
    // Calls fn(t) at every multiple of `period` T-states while set (a recorder's sampling clock);
    // the batches end there. period 0 removes it.
    void set_sampler(std::uint64_t period, std::function<void(std::uint64_t t)> fn);
    // Connects a serial terminal to SID (its TXD) and SOD (its RXD) and attaches it as a part (it
    // must outlive the machine; one terminal, connected once). SID follows the terminal's line from
    // now on.
    void connect_serial(periph::SerialTerminal& terminal);
    periph::SerialTerminal* serial() const { return serial_; }
    // Installs a logic analyzer (it must outlive its installation; installed twice it is still
    // one), and takes one off; see PinProbe.
    void add_probe(PinProbe* probe);
    void remove_probe(PinProbe* probe);
    bool has_probe(const PinProbe* probe) const;
    // The 8085's pins a logic analyzer shows (scope "8085"): SOD, SID, TRAP, RST7_5, RST6_5,
    // RST5_5, INTR, INTA (active low: high, INTR is not wired on this board), HLT (the halt state,
    // seen at instruction boundaries: sampled).
    void cpu_pins(periph::Pins& p) const;
    // While paused the sampler (and the probes) is not called (a debugger re-executing the past: those samples
    // were taken the first time).
    void pause_sampler(bool paused) { sampler_paused_ = paused; }

    // ---- snapshots -------------------------------------------------------------------------------
    // The whole machine (CPU, memories, every part, pending inputs; breakpoints and the input log
    // are not part of it) to a versioned file, written atomically; load refuses an incompatible or corrupt file
    // with a SnapshotError and leaves the machine unchanged.
    void save_snapshot(const std::filesystem::path& path) const;
    void load_snapshot(const std::filesystem::path& path);
    std::vector<std::uint8_t> snapshot_bytes() const;
    void restore_bytes(const std::vector<std::uint8_t>& bytes);

private:
    class Hooks;

    class Decoder;

    void wire();
    void fit(const std::string_view option, bool fitted);
    void drive(board::CpuPin pin, bool level, std::uint64_t t);
    void deliver_inputs(std::uint64_t now);
    void apply(const InputEvent& e);
    void sync_parts(std::uint64_t now) {
        for (periph::Part* p : parts_) p->advance(now);
    }
    std::uint64_t next_part_event() const {
        std::uint64_t next = next_sample_;
        for (const PinProbe* p : probes_) next = std::min(next, p->next());
        for (const periph::Part* p : parts_) next = std::min(next, p->next_event());
        return next;
    }
    void probe_clock(std::uint64_t t);
    void probe_look(std::uint64_t t) {
        if (sampler_paused_) return;
        for (PinProbe* p : probes_) p->look(t);
    }
    void drive_tool(std::uint64_t t);          // port A's pins to the sequencers
    std::uint8_t sense_tool(std::uint64_t t);  // the transducers to port B's pins
    void sample(std::uint64_t t);
    void update_hooks();
    void update_sod();  // the CPU's on_sod while a probe or a terminal listens to SOD
    void restore_sections(const std::vector<std::uint8_t>& bytes);

    Options options_;
    std::vector<std::vector<std::uint8_t>> stores_;  // per region of the description (none for a chip's RAM)
    std::vector<std::string_view> fitted_;          // the options fitted
    std::vector<board::MemoryRegion> map_;
    Bus bus_;
    I8085 cpu_;
    periph::I8155 rio_;
    std::unique_ptr<periph::I8155> rio2_;
    std::unique_ptr<periph::I8355> rom8355_;
    periph::I8279 kdc_;
    periph::Keypad keypad_;
    periph::MachineTool tool_;
    InputQueue inputs_;
    std::vector<InputEvent> input_log_;
    std::uint64_t sample_period_ = 0;
    std::uint64_t next_sample_ = periph::Part::kNever;
    std::function<void(std::uint64_t)> sampler_;
    bool sampler_paused_ = false;
    std::vector<PinProbe*> probes_;
    periph::SerialTerminal* serial_ = nullptr;
    std::vector<periph::Part*> parts_;

    std::vector<std::unique_ptr<Decoder>> decoders_;  // the chips' decoding, per device of the description
    std::unique_ptr<Hooks> hooks_;
};

}  // namespace alp85
