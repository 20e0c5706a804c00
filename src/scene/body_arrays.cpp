#include "scene/body_arrays.hpp"

#include <algorithm>
#include <string>

#include "scene/limits.hpp"
#include "sim/simulation.hpp"

namespace tumble::scene::detail {
namespace {

using physics::Vec3;

// Body colours when a scene gives none (sRGB): distinct, and calm enough for documentation.
const std::array<Vec3, 5> kPalette = {Vec3(0.89, 0.40, 0.18), Vec3(0.20, 0.51, 0.78),
                                      Vec3(0.35, 0.67, 0.33), Vec3(0.85, 0.70, 0.20),
                                      Vec3(0.60, 0.40, 0.70)};

// One count: a whole number from 1 to kMaxBodies.
std::int64_t count_of(const TableReader& in, const toml::node& node) {
  if (!node.is_integer()) {
    in.fail("count", "expected a whole number of bodies, or [nx, ny, nz], found " +
                         (node.is_floating_point() ? format_number(*node.value<double>())
                                                   : std::string(type_name(node))));
  }
  const std::int64_t value = node.as_integer()->get();
  if (value < 1 || value > kMaxBodies) {
    in.fail("count", "must be from 1 to " + std::to_string(kMaxBodies) + " (got " +
                         std::to_string(value) + ")");
  }
  return value;
}

// count = n (a line) or [nx, ny, nz] (a grid) into `array`, and its steps from `spacing`.
void read_counts(TableReader& in, BodyArray& array) {
  const toml::node& count = *in.table().get("count");
  if (!in.has("spacing")) {
    in.fail("count", "a body array needs spacing = [x, y, z] (m) beside its count");
  }
  const Vec3 spacing = in.required_vector("spacing");
  if (const toml::array* grid = count.as_array()) {
    if (grid->size() != 3) {
      in.fail("count", "expected a whole number, or [nx, ny, nz] for a grid, found an array of " +
                           std::to_string(grid->size()));
    }
    for (int axis = 0; axis < 3; ++axis) {
      const auto a = static_cast<std::size_t>(axis);
      array.counts[a] = count_of(in, (*grid)[a]);
      array.steps[a][axis] = spacing[axis];
      if (array.counts[a] > 1 && spacing[axis] == 0.0) {
        in.fail("spacing", std::string("spacing along ") + "xyz"[axis] + " is 0 but the grid has " +
                               std::to_string(array.counts[a]) +
                               " bodies that way: they would all be in one place");
      }
    }
  } else {
    array.counts[0] = count_of(in, count);
    array.steps[0] = spacing;
    if (array.counts[0] > 1 && spacing.isZero(0.0)) {
      in.fail("spacing", "must not be [0, 0, 0]: every body of the line would be in one place");
    }
  }
  if (array.size() > kMaxBodies) {
    in.fail("count", std::to_string(array.size()) + " bodies, more than the limit of " +
                         std::to_string(kMaxBodies));
  }
}

}  // namespace

common::Color default_body_color(std::size_t index) {
  return kPalette[index % kPalette.size()];
}

BodyArray read_body_array(TableReader& in, const Vec3& position) {
  BodyArray array;
  array.written = in.has("count");
  if (!array.written) {
    for (const char* key : {"spacing", "colors"}) {
      if (in.has(key)) in.fail(key, std::string("only a body array (count = n) takes ") + key);
    }
    return array;
  }
  read_counts(in, array);
  // The farthest body from the origin is at a corner of the array's box (its distance is
  // convex): each of the 8, first body's and last body's ends along each axis.
  double reach = 0.0;  // m
  for (int corner = 0; corner < 8; ++corner) {
    Vec3 at = position;
    for (std::size_t a = 0; a < 3; ++a) {
      if (corner & (1 << a)) at += static_cast<double>(array.counts[a] - 1) * array.steps[a];
    }
    reach = std::max(reach, at.stableNorm());
  }
  if (!(reach <= sim::kMaxPosition)) {
    in.fail("spacing", "puts the array's farthest body " + format_number(reach) +
                           " m from the origin, past the " + format_number(sim::kMaxPosition) +
                           " m tumble can simulate");
  }
  if (in.has("colors")) {
    if (in.has("color")) in.fail("colors", "give color (every body) or colors (in turn), not both");
    const toml::array* colors = in.table().get("colors")->as_array();
    if (!colors || colors->empty()) {
      in.fail("colors", "expected an array of one or more colours [\"#rrggbb\", [r, g, b], ...]");
    }
    for (const toml::node& color : *colors) array.colors.push_back(in.color("colors", color));
  }
  return array;
}

std::vector<BodySpec> expand_body_array(TableReader& in, const BodySpec& body,
                                        const BodyArray& array, std::size_t index) {
  if (!array.written) return {body};
  const std::string last_name = body.name + "_" + std::to_string(array.size() - 1);
  if (!is_safe_name(last_name)) {
    in.fail("name",
            "the array's names (up to " + in_quotes(last_name) + ") " + std::string(kSafeNameRule));
  }
  const bool colored = in.has("color");
  std::vector<BodySpec> out;
  out.reserve(static_cast<std::size_t>(array.size()));
  for (std::int64_t k = 0; k < array.counts[2]; ++k) {
    for (std::int64_t j = 0; j < array.counts[1]; ++j) {
      for (std::int64_t i = 0; i < array.counts[0]; ++i) {
        const std::size_t n = out.size();
        BodySpec copy = body;
        copy.name = body.name + "_" + std::to_string(n);
        copy.position = body.position + static_cast<double>(i) * array.steps[0] +
                        static_cast<double>(j) * array.steps[1] +
                        static_cast<double>(k) * array.steps[2];
        if (!array.colors.empty()) {
          copy.color = array.colors[n % array.colors.size()];
        } else if (!colored) {
          copy.color = default_body_color(index + n);
        }
        out.push_back(std::move(copy));
      }
    }
  }
  return out;
}

}  // namespace tumble::scene::detail
