#include "render/box_instances.hpp"

#include <algorithm>

#include "render/geometry.hpp"

namespace tumble::render {

std::vector<BoxInstance> box_instances(
    const std::vector<Box>& boxes, const Vec3& eye, Solid solid, std::uint32_t mesh,
    const std::vector<std::array<int, kOccludersPerBody>>* occluders) {
  std::vector<double> distance(boxes.size());  // squared, from the eye to the centre (m²)
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    distance[i] = (boxes[i].position - eye).squaredNorm();
    if (boxes[i].solid == solid && (solid != Solid::hull || boxes[i].mesh == mesh)) {
      order.push_back(i);
    }
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return distance[a] < distance[b]; });
  if (occluders) {
    std::stable_partition(order.begin(), order.end(),
                          [&](std::size_t i) { return (*occluders)[i][0] < 0; });
  }
  std::vector<BoxInstance> out(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Box& box = boxes[order[i]];
    BoxInstance& instance = out[i];
    Eigen::Map<Eigen::Matrix4f>(instance.model) = model_matrix(box).cast<float>();
    Eigen::Map<Eigen::Matrix3f>(instance.rotation) =
        box.orientation.normalized().toRotationMatrix().cast<float>();
    Eigen::Map<Eigen::Vector3f>(instance.size) = box.size.cast<float>();
    Eigen::Map<Eigen::Vector3f>(instance.albedo) = linear_from_srgb(box.color);
    if (occluders) {
      for (int k = 0; k < kOccludersPerBody; ++k) {
        instance.occluders[k] = static_cast<float>((*occluders)[order[i]][k] + 1);
      }
    }
  }
  return out;
}

}  // namespace tumble::render
