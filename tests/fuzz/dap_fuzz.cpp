// libFuzzer target: the DAP server's input as bytes on the wire - framing (Content-Length headers)
// then each body given to the adapter, whose runs advance a bounded number of slices. Nothing a
// client sends may end the session: every frame is answered or ignored, never a crash. The seed
// corpus holds real sessions (initialize, launch of a small program, breakpoints, steps,
// evaluate), so that the fuzzer mutates requests the adapter gets that far with.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>

#include "emu/dap/adapter.h"
#include "emu/dap/framing.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // The program the seeds launch (a loop with a call, so that there is a stack to look at).
    std::ofstream("/tmp/alp85-dap-fuzz.asm") << "\tORG 0800H\nSTART:\tLXI SP,2000H\nLOOP:\tMVI A,5\n\tCALL SUB\n"
                                                "\tJMP LOOP\nSUB:\tDCR A\n\tJNZ SUB\n\tRET\n\tEND START\n";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 1024) return 0;
    using namespace alp85::dap;
    std::size_t sent = 0;
    Adapter a([&sent](const Json&) { ++sent; });
    FrameReader r;
    r.feed(std::string_view(reinterpret_cast<const char*>(data), size));
    int frames = 0;
    while (auto f = r.next()) {
        if (++frames > 64) break;
        if (!f->error.empty()) a.refuse_frame(f->error);
        else a.receive(f->body);
        // Three slices a frame (an unpaced slice is 20 ms of host time): enough for a run to go,
        // stop or be paused; more only made each input take seconds (the hour's run stalled on
        // a launch without stopOnEntry, 64 frames x 1 s, under a starved CPU).
        for (int i = 0; i < 3 && a.running(); ++i) (void)a.advance();
        if (a.finished()) break;
    }
    return 0;
}
