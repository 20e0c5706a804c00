#include "scene/mesh_file.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace tumble::scene {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// tinyobjloader's messages end with newlines; one line of them is enough.
std::string first_line(const std::string& text) {
  const std::size_t end = text.find('\n');
  return end == std::string::npos ? text : text.substr(0, end);
}

Result<std::vector<physics::Vec3>> read_obj(const std::string& path) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.mtl_search_path = "";  // no materials: a hull needs the vertices only
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    return Error{path + ": not a readable OBJ file (" +
                 first_line(reader.Error().empty() ? "no message" : reader.Error()) + ")"};
  }
  const std::vector<tinyobj::real_t>& v = reader.GetAttrib().vertices;
  std::vector<physics::Vec3> out;
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
    out.emplace_back(static_cast<double>(v[i]), static_cast<double>(v[i + 1]),
                     static_cast<double>(v[i + 2]));
  }
  return out;
}

Result<std::vector<physics::Vec3>> read_ascii_stl(const std::string& path,
                                                  const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::vector<physics::Vec3> out;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    std::istringstream words(line);
    std::string word;
    if (!(words >> word) || lower(word) != "vertex") continue;
    double x = 0.0, y = 0.0, z = 0.0;
    if (!(words >> x >> y >> z)) {
      return Error{path + ":" + std::to_string(number) +
                   ": a vertex needs three numbers (ASCII STL: vertex x y z)"};
    }
    out.emplace_back(x, y, z);
  }
  return out;
}

Result<std::vector<physics::Vec3>> read_stl(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return Error{path + ": cannot open the mesh file"};
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  // Binary: 80 bytes, a count, 50 bytes a triangle (normal, three corners, 2 bytes), exactly.
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * static_cast<std::size_t>(count)) {
      std::vector<physics::Vec3> out;
      for (std::uint32_t t = 0; t < count; ++t) {
        for (int corner = 0; corner < 3; ++corner) {
          float xyz[3];
          std::memcpy(xyz, bytes.data() + 84 + 50 * static_cast<std::size_t>(t) + 12 + 12 * corner,
                      12);
          out.emplace_back(xyz[0], xyz[1], xyz[2]);
        }
      }
      return out;
    }
  }
  if (bytes.rfind("solid", 0) == 0) return read_ascii_stl(path, bytes);
  return Error{path + ": not an STL file (neither binary, 84 + 50 bytes a triangle, nor ASCII, " +
               "starting with \"solid\")"};
}

}  // namespace

Result<std::vector<physics::Vec3>> read_mesh_vertices(const std::string& path, double scale) {
  const std::string name = lower(path);
  const auto ends_with = [&](const char* suffix) {
    const std::size_t n = std::strlen(suffix);
    return name.size() >= n && name.compare(name.size() - n, n, suffix) == 0;
  };
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return Error{path + ": cannot open the mesh file"};
  // Not a device or a pipe (never ending), and of a size a mesh has.
  if (!std::filesystem::is_regular_file(path, error)) {
    return Error{path + ": a mesh file must be a regular file"};
  }
  if (std::filesystem::file_size(path, error) > kMostMeshBytes) {
    return Error{path + ": a mesh file may have at most " +
                 std::to_string(kMostMeshBytes / (1024 * 1024)) + " MiB"};
  }
  if (!std::ifstream(path)) return Error{path + ": cannot open the mesh file"};
  Result<std::vector<physics::Vec3>> read =
      ends_with(".obj")   ? read_obj(path)
      : ends_with(".stl") ? read_stl(path)
                          : Result<std::vector<physics::Vec3>>(
                                Error{path + ": a mesh file must be OBJ (.obj) or STL (.stl)"});
  if (!read) return read;
  std::vector<physics::Vec3> vertices = std::move(read).value();
  if (vertices.empty()) return Error{path + ": the mesh has no vertex"};
  for (physics::Vec3& v : vertices) {
    if (!v.allFinite()) return Error{path + ": a vertex is not a finite number"};
    v *= scale;
  }
  return vertices;
}

}  // namespace tumble::scene
