#include "io/glb_writer.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "io/atomic_file.hpp"

namespace tumble::io {
namespace {

// GLB's header and chunks count their bytes in 32 bits (Specification.adoc, "Binary glTF
// Layout"). The BIN chunk is refused past this, leaving 64 MiB of the 4 GiB for the JSON; the
// file's own length is checked after writing.
constexpr std::size_t kMaxBinBytes = 0xFFFFFFFFull - (std::size_t{64} << 20);

constexpr int kArrayBuffer = TINYGLTF_TARGET_ARRAY_BUFFER;                 // vertex attributes
constexpr int kElementArrayBuffer = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;  // indices

// buffers[0]'s bytes and the bufferViews and accessors over them, appended in the order asked,
// each view starting on a 4-byte boundary (every component here is 2 or 4 bytes, and an
// accessor's offset must be a multiple of its component's size).
class BinWriter {
 public:
  explicit BinWriter(tinygltf::Model& model) : model_(model) {}

  template <class T>
  int view(const std::vector<T>& values, int target) {
    while (bytes_.size() % 4 != 0) bytes_.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = bytes_.size();
    view.byteLength = values.size() * sizeof(T);
    view.target = target;
    const auto* begin = reinterpret_cast<const unsigned char*>(values.data());
    bytes_.insert(bytes_.end(), begin, begin + view.byteLength);
    model_.bufferViews.push_back(std::move(view));
    return static_cast<int>(model_.bufferViews.size() - 1);
  }

  // An accessor of the whole view `view`: `count` elements of `type` (TINYGLTF_TYPE_*), each of
  // `component` (TINYGLTF_COMPONENT_TYPE_*), with min and max when given.
  int accessor(int view, int component, int type, std::size_t count, std::vector<double> min = {},
               std::vector<double> max = {}) {
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.componentType = component;
    accessor.type = type;
    accessor.count = count;
    accessor.minValues = std::move(min);
    accessor.maxValues = std::move(max);
    model_.accessors.push_back(std::move(accessor));
    return static_cast<int>(model_.accessors.size() - 1);
  }

  std::size_t size() const { return bytes_.size(); }

  // Into buffers[0], with no uri: the GLB's BIN chunk. Its length is padded to 4 bytes here, so
  // that the buffer's byteLength is the chunk's.
  void finish() {
    while (bytes_.size() % 4 != 0) bytes_.push_back(0);
    tinygltf::Buffer buffer;
    buffer.data = std::move(bytes_);
    model_.buffers.push_back(std::move(buffer));
  }

