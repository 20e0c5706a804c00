// Base64 (RFC 4648, section 4: the standard alphabet, '=' padding, no line breaks): how a page
// carries binary data in its text, as the html replay carries its glTF (io/replay_page.hpp).
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace tumble::io {

// 4 characters for every 3 bytes or part of them.
std::string base64(std::span<const std::uint8_t> bytes);

}  // namespace tumble::io
