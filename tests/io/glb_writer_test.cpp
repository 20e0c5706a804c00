// io::glb_bytes: a small scene written and read back by tinygltf, held to the GLB rules
// (support/glb_checks.hpp), its values as given, its errors.
#include "io/glb_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/glb_checks.hpp"

namespace tumble::io {
namespace {

// A tetrahedron (5 positions: one unused is allowed), a camera and a moving node.
GltfScene small_scene() {
  GltfScene scene;
  scene.name = "small";
  scene.generator = "tumble test";
  scene.materials.push_back({.name = "red", .base_color = {0.8, 0.1, 0.05, 1.0}});
  GltfMesh mesh;
  mesh.name = "tetrahedron";
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 2, 2}};
  mesh.normals = {{0, 0, -1}, {0, -1, 0}, {-1, 0, 0}, {0.6f, 0.8f, 0}, {0, 1, 0}};
  mesh.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  scene.meshes.push_back(mesh);
  scene.cameras.push_back(
      {.name = "camera", .yfov = 0.7, .aspect_ratio = 1.5, .znear = 0.1, .zfar = 50.0});
  scene.nodes.push_back({.name = "body", .mesh = 0, .camera = {}, .pose = {}});
  scene.nodes.push_back({.name = "camera",
                         .mesh = {},
                         .camera = 0,
                         .pose = {.translation = {0, 1, 5}, .rotation = {0, 0, 0, 1}}});
  GltfAnimation animation{.name = "motion", .times = {0.0, 0.5, 1.0}, .tracks = {}};
  // The second rotation is the first's negative (the same turn), the third twice as long as unit.
  animation.tracks.push_back({.node = 0,
                              .poses = {{.translation = {0, 3, 0}, .rotation = {0, 0, 0.6, 0.8}},
                                        {.translation = {0, 2, 0}, .rotation = {0, 0, -0.6, -0.8}},
                                        {.translation = {1, 1, 0}, .rotation = {0, 0, 2, 0}}}});
  scene.animation = animation;
  return scene;
}

tinygltf::Model read_back(const std::vector<std::uint8_t>& bytes) {
  tinygltf::Model model;
  std::string error;
  EXPECT_TRUE(testing::load_glb(bytes, model, error)) << error;
  return model;
}

TEST(GlbWriter, ASmallSceneKeepsTheGlbRules) {
  const Result<std::vector<std::uint8_t>> bytes = glb_bytes(small_scene());
  ASSERT_TRUE(bytes) << bytes.error();
  const std::vector<std::string> problems = testing::glb_problems(*bytes);
  EXPECT_TRUE(problems.empty()) << ::testing::PrintToString(problems);
  EXPECT_EQ(bytes->size() % 4, 0u);
}

TEST(GlbWriter, ValuesReadBackAsGiven) {
  const Result<std::vector<std::uint8_t>> bytes = glb_bytes(small_scene());
  ASSERT_TRUE(bytes) << bytes.error();
  const tinygltf::Model model = read_back(*bytes);
  EXPECT_EQ(model.asset.generator, "tumble test");
  ASSERT_EQ(model.meshes.size(), 1u);
  const tinygltf::Primitive& primitive = model.meshes[0].primitives.at(0);
  EXPECT_EQ(testing::accessor_indices(model, primitive.indices), small_scene().meshes[0].triangles);
  const std::vector<float> positions =
      testing::accessor_floats(model, primitive.attributes.at("POSITION"));
  ASSERT_EQ(positions.size(), 15u);
  EXPECT_EQ(positions[12], 2.0f);
  const tinygltf::Material& material = model.materials.at(0);
  EXPECT_EQ(material.pbrMetallicRoughness.baseColorFactor,
            (std::vector<double>{0.8, 0.1, 0.05, 1.0}));
  EXPECT_EQ(material.pbrMetallicRoughness.metallicFactor, 0.0);
  ASSERT_EQ(model.cameras.size(), 1u);
  EXPECT_DOUBLE_EQ(model.cameras[0].perspective.aspectRatio, 1.5);
  EXPECT_EQ(model.nodes.at(1).camera, 0);
  EXPECT_EQ(model.nodes.at(1).translation, (std::vector<double>{0, 1, 5}));
  ASSERT_EQ(model.animations.size(), 1u);
  const tinygltf::Animation& animation = model.animations[0];
  ASSERT_EQ(animation.channels.size(), 2u);
  EXPECT_EQ(animation.channels[0].target_path, "translation");
  EXPECT_EQ(animation.channels[1].target_path, "rotation");
  const std::vector<float> times = testing::accessor_floats(model, animation.samplers[0].input);
  EXPECT_EQ(times, (std::vector<float>{0.0f, 0.5f, 1.0f}));
  const std::vector<float> moves = testing::accessor_floats(
      model, animation.samplers[static_cast<std::size_t>(animation.channels[0].sampler)].output);
  EXPECT_EQ(moves, (std::vector<float>{0, 3, 0, 0, 2, 0, 1, 1, 0}));
  // Unit, x y z w, and each on the side of the one before: -q comes back as q; (0, 0, 2, 0) as
  // (0, 0, 1, 0), whose dot with (0, 0, 0.6, 0.8) is positive.
  const std::vector<float> turns = testing::accessor_floats(
      model, animation.samplers[static_cast<std::size_t>(animation.channels[1].sampler)].output);
  EXPECT_EQ(turns, (std::vector<float>{0, 0, 0.6f, 0.8f, 0, 0, 0.6f, 0.8f, 0, 0, 1, 0}));
}

