// A .glb read back by tinygltf (a reader that knows nothing of io::GltfScene) and held to the
// rules the Khronos glTF-Validator checks first, which tests cannot run (it is an npm package):
// the GLB's header and chunks (KhronosGroup/glTF, specification/2.0/Specification.adoc, "Binary
// glTF Layout"), and the JSON's references, ranges and animation data.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tumble::testing {

// The file's bytes as tinygltf reads them; false with `error` when it cannot.
bool load_glb(const std::vector<std::uint8_t>& bytes, tinygltf::Model& model, std::string& error);

// Every rule the bytes break, one line each; empty when the file passes:
// - the header: magic "glTF", version 2, length the file's;
// - the chunks: JSON then BIN, each a multiple of 4 bytes long and starting on a 4-byte boundary,
//   together the whole file; buffers[0] is the BIN chunk (no uri, its byteLength within 3 bytes
//   of the chunk's);
// - every bufferView within its buffer, every accessor within its bufferView and aligned to its
//   component;
// - min and max present and right on every POSITION and every animation input;
// - animation times strictly increasing, rotations unit (within 1e-6), one output per time;
// - every mesh index below its POSITION count, normals unit (within 1e-5);
// - every index of a node, mesh, material, camera, scene, sampler and channel in range;
//   perspective cameras with 0 < znear < zfar and yfov > 0.
std::vector<std::string> glb_problems(const std::vector<std::uint8_t>& bytes);

// An accessor's floats (FLOAT components only), element after element.
std::vector<float> accessor_floats(const tinygltf::Model& model, int accessor);

// An accessor's unsigned integers (UNSIGNED_BYTE, _SHORT or _INT components).
std::vector<std::uint32_t> accessor_indices(const tinygltf::Model& model, int accessor);

}  // namespace tumble::testing
