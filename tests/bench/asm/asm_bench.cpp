// How long asm85 takes for a generated 10,000-line program: instructions of every shape, labels
// with forward references, data, EQUs, a macro and a REPT, as a large firmware source would have.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>

#include "asm/asm85.h"

namespace {

std::string generate(int lines) {
    std::string s = "\tORG 100H\nPORT\tEQU 20H\nCOUNT\tSET 0\n"
                    "BUMP\tMACRO R,V\n\tMVI R,V\n\tINR R\n\tENDM\n";
    int n = 5, i = 0;
    for (; n < lines; ++i) {
        std::string l = "L" + std::to_string(i);
        s += l + ":\tLXI H," + "L" + std::to_string(i + 1) + "\n";  // forward reference
        s += "\tMOV A,M\n\tADI 12H\n\tOUT PORT\n\tJNZ " + l + "\n";
        s += "\tBUMP B,%COUNT AND 7FH\n";                             // 3 lines when expanded
        s += "\tDB 'TEXT',0DH,0AH,HIGH " + l + ",LOW " + l + "\n";
        s += "\tDW " + l + ",$+2\n";
        s += "COUNT\tSET COUNT+1\n";
        n += 9;  // source lines per block (the macro adds 3 expanded lines)
    }
    s += "L" + std::to_string(i) + ":\tREPT 4\n\tNOP\n\tENDM\n";
    s += "\tEND 100H\n";
    return s;
}

void BM_Assemble10kLines(benchmark::State& state) {
    static const std::string src = generate(10000);
    alp85::asm85::Options o;
    std::size_t bytes = 0;
    for (auto _ : state) {
        auto r = alp85::asm85::assemble_string(src, o, "bench.asm");
        if (!r.ok()) state.SkipWithError("assembly failed");
        bytes = r.image.size();
        benchmark::DoNotOptimize(r);
    }
    state.counters["bytes"] = static_cast<double>(bytes);
    state.counters["lines"] = static_cast<double>(std::count(src.begin(), src.end(), '\n'));
}
BENCHMARK(BM_Assemble10kLines)->Unit(benchmark::kMillisecond);

void BM_WriteHexListingMap(benchmark::State& state) {
    static const std::string src = generate(10000);
    auto r = alp85::asm85::assemble_string(src, {}, "bench.asm");
    for (auto _ : state) {
        benchmark::DoNotOptimize(alp85::asm85::write_intel_hex(r.image));
        benchmark::DoNotOptimize(alp85::asm85::write_listing(r));
        benchmark::DoNotOptimize(alp85::asm85::write_json_map(r));
    }
}
BENCHMARK(BM_WriteHexListingMap)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
