// Compiler-style diagnostics: file:line:col: severity: message, the line, and a caret.
#include "asm/asm85.h"

namespace alp85::asm85 {

std::string format_diagnostic(const Diagnostic& d) {
    std::string out;
    out += d.file.empty() ? std::string("asm85") : d.file;
    if (d.line > 0) out += ":" + std::to_string(d.line);
    if (d.line > 0 && d.col > 0) out += ":" + std::to_string(d.col);
    out += d.severity == Severity::Error ? ": error: " : d.severity == Severity::Warning ? ": warning: " : ": note: ";
    out += d.message;
    out += '\n';
    if (d.line > 0 && !d.source_line.empty()) {
        out += d.source_line;
        out += '\n';
        if (d.col > 0) {
            // Keep tabs so the caret lines up under the column in a terminal.
            std::size_t n = std::min(static_cast<std::size_t>(d.col - 1), d.source_line.size());
            for (std::size_t i = 0; i < n; ++i) out += d.source_line[i] == '\t' ? '\t' : ' ';
            out += "^\n";
        }
    }
    return out;
}

}  // namespace alp85::asm85
