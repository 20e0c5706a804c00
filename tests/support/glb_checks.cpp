#include "support/glb_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tumble::testing {
namespace {

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"

std::uint32_t word_at(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  std::uint32_t word = 0;
  for (std::size_t i = 0; i < 4; ++i) word |= static_cast<std::uint32_t>(bytes[at + i]) << (8 * i);
  return word;
}

// The header and the chunks; the BIN chunk's length into `bin_length` (0 without one).
void check_layout(const std::vector<std::uint8_t>& bytes, std::vector<std::string>& problems,
                  std::size_t& bin_length) {
  bin_length = 0;
  if (bytes.size() < 20) {
    problems.push_back("shorter than a header and one chunk header");
    return;
  }
  if (word_at(bytes, 0) != kMagic) problems.push_back("magic is not \"glTF\"");
  if (word_at(bytes, 4) != 2) problems.push_back("version is not 2");
  if (word_at(bytes, 8) != bytes.size()) problems.push_back("header length is not the file's");
  std::size_t at = 12;
  for (int chunk = 0; at < bytes.size(); ++chunk) {
    if (at % 4 != 0 || at + 8 > bytes.size()) {
      problems.push_back("chunk " + std::to_string(chunk) + " starts off a 4-byte boundary");
      return;
    }
    const std::size_t length = word_at(bytes, at);
    const std::uint32_t type = word_at(bytes, at + 4);
    if (length % 4 != 0) problems.push_back("chunk " + std::to_string(chunk) + " not padded to 4");
    if (chunk == 0 && type != kJsonChunk) problems.push_back("first chunk is not JSON");
    if (chunk == 1 && type != kBinChunk) problems.push_back("second chunk is not BIN");
    if (chunk > 1) problems.push_back("more than two chunks");
    if (chunk == 1) bin_length = length;
    if (chunk == 0 && length > 0 && bytes[at + 8 + length - 1] != ' ' &&
        bytes[at + 8 + length - 1] != '}') {
      problems.push_back("JSON chunk padded with something other than spaces");
    }
    at += 8 + length;
  }
  if (at != bytes.size()) problems.push_back("chunks do not end where the file does");
}

std::size_t element_size(const tinygltf::Accessor& accessor) {
  return static_cast<std::size_t>(
      tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType)) *
      tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type)));
}

void check_buffers(const tinygltf::Model& model, std::size_t bin_length,
                   std::vector<std::string>& problems) {
  if (model.buffers.size() != 1) problems.push_back("not exactly one buffer");
  if (model.buffers.empty()) return;
  const tinygltf::Buffer& buffer = model.buffers[0];
  if (!buffer.uri.empty()) problems.push_back("buffers[0] has a uri");
  if (buffer.data.size() > bin_length || bin_length - buffer.data.size() > 3) {
    problems.push_back("buffers[0] is not the BIN chunk");
  }
  for (std::size_t i = 0; i < model.bufferViews.size(); ++i) {
    const tinygltf::BufferView& view = model.bufferViews[i];
    if (view.buffer != 0 || view.byteLength == 0 ||
        view.byteOffset + view.byteLength > buffer.data.size() || view.byteOffset % 4 != 0) {
      problems.push_back("bufferView " + std::to_string(i) + " outside buffers[0] or unaligned");
    }
  }
  for (std::size_t i = 0; i < model.accessors.size(); ++i) {
    const tinygltf::Accessor& accessor = model.accessors[i];
    const std::size_t size = element_size(accessor);
    const bool in_views = accessor.bufferView >= 0 &&
                          static_cast<std::size_t>(accessor.bufferView) < model.bufferViews.size();
    if (!in_views || size == 0 || accessor.count == 0) {
      problems.push_back("accessor " + std::to_string(i) + " has no bufferView, type or count");
      continue;
    }
    const tinygltf::BufferView& view =
        model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    const std::size_t stride = view.byteStride ? view.byteStride : size;
    const std::size_t component = static_cast<std::size_t>(
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType)));
    if (accessor.byteOffset + stride * (accessor.count - 1) + size > view.byteLength ||
        (view.byteOffset + accessor.byteOffset) % component != 0) {
      problems.push_back("accessor " + std::to_string(i) + " outside its bufferView or unaligned");
    }
  }
}