TEST(GlbWriter, TheSameSceneGivesTheSameBytes) {
  const Result<std::vector<std::uint8_t>> first = glb_bytes(small_scene());
  const Result<std::vector<std::uint8_t>> second = glb_bytes(small_scene());
  ASSERT_TRUE(first && second);
  EXPECT_EQ(*first, *second);
}

TEST(GlbWriter, ManyPositionsTakeUnsignedIntIndices) {
  GltfScene scene = small_scene();
  GltfMesh& mesh = scene.meshes[0];
  mesh.positions.resize(70000, {0, 0, 0});
  mesh.normals.resize(70000, {0, 1, 0});
  mesh.triangles.insert(mesh.triangles.end(), {0, 1, 69999});
  const Result<std::vector<std::uint8_t>> bytes = glb_bytes(scene);
  ASSERT_TRUE(bytes) << bytes.error();
  EXPECT_TRUE(testing::glb_problems(*bytes).empty());
  const tinygltf::Model model = read_back(*bytes);
  const tinygltf::Primitive& primitive = model.meshes[0].primitives.at(0);
  EXPECT_EQ(model.accessors[static_cast<std::size_t>(primitive.indices)].componentType,
            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  EXPECT_EQ(testing::accessor_indices(model, primitive.indices).back(), 69999u);
}

TEST(GlbWriter, InconsistentScenesAreRefusedNamingWhat) {
  GltfScene scene = small_scene();
  scene.meshes[0].triangles.push_back(5);
  scene.meshes[0].triangles.insert(scene.meshes[0].triangles.end(), {0, 1});
  Result<std::vector<std::uint8_t>> bytes = glb_bytes(scene);
  ASSERT_FALSE(bytes);
  EXPECT_NE(bytes.error().find("index 5 of 5 positions"), std::string::npos) << bytes.error();

  scene = small_scene();
  scene.nodes[0].mesh = 3;
  bytes = glb_bytes(scene);
  ASSERT_FALSE(bytes);
  EXPECT_NE(bytes.error().find("node body: mesh 3 of 1"), std::string::npos) << bytes.error();

  scene = small_scene();
  scene.animation->times = {0.0, 1.0, 1.0};
  bytes = glb_bytes(scene);
  ASSERT_FALSE(bytes);
  EXPECT_NE(bytes.error().find("strictly increasing"), std::string::npos) << bytes.error();

  scene = small_scene();
  scene.animation->tracks[0].poses[1].rotation = {0, 0, 0, 0};
  bytes = glb_bytes(scene);
  ASSERT_FALSE(bytes);
  EXPECT_NE(bytes.error().find("pose 1"), std::string::npos) << bytes.error();

  scene = small_scene();
  scene.cameras[0].zfar = 0.05;
  EXPECT_FALSE(glb_bytes(scene));
}

TEST(GlbWriter, AStillSceneHasNoAnimation) {
  GltfScene scene = small_scene();
  scene.animation.reset();
  const Result<std::vector<std::uint8_t>> bytes = glb_bytes(scene);
  ASSERT_TRUE(bytes) << bytes.error();
  EXPECT_TRUE(testing::glb_problems(*bytes).empty());
  EXPECT_TRUE(read_back(*bytes).animations.empty());
}

TEST(GlbWriter, TheCheckerFindsABrokenHeaderAndAMisalignedChunk) {
  // The checker must be able to fail: a wrong version, then a length off by one.
  Result<std::vector<std::uint8_t>> bytes = glb_bytes(small_scene());
  ASSERT_TRUE(bytes);
  std::vector<std::uint8_t> broken = *bytes;
  broken[4] = 1;
  EXPECT_FALSE(testing::glb_problems(broken).empty());
  broken = *bytes;
  broken.push_back(0);
  EXPECT_FALSE(testing::glb_problems(broken).empty());
}

TEST(GlbWriter, WriteGlbNamesAPathItCannotWrite) {
  const Result<void> written = write_glb("/nonexistent-folder/x.glb", small_scene());
  ASSERT_FALSE(written);
  EXPECT_NE(written.error().find("/nonexistent-folder/x.glb"), std::string::npos);
}

}  // namespace
}  // namespace tumble::io
