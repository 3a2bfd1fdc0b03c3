#include "emu/core/bus.h"

#include <stdexcept>
#include <string>

namespace alp85 {

namespace {
// What a read of an unmapped address returns: the floating data bus, pulled up to FFH.
constexpr std::array<std::uint8_t, Bus::kPageSize> make_open_bus() {
    std::array<std::uint8_t, Bus::kPageSize> page{};
    for (auto& b : page) b = 0xFF;
    return page;
}
constexpr std::array<std::uint8_t, Bus::kPageSize> kOpenBus = make_open_bus();
}  // namespace

Bus::Bus() { unmap(0, 0x10000); }

void Bus::check_range(std::uint32_t base, std::uint32_t size) const {
    if (base % kPageSize != 0 || size % kPageSize != 0 || size == 0 || base + size > 0x10000u)
        throw std::invalid_argument("bus mapping " + std::to_string(base) + "+" + std::to_string(size) +
                                    " is not whole 256-byte pages inside 64 KiB");
}

void Bus::map_ram(std::uint32_t base, std::uint32_t size, std::uint8_t* storage) {
    check_range(base, size);
    for (std::uint32_t off = 0; off < size; off += kPageSize) {
        const unsigned page = (base + off) >> kPageBits;
        read_[page] = storage + off;
        write_[page] = storage + off;
        device_[page] = nullptr;
        kind_[page] = PageKind::Ram;
    }
    mapped();
}

void Bus::map_rom(std::uint32_t base, std::uint32_t size, const std::uint8_t* storage) {
    check_range(base, size);
    for (std::uint32_t off = 0; off < size; off += kPageSize) {
        const unsigned page = (base + off) >> kPageBits;
        read_[page] = storage + off;
        write_[page] = nullptr;
        device_[page] = nullptr;
        kind_[page] = PageKind::Rom;
    }
    mapped();
}

void Bus::map_device(std::uint32_t base, std::uint32_t size, MemoryDevice& device) {
    check_range(base, size);
    for (std::uint32_t off = 0; off < size; off += kPageSize) {
        const unsigned page = (base + off) >> kPageBits;
        read_[page] = nullptr;
        write_[page] = nullptr;
        device_[page] = &device;
        kind_[page] = PageKind::Device;
    }
    mapped();
}

void Bus::unmap(std::uint32_t base, std::uint32_t size) {
    check_range(base, size);
    for (std::uint32_t off = 0; off < size; off += kPageSize) {
        const unsigned page = (base + off) >> kPageBits;
        read_[page] = kOpenBus.data();
        write_[page] = nullptr;
        device_[page] = nullptr;
        kind_[page] = PageKind::Unmapped;
    }
    mapped();
}

void Bus::mapped() {
    ++map_changes_;
    flat_ = nullptr;
    std::uint8_t* const base = write_[0];
    if (!base) return;
    for (unsigned page = 0; page < kPages; ++page)
        if (kind_[page] != PageKind::Ram || write_[page] != base + page * kPageSize) return;
    flat_ = base;
}

void Bus::map_io(std::uint8_t first, std::uint8_t last, IoDevice& device) {
    for (unsigned p = first; p <= last; ++p) io_[p] = &device;
}

void Bus::unmap_io(std::uint8_t first, std::uint8_t last) {
    for (unsigned p = first; p <= last; ++p) io_[p] = nullptr;
}

void Bus::write(std::uint16_t addr, std::uint8_t value, std::uint64_t tstate) {
    const unsigned page = addr >> kPageBits;
    switch (kind_[page]) {
        case PageKind::Ram: write_[page][addr & (kPageSize - 1)] = value; break;
        case PageKind::Device: device_[page]->write(addr, value, tstate); break;
        case PageKind::Rom: ++rom_writes_; break;
        case PageKind::Unmapped: ++unmapped_writes_; break;
    }
}

std::uint8_t Bus::peek(std::uint16_t addr) const {
    const unsigned page = addr >> kPageBits;
    if (kind_[page] == PageKind::Device) return device_[page]->peek(addr);
    return read_[page][addr & (kPageSize - 1)];
}

bool Bus::poke(std::uint16_t addr, std::uint8_t value) {
    const unsigned page = addr >> kPageBits;
    if (kind_[page] != PageKind::Ram) return false;
    write_[page][addr & (kPageSize - 1)] = value;
    return true;
}

}  // namespace alp85
