// The punched-tape reader on input channel 0, with its one-word buffer (paper §2.4: "Each input
// device is thus provided with a buffer whose length need only be a word"; "As soon as a buffer has
// been completely filled, a flag is lifted and the external device stops itself").
//
// Pins as modelled: RUN (start, from the program: SET RUN), RDR (buffer-full flag, to the program;
// RST RDR lowers it), EOT (no tape left), the buffer's eight digits in the external code (BCD).
//
// One tape word (an address letter, a sign for X Y I J, its digits in the fixed format of tape.h)
// fills the buffer; the reader's decoding logic puts the letter's code in the lowest digit, the sign
// in the highest (0 +, 9 -) and the digits between, right-aligned:
//
//     digit  7    6 .. 1     0
//            S    v5 .. v0   L     L: N 1, G 2, X 3, Y 4, I 5, J 6, F 7, end of block 8
//
// so that IN 0,1 gives the letter and IN 0,8 then a one-digit SHR the value (docs/pisa.md).
// Timing: one character every char_steps digit steps (300 characters/s by default), counted from
// the start; the flag rises when the word's last character has been read.
//
// Not emulated: the tape's mechanics (start and stop times, skew), parity, reading backwards.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace alp85::pisa {

enum LetterCode : std::uint8_t { kN = 1, kG = 2, kX = 3, kY = 4, kI = 5, kJ = 6, kF = 7, kEob = 8 };

struct TapeWord {
    std::uint8_t letter = kEob;
    bool negative = false;
    std::uint32_t value = 0;  // up to six digits
    int chars = 1;            // characters on tape: letter, sign, digits (fixed format)
    int line = 0;             // where it came from in the tape file (1-based)
};

class TapeReader {
public:
    static constexpr std::uint64_t kNever = ~std::uint64_t{0};
    struct Params {
        std::uint64_t char_steps = 33'333;  // 300 characters/s at 100 ns a step
    };
    TapeReader() = default;
    explicit TapeReader(Params p) : p_(p) {}

    void load(std::vector<TapeWord> words);
    void reset();

    void start(std::uint64_t now);   // SET RUN: read the next word (or raise EOT at the end)
    void stop() { due_ = kNever; }    // RST RUN
    void advance(std::uint64_t now); // the flag rises when the word is in

    bool flag() const { return flag_; }
    void reset_flag() { flag_ = false; }
    bool running() const { return due_ != kNever; }
    bool at_end() const { return eot_; }
    const std::array<std::uint8_t, 8>& buffer() const { return buffer_; }  // external BCD digits
    std::uint64_t next_event() const { return due_; }
    // When the last word was read in (digit steps): for "reading never stalls" checks.
    std::uint64_t last_fill() const { return last_fill_; }

private:
    Params p_;
    std::vector<TapeWord> words_;
    std::size_t next_ = 0;
    std::uint64_t due_ = kNever;
    std::uint64_t last_fill_ = 0;
    bool flag_ = false;
    bool eot_ = false;
    std::array<std::uint8_t, 8> buffer_{};
};

}  // namespace alp85::pisa
