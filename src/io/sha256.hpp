// SHA-256 of bytes (FIPS 180-4, libavutil's), as lowercase hex: what `sha256sum` prints. A
// render names the scene it drew by it, and `tumble join` compares the names.
#pragma once

#include <string>
#include <string_view>

namespace tumble::io {

std::string sha256_hex(std::string_view bytes);

}  // namespace tumble::io
