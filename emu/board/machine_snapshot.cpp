// Machine snapshots: every part's state in one versioned, checksummed file (emu/snapshot_file.h).
#include <string>

#include "emu/board/machine.h"
#include "emu/board/snapshot_file.h"

namespace alp85 {
namespace {

using snapshot::Section;

constexpr std::uint8_t kMachineVersion = 1;

std::vector<std::uint8_t> bytes_of(std::span<const std::uint8_t> s) { return {s.begin(), s.end()}; }

struct MachineSection {
    Variant variant = Variant::I8085;
    std::uint64_t next_seq = 0;
    std::vector<InputEvent> pending;
};

MachineSection parse_machine(const Section& s) {
    ByteReader r(s.data, "machine");
    MachineSection m;
    if (r.u8() != kMachineVersion) r.fail("unknown machine section version");
    const std::uint8_t v = r.u8();
    if (v > 1) r.fail("unknown CPU variant");
    m.variant = static_cast<Variant>(v);
    m.next_seq = r.u64();
    const std::uint32_t n = r.u32();
    for (std::uint32_t i = 0; i < n; ++i) {
        InputEvent e;
        e.at = r.u64();
        e.seq = r.u64();
        const std::uint8_t kind = r.u8();
        if (kind > static_cast<std::uint8_t>(InputKind::Reset)) r.fail("unknown input kind");
        e.kind = static_cast<InputKind>(kind);
        e.code = r.u16();
        e.level = r.boolean();
        if (e.kind == InputKind::Key && e.code >= periph::Keypad::kKeyCount) r.fail("unknown key");
        m.pending.push_back(e);
    }
    r.expect_end();
    return m;
}

void copy_exact(const Section& s, std::span<std::uint8_t> dst, const char* what) {
    if (s.data.size() != dst.size())
        throw snapshot::SnapshotError(std::string(what) + " snapshot: size " + std::to_string(s.data.size()) +
                                      ", expected " + std::to_string(dst.size()));
    std::copy(s.data.begin(), s.data.end(), dst.begin());
}

}  // namespace

std::vector<std::uint8_t> Machine::snapshot_bytes() const {
    std::vector<Section> sections;
    {
        Section s{"MACH", {}};
        ByteWriter w(s.data);
        w.u8(kMachineVersion);
        w.u8(static_cast<std::uint8_t>(options_.cpu));
        w.u64(inputs_.next_seq());
        const auto pending = inputs_.pending();
        w.u32(static_cast<std::uint32_t>(pending.size()));
        for (const InputEvent& e : pending) {
            w.u64(e.at);
            w.u64(e.seq);
            w.u8(static_cast<std::uint8_t>(e.kind));
            w.u16(e.code);
            w.boolean(e.level);
        }
        sections.push_back(std::move(s));
    }
    {
        Section s{"CPU ", {}};
        cpu_.save(s.data);
        sections.push_back(std::move(s));
    }
    sections.push_back({"MON ", bytes_of(monitor_)});
    sections.push_back({"USER", bytes_of(user_)});
    sections.push_back({"RAM ", bytes_of(ram_)});
    {
        Section s{"8155", {}};
        rio_.save(s.data);
        sections.push_back(std::move(s));
    }
    {
        Section s{"8279", {}};
        kdc_.save(s.data);
        sections.push_back(std::move(s));
    }
    {
        Section s{"KEYS", {}};
        keypad_.save(s.data);
        sections.push_back(std::move(s));
    }
    return snapshot::encode(sections);
}

void Machine::restore_bytes(const std::vector<std::uint8_t>& bytes) {
    const std::vector<Section> sections = snapshot::decode(bytes);
    const MachineSection m = parse_machine(snapshot::find(sections, "MACH"));
    if (m.variant != options_.cpu)
        throw snapshot::SnapshotError(std::string("snapshot was taken on an ") +
                                      (m.variant == Variant::I8080 ? "8080" : "8085") + " machine, this one is an " +
                                      (options_.cpu == Variant::I8080 ? "8080" : "8085"));
    // Validate every part on scratch copies first: a bad file leaves this machine untouched.
    {
        Bus scratch_bus;
        I8085 scratch_cpu(scratch_bus, options_.cpu);
        scratch_cpu.load(snapshot::find(sections, "CPU ").data);
        periph::I8155 scratch_rio;
        scratch_rio.load(snapshot::find(sections, "8155").data);
        periph::I8279 scratch_kdc;
        scratch_kdc.load(snapshot::find(sections, "8279").data);
        // The machine keeps its chips caught up with the CPU (sync_chips after every run), so a
        // chip at another time is a damaged file; a timer far behind would also take ages to
        // catch up, one event at a time.
        if (scratch_rio.state().now != scratch_cpu.cycles() || scratch_kdc.state().now != scratch_cpu.cycles())
            throw snapshot::SnapshotError("the chips' time differs from the CPU's");
        periph::Keypad scratch_keys;
        scratch_keys.load(snapshot::find(sections, "KEYS").data);
        std::array<std::uint8_t, 0x1000> scratch_mem{};
        copy_exact(snapshot::find(sections, "MON "), std::span(scratch_mem).first(monitor_.size()), "monitor EPROM");
        copy_exact(snapshot::find(sections, "USER"), std::span(scratch_mem).first(user_.size()), "user EPROM");
        copy_exact(snapshot::find(sections, "RAM "), std::span(scratch_mem).first(ram_.size()), "RAM");
    }
    cpu_.load(snapshot::find(sections, "CPU ").data);
    rio_.load(snapshot::find(sections, "8155").data);
    kdc_.load(snapshot::find(sections, "8279").data);
    keypad_.load(snapshot::find(sections, "KEYS").data);
    copy_exact(snapshot::find(sections, "MON "), monitor_, "monitor EPROM");
    copy_exact(snapshot::find(sections, "USER"), user_, "user EPROM");
    copy_exact(snapshot::find(sections, "RAM "), ram_, "RAM");
    inputs_.restore(m.pending, m.next_seq);
}

void Machine::save_snapshot(const std::filesystem::path& path) const {
    snapshot::write_atomic(path, snapshot_bytes());
}

void Machine::load_snapshot(const std::filesystem::path& path) {
    const std::vector<std::uint8_t> bytes = snapshot::read_bytes(path);
    try {
        restore_bytes(bytes);
    } catch (const snapshot::SnapshotError& e) {
        throw snapshot::SnapshotError(path.string() + ": " + e.what());
    }
}

}  // namespace alp85
