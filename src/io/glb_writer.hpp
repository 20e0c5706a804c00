// A scene of rigid meshes moving over time as a binary glTF 2.0 file (.glb), written with
// tinygltf (Debian's libtinygltf-dev). The scene is described as plain data (GltfScene: meshes,
// materials, nodes, cameras and one animation of sampled poses), so that io needs no physics and
// no scene: job/gltf_scene.hpp fills it from a render. `[output] formats = ["gltf"]` writes it as
// <scene>.glb; the html replay page embeds glb_bytes().
//
// What the format asks (KhronosGroup/glTF, specification/2.0/Specification.adoc): metres, +y up,
// right-handed (tumble's own axes, so nothing is swizzled); rotations as unit quaternions written
// x, y, z, w; a colour factor in linear light; animation times in seconds, strictly increasing,
// with min and max on every sampler input and on every POSITION. In the GLB the BIN chunk is
// buffers[0], which has no uri, and every chunk is padded to 4 bytes (JSON with spaces, BIN with
// zeros; tinygltf's WriteGltfSceneToStream does both).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/result.hpp"

namespace tumble::io {

// A triangle mesh of one material, in the frame of the nodes that show it (m).
struct GltfMesh {
  std::string name;
  std::vector<std::array<float, 3>> positions;  // node frame (m)
  std::vector<std::array<float, 3>> normals;    // unit, node frame: one per position
  std::vector<std::uint32_t> triangles;  // 3 positions' indices each, counter-clockwise outside
  std::size_t material = 0;              // in GltfScene::materials
};

// A metallic-roughness material without textures.
struct GltfMaterial {
  std::string name;
  // glTF's baseColorFactor: red, green and blue in LINEAR light (not sRGB-encoded), and opacity,
  // each in [0, 1]. An opacity below 1 makes the material blended (alphaMode BLEND).
  std::array<double, 4> base_color = {1.0, 1.0, 1.0, 1.0};
  double metallic = 0.0;   // 0 (a dielectric) to 1 (a metal)
  double roughness = 1.0;  // 0 (a mirror) to 1 (matte)
  bool double_sided = false;
};

// Where a node is: its frame relative to the scene's (glTF's TRS without the scale).
struct GltfPose {
  std::array<double, 3> translation = {0.0, 0.0, 0.0};  // world frame (m)
  // Node-to-world rotation as a quaternion (x, y, z, w): w is the scalar part, as glTF writes
  // it. Need not be exactly unit: the writer normalises.
  std::array<double, 4> rotation = {0.0, 0.0, 0.0, 1.0};
};

// A perspective camera; it looks down its node's -z with +y up (glTF's camera convention).
struct GltfCamera {
  std::string name;
  double yfov = 0.7;          // vertical field of view (rad)
  double aspect_ratio = 1.0;  // width / height of the picture
  double znear = 0.1;         // m, > 0
  double zfar = 100.0;        // m, > znear
};

// A node of the scene, every one a root: a mesh's, a camera's, or an empty one.
struct GltfNode {
  std::string name;
  std::optional<std::size_t> mesh;    // in GltfScene::meshes
  std::optional<std::size_t> camera;  // in GltfScene::cameras
  GltfPose pose;  // where it is when no animation moves it (a body's: its first frame's)
};

// One node's poses at the animation's times: a translation and a rotation channel (LINEAR).
struct GltfTrack {
  std::size_t node = 0;         // in GltfScene::nodes; a node has at most one track
  std::vector<GltfPose> poses;  // one per GltfAnimation::times
};

struct GltfAnimation {
  std::string name;
  std::vector<double> times;  // s, strictly increasing (also once rounded to float)
  std::vector<GltfTrack> tracks;
};

struct GltfScene {
  std::string name;       // the glTF scene's name
  std::string generator;  // asset.generator: "tumble 0.1.0"
  std::vector<GltfMaterial> materials;
  std::vector<GltfMesh> meshes;
  std::vector<GltfCamera> cameras;
  std::vector<GltfNode> nodes;
  std::optional<GltfAnimation> animation;  // none: a still scene
};

// The GLB file's bytes: its 12-byte header, the JSON chunk, the BIN chunk. Every float the
// glTF stores (positions, normals, times, poses) is the double given rounded to float; each
// rotation is normalised, and turned to the sign that keeps it on the side of the track's pose
// before it (q and -q are the same rotation), so that a reader that interpolates component by
// component turns the short way too. Positions, normals and animations are each in bufferViews
// of their own, 4-byte aligned; indices are unsigned shorts when a mesh's positions number at
// most 65536, else unsigned ints. An error names what is inconsistent (an index out of range,
// times not increasing) or a file past GLB's 4 GiB.
Result<std::vector<std::uint8_t>> glb_bytes(const GltfScene& scene);

// glb_bytes written atomically to `path` (io/atomic_file.hpp); the error names the path.
Result<void> write_glb(const std::string& path, const GltfScene& scene);

}  // namespace tumble::io