// The accessor's min and max are present, of its width, and its data's.
void check_bounds(const tinygltf::Model& model, int index, const std::string& what,
                  std::vector<std::string>& problems) {
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const std::size_t width = static_cast<std::size_t>(
      tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type)));
  if (accessor.minValues.size() != width || accessor.maxValues.size() != width) {
    problems.push_back(what + ": accessor " + std::to_string(index) + " lacks min or max");
    return;
  }
  const std::vector<float> values = accessor_floats(model, index);
  for (std::size_t c = 0; c < width; ++c) {
    float low = values[c], high = values[c];
    for (std::size_t k = c; k < values.size(); k += width) {
      low = std::min(low, values[k]);
      high = std::max(high, values[k]);
    }
    if (static_cast<float>(accessor.minValues[c]) != low ||
        static_cast<float>(accessor.maxValues[c]) != high) {
      problems.push_back(what + ": accessor " + std::to_string(index) +
                         "'s min or max is not its data's");
    }
  }
}

bool in_range(int index, std::size_t size) {
  return index >= 0 && static_cast<std::size_t>(index) < size;
}

void check_meshes(const tinygltf::Model& model, std::vector<std::string>& problems) {
  for (std::size_t m = 0; m < model.meshes.size(); ++m) {
    const std::string what = "mesh " + std::to_string(m);
    for (const tinygltf::Primitive& primitive : model.meshes[m].primitives) {
      const auto position = primitive.attributes.find("POSITION");
      if (position == primitive.attributes.end() ||
          !in_range(position->second, model.accessors.size())) {
        problems.push_back(what + ": no POSITION");
        continue;
      }
      check_bounds(model, position->second, what + " POSITION", problems);
      const std::size_t count = model.accessors[static_cast<std::size_t>(position->second)].count;
      if (!in_range(primitive.material, model.materials.size())) {
        problems.push_back(what + ": material out of range");
      }
      if (!in_range(primitive.indices, model.accessors.size())) {
        problems.push_back(what + ": no indices");
        continue;
      }
      const std::vector<std::uint32_t> indices = accessor_indices(model, primitive.indices);
      if (indices.size() % 3 != 0 || std::any_of(indices.begin(), indices.end(),
                                                 [&](std::uint32_t i) { return i >= count; })) {
        problems.push_back(what + ": an index past its positions, or a partial triangle");
      }
      const auto normal = primitive.attributes.find("NORMAL");
      if (normal == primitive.attributes.end()) continue;
      const std::vector<float> normals = accessor_floats(model, normal->second);
      if (normals.size() != 3 * count) problems.push_back(what + ": not one normal per position");
      for (std::size_t k = 0; k + 2 < normals.size(); k += 3) {
        if (std::abs(std::hypot(normals[k], normals[k + 1], normals[k + 2]) - 1.0) > 1e-5) {
          problems.push_back(what + ": normal " + std::to_string(k / 3) + " is not unit");
          break;
        }
      }
    }
  }
}

void check_nodes(const tinygltf::Model& model, std::vector<std::string>& problems) {
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    const tinygltf::Node& node = model.nodes[n];
    const std::string what = "node " + std::to_string(n);
    if (node.mesh != -1 && !in_range(node.mesh, model.meshes.size())) {
      problems.push_back(what + ": mesh out of range");
    }
    if (node.camera != -1 && !in_range(node.camera, model.cameras.size())) {
      problems.push_back(what + ": camera out of range");
    }
    if (!node.matrix.empty()) problems.push_back(what + ": a matrix (animated nodes need TRS)");
    if (node.rotation.size() == 4) {
      const double norm =
          std::sqrt(node.rotation[0] * node.rotation[0] + node.rotation[1] * node.rotation[1] +
                    node.rotation[2] * node.rotation[2] + node.rotation[3] * node.rotation[3]);
      if (std::abs(norm - 1.0) > 1e-6) problems.push_back(what + ": rotation not unit");
    }
  }
  for (const tinygltf::Scene& scene : model.scenes) {
    for (const int node : scene.nodes) {
      if (!in_range(node, model.nodes.size())) problems.emplace_back("a scene's node out of range");
    }
  }
  if (!in_range(model.defaultScene, model.scenes.size())) problems.push_back("no default scene");
  for (std::size_t c = 0; c < model.cameras.size(); ++c) {
    const tinygltf::PerspectiveCamera& p = model.cameras[c].perspective;
    if (model.cameras[c].type != "perspective" || !(p.yfov > 0.0) || !(p.znear > 0.0) ||
        !(p.zfar > p.znear)) {
      problems.push_back("camera " + std::to_string(c) + ": not a valid perspective camera");
    }
  }
}