 private:
  tinygltf::Model& model_;
  std::vector<unsigned char> bytes_;
};

// Each component's least and greatest value over `values`.
template <std::size_t N>
void bounds(const std::vector<std::array<float, N>>& values, std::vector<double>& min,
            std::vector<double>& max) {
  min.assign(N, std::numeric_limits<double>::infinity());
  max.assign(N, -std::numeric_limits<double>::infinity());
  for (const std::array<float, N>& value : values) {
    for (std::size_t i = 0; i < N; ++i) {
      min[i] = std::min(min[i], static_cast<double>(value[i]));
      max[i] = std::max(max[i], static_cast<double>(value[i]));
    }
  }
}

bool finite(const std::array<double, 3>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// `rotation` normalised, or nothing when it has no direction (or is not finite).
std::optional<std::array<double, 4>> unit(const std::array<double, 4>& rotation) {
  const double norm = std::sqrt(rotation[0] * rotation[0] + rotation[1] * rotation[1] +
                                rotation[2] * rotation[2] + rotation[3] * rotation[3]);
  if (!std::isfinite(norm) || norm == 0.0) return std::nullopt;
  return std::array<double, 4>{rotation[0] / norm, rotation[1] / norm, rotation[2] / norm,
                               rotation[3] / norm};
}

std::string mesh_label(std::size_t i, const GltfMesh& mesh) {
  return "glTF mesh " + std::to_string(i) + (mesh.name.empty() ? "" : " (" + mesh.name + ")");
}

Result<void> add_mesh(const GltfScene& scene, std::size_t index, BinWriter& bin,
                      tinygltf::Model& model) {
  const GltfMesh& mesh = scene.meshes[index];
  if (mesh.positions.empty() || mesh.triangles.empty() || mesh.triangles.size() % 3 != 0 ||
      mesh.normals.size() != mesh.positions.size()) {
    return Error{mesh_label(index, mesh) +
                 ": needs positions, as many normals and whole triangles (3 indices each)"};
  }
  if (mesh.material >= scene.materials.size()) {
    return Error{mesh_label(index, mesh) + ": material " + std::to_string(mesh.material) + " of " +
                 std::to_string(scene.materials.size())};
  }
  const std::uint32_t highest = *std::max_element(mesh.triangles.begin(), mesh.triangles.end());
  if (highest >= mesh.positions.size()) {
    return Error{mesh_label(index, mesh) + ": index " + std::to_string(highest) + " of " +
                 std::to_string(mesh.positions.size()) + " positions"};
  }
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = static_cast<int>(mesh.material);
  std::vector<double> min, max;
  bounds(mesh.positions, min, max);
  primitive.attributes["POSITION"] =
      bin.accessor(bin.view(mesh.positions, kArrayBuffer), TINYGLTF_COMPONENT_TYPE_FLOAT,
                   TINYGLTF_TYPE_VEC3, mesh.positions.size(), min, max);
  primitive.attributes["NORMAL"] =
      bin.accessor(bin.view(mesh.normals, kArrayBuffer), TINYGLTF_COMPONENT_TYPE_FLOAT,
                   TINYGLTF_TYPE_VEC3, mesh.normals.size());
  if (mesh.positions.size() <= 65536) {
    const std::vector<std::uint16_t> shorts(mesh.triangles.begin(), mesh.triangles.end());
    primitive.indices =
        bin.accessor(bin.view(shorts, kElementArrayBuffer), TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                     TINYGLTF_TYPE_SCALAR, shorts.size());
  } else {
    primitive.indices = bin.accessor(bin.view(mesh.triangles, kElementArrayBuffer),
                                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                     mesh.triangles.size());
  }
  tinygltf::Mesh out;
  out.name = mesh.name;
  out.primitives.push_back(std::move(primitive));
  model.meshes.push_back(std::move(out));
  return {};
}

void add_material(const GltfMaterial& material, tinygltf::Model& model) {
  tinygltf::Material out;
  out.name = material.name;
  out.pbrMetallicRoughness.baseColorFactor.assign(material.base_color.begin(),
                                                  material.base_color.end());
  out.pbrMetallicRoughness.metallicFactor = material.metallic;
  out.pbrMetallicRoughness.roughnessFactor = material.roughness;
  out.doubleSided = material.double_sided;
  if (material.base_color[3] < 1.0) out.alphaMode = "BLEND";
  model.materials.push_back(std::move(out));
}

Result<void> add_camera(const GltfCamera& camera, tinygltf::Model& model) {
  if (!(camera.yfov > 0.0 && camera.yfov < M_PI && camera.aspect_ratio > 0.0 &&
        camera.znear > 0.0 && camera.zfar > camera.znear && std::isfinite(camera.zfar) &&
        std::isfinite(camera.aspect_ratio))) {
    return Error{"glTF camera " + camera.name +
                 ": needs 0 < yfov < pi, aspect_ratio > 0 and 0 < znear < zfar, all finite"};
  }
  tinygltf::Camera out;
  out.name = camera.name;
  out.type = "perspective";
  out.perspective.yfov = camera.yfov;
  out.perspective.aspectRatio = camera.aspect_ratio;
  out.perspective.znear = camera.znear;
  out.perspective.zfar = camera.zfar;
  model.cameras.push_back(std::move(out));
  return {};
}

Result<void> add_node(const GltfScene& scene, const GltfNode& node, tinygltf::Model& model) {
  const std::string label = "glTF node " + node.name;
  if (node.mesh && *node.mesh >= scene.meshes.size()) {
    return Error{label + ": mesh " + std::to_string(*node.mesh) + " of " +
                 std::to_string(scene.meshes.size())};
  }
  if (node.camera && *node.camera >= scene.cameras.size()) {
    return Error{label + ": camera " + std::to_string(*node.camera) + " of " +
                 std::to_string(scene.cameras.size())};
  }
  const std::optional<std::array<double, 4>> rotation = unit(node.pose.rotation);
  if (!rotation || !finite(node.pose.translation)) {
    return Error{label + ": its pose is not finite, or its rotation is zero"};
  }
  tinygltf::Node out;
  out.name = node.name;
  if (node.mesh) out.mesh = static_cast<int>(*node.mesh);
  if (node.camera) out.camera = static_cast<int>(*node.camera);
  out.translation.assign(node.pose.translation.begin(), node.pose.translation.end());
  out.rotation.assign(rotation->begin(), rotation->end());
  model.nodes.push_back(std::move(out));
  return {};
}

// The track's translations and rotations as floats, each rotation unit and on the side of the one
// before it.
Result<void> track_values(const GltfTrack& track, std::vector<std::array<float, 3>>& translations,
                          std::vector<std::array<float, 4>>& rotations) {
  std::array<double, 4> before = {0.0, 0.0, 0.0, 1.0};
  for (std::size_t k = 0; k < track.poses.size(); ++k) {
    const GltfPose& pose = track.poses[k];
    std::optional<std::array<double, 4>> rotation = unit(pose.rotation);
    if (!rotation || !finite(pose.translation)) {
      return Error{"glTF animation, node " + std::to_string(track.node) + ", pose " +
                   std::to_string(k) + ": not finite, or its rotation is zero"};
    }
    double dot = 0.0;
    for (std::size_t i = 0; i < 4; ++i) dot += (*rotation)[i] * before[i];
    if (k > 0 && dot < 0.0) {
      for (double& component : *rotation) component = -component;
    }
    before = *rotation;
    translations.push_back({static_cast<float>(pose.translation[0]),
                            static_cast<float>(pose.translation[1]),
                            static_cast<float>(pose.translation[2])});
    rotations.push_back({static_cast<float>((*rotation)[0]), static_cast<float>((*rotation)[1]),
                         static_cast<float>((*rotation)[2]), static_cast<float>((*rotation)[3])});
  }
  return {};
}

Result<void> add_animation(const GltfScene& scene, const GltfAnimation& animation, BinWriter& bin,
                           tinygltf::Model& model) {
  std::vector<float> times;
  for (const double t : animation.times) times.push_back(static_cast<float>(t));
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k]) || (k > 0 && !(times[k] > times[k - 1]))) {
      return Error{
          "glTF animation: its times must be finite and strictly increasing as floats "
          "(time " +
          std::to_string(k) + ")"};
    }
  }
  if (times.empty() || animation.tracks.empty()) return {};  // nothing moves
  tinygltf::Animation out;
  out.name = animation.name;
  const int input =
      bin.accessor(bin.view(times, 0), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR,
                   times.size(), {times.front()}, {times.back()});
  std::vector<bool> animated(scene.nodes.size(), false);
  for (const GltfTrack& track : animation.tracks) {
    if (track.node >= scene.nodes.size() || animated[track.node] ||
        track.poses.size() != times.size()) {
      return Error{"glTF animation: the track of node " + std::to_string(track.node) +
                   " is of no node, a node's second, or not of one pose per time"};
    }
    animated[track.node] = true;
    std::vector<std::array<float, 3>> translations;
    std::vector<std::array<float, 4>> rotations;
    if (Result<void> made = track_values(track, translations, rotations); !made) return made;
    const int moves = bin.accessor(bin.view(translations, 0), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                   TINYGLTF_TYPE_VEC3, translations.size());
    const int turns = bin.accessor(bin.view(rotations, 0), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                   TINYGLTF_TYPE_VEC4, rotations.size());
    for (const auto& [output, path] : {std::pair{moves, "translation"}, {turns, "rotation"}}) {
      tinygltf::AnimationSampler sampler;
      sampler.input = input;
      sampler.output = output;
      sampler.interpolation = "LINEAR";
      out.samplers.push_back(std::move(sampler));
      tinygltf::AnimationChannel channel;
      channel.sampler = static_cast<int>(out.samplers.size() - 1);
      channel.target_node = static_cast<int>(track.node);
      channel.target_path = path;
      out.channels.push_back(std::move(channel));
    }
  }
  model.animations.push_back(std::move(out));
  return {};
}

