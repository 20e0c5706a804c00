// Mesh files for hull bodies (scene/mesh_file.hpp): the same tetrahedron as OBJ, binary STL and
// ASCII STL gives the same vertices (scaled), and each kind of bad file is an error naming it.
#include "scene/mesh_file.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace tumble::scene {
namespace {

namespace fs = std::filesystem;
using physics::Vec3;

class MeshFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("tumble_mesh_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& bytes) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
  }
  fs::path dir_;
};

const Vec3 kCorners[4] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 2, 0), Vec3(0, 0, 3)};
const int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

TEST_F(MeshFile, ObjAndBothStlsGiveTheSameScaledVertices) {
  std::string obj = "# a tetrahedron\n";
  for (const Vec3& c : kCorners) {
    obj += "v " + std::to_string(c.x()) + " " + std::to_string(c.y()) + " " +
           std::to_string(c.z()) + "\n";
  }
  for (const auto& f : kFaces) {
    obj += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " +
           std::to_string(f[2] + 1) + "\n";
  }
  std::string binary(80, ' ');
  const std::uint32_t count = 4;
  binary.append(reinterpret_cast<const char*>(&count), 4);
  std::string ascii = "solid tetra\n";
  for (const auto& f : kFaces) {
    binary.append(12, '\0');  // the normal, unused
    ascii += " facet normal 0 0 0\n  outer loop\n";
    for (const int k : f) {
      const float xyz[3] = {static_cast<float>(kCorners[k].x()),
                            static_cast<float>(kCorners[k].y()),
                            static_cast<float>(kCorners[k].z())};
      binary.append(reinterpret_cast<const char*>(xyz), 12);
      ascii += "   vertex " + std::to_string(xyz[0]) + " " + std::to_string(xyz[1]) + " " +
               std::to_string(xyz[2]) + "\n";
    }
    binary.append(2, '\0');
    ascii += "  endloop\n endfacet\n";
  }
  ascii += "endsolid tetra\n";
  for (const std::string& path :
       {write("t.obj", obj), write("t.STL", binary), write("a.stl", ascii)}) {
    SCOPED_TRACE(path);
    const Result<std::vector<Vec3>> read = read_mesh_vertices(path, 0.5);
    ASSERT_TRUE(read) << read.error();
    // Every corner, scaled, is among the vertices, and every vertex is a corner.
    for (const Vec3& v : read.value()) {
      double nearest = 1.0;
      for (const Vec3& c : kCorners) nearest = std::min(nearest, (v - 0.5 * c).norm());
      EXPECT_LT(nearest, 1e-7);
    }
    EXPECT_GE(read.value().size(), 4u);
  }
}

TEST_F(MeshFile, BadFilesAreErrorsNamingThem) {
  const std::string missing = (dir_ / "none.obj").string();
  Result<std::vector<Vec3>> read = read_mesh_vertices(missing, 1.0);
  ASSERT_FALSE(read);
  EXPECT_EQ(read.error(), missing + ": cannot open the mesh file");
  const std::string text = write("part.ply", "ply\n");
  read = read_mesh_vertices(text, 1.0);
  ASSERT_FALSE(read);
  EXPECT_EQ(read.error(), text + ": a mesh file must be OBJ (.obj) or STL (.stl)");
  const std::string empty = write("empty.obj", "# nothing\n");
  read = read_mesh_vertices(empty, 1.0);
  ASSERT_FALSE(read);
  EXPECT_EQ(read.error(), empty + ": the mesh has no vertex");
  const std::string short_stl = write("short.stl", std::string(90, 'x'));
  read = read_mesh_vertices(short_stl, 1.0);
  ASSERT_FALSE(read);
  EXPECT_NE(read.error().find("not an STL file"), std::string::npos) << read.error();
}

}  // namespace
}  // namespace tumble::scene
