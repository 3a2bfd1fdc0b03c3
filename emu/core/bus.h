// The 8085's view of the outside world: 64 KiB of memory in 256-byte pages and 256 I/O ports.
//
// Memory goes through a page table of direct pointers so that ordinary RAM and ROM accesses cost
// two loads: a read pointer (RAM, ROM or the open-bus page) and a write pointer (RAM only). A page
// whose read pointer is null belongs to a memory-mapped device and is served by its handler; a
// page whose write pointer is null is ROM (writes ignored and counted), a device, or unmapped
// (writes ignored and counted). Unmapped reads return FFH, the value of a floating data bus with
// the usual pull-ups. I/O ports go through handlers only; an unmapped port reads FFH.
//
// The bus knows nothing about the CPU or the board; handlers receive the CPU's T-state of the
// access so that devices can catch up with their own clocks.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>

namespace alp85 {

// A memory-mapped device occupying whole 256-byte pages.
class MemoryDevice {
public:
    virtual ~MemoryDevice() = default;
    virtual std::uint8_t read(std::uint16_t addr, std::uint64_t tstate) = 0;
    virtual void write(std::uint16_t addr, std::uint8_t value, std::uint64_t tstate) = 0;
    // Side-effect-free read for debuggers and disassemblers.
    virtual std::uint8_t peek(std::uint16_t addr) const { (void)addr; return 0xFF; }
};

// A device on one or more I/O ports (IN/OUT). The port number is the 8-bit address the 8085
// places on A0-A7 (and duplicates on A8-A15).
class IoDevice {
public:
    virtual ~IoDevice() = default;
    virtual std::uint8_t in(std::uint8_t port, std::uint64_t tstate) = 0;
    virtual void out(std::uint8_t port, std::uint8_t value, std::uint64_t tstate) = 0;
};

// An IoDevice made of two function objects, for tests and small front ends.
class IoFunctions final : public IoDevice {
public:
    std::function<std::uint8_t(std::uint8_t port, std::uint64_t tstate)> on_in;
    std::function<void(std::uint8_t port, std::uint8_t value, std::uint64_t tstate)> on_out;
    std::uint8_t in(std::uint8_t port, std::uint64_t tstate) override {
        return on_in ? on_in(port, tstate) : 0xFF;
    }
    void out(std::uint8_t port, std::uint8_t value, std::uint64_t tstate) override {
        if (on_out) on_out(port, value, tstate);
    }
};

class Bus {
public:
    static constexpr unsigned kPageBits = 8;
    static constexpr unsigned kPageSize = 1u << kPageBits;
    static constexpr unsigned kPages = 0x10000u / kPageSize;

    enum class PageKind : std::uint8_t { Unmapped, Ram, Rom, Device };

    Bus();
    Bus(const Bus&) = delete;
    Bus& operator=(const Bus&) = delete;

    // base and size must be multiples of 256 and lie inside 64 KiB (std::invalid_argument if not).
    // The storage stays owned by the caller and must outlive the mapping.
    void map_ram(std::uint32_t base, std::uint32_t size, std::uint8_t* storage);
    void map_rom(std::uint32_t base, std::uint32_t size, const std::uint8_t* storage);
    void map_device(std::uint32_t base, std::uint32_t size, MemoryDevice& device);
    void unmap(std::uint32_t base, std::uint32_t size);
    void map_io(std::uint8_t first, std::uint8_t last, IoDevice& device);
    void unmap_io(std::uint8_t first, std::uint8_t last);  // those ports read FFH again

    PageKind page_kind(std::uint16_t addr) const { return kind_[addr >> kPageBits]; }

    // Full-path accesses (device handlers, ROM/unmapped write counting). The CPU's hot path
    // reads the page tables itself and only falls back to these.
    std::uint8_t read(std::uint16_t addr, std::uint64_t tstate) {
        const std::uint8_t* p = read_[addr >> kPageBits];
        return p ? p[addr & (kPageSize - 1)] : device_[addr >> kPageBits]->read(addr, tstate);
    }
    void write(std::uint16_t addr, std::uint8_t value, std::uint64_t tstate);
    std::uint8_t in(std::uint8_t port, std::uint64_t tstate) {
        return io_[port] ? io_[port]->in(port, tstate) : 0xFF;
    }
    void out(std::uint8_t port, std::uint8_t value, std::uint64_t tstate) {
        if (io_[port]) io_[port]->out(port, value, tstate);
    }

    // Debugger access without side effects: peek uses MemoryDevice::peek; poke writes RAM only
    // (ROM images are loaded into the storage their owner maps). poke returns false when the
    // page is not RAM.
    std::uint8_t peek(std::uint16_t addr) const;
    bool poke(std::uint16_t addr, std::uint8_t value);

    std::uint64_t rom_writes_ignored() const { return rom_writes_; }
    std::uint64_t unmapped_writes_ignored() const { return unmapped_writes_; }

    // All 64 KiB plain RAM in one contiguous block (then its start), or null. The CPU core then
    // runs without the page table. map_changes() counts mapping calls, so the core can notice a
    // handler that remaps memory.
    std::uint8_t* flat_ram() const { return flat_; }
    std::uint64_t map_changes() const { return map_changes_; }

    // The page tables, for the CPU core.
    const std::uint8_t* const* read_pages() const { return read_.data(); }
    std::uint8_t* const* write_pages() const { return write_.data(); }

private:
    void check_range(std::uint32_t base, std::uint32_t size) const;
    void mapped();  // after every mapping change: flat_ and map_changes_

    std::array<const std::uint8_t*, kPages> read_{};
    std::array<std::uint8_t*, kPages> write_{};
    std::array<MemoryDevice*, kPages> device_{};
    std::array<PageKind, kPages> kind_{};
    std::array<IoDevice*, 256> io_{};
    std::uint64_t rom_writes_ = 0;
    std::uint64_t unmapped_writes_ = 0;
    std::uint8_t* flat_ = nullptr;
    std::uint64_t map_changes_ = 0;
};

}  // namespace alp85
