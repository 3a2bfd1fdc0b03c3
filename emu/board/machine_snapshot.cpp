// Machine snapshots: the machine's own section, the CPU, the memories and every part's record in
// one checksummed file (emu/board/snapshot_file.h). Each section opens with ByteWriter::header.
#include <string>

#include "emu/board/machine.h"
#include "emu/board/snapshot_file.h"

namespace alp85 {
namespace {

using snapshot::Section;

// Version 2: parts framed by their own headers and saved through one field list each.
constexpr std::uint8_t kMachineVersion = 2;

struct MachineSection {
    Variant variant = Variant::I8085;
    std::uint64_t next_seq = 0;
    std::vector<InputEvent> pending;
};

template <class E, class Io>
void event_fields(E& e, Io& io) {
    io(e.at), io(e.seq), io(e.kind, InputKind::Serial), io(e.code), io(e.level);
}

Section machine_section(Variant variant, const InputQueue& inputs) {
    Section s{"MACH", {}};
    StateWriter w(s.data);
    w.header('M', 'A', kMachineVersion);
    w(variant), w(inputs.next_seq());
    const auto pending = inputs.pending();
    w(static_cast<std::uint32_t>(pending.size()));
    for (const InputEvent& e : pending) event_fields(e, w);
    return s;
}

MachineSection parse_machine(const Section& s) {
    StateReader r(s.data, "machine");
    if (r.remaining() >= 3 && s.data[0] == 'M' && s.data[1] == 'A' && s.data[2] != kMachineVersion)
        throw SnapshotError("snapshot was written by another ALP85 (machine section version " +
                            std::to_string(s.data[2]) + "; this one reads version " +
                            std::to_string(kMachineVersion) + ")");
    r.expect_header('M', 'A', kMachineVersion);
    MachineSection m;
    r(m.variant, Variant::I8080), r(m.next_seq);
    std::uint32_t n = 0;
    r(n);
    if (n > r.remaining()) r.fail("invalid event count");
    for (std::uint32_t i = 0; i < n; ++i) {
        InputEvent e;
        event_fields(e, r);
        if (e.kind == InputKind::Key && e.code >= periph::Keypad::kKeyCount) r.fail("unknown key");
        if (e.kind == InputKind::Serial && e.code > 0xFF) r.fail("a serial character beyond a byte");
        m.pending.push_back(e);
    }
    r.expect_end();
    return m;
}

// A memory as a section: header and the bytes.
Section memory_section(const char* tag, std::span<const std::uint8_t> bytes) {
    Section s{tag, {}};
    ByteWriter w(s.data);
    w.header(tag[0], tag[1], 1);
    w.bytes(bytes);
    return s;
}

void load_memory(const Section& s, std::span<std::uint8_t> dst, const char* what) {
    ByteReader r(s.data, what);
    r.expect_header(s.tag[0], s.tag[1], 1);
    if (r.remaining() != dst.size())
        r.fail("size " + std::to_string(r.remaining()) + ", expected " + std::to_string(dst.size()));
    r.bytes(dst);
}

}  // namespace

std::vector<std::uint8_t> Machine::snapshot_bytes() const {
    std::vector<Section> sections;
    sections.push_back(machine_section(options_.cpu, inputs_));
    {
        Section s{"CPU ", {}};
        cpu_.save(s.data);
        sections.push_back(std::move(s));
    }
    // The board's own memories, in the order of its description, the optional ones while fitted.
    for (std::size_t i = 0; i < options_.board->memory.size(); ++i) {
        const board::MemoryRegion& r = options_.board->memory[i];
        if (!r.tag.empty() && (r.option.empty() || option(r.option)))
            sections.push_back(memory_section(std::string(r.tag).c_str(),
                                              r.id == board::Memory::Rom8355 ? std::span<const std::uint8_t>(rom8355_->rom())
                                                                             : std::span<const std::uint8_t>(stores_[i])));
    }
    for (const periph::Part* p : parts_) {
        Section s{std::string(p->tag()), {}};
        p->save(s.data);
        sections.push_back(std::move(s));
    }
    return snapshot::encode(sections);
}

void Machine::restore_sections(const std::vector<std::uint8_t>& bytes) {
    const std::vector<Section> sections = snapshot::decode(bytes);
    const MachineSection m = parse_machine(snapshot::find(sections, "MACH"));
    if (m.variant != options_.cpu)
        throw SnapshotError(std::string("snapshot was taken on an ") + (m.variant == Variant::I8080 ? "8080" : "8085") +
                            " machine, this one is an " + (options_.cpu == Variant::I8080 ? "8080" : "8085"));
    for (const Section& s : sections) {
        const bool known = s.tag == "MACH" || s.tag == "CPU " ||
                           std::any_of(options_.board->memory.begin(), options_.board->memory.end(),
                                       [&](const board::MemoryRegion& r) {
                                           return !r.tag.empty() && r.tag == s.tag && (r.option.empty() || option(r.option));
                                       }) ||
                           std::any_of(parts_.begin(), parts_.end(), [&](const periph::Part* p) { return p->tag() == s.tag; });
        if (!known) throw SnapshotError("snapshot has a part this machine lacks ('" + s.tag + "')");
    }
    cpu_.load(snapshot::find(sections, "CPU ").data);
    for (std::size_t i = 0; i < options_.board->memory.size(); ++i) {
        const board::MemoryRegion& r = options_.board->memory[i];
        if (!r.tag.empty() && (r.option.empty() || option(r.option)))
            load_memory(snapshot::find(sections, std::string(r.tag)), storage(r.id), std::string(r.name).c_str());
    }
    for (periph::Part* p : parts_) p->load(snapshot::find(sections, p->tag()).data);
    // The machine keeps its parts caught up with the CPU (sync_parts after every run), so a part
    // at another time is a damaged file; a timer far behind would also take ages to catch up.
    for (const periph::Part* p : parts_) {
        if (p->now() != cpu_.tstates()) throw SnapshotError("the chips' time differs from the CPU's");
    }
    inputs_.restore(m.pending, m.next_seq);
}

void Machine::restore_bytes(const std::vector<std::uint8_t>& bytes) {
    // Parts load one by one; should a later one refuse, the whole machine goes back to where it
    // was, so a bad file leaves it untouched.
    const std::vector<std::uint8_t> before = snapshot_bytes();
    try {
        restore_sections(bytes);
    } catch (const SnapshotError&) {
        restore_sections(before);
        throw;
    }
    // Inputs applied after the restored moment have not happened (yet) in this run.
    std::erase_if(input_log_, [this](const InputEvent& e) { return e.at > now(); });
}

void Machine::save_snapshot(const std::filesystem::path& path) const {
    snapshot::write_atomic(path, snapshot_bytes());
}

void Machine::load_snapshot(const std::filesystem::path& path) {
    const std::vector<std::uint8_t> bytes = snapshot::read_bytes(path);
    try {
        restore_bytes(bytes);
    } catch (const SnapshotError& e) {
        throw SnapshotError(path.string() + ": " + e.what());
    }
}

}  // namespace alp85
