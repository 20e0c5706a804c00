#include "physics/convex_hull.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

extern "C" {
#include <libqhull_r/libqhull_r.h>
}

namespace tumble::physics {
namespace {

// How far the points reach off the plane that fits them best (m), and their extent (m): the
// smallest singular value of their spread about the mean, against the largest.
std::pair<double, double> thickness(std::span<const Vec3> points) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Mat3 spread = Mat3::Zero();
  for (const Vec3& p : points) spread += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(spread / static_cast<double>(points.size()));
  const Vec3 values = solver.eigenvalues().cwiseMax(0.0);
  return {std::sqrt(values.x()), std::sqrt(values.z())};
}

// Qhull's state, freed whatever happens.
class Qhull {
 public:
  Qhull() { qh_zero(&qh_, nullptr); }
  ~Qhull() {
    qh_freeqhull(&qh_, !qh_ALL);
    int long_left = 0, total_left = 0;
    qh_memfreeshort(&qh_, &long_left, &total_left);
  }
  Qhull(const Qhull&) = delete;
  Qhull& operator=(const Qhull&) = delete;
  qhT* get() { return &qh_; }

 private:
  qhT qh_;
};

// The face's corners in counter-clockwise order about its outward `normal`, starting from the
// lowest index so that the order is the same on every run.
void wind(const std::vector<Vec3>& vertices, const Vec3& normal, std::vector<std::uint32_t>& face) {
  Vec3 centre = Vec3::Zero();
  for (const std::uint32_t v : face) centre += vertices[v];
  centre /= static_cast<double>(face.size());
  const Vec3 u = (vertices[face[0]] - centre).normalized();
  const Vec3 w = normal.cross(u);
  std::vector<std::pair<double, std::uint32_t>> by_angle;
  for (const std::uint32_t v : face) {
    const Vec3 d = vertices[v] - centre;
    by_angle.emplace_back(std::atan2(d.dot(w), d.dot(u)), v);
  }
  std::sort(by_angle.begin(), by_angle.end());
  for (std::size_t k = 0; k < face.size(); ++k) face[k] = by_angle[k].second;
  std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
}

// Into `out`: the corners and faces of the hull Qhull built of `points`, the faces' corners in
// Qhull's order and their outward normals.
void read_hull(qhT* qh, std::span<const Vec3> points, ConvexHull& out) {  // `qh`: as FOR* name it
  std::map<int, std::uint32_t> index_of;  // Qhull's point id to the hull's corner
  facetT* facet = nullptr;
  vertexT* vertex = nullptr;
  vertexT** vertexp = nullptr;
  FORALLfacets {
    std::vector<std::uint32_t> face;
    FOREACHvertex_(facet->vertices) {
      const int id = qh_pointid(qh, vertex->point);
      const auto [at, added] =
          index_of.try_emplace(id, static_cast<std::uint32_t>(out.vertices.size()));
      if (added) out.vertices.push_back(points[static_cast<std::size_t>(id)]);
      face.push_back(at->second);
    }
    const Vec3 normal(facet->normal[0], facet->normal[1], facet->normal[2]);  // outward
    out.faces.push_back(std::move(face));
    out.normals.push_back(normal.normalized());
  }
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> ConvexHull::triangles() const {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const std::vector<std::uint32_t>& face : faces) {
    for (std::size_t k = 1; k + 1 < face.size(); ++k)
      out.push_back({face[0], face[k], face[k + 1]});
  }
  return out;
}

Result<ConvexHull> convex_hull(std::span<const Vec3> points) {
  if (points.size() < 4) {
    return Error{"a hull needs at least 4 points that do not lie on one plane (got " +
                 std::to_string(points.size()) + ")"};
  }
  const auto [thin, wide] = thickness(points);
  if (!(wide > 0.0) || thin <= 1e-9 * wide) {
    char reach[64];
    std::snprintf(reach, sizeof reach, "%.3g m", thin);
    return Error{"a hull needs at least 4 points that do not lie on one plane (these " +
                 std::to_string(points.size()) + " reach " + reach + " off their plane)"};
  }
  std::vector<coordT> coordinates;
  coordinates.reserve(3 * points.size());
  for (const Vec3& p : points) coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
  // Qhull's messages go to a stream in memory, closed only once Qhull is freed (it may write
  // there until then).
  char* message = nullptr;
  std::size_t message_size = 0;
  FILE* errors = open_memstream(&message, &message_size);
  ConvexHull hull;
  int code = 0;
  {
    Qhull qhull;
    char command[] = "qhull";
    code = qh_new_qhull(qhull.get(), 3, static_cast<int>(points.size()), coordinates.data(), False,
                        command, nullptr, errors);
    if (code == 0) read_hull(qhull.get(), points, hull);
  }
  std::fclose(errors);
  const std::string said = message ? std::string(message, message_size) : std::string();
  std::free(message);
  if (code != 0) return Error{"the hull's points could not be wrapped (Qhull: " + said + ")"};
  for (std::size_t f = 0; f < hull.faces.size(); ++f) {
    wind(hull.vertices, hull.normals[f], hull.faces[f]);
  }
  return hull;
}

}  // namespace tumble::physics
