#include "pirouette/vision/mask_source.h"

namespace pirouette::vision {

std::optional<MaskSource> ParseMaskSource(std::string_view name) {
  if (name == "paper") return MaskSource::kPaper;
  if (name == "default") return MaskSource::kDefault;
  if (name == "truth") return MaskSource::kTruth;
  return std::nullopt;
}

std::string_view MaskSourceName(MaskSource source) {
  switch (source) {
    case MaskSource::kPaper:
      return "paper";
    case MaskSource::kDefault:
      return "default";
    case MaskSource::kTruth:
      return "truth";
  }
  return "default";
}

}  // namespace pirouette::vision
