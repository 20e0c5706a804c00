#include "job/quality_preset.hpp"

namespace tumble::job {

std::optional<QualityPreset> quality_preset(std::string_view name) {
  for (const QualityPreset& preset : kQualityPresets) {
    if (name == preset.name) return preset;
  }
  return std::nullopt;
}

const char* quality_preset_names() {
  return "low, medium, high, production, 4k";
}

}  // namespace tumble::job
