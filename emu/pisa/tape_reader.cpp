// The tape reader: one word into the buffer per start, the flag when it is in.
#include "emu/pisa/tape_reader.h"

namespace alp85::pisa {

void TapeReader::load(std::vector<TapeWord> words) {
    words_ = std::move(words);
    reset();
}

void TapeReader::reset() {
    next_ = 0;
    due_ = kNever;
    flag_ = false;
    eot_ = false;
    buffer_.fill(0);
    last_fill_ = 0;
}

void TapeReader::start(std::uint64_t now) {
    if (running()) return;
    if (next_ >= words_.size()) {
        eot_ = true;
        return;
    }
    due_ = now + p_.char_steps * static_cast<std::uint64_t>(words_[next_].chars);
}

void TapeReader::advance(std::uint64_t now) {
    if (due_ == kNever || now < due_) return;
    const TapeWord& w = words_[next_++];
    std::uint32_t v = w.value;
    buffer_[0] = w.letter;
    for (std::size_t i = 1; i <= 6; ++i) {
        buffer_[i] = static_cast<std::uint8_t>(v % 10);
        v /= 10;
    }
    buffer_[7] = w.negative ? 9 : 0;
    flag_ = true;
    last_fill_ = due_;
    due_ = kNever;  // "the external device stops itself"
}

}  // namespace alp85::pisa
