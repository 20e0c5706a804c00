#include "job/scene_hash.hpp"

#include "io/json_text.hpp"
#include "io/sha256.hpp"

namespace tumble::job {

std::string scene_hash(std::string_view file_bytes, const scene::Scene& rendered) {
  std::string text(file_bytes);
  text += "\n# as rendered: width=" + std::to_string(rendered.render.width) +
          " height=" + std::to_string(rendered.render.height) +
          " fps=" + std::to_string(rendered.fps) + " msaa=" + std::to_string(rendered.render.msaa) +
          " duration=" + io::json_number(rendered.duration) + "\n";
  return io::sha256_hex(text);
}

}  // namespace tumble::job
