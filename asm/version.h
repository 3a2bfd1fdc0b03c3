// ALP85's version, shared by alp85, asm85 and pisa-asm (--version): "0.1.0", followed in a git
// checkout by the commit it was built from, "0.1.0 (git 92e6e13c5a1b)", "-dirty" when the work
// tree had changes. The text is generated at build time (scripts/packaging/version.cmake).
#pragma once

#include <string_view>

namespace alp85 {
std::string_view version();
}  // namespace alp85
