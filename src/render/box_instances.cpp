#include "render/box_instances.hpp"

#include "render/geometry.hpp"

namespace tumble::render {

std::vector<BoxInstance> box_instances(const std::vector<Box>& boxes) {
  std::vector<BoxInstance> out(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Box& box = boxes[i];
    BoxInstance& instance = out[i];
    Eigen::Map<Eigen::Matrix4f>(instance.model) = model_matrix(box).cast<float>();
    Eigen::Map<Eigen::Matrix3f>(instance.rotation) =
        box.orientation.normalized().toRotationMatrix().cast<float>();
    Eigen::Map<Eigen::Vector3f>(instance.size) = box.size.cast<float>();
    Eigen::Map<Eigen::Vector3f>(instance.albedo) = linear_from_srgb(box.color);
  }
  return out;
}

}  // namespace tumble::render
