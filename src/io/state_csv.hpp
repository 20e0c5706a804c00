// CSV dumps of body states: one row per body per sampled step, numbers at full precision (%.17g)
// so that a dump can be read back bit for bit.
#pragma once

#include <array>
#include <cstdio>
#include <string_view>

namespace tumble::io {

// The columns after `t` and `body`, in order.
inline constexpr std::array<std::string_view, 20> kStateColumns = {
    "x",  "y",  "z",  "vx", "vy", "vz", "qw", "qx", "qy", "qz",
    "wx", "wy", "wz", "px", "py", "pz", "Lx", "Ly", "Lz", "energy"};

using StateRow = std::array<double, kStateColumns.size()>;

// Both return false if the stream reported an error.
bool write_state_header(std::FILE* out);
bool write_state_row(std::FILE* out, double t, std::string_view body, const StateRow& values);

}  // namespace tumble::io