void check_sampler(const tinygltf::Model& model, const tinygltf::AnimationSampler& sampler,
                   const std::string& path, const std::string& what,
                   std::vector<std::string>& problems) {
  if (!in_range(sampler.input, model.accessors.size()) ||
      !in_range(sampler.output, model.accessors.size())) {
    problems.push_back(what + ": input or output out of range");
    return;
  }
  check_bounds(model, sampler.input, what + " input", problems);
  const std::vector<float> times = accessor_floats(model, sampler.input);
  for (std::size_t k = 1; k < times.size(); ++k) {
    if (!(times[k] > times[k - 1])) {
      problems.push_back(what + ": times not strictly increasing at " + std::to_string(k));
      break;
    }
  }
  const std::size_t width = path == "rotation" ? 4 : 3;
  const std::vector<float> values = accessor_floats(model, sampler.output);
  if (values.size() != width * times.size()) {
    problems.push_back(what + ": not one " + path + " per time");
    return;
  }
  if (sampler.interpolation != "LINEAR") problems.push_back(what + ": not LINEAR");
  for (std::size_t k = 0; width == 4 && k < values.size(); k += 4) {
    const double norm =
        std::sqrt(double{values[k]} * values[k] + double{values[k + 1]} * values[k + 1] +
                  double{values[k + 2]} * values[k + 2] + double{values[k + 3]} * values[k + 3]);
    if (std::abs(norm - 1.0) > 1e-6) {
      problems.push_back(what + ": rotation " + std::to_string(k / 4) + " not unit");
      break;
    }
  }
}

void check_animations(const tinygltf::Model& model, std::vector<std::string>& problems) {
  for (std::size_t a = 0; a < model.animations.size(); ++a) {
    const tinygltf::Animation& animation = model.animations[a];
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
      const tinygltf::AnimationChannel& channel = animation.channels[c];
      const std::string what = "animation " + std::to_string(a) + " channel " + std::to_string(c);
      if (!in_range(channel.target_node, model.nodes.size()) ||
          !in_range(channel.sampler, animation.samplers.size()) ||
          (channel.target_path != "translation" && channel.target_path != "rotation")) {
        problems.push_back(what + ": node, sampler or path out of range");
        continue;
      }
      check_sampler(model, animation.samplers[static_cast<std::size_t>(channel.sampler)],
                    channel.target_path, what, problems);
    }
  }
}

}  // namespace

bool load_glb(const std::vector<std::uint8_t>& bytes, tinygltf::Model& model, std::string& error) {
  tinygltf::TinyGLTF loader;
  std::string warning;
  const bool loaded = loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(),
                                                  static_cast<unsigned int>(bytes.size()));
  if (!warning.empty()) error += (error.empty() ? "" : "; ") + warning;
  return loaded && warning.empty();
}

std::vector<std::string> glb_problems(const std::vector<std::uint8_t>& bytes) {
  std::vector<std::string> problems;
  std::size_t bin_length = 0;
  check_layout(bytes, problems, bin_length);
  if (!problems.empty()) return problems;
  tinygltf::Model model;
  std::string error;
  if (!load_glb(bytes, model, error)) return {"tinygltf cannot read it: " + error};
  if (model.asset.version != "2.0") problems.push_back("asset.version is not 2.0");
  check_buffers(model, bin_length, problems);
  if (!problems.empty()) return problems;  // the data checks below read through the views
  check_meshes(model, problems);
  check_nodes(model, problems);
  check_animations(model, problems);
  return problems;
}

std::vector<float> accessor_floats(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) return {};
  const tinygltf::BufferView& view =
      model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
  const std::size_t width = static_cast<std::size_t>(
      tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type)));
  const std::size_t stride = view.byteStride ? view.byteStride : width * sizeof(float);
  const std::uint8_t* base = model.buffers[static_cast<std::size_t>(view.buffer)].data.data() +
                             view.byteOffset + accessor.byteOffset;
  std::vector<float> out(accessor.count * width);
  for (std::size_t k = 0; k < accessor.count; ++k) {
    std::memcpy(&out[k * width], base + k * stride, width * sizeof(float));
  }
  return out;
}

std::vector<std::uint32_t> accessor_indices(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const tinygltf::BufferView& view =
      model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
  const std::uint8_t* base = model.buffers[static_cast<std::size_t>(view.buffer)].data.data() +
                             view.byteOffset + accessor.byteOffset;
  std::vector<std::uint32_t> out;
  for (std::size_t k = 0; k < accessor.count; ++k) {
    switch (accessor.componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        out.push_back(base[k]);
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t value = 0;
        std::memcpy(&value, base + 2 * k, 2);
        out.push_back(value);
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t value = 0;
        std::memcpy(&value, base + 4 * k, 4);
        out.push_back(value);
        break;
      }
      default:
        return {};
    }
  }
  return out;
}

}  // namespace tumble::testing
