// The vertices of a mesh file, for a hull body (scene key `mesh`): Wavefront OBJ (read by
// tinyobjloader, Debian's libtinyobjloader-dev) or STL, binary or ASCII (read here: the format is
// 80 bytes of header, a triangle count and 50 bytes a triangle; or "solid", then "vertex x y z"
// lines). Errors name the file, and the line where the format has lines.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "physics/rigid_body.hpp"

namespace tumble::scene {

// A mesh file is read whole: at most this many bytes (64 MiB, a million triangles of binary STL).
inline constexpr std::uintmax_t kMostMeshBytes = 64u * 1024u * 1024u;

// Every vertex of the mesh at `path` (its units, scaled by `scale`): an error when the file cannot
// be read (or is not a regular file, or is larger than kMostMeshBytes), is not OBJ or STL (by its
// extension, .obj or .stl, any case), does not parse, or has no vertex.
Result<std::vector<physics::Vec3>> read_mesh_vertices(const std::string& path, double scale);

}  // namespace tumble::scene
