// The headers nearly every unit of the sanitizer build includes, compiled once per optimisation
// level into a precompiled header that the whole build reuses (CMakeLists.txt, clang only). A
// unit still includes what it uses; this file only makes those includes cheap.
#pragma once
#include <gtest/gtest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <bitset>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
