// The per-box records of the instanced draw (render/box_instances.hpp).
#include "render/box_instances.hpp"

#include <gtest/gtest.h>

#include "render/geometry.hpp"

namespace tumble::render {
namespace {

TEST(BoxInstances, NearestBoxComesFirstAndEqualDistancesKeepTheirOrder) {
  const Vec3 eye(0, 0, 10);
  std::vector<Box> boxes;
  for (const double z : {-2.0, 3.0, 0.0, 3.0}) {  // boxes 1 and 3 are as far from the eye
    // The x edge tells the boxes apart: 1, 2, 3, 4 m.
    boxes.push_back(Box{.position = Vec3(0, 0, z), .size = Vec3(boxes.size() + 1.0, 1, 1)});
  }
  const std::vector<BoxInstance> instances = box_instances(boxes, eye);
  ASSERT_EQ(instances.size(), 4u);
  const float expected_order[] = {2.0f, 4.0f, 3.0f, 1.0f};  // boxes 1, 3, 2, 0
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(instances[i].size[0], expected_order[i]);
}

TEST(BoxInstances, RecordHoldsTheBoxsMatricesSizeAndLinearColour) {
  const Box box{.position = Vec3(1, 2, 3),
                .orientation = Quat(Eigen::AngleAxisd(0.8, Vec3(1, 2, 0.5).normalized())),
                .size = Vec3(0.2, 0.5, 1.5),
                .color = Color(0.9, 0.5, 0.1)};
  const BoxInstance instance = box_instances({box}, Vec3::Zero()).front();
  EXPECT_EQ(Eigen::Map<const Eigen::Matrix4f>(instance.model), model_matrix(box).cast<float>());
  EXPECT_EQ(Eigen::Map<const Eigen::Matrix3f>(instance.rotation),
            box.orientation.toRotationMatrix().cast<float>());
  EXPECT_EQ(Eigen::Map<const Eigen::Vector3f>(instance.size), box.size.cast<float>());
  EXPECT_EQ(Eigen::Map<const Eigen::Vector3f>(instance.albedo), linear_from_srgb(box.color));
}

}  // namespace
}  // namespace tumble::render
