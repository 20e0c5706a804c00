// job::gltf_scene through a whole render (job::render_scene with [output] formats = ["gltf"]):
// the .glb read back by tinygltf, held to the GLB rules (support/glb_checks.hpp), and its poses
// compared with the states the frames are drawn from, taken again from the same code path
// (view::checked_states_at on a simulation of the scene), not from the writer.
#include "job/gltf_scene.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "job/render_job.hpp"
#include "scene/scene_builder.hpp"
#include "scene/scene_loader.hpp"
#include "support/glb_checks.hpp"
#include "support/scene_text.hpp"
#include "view/scene_view.hpp"

namespace tumble::job {
namespace {

namespace fs = std::filesystem;

class GltfScene : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) /
           ("tumble_gltf_" + std::string(test->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `scene` rendered at 64 × 36 with only a glTF (no frames, no video) into a folder `name`, as
  // tumble render does it; the job into `job`, the .glb's bytes returned.
  std::vector<std::uint8_t> render_gltf(const scene::Scene& scene, const std::string& name,
                                        RenderOptions options = {}) {
    options.width = 64;
    options.height = 36;
    options.formats = {"gltf"};
    options.frames = false;
    options.output_root = (dir_ / name).string();
    Result<RenderJob> made = make_render_job(scene, options);
    EXPECT_TRUE(made) << (made ? "" : made.error());
    if (!made) return {};
    job_ = std::move(*made);
    job_.stills = false;
    fs::create_directories(job_.directory);
    RenderResult result;
    const Result<void> rendered = render_scene(
        job_, job_.directory, [] { return false; }, [](std::int64_t) {}, result);
    EXPECT_TRUE(rendered) << (rendered ? "" : rendered.error());
    std::ifstream file(job_.gltf_path(job_.directory), std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  }

  static scene::Scene scene_file(const std::string& name) {
    Result<scene::Scene> loaded =
        scene::load_scene_file(std::string(TUMBLE_SOURCE_DIR) + "/scenes/" + name);
    EXPECT_TRUE(loaded) << (loaded ? "" : loaded.error());
    return loaded ? std::move(*loaded) : scene::Scene{};
  }

  fs::path dir_;
  RenderJob job_;
};

tinygltf::Model read_back(const std::vector<std::uint8_t>& bytes) {
  tinygltf::Model model;
  std::string error;
  EXPECT_TRUE(testing::load_glb(bytes, model, error)) << error;
  return model;
}

int node_named(const tinygltf::Model& model, const std::string& name) {
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    if (model.nodes[i].name == name) return static_cast<int>(i);
  }
  ADD_FAILURE() << "no node " << name;
  return -1;
}

// The times and the values of the channel that moves `node` along `path`; empty when none does.
struct Channel {
  std::vector<float> times;
  std::vector<float> values;
};
Channel channel(const tinygltf::Model& model, int node, const std::string& path) {
  for (const tinygltf::Animation& animation : model.animations) {
    for (const tinygltf::AnimationChannel& c : animation.channels) {
      if (c.target_node != node || c.target_path != path) continue;
      const tinygltf::AnimationSampler& sampler =
          animation.samplers[static_cast<std::size_t>(c.sampler)];
      return {testing::accessor_floats(model, sampler.input),
              testing::accessor_floats(model, sampler.output)};
    }
  }
  return {};
}

// |q1 - q2| with q2's sign chosen nearer q1 (q and -q are one rotation); q1 as x, y, z, w.
double chord(const float* q1, const physics::Quat& q2) {
  double same = 0.0, opposite = 0.0;
  const double other[4] = {q2.x(), q2.y(), q2.z(), q2.w()};
  for (int i = 0; i < 4; ++i) {
    same += (q1[i] - other[i]) * (q1[i] - other[i]);
    opposite += (q1[i] + other[i]) * (q1[i] + other[i]);
  }
  return std::sqrt(std::min(same, opposite));
}

TEST_F(GltfScene, DroppedCubeFollowsTheInterpolatedStatesAtEveryFrame) {
  // 1.2 s: the fall, the first impact on a corner at 0.63 s and the bounces after it.
  scene::Scene scene = scene_file("dropped_cube.toml");
  RenderOptions options;
  options.duration = 1.2;
  const std::vector<std::uint8_t> bytes = render_gltf(scene, "cube", options);
  ASSERT_FALSE(bytes.empty());
  const std::vector<std::string> problems = testing::glb_problems(bytes);
  EXPECT_TRUE(problems.empty()) << ::testing::PrintToString(problems);
  const tinygltf::Model model = read_back(bytes);
  const int cube = node_named(model, "cube");
  const Channel moves = channel(model, cube, "translation");
  const Channel turns = channel(model, cube, "rotation");
  const std::int64_t frames = job_.frame_count;
  ASSERT_EQ(frames, 72);
  ASSERT_EQ(moves.times.size(), static_cast<std::size_t>(frames));
  ASSERT_EQ(moves.values.size(), 3u * frames);
  ASSERT_EQ(turns.values.size(), 4u * frames);
  EXPECT_EQ(turns.times, moves.times);

  // The reference: the states each frame is drawn from, on a simulation of its own.
  sim::Simulation simulation = scene::build_simulation(job_.scene);
  double worst_translation = 0.0, worst_rotation = 0.0, lowest = 1e9;
  for (std::int64_t k = 0; k < frames; ++k) {
    const double t = static_cast<double>(k) / job_.scene.fps;
    const Result<std::vector<physics::BodyState>> states =
        view::checked_states_at(simulation, job_.scene, t, [] { return false; });
    ASSERT_TRUE(states) << states.error();
    const physics::BodyState& state = states->front();
    const std::size_t i = static_cast<std::size_t>(k);
    EXPECT_EQ(moves.times[i], static_cast<float>(t));
    for (int axis = 0; axis < 3; ++axis) {
      worst_translation = std::max(
          worst_translation,
          std::abs(moves.values[3 * i + static_cast<std::size_t>(axis)] - state.position()[axis]));
    }
    worst_rotation = std::max(worst_rotation, chord(&turns.values[4 * i], state.orientation()));
    lowest = std::min(lowest, state.position().y());
  }
  EXPECT_LE(worst_translation, 1e-6);
  EXPECT_LE(worst_rotation, 1e-6);
  EXPECT_LT(lowest, 1.2);  // the cube did reach the floor: the poses compared are not all a fall
  ::testing::Test::RecordProperty("max_translation_error_m", std::to_string(worst_translation));
  ::testing::Test::RecordProperty("max_rotation_chord", std::to_string(worst_rotation));
  std::printf(
      "dropped cube .glb: %zu bytes; max |translation error| %.3g m, max rotation chord "
      "%.3g\n",
      bytes.size(), worst_translation, worst_rotation);

  // A still camera: a node at the scene's camera, looking at its look_at, and no channel.
  const tinygltf::Node& camera = model.nodes[static_cast<std::size_t>(node_named(model, "camera"))];
  EXPECT_EQ(camera.translation, (std::vector<double>{4.0, 3.0, 7.0}));
  const physics::Quat rotation(camera.rotation[3], camera.rotation[0], camera.rotation[1],
                               camera.rotation[2]);
  const physics::Vec3 looks = rotation * -physics::Vec3::UnitZ();
  EXPECT_NEAR(looks.dot((physics::Vec3(0, 1, 0) - physics::Vec3(4, 3, 7)).normalized()), 1.0,
              1e-12);
  EXPECT_TRUE(channel(model, node_named(model, "camera"), "translation").times.empty());
  ASSERT_EQ(model.cameras.size(), 1u);
  EXPECT_NEAR(model.cameras[0].perspective.yfov, 40.0 * M_PI / 180.0, 1e-15);
  EXPECT_NEAR(model.cameras[0].perspective.aspectRatio, 64.0 / 36.0, 1e-15);
}

TEST_F(GltfScene, TwoRendersGiveTheSameBytesPipelinedOrSerial) {
  const scene::Scene scene = scene_file("dropped_cube.toml");
  RenderOptions options;
  options.duration = 0.5;
  const std::vector<std::uint8_t> first = render_gltf(scene, "first", options);
  options.serial = true;
  const std::vector<std::uint8_t> second = render_gltf(scene, "second", options);
  ASSERT_FALSE(first.empty());
  EXPECT_EQ(first, second);
}

TEST_F(GltfScene, AFrameRangeHoldsThoseFramesAtTheirOwnTimes) {
  RenderOptions options;
  options.first_frame = 10;
  options.end_frame = 20;
  const std::vector<std::uint8_t> bytes =
      render_gltf(scene_file("dropped_cube.toml"), "range", options);
  ASSERT_FALSE(bytes.empty());
  const tinygltf::Model model = read_back(bytes);
  const Channel moves = channel(model, node_named(model, "cube"), "translation");
  ASSERT_EQ(moves.times.size(), 10u);
  EXPECT_EQ(moves.times.front(), static_cast<float>(10.0 / 60.0));
  EXPECT_EQ(moves.times.back(), static_cast<float>(19.0 / 60.0));
}

TEST_F(GltfScene, ShapesKeepTheirSizesAndColoursTurnLinear) {
  // A ball, a capsule, a cylinder, a hull and a wall; an orbiting camera.
  const scene::Scene scene = testing::parse_valid(
      "name = \"shapes\"\nduration = 0.25\n"
      "[[bodies]]\nname = \"ball\"\nshape = \"sphere\"\nradius = 0.25\nmass = 1.0\n"
      "color = \"#808080\"\n"
      "[[bodies]]\nname = \"capsule\"\nshape = \"capsule\"\nradius = 0.1\nlength = 0.6\nmass = "
      "1.0\n"
      "position = [1.0, 0.0, 0.0]\ncolor = \"#ff0000\"\n"
      "[[bodies]]\nname = \"cylinder\"\nshape = \"cylinder\"\nradius = 0.2\nlength = 0.3\nmass = "
      "1.0\n"
      "position = [-1.0, 0.0, 0.0]\n"
      "[[bodies]]\nname = \"hull\"\nshape = \"hull\"\nmass = 1.0\n"
      "points = [[0, 0, 0], [0.4, 0, 0], [0, 0.5, 0], [0, 0, 0.6]]\nposition = [0.0, 0.0, 1.0]\n"
      "[[planes]]\nname = \"wall\"\npoint = [0.0, 0.0, -3.0]\nnormal = [0.0, 0.0, 1.0]\n"
      "size = [4.0, 2.0]\n"
      "[camera]\nposition = [0.0, 2.0, 6.0]\nlook_at = [0.0, 0.0, 0.0]\norbit_period = 2.0\n");
  const std::vector<std::uint8_t> bytes = render_gltf(scene, "shapes");
  ASSERT_FALSE(bytes.empty());
  const std::vector<std::string> problems = testing::glb_problems(bytes);
  EXPECT_TRUE(problems.empty()) << ::testing::PrintToString(problems);
  const tinygltf::Model model = read_back(bytes);
  // Each mesh's box is its body's (m), in the body's frame: the POSITION accessor's max.
  const auto extent = [&](const std::string& name) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(node_named(model, name))];
    const tinygltf::Primitive& p = model.meshes[static_cast<std::size_t>(node.mesh)].primitives[0];
    return model.accessors[static_cast<std::size_t>(p.attributes.at("POSITION"))].maxValues;
  };
  const auto near = [](const std::vector<double>& got, std::vector<double> expected) {
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expected[i], 1e-6) << i;
  };
  near(extent("ball"), {0.25, 0.25, 0.25});
  near(extent("capsule"), {0.1, 0.4, 0.1});  // the half length plus the radius along y
  near(extent("cylinder"), {0.2, 0.15, 0.2});
  near(extent("wall"), {2.0, 0.0, 1.0});  // the quad in its own frame, its front +y
  // #808080 is sRGB 128/255: linear ((128/255 + 0.055) / 1.055)^2.4 = 0.2158605.
  const tinygltf::Node& ball = model.nodes[static_cast<std::size_t>(node_named(model, "ball"))];
  const int material = model.meshes[static_cast<std::size_t>(ball.mesh)].primitives[0].material;
  const std::vector<double>& color =
      model.materials[static_cast<std::size_t>(material)].pbrMetallicRoughness.baseColorFactor;
  EXPECT_NEAR(color[0], 0.2158605, 1e-6);
  EXPECT_NEAR(color[1], 0.2158605, 1e-6);
  EXPECT_EQ(color[3], 1.0);
  // The orbiting camera is animated, and looks at [0, 0, 0] at every frame.
  const int camera = node_named(model, "camera");
  const Channel moves = channel(model, camera, "translation");
  const Channel turns = channel(model, camera, "rotation");
  ASSERT_EQ(moves.times.size(), 15u);
  for (std::size_t k = 0; k < moves.times.size(); ++k) {
    const physics::Vec3 eye(moves.values[3 * k], moves.values[3 * k + 1], moves.values[3 * k + 2]);
    const physics::Quat q(turns.values[4 * k + 3], turns.values[4 * k], turns.values[4 * k + 1],
                          turns.values[4 * k + 2]);
    EXPECT_NEAR((q * -physics::Vec3::UnitZ()).dot(-eye.normalized()), 1.0, 1e-6) << k;
    EXPECT_NEAR(eye.norm(), std::sqrt(40.0), 1e-5) << k;
  }
  // A quarter of the 2 s turn less a frame: x went from 0 to 6 sin(2π · 14/60 / 2).
  EXPECT_NEAR(moves.values[3 * 14], 6.0 * std::sin(M_PI * 14.0 / 60.0), 1e-5);
}

}  // namespace
}  // namespace tumble::job