Result<tinygltf::Model> gltf_model(const GltfScene& scene) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = scene.generator;
  BinWriter bin(model);
  for (const GltfMaterial& material : scene.materials) add_material(material, model);
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    if (Result<void> added = add_mesh(scene, i, bin, model); !added) return Error{added.error()};
  }
  for (const GltfCamera& camera : scene.cameras) {
    if (Result<void> added = add_camera(camera, model); !added) return Error{added.error()};
  }
  tinygltf::Scene root;
  root.name = scene.name;
  for (const GltfNode& node : scene.nodes) {
    if (Result<void> added = add_node(scene, node, model); !added) return Error{added.error()};
    root.nodes.push_back(static_cast<int>(model.nodes.size() - 1));
  }
  model.scenes.push_back(std::move(root));
  model.defaultScene = 0;
  if (scene.animation) {
    if (Result<void> added = add_animation(scene, *scene.animation, bin, model); !added) {
      return Error{added.error()};
    }
  }
  if (bin.size() > kMaxBinBytes) {
    return Error{"glTF: " + std::to_string(bin.size()) +
                 " bytes of meshes and animation, past what a GLB holds (4 GiB): render fewer "
                 "frames (--frames) or a lower fps"};
  }
  bin.finish();
  return model;
}

std::uint32_t little_endian_word(const std::string& bytes, std::size_t at) {
  std::uint32_t word = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    word |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  }
  return word;
}

}  // namespace

Result<std::vector<std::uint8_t>> glb_bytes(const GltfScene& scene) {
  Result<tinygltf::Model> model = gltf_model(scene);
  if (!model) return Error{model.error()};
  std::ostringstream stream;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&*model, stream, false, true) || !stream) {
    return Error{"glTF: tinygltf could not write the GLB"};
  }
  const std::string bytes = std::move(stream).str();
  // The header's length is 32 bits: a JSON that took the file past 4 GiB would wrap it.
  if (bytes.size() < 12 || little_endian_word(bytes, 8) != bytes.size()) {
    return Error{"glTF: " + std::to_string(bytes.size()) +
                 " bytes, past what a GLB holds (4 GiB): render fewer frames (--frames) or a "
                 "lower fps"};
  }
  return std::vector<std::uint8_t>(bytes.begin(), bytes.end());
}

Result<void> write_glb(const std::string& path, const GltfScene& scene) {
  const Result<std::vector<std::uint8_t>> bytes = glb_bytes(scene);
  if (!bytes) return Error{path + ": " + bytes.error()};
  Result<AtomicFile> file = AtomicFile::open(path);
  if (!file) return Error{file.error()};
  // A short write is caught by commit(), which checks the stream's error flag.
  std::fwrite(bytes->data(), 1, bytes->size(), file->stream());
  return file->commit();
}

}  // namespace tumble::io
